// Dual2 (simulate/dual2.hpp), the second-order forward-mode numbers behind the membrane energy's gradient and
// Hessian: every operation against hand-derived derivatives, and a composition like the energy's (the
// eigenvalues of the Cauchy-Green tensor) against finite differences. A wrong chain-rule term would only show
// up downstream as a slower Newton solve, so it is checked here directly.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "simulate/dual2.hpp"

using namespace billow;
using detail::Dual2;

namespace {

// The three variables at point c.
struct Vars {
  Dual2 x, y, z;
  explicit Vars(const Eigen::Vector3d& c)
      : x(Dual2::variable(c[0], 0)), y(Dual2::variable(c[1], 1)), z(Dual2::variable(c[2], 2)) {}
};

void expectNear(const Dual2& d, double v, const Eigen::Vector3d& g, const Eigen::Matrix3d& h, double tol) {
  EXPECT_NEAR(d.v, v, tol);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(d.g[i], g[i], tol) << "gradient " << i;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(d.h(i, j), h(i, j), tol) << "Hessian " << i << "," << j;
}

// Central differences of f's value (gradient) and of its Dual2 gradient (Hessian), step s.
void expectMatchesFiniteDifferences(const std::function<Dual2(const Vars&)>& f, const Eigen::Vector3d& c, double s,
                                    double tol) {
  const Dual2 d = f(Vars(c));
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = s * Eigen::Vector3d::Unit(i);
    const Dual2 plus = f(Vars(c + e)), minus = f(Vars(c - e));
    EXPECT_NEAR(d.g[i], (plus.v - minus.v) / (2 * s), tol) << "gradient " << i;
    const Eigen::Vector3d column = (plus.g - minus.g) / (2 * s);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(d.h(j, i), column[j], tol) << "Hessian " << j << "," << i;
  }
}

}  // namespace

TEST(Dual2, VariablesAndConstantsCarryUnitAndZeroDerivatives) {
  const Dual2 c = Dual2::constant(2.5), y = Dual2::variable(-1.5, 1);
  expectNear(c, 2.5, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(), 0);
  expectNear(y, -1.5, Eigen::Vector3d::UnitY(), Eigen::Matrix3d::Zero(), 0);
}

TEST(Dual2, SumsDifferencesAndScalingAreLinear) {
  // f = 3 (x - y) + z + 4: gradient (3, -3, 1), no curvature.
  const Vars a(Eigen::Vector3d(1.0, 2.0, 5.0));
  const Dual2 f = 3.0 * (a.x - a.y) + a.z + 4.0;
  expectNear(f, 3 * (1.0 - 2.0) + 5.0 + 4.0, Eigen::Vector3d(3, -3, 1), Eigen::Matrix3d::Zero(), 1e-15);
}

TEST(Dual2, AProductHasTheMixedSecondDerivative) {
  // f = x y: gradient (y, x, 0), Hessian 1 off the diagonal in (x, y); f = x x: 2x and 2.
  const double x = 1.5, y = -0.75;
  const Vars a(Eigen::Vector3d(x, y, 0.3));
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  h(0, 1) = h(1, 0) = 1;
  expectNear(a.x * a.y, x * y, Eigen::Vector3d(y, x, 0), h, 1e-15);
  h.setZero();
  h(0, 0) = 2;
  expectNear(a.x * a.x, x * x, Eigen::Vector3d(2 * x, 0, 0), h, 1e-15);
}

TEST(Dual2, TheLengthOfAVectorHasTheProjectionAsItsHessian) {
  // r = sqrt(x^2 + y^2 + z^2): gradient c / r, Hessian (I - c c^T / r^2) / r.
  const Eigen::Vector3d c(0.6, -1.2, 2.0);
  const Vars a(c);
  const Dual2 r = detail::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  const double n = c.norm();
  expectNear(r, n, c / n, (Eigen::Matrix3d::Identity() - c * c.transpose() / (n * n)) / n, 1e-14);
}

TEST(Dual2, InverseOfAProductAndInverseSquareRootFollowThePowerRule) {
  // 1 / (x y): gradient -(1 / (x^2 y), 1 / (x y^2)), Hessian [[2 / (x^3 y), 1 / (x y)^2], [., 2 / (x y^3)]].
  const double x = 1.25, y = 0.8;
  const Vars a(Eigen::Vector3d(x, y, 7));
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  h(0, 0) = 2 / (x * x * x * y), h(1, 1) = 2 / (x * y * y * y), h(0, 1) = h(1, 0) = 1 / (x * x * y * y);
  expectNear(detail::inverse(a.x * a.y), 1 / (x * y), Eigen::Vector3d(-1 / (x * x * y), -1 / (x * y * y), 0), h, 1e-14);
  // z^(-1/2): -z^(-3/2) / 2 and 3 z^(-5/2) / 4.
  const double z = 2.25;  // sqrt(z) = 1.5
  const Dual2 t = detail::inverseSqrt(Dual2::variable(z, 2));
  h.setZero();
  h(2, 2) = 0.75 / std::pow(1.5, 5);
  expectNear(t, 1 / 1.5, Eigen::Vector3d(0, 0, -0.5 / std::pow(1.5, 3)), h, 1e-15);
  // sqrt(z): z^(-1/2) / 2 and -z^(-3/2) / 4.
  h(2, 2) = -0.25 / std::pow(1.5, 3);
  expectNear(detail::sqrt(Dual2::variable(z, 2)), 1.5, Eigen::Vector3d(0, 0, 0.5 / 1.5), h, 1e-15);
}

