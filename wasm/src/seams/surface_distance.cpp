#include "seams/surface_distance.hpp"

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

}  // namespace billow
