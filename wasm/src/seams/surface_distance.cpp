#include "seams/surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace billow {

Eigen::VectorXd signedDistances(const TriMesh& target, const SurfaceProjector& projector, const Vertices& points) {
  Eigen::VectorXd d(points.rows());
  for (int i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose();
    double distance = 0;
    const SurfacePoint p = projector.project(q, &distance);
    const Eigen::Vector3d a = target.V.row(target.F(p.face, 0)).transpose();
    const Eigen::Vector3d b = target.V.row(target.F(p.face, 1)).transpose();
    const Eigen::Vector3d c = target.V.row(target.F(p.face, 2)).transpose();
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    d[i] = (q - position(target, p)).dot(normal) < 0 ? -distance : distance;
  }
  return d;
}

DistanceSummary summarizeDistances(const Eigen::VectorXd& distances, const Triangles& surface, double diagonal) {
  std::vector<char> used(distances.size(), surface.rows() == 0);
  for (int t = 0; t < surface.rows(); ++t)
    for (int k = 0; k < 3; ++k) used[surface(t, k)] = 1;
  DistanceSummary s;
  int n = 0;
  for (int v = 0; v < distances.size(); ++v) {
    if (!used[v]) continue;
    s.rms += distances[v] * distances[v], s.max = std::max(s.max, std::abs(distances[v])), ++n;
  }
  s.rms = n ? std::sqrt(s.rms / n) / diagonal : 0;
  s.max /= diagonal;
  return s;
}

}  // namespace billow
