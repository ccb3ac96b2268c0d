#include "optimize/optimization_target.hpp"

#include <optional>

#include "mesh/simplify.hpp"
#include "seams/surface_point.hpp"

namespace billow {

OptimizationTarget::OptimizationTarget(const TriMesh& target, const ImlsOptions& options) {
  std::optional<TriMesh> copy = workingCopy(target);
  if (!copy) {
    distance_ = std::make_unique<ImlsDistance>(target, options);
    return;
  }
  distance_ = std::make_unique<ImlsDistance>(*copy, options);
  whole_ = std::make_unique<TriMesh>(target);
  wholeProjector_ = std::make_unique<SurfaceProjector>(*whole_);
}

OptimizationTarget::~OptimizationTarget() = default;

double OptimizationTarget::closestDistance(const Eigen::Vector3d& x, int* face) const {
  if (!wholeProjector_) return distance_->closestDistance(x, face);
  double d = 0;
  const SurfacePoint p = wholeProjector_->project(x, &d, face ? *face : -1);
  if (face) *face = p.face;
  return d;
}

}  // namespace billow
