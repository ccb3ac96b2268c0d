#include "simulate/enclosed_volume.hpp"

#include "util/skew.hpp"

namespace billow {
namespace {}  // namespace

void triangleVolumeDerivatives(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                               Vector9d* grad, Matrix9d* hess) {
  if (grad) {
    grad->segment<3>(0) = b.cross(c) / 6.0;
    grad->segment<3>(3) = c.cross(a) / 6.0;
    grad->segment<3>(6) = a.cross(b) / 6.0;
  }
  if (hess) {
    const Eigen::Vector3d x[3] = {a, b, c};
    hess->setZero();
    // Block (i, j), j = i+1 cyclic, is d/dx_j of (x_j x x_k)/6 = -[x_k]x / 6 with k the remaining corner.
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const Eigen::Matrix3d block = -skew(x[k]) / 6.0;
      hess->block<3, 3>(3 * i, 3 * j) = block;
      hess->block<3, 3>(3 * j, 3 * i) = block.transpose();
    }
  }
}

}  // namespace billow
