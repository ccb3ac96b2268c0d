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

std::string describeLocation(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                             const UpAxis& up) {
  static const char* kY[] = {"bottom", "", "top"};
  static const char* kX[] = {"left", "", "right"};
  static const char* kZ[] = {"back", "", "front"};
  // The box turned into the up frame is still a box: its corners' min and max along each up-frame axis.
  const Eigen::Matrix3d r = upFrame(up);
  const Eigen::Vector3d a = r * lo, b = r * hi, q = r * p;
  const Eigen::Vector3d boxLo = a.cwiseMin(b), boxHi = a.cwiseMax(b);
  std::vector<std::string> words;
  const int y = third(q.y(), boxLo.y(), boxHi.y());
  const int x = third(q.x(), boxLo.x(), boxHi.x());
  const int z = third(q.z(), boxLo.z(), boxHi.z());
  if (y != 1) words.push_back(kY[y]);
  if (x != 1) words.push_back(kX[x]);
  if (z != 1) words.push_back(kZ[z]);
  if (words.empty()) return "near the middle of the shape";
  std::string s = "near the";
  for (const auto& w : words) s += " " + w;
  return s + " of the shape";
}

}  // namespace billow
