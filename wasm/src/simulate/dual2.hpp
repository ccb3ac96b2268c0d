// Second-order forward-mode dual numbers over the three entries c = (C11, C22, C12) of the right
// Cauchy-Green tensor. The relaxed density (membrane_energy.cpp) is a composition of a few smooth scalar
// functions; carrying value, gradient and Hessian through the composition keeps all three exactly
// consistent, which hand-derived eigenvalue chains rarely are.
#pragma once
#include <Eigen/Dense>
#include <cmath>

namespace billow::detail {

struct Dual2 {
  double v = 0;
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();

  static Dual2 constant(double value) {
    Dual2 d;
    d.v = value;
    return d;
  }
  static Dual2 variable(double value, int index) {
    Dual2 d;
    d.v = value;
    d.g[index] = 1;
    return d;
  }
};

inline Dual2 operator+(const Dual2& a, const Dual2& b) { return {a.v + b.v, a.g + b.g, a.h + b.h}; }
inline Dual2 operator-(const Dual2& a, const Dual2& b) { return {a.v - b.v, a.g - b.g, a.h - b.h}; }
inline Dual2 operator+(const Dual2& a, double s) { return {a.v + s, a.g, a.h}; }
inline Dual2 operator*(double s, const Dual2& a) { return {s * a.v, s * a.g, s * a.h}; }
inline Dual2 operator*(const Dual2& a, const Dual2& b) {
  const Eigen::Matrix3d cross = a.g * b.g.transpose();
  return {a.v * b.v, a.v * b.g + b.v * a.g, a.v * b.h + b.v * a.h + cross + cross.transpose()};
}

// f(a) given f(a.v), f'(a.v), f''(a.v): the chain rule to second order.
inline Dual2 apply(const Dual2& a, double f, double f1, double f2) {
  return {f, f1 * a.g, f1 * a.h + f2 * a.g * a.g.transpose()};
}
inline Dual2 sqrt(const Dual2& a) {
  const double s = std::sqrt(a.v);
  return apply(a, s, 0.5 / s, -0.25 / (s * a.v));
}
inline Dual2 inverse(const Dual2& a) {
  const double i = 1.0 / a.v;
  return apply(a, i, -i * i, 2 * i * i * i);
}
// The same on plain values, so one formula serves both (membrane_energy.cpp).
inline double sqrt(double a) { return std::sqrt(a); }
inline double inverse(double a) { return 1.0 / a; }
inline double inverseSqrt(double a) { return 1.0 / std::sqrt(a); }
inline Dual2 inverseSqrt(const Dual2& a) {
  const double i = 1.0 / std::sqrt(a.v);
  return apply(a, i, -0.5 * i / a.v, 0.75 * i / (a.v * a.v));
}

}  // namespace billow::detail
