// Where on a shape a point is, in words a designer can follow ("near the top left front").
#pragma once
#include <Eigen/Core>
#include <string>

#include "mesh/up_axis.hpp"

namespace billow {

// Describes p relative to the box [lo, hi] of the target's own coordinates, read as the target stands on `up`
// (then y up, x right, z towards the viewer, as in the target pane).
std::string describeLocation(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                             const UpAxis& up = {});

}  // namespace billow
