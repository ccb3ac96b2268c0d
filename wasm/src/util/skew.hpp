// The cross-product matrix: skew(v) w = v x w, for rotations (rigid alignment) and volume derivatives.
#pragma once
#include <Eigen/Dense>

namespace billow {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

}  // namespace billow
