// Enclosed volume of the outer surface and its exact derivatives (pressure load, Skouras et al. 2014 Sec. 4).
// V(x) = 1/6 sum over outer triangles of x_a . (x_b x x_c). Internal panels have the same pressure on both
// sides and carry no net load, so callers pass the outer triangles only.
#pragma once
#include <Eigen/Dense>

#include "simulate/membrane_energy.hpp"

namespace billow {

// Signed volume contribution of one triangle (positive when it faces away from the origin side).
inline double triangleVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return a.dot(b.cross(c)) / 6.0;
}

// Gradient (9) and Hessian (9x9, symmetric, zero diagonal blocks) of triangleVolume in (a, b, c).
// dV/da = (b x c)/6 (cyclic); d2V/da db = -[c]x / 6, the skew matrix of the third corner.
void triangleVolumeDerivatives(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                               Vector9d* grad, Matrix9d* hess);

}  // namespace billow