TEST(Dual2, ApplyIsTheChainRuleToSecondOrder) {
  // exp(x y) through apply: gradient e (y, x, 0), Hessian e [[y^2, 1 + x y], [1 + x y, x^2]].
  const double x = 0.4, y = -0.9, e = std::exp(x * y);
  const Vars a(Eigen::Vector3d(x, y, 0));
  const Dual2 u = a.x * a.y;
  const Dual2 f = detail::apply(u, e, e, e);
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  h(0, 0) = e * y * y, h(1, 1) = e * x * x, h(0, 1) = h(1, 0) = e * (1 + x * y);
  expectNear(f, e, Eigen::Vector3d(e * y, e * x, 0), h, 1e-15);
}

TEST(Dual2, TheLargerEigenvalueOfTheCauchyGreenTensorMatchesItsEigenvectorAndFiniteDifferences) {
  // The membrane energy's first step: c = (C11, C22, C12), l1 = m + sqrt(a^2 + C12^2) with m and a the half
  // sum and half difference. For a symmetric matrix, d l1 / dC = v v^T for the unit eigenvector v, so the
  // gradient over (C11, C22, C12) is (v1^2, v2^2, 2 v1 v2) (C12 stands for both off-diagonal entries).
  const auto l1 = [](const Vars& a) {
    const Dual2 m = 0.5 * (a.x + a.y), h = 0.5 * (a.x - a.y);
    return m + detail::sqrt(h * h + a.z * a.z);
  };
  const Eigen::Vector3d c(1.3, 0.9, 0.25);
  Eigen::Matrix2d C;
  C << c[0], c[2], c[2], c[1];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(C);
  const Eigen::Vector2d v = eig.eigenvectors().col(1);  // ascending: column 1 is the larger
  const Dual2 d = l1(Vars(c));
  EXPECT_NEAR(d.v, eig.eigenvalues()[1], 1e-14);
  EXPECT_NEAR(d.g[0], v[0] * v[0], 1e-14);
  EXPECT_NEAR(d.g[1], v[1] * v[1], 1e-14);
  EXPECT_NEAR(d.g[2], 2 * v[0] * v[1], 1e-14);
  EXPECT_TRUE(d.h.isApprox(d.h.transpose(), 1e-15)) << "a Hessian is symmetric";
  expectMatchesFiniteDifferences(l1, c, 1e-5, 1e-8);
}

TEST(Dual2, AnEnergyLikeCompositionMatchesFiniteDifferences) {
  // psi = l1 + l2 + 1 / (l1 l2) - 3 with both eigenvalues of C: the neo-Hookean-like core of the relaxed
  // density, without the smooth clamps.
  const auto psi = [](const Vars& a) {
    const Dual2 m = 0.5 * (a.x + a.y), h = 0.5 * (a.x - a.y);
    const Dual2 r = detail::sqrt(h * h + a.z * a.z);
    const Dual2 l1 = m + r, l2 = m - r;
    return l1 + l2 + detail::inverse(l1 * l2) + (-3.0);
  };
  for (const Eigen::Vector3d& c :
       {Eigen::Vector3d(1.1, 0.95, 0.05), Eigen::Vector3d(1.6, 1.2, -0.3), Eigen::Vector3d(0.8, 1.4, 0.2)}) {
    const Dual2 d = psi(Vars(c));
    // l1 + l2 is the trace and l1 l2 the determinant: psi = C11 + C22 + 1 / det - 3.
    const double det = c[0] * c[1] - c[2] * c[2];
    EXPECT_NEAR(d.v, c[0] + c[1] + 1 / det - 3, 1e-13);
    EXPECT_NEAR(d.g[0], 1 - c[1] / (det * det), 1e-12);
    EXPECT_NEAR(d.g[1], 1 - c[0] / (det * det), 1e-12);
    EXPECT_NEAR(d.g[2], 2 * c[2] / (det * det), 1e-12);
    expectMatchesFiniteDifferences(psi, c, 1e-5, 1e-7);
  }
}
