// The target as the pattern optimizer measures it. E_target and E_cover are measured on the target's working copy
// where it is a fine one (mesh/simplify.hpp workingCopy): on five scans of 27,000-100,000 triangles the rigid
// alignment's distances took 48 s of 131, on their copies 26 s of 107, at the same distances (bench/README.md "The
// target's resolution"). The figures, the distance both ways, are measured on the target itself.
#pragma once
#include <Eigen/Core>
#include <memory>

#include "mesh/tri_mesh.hpp"
#include "optimize/imls_distance.hpp"

namespace billow {

class SurfaceProjector;

class OptimizationTarget {
 public:
  // target: closed, outward-oriented [m]; copied.
  explicit OptimizationTarget(const TriMesh& target, const ImlsOptions& options = {});
  ~OptimizationTarget();

  // E_target's and E_cover's: on the working copy of a fine target, else on the target.
  const ImlsDistance& distance() const { return *distance_; }
  // What the figures measure: the target itself.
  const TriMesh& whole() const { return whole_ ? *whole_ : distance_->target(); }
  bool copied() const { return whole_ != nullptr; }
  // Unsigned distance from x to the closest point of whole() [m]; face as ImlsDistance::closestDistance's.
  double closestDistance(const Eigen::Vector3d& x, int* face = nullptr) const;

 private:
  std::unique_ptr<ImlsDistance> distance_;
  std::unique_ptr<TriMesh> whole_;  // only where distance_ is on a copy
  std::unique_ptr<SurfaceProjector> wholeProjector_;
};

}  // namespace billow
