#include "mesh/location.hpp"

#include <vector>

namespace billow {

namespace {
// Thirds of the box along one axis: low, middle, high.
int third(double v, double lo, double hi) {
  const double extent = hi - lo;
  if (extent <= 0) return 1;
  const double t = (v - lo) / extent;
  return t < 1.0 / 3.0 ? 0 : (t > 2.0 / 3.0 ? 2 : 1);
}
}  // namespace

std::string describeLocation(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  static const char* kY[] = {"bottom", "", "top"};
  static const char* kX[] = {"left", "", "right"};
  static const char* kZ[] = {"back", "", "front"};
  std::vector<std::string> words;
  const int y = third(p.y(), lo.y(), hi.y());
  const int x = third(p.x(), lo.x(), hi.x());
  const int z = third(p.z(), lo.z(), hi.z());
  if (y != 1) words.push_back(kY[y]);
  if (x != 1) words.push_back(kX[x]);
  if (z != 1) words.push_back(kZ[z]);
  if (words.empty()) return "near the middle of the shape";
  std::string s = "near the";
  for (const auto& w : words) s += " " + w;
  return s + " of the shape";
}

}  // namespace billow
