#include "suggest/valleys.hpp"

#include <algorithm>
#include <cmath>

namespace billow {

namespace {

// Levels the girth is measured at, evenly across the extent: a valley narrower than the extent over this is missed.
constexpr int kGirthLevels = 96;

// The girth at each of `levels` (ascending) along `axis`: each face the plane crosses adds the segment it cuts.
std::vector<double> girthAt(const TriMesh& target, int axis, const std::vector<double>& levels) {
  std::vector<double> girth(levels.size(), 0.0);
  for (int f = 0; f < target.F.rows(); ++f) {
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) p[k] = target.V.row(target.F(f, k)).transpose();
    const double lo = std::min({p[0][axis], p[1][axis], p[2][axis]});
    const double hi = std::max({p[0][axis], p[1][axis], p[2][axis]});
    auto first = std::lower_bound(levels.begin(), levels.end(), lo);
    for (auto it = first; it != levels.end() && *it < hi; ++it) {
      const double t = *it;
      Eigen::Vector3d cut[2];
      int n = 0;
      for (int k = 0; k < 3 && n < 2; ++k) {
        const Eigen::Vector3d &a = p[k], &b = p[(k + 1) % 3];
        const double da = a[axis] - t, db = b[axis] - t;
        if ((da < 0) != (db < 0)) cut[n++] = a + (b - a) * (da / (da - db));
      }
      if (n == 2) girth[size_t(it - levels.begin())] += (cut[0] - cut[1]).norm();
    }
  }
  return girth;
}

}  // namespace

std::vector<Valley> findValleys(const TriMesh& target, int axis, double minDepth) {
  std::vector<Valley> out;
  if (target.F.rows() == 0) return out;
  const double lo = target.V.col(axis).minCoeff(), hi = target.V.col(axis).maxCoeff(), extent = hi - lo;
  if (!(extent > 0)) return out;
  std::vector<double> levels(kGirthLevels);
  for (int i = 0; i < kGirthLevels; ++i) levels[size_t(i)] = lo + (i + 0.5) / kGirthLevels * extent;
  const std::vector<double> raw = girthAt(target, axis, levels);
  // Averaged over three levels: a mesh's rows of edges make the girth ripple from level to level.
  std::vector<double> girth(raw.size());
  for (size_t i = 0; i < raw.size(); ++i)
    girth[i] = (raw[i > 0 ? i - 1 : i] + raw[i] + raw[i + 1 < raw.size() ? i + 1 : i]) / 3;
  std::vector<double> widestBefore(girth.size()), widestAfter(girth.size());
  for (size_t i = 0; i < girth.size(); ++i) widestBefore[i] = std::max(i > 0 ? widestBefore[i - 1] : 0.0, girth[i]);
  for (size_t i = girth.size(); i-- > 0;)
    widestAfter[i] = std::max(i + 1 < girth.size() ? widestAfter[i + 1] : 0.0, girth[i]);
  std::vector<Valley> candidates;
  for (size_t i = 1; i + 1 < girth.size(); ++i) {
    if (!(girth[i] < girth[i - 1] && girth[i] <= girth[i + 1])) continue;
    const double depth = 1 - girth[i] / std::min(widestBefore[i - 1], widestAfter[i + 1]);
    if (depth >= minDepth) candidates.push_back({levels[i], depth});
  }
  std::sort(candidates.begin(), candidates.end(), [](const Valley& a, const Valley& b) { return a.depth > b.depth; });
  for (const Valley& v : candidates)
    if (std::none_of(out.begin(), out.end(),
                     [&](const Valley& w) { return std::abs(w.level - v.level) < kValleyApart * extent; }))
      out.push_back(v);
  return out;
}

}  // namespace billow
