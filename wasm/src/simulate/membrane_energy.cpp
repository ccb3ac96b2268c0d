// Relaxed membrane energy (Skouras et al. 2014, Eqs. 1-5) with our C2 smoothing; see the header.
#include "simulate/membrane_energy.hpp"

#include <cmath>

#include "simulate/dual2.hpp"

namespace billow {
namespace {

using detail::Dual2;

// C2 soft version of max(u, 0) over [-band, band]: soft'' = 15/(16 band) (1 - s^2)^2, s = u / band.
double soft(double u, double band) {
  if (u <= -band) return 0;
  if (u >= band) return u;
  const double s = u / band, s2 = s * s;
  return band * (15.0 / 16.0 * (s2 / 2 - s2 * s2 / 6 + s2 * s2 * s2 / 30) + s / 2 + 5.0 / 32.0);
}
Dual2 soft(const Dual2& u, double band) {
  if (u.v <= -band) return Dual2::constant(0);
  if (u.v >= band) return u;
  const double s = u.v / band, s2 = s * s;
  const double f1 = 15.0 / 16.0 * (s - 2 * s * s2 / 3 + s * s2 * s2 / 5) + 0.5;
  const double f2 = 15.0 / (16.0 * band) * (1 - s2) * (1 - s2);
  return detail::apply(u, soft(u.v, band), f1, f2);
}

// Taut regime, Eq. 3 in invariants: psi = kappa (tr C + 1/det C - 3). No eigen-decomposition.
double tautPsi(const Eigen::Vector3d& c, double kappa) {
  return kappa * (c[0] + c[1] + 1 / (c[0] * c[1] - c[2] * c[2]) - 3);
}
Density tautDensity(const Eigen::Vector3d& c, double kappa) {
  const double det = c[0] * c[1] - c[2] * c[2];
  const Eigen::Vector3d dDet(c[1], c[0], -2 * c[2]);
  Eigen::Matrix3d hDet;
  hDet << 0, 1, 0, 1, 0, 0, 0, 0, -2;
  Density d;
  d.psi = tautPsi(c, kappa);
  d.grad = kappa * (Eigen::Vector3d(1, 1, 0) - dDet / (det * det));
  d.hess = kappa * (2 * dDet * dDet.transpose() / (det * det * det) - hDet / (det * det));
  return d;
}

// Bands and the wrinkled regime: psi(l1*, l2*) through the eigenvalues (distinct here, r > 0). On values (the line
// search's energies) or on dual numbers (the Newton step's derivatives): the same operations, so the same values.
template <class T>
T smoothedPsi(const T& c11, const T& c22, const T& c12, double kappa, double band) {
  using detail::inverse, detail::inverseSqrt, detail::sqrt;
  const T m = 0.5 * (c11 + c22), a = 0.5 * (c11 - c22);
  const T r = sqrt(a * a + c12 * c12);
  const T l1 = m + r, l2 = m - r;
  const T l1s = soft(l1 + (-1.0), band) + 1.0;  // l1* = max(l1, 1), smoothed
  const T t = inverseSqrt(l1s);                 // Eq. 5: energetic minimum of l2
  const T l2s = t + soft(l2 - t, band);         // l2* = max(l2, t), smoothed
  return kappa * (l1s + l2s + inverse(l1s * l2s) + (-3.0));
}

struct Eigenvalues {
  double l1, l2, r;
};
Eigenvalues eigenvaluesOf(const Eigen::Vector3d& c) {
  const double m = 0.5 * (c[0] + c[1]), a = 0.5 * (c[0] - c[1]);
  const double r = std::sqrt(a * a + c[2] * c[2]);
  return {m + r, m - r, r};
}

// Which form psi~ takes at C (Eq. 4, with our bands).
enum class Branch { Slack, Taut, Smoothed };
Branch branchOf(const Eigen::Vector3d& c, double band) {
  const Eigenvalues e = eigenvaluesOf(c);
  if (e.l1 <= 1 - band) return Branch::Slack;
  if (e.l1 >= 1 + band && e.l2 - 1 / std::sqrt(e.l1) >= band) return Branch::Taut;
  // Isotropic C inside a band: the eigenvalue map has a kink here; fall back to unsmoothed Eq. 4.
  if (e.r < 1e-12) return e.l1 >= 1 ? Branch::Taut : Branch::Slack;
  return Branch::Smoothed;
}

}  // namespace

Density relaxedDensity(const Eigen::Vector3d& c, double kappa, double band) {
  switch (branchOf(c, band)) {
    case Branch::Slack:
      return {};
    case Branch::Taut:
      return tautDensity(c, kappa);
    case Branch::Smoothed:
      break;
  }
  const Dual2 psi =
      smoothedPsi(Dual2::variable(c[0], 0), Dual2::variable(c[1], 1), Dual2::variable(c[2], 2), kappa, band);
  return {psi.v, psi.g, psi.h};
}

double relaxedEnergyDensity(const Eigen::Vector3d& c, double kappa, double band) {
  switch (branchOf(c, band)) {
    case Branch::Slack:
      return 0;
    case Branch::Taut:
      return tautPsi(c, kappa);
    case Branch::Smoothed:
      break;
  }
  return smoothedPsi(c[0], c[1], c[2], kappa, band);
}

ElementRest makeElementRest(const Eigen::Vector2d& X0, const Eigen::Vector2d& X1, const Eigen::Vector2d& X2) {
  Eigen::Matrix2d Dm;
  Dm.col(0) = X1 - X0;
  Dm.col(1) = X2 - X0;
  ElementRest rest;
  const double det = Dm.determinant();
  rest.area = 0.5 * det;
  if (det != 0) rest.DmInv = Dm.inverse();
  return rest;
}

namespace {

// f_i = sum_a w(a, i) x_a: the columns of F as weights of the three corners (F = Ds Dm^-1).
Eigen::Matrix<double, 3, 2> cornerWeights(const Eigen::Matrix2d& DmInv) {
  Eigen::Matrix<double, 3, 2> w;
  w.row(1) = DmInv.row(0);
  w.row(2) = DmInv.row(1);
  w.row(0) = -(w.row(1) + w.row(2));
  return w;
}

Eigen::Matrix<double, 3, 2> deformationGradient(const ElementRest& rest, const Eigen::Vector3d& x0,
                                                const Eigen::Vector3d& x1, const Eigen::Vector3d& x2) {
  Eigen::Matrix<double, 3, 2> Ds;
  Ds.col(0) = x1 - x0;
  Ds.col(1) = x2 - x0;
  return Ds * rest.DmInv;
}

Eigen::Vector3d cauchyGreen(const Eigen::Matrix<double, 3, 2>& F) {
  return {F.col(0).squaredNorm(), F.col(1).squaredNorm(), F.col(0).dot(F.col(1))};
}

// Clamps the negative eigenvalues of a symmetric 2x2 or 3x3 matrix at zero. Most matrices are already
// positive definite (taut and wrinkled elements outside the bands): a Cholesky test skips the eigensolver.
template <int N>
Eigen::Matrix<double, N, N> clampedPsd(const Eigen::Matrix<double, N, N>& m) {
  if (Eigen::LLT<Eigen::Matrix<double, N, N>>(m).info() == Eigen::Success) return m;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es;
  es.computeDirect(m);  // closed form for 2x2 and 3x3
  if (es.eigenvalues().minCoeff() >= 0) return m;
  return es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).asDiagonal() * es.eigenvectors().transpose();
}

// J = dc/dx (3x9): dC11 = 2 f1.df1, dC22 = 2 f2.df2, dC12 = f1.df2 + f2.df1, df_i/dx_a = w(a,i) I.
Eigen::Matrix<double, 3, 9> strainJacobian(const Eigen::Matrix<double, 3, 2>& F, const Eigen::Matrix<double, 3, 2>& w) {
  const Eigen::Vector3d f1 = F.col(0), f2 = F.col(1);
  Eigen::Matrix<double, 3, 9> J;
  for (int a = 0; a < 3; ++a) {
    J.block<1, 3>(0, 3 * a) = 2 * w(a, 0) * f1.transpose();
    J.block<1, 3>(1, 3 * a) = 2 * w(a, 1) * f2.transpose();
    J.block<1, 3>(2, 3 * a) = (w(a, 0) * f2 + w(a, 1) * f1).transpose();
  }
  return J;
}

// The Hessian is J^T (d2psi/dc2) J, the material part, plus the geometric part 2 (w_a^T P w_b) I with
// P = dpsi/dC (symmetric); both clamped to PSD when projecting.
void hessianParts(const Density& d, const ElementOptions& options, Eigen::Matrix3d* Hc, Eigen::Matrix2d* P) {
  *P << d.grad[0], 0.5 * d.grad[2], 0.5 * d.grad[2], d.grad[1];
  *Hc = d.hess;
  if (options.projectHessian) {
    *Hc = clampedPsd<3>(*Hc);
    *P = clampedPsd<2>(*P);
  }
}

}  // namespace

double membraneElementEnergy(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                             const Eigen::Vector3d& x2, const MembraneMaterial& material) {
  const Eigen::Vector3d c = cauchyGreen(deformationGradient(rest, x0, x1, x2));
  return material.thickness * rest.area * relaxedEnergyDensity(c, material.kappa(), material.band);
}

double membraneElement(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                       const Eigen::Vector3d& x2, const MembraneMaterial& material, const ElementOptions& options,
                       Vector9d* grad, Matrix9d* hess) {
  const Eigen::Matrix<double, 3, 2> F = deformationGradient(rest, x0, x1, x2);
  const Eigen::Vector3d c = cauchyGreen(F);
  const Density d = relaxedDensity(c, material.kappa(), material.band);
  const double scale = material.thickness * rest.area;  // element energy h A_e psi~
  const bool slack = d.psi == 0 && d.grad.isZero(0);
  if (grad) grad->setZero();
  if (hess) hess->setZero();
  if (slack) return 0;

  const Eigen::Matrix<double, 3, 2> w = cornerWeights(rest.DmInv);
  const Eigen::Matrix<double, 3, 9> J = strainJacobian(F, w);
  if (grad) *grad = scale * J.transpose() * d.grad;
  if (hess && options.wantHessian) {
    Eigen::Matrix3d Hc;
    Eigen::Matrix2d P;
    hessianParts(d, options, &Hc, &P);
    // A coefficient-wise product: Eigen sends a 9x9 result of a general product to its blocked GEMM, which is
    // slower at this size.
    const Eigen::Matrix<double, 9, 3> JtHc = J.transpose() * Hc;
    *hess = JtHc.lazyProduct(J);
    const Eigen::Matrix3d Wg = 2 * w * P * w.transpose();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) hess->block<3, 3>(3 * a, 3 * b).diagonal().array() += Wg(a, b);
    *hess *= scale;
  }
  return scale * d.psi;
}

double membraneElementCorner(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                             const Eigen::Vector3d& x2, const MembraneMaterial& material, int corner,
                             const ElementOptions& options, Eigen::Vector3d* grad, Eigen::Matrix3d* hess) {
  const Eigen::Matrix<double, 3, 2> F = deformationGradient(rest, x0, x1, x2);
  const Density d = relaxedDensity(cauchyGreen(F), material.kappa(), material.band);
  const double scale = material.thickness * rest.area;
  if (grad) grad->setZero();
  if (hess) hess->setZero();
  if (d.psi == 0 && d.grad.isZero(0)) return 0;
  const Eigen::Matrix<double, 3, 2> w = cornerWeights(rest.DmInv);
  const Eigen::Matrix3d Ja = strainJacobian(F, w).block<3, 3>(0, 3 * corner);
  if (grad) *grad = scale * Ja.transpose() * d.grad;
  if (hess) {
    Eigen::Matrix3d Hc;
    Eigen::Matrix2d P;
    hessianParts(d, options, &Hc, &P);
    *hess = Ja.transpose() * Hc * Ja;
    hess->diagonal().array() += 2 * w.row(corner).dot(P * w.row(corner).transpose());
    *hess *= scale;
  }
  return scale * d.psi;
}

ElementState membraneElementState(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                                  const Eigen::Vector3d& x2, const MembraneMaterial& material) {
  const Eigen::Matrix<double, 3, 2> F = deformationGradient(rest, x0, x1, x2);
  const Eigen::Vector3d c = cauchyGreen(F);
  const Eigenvalues e = eigenvaluesOf(c);
  ElementState s;
  s.lambda1 = e.l1;
  s.lambda2 = e.l2;
  if (e.l1 < 1) {
    s.regime = Regime::Slack;
    s.compression = 1 - std::sqrt(std::max(e.l2, 0.0));
  } else if (e.l2 < 1 / std::sqrt(e.l1)) {
    s.regime = Regime::Wrinkled;
    s.compression = 1 - std::sqrt(std::max(e.l2, 0.0) * std::sqrt(e.l1));
  } else {
    s.regime = Regime::Taut;
  }
  if (s.regime != Regime::Taut && e.r > 0) {
    // Eigenvector N2 of C for lambda2: the better conditioned of the two rows of (C - lambda2 I).
    Eigen::Vector2d n1(c[2], e.l2 - c[0]), n2(e.l2 - c[1], c[2]);
    const Eigen::Vector2d N2 = n1.squaredNorm() > n2.squaredNorm() ? n1 : n2;
    const Eigen::Vector3d dir = F * N2;
    if (dir.norm() > 0) s.direction = dir.normalized();
  }
  // Second Piola-Kirchhoff S = 2 dpsi/dC; principal Cauchy stresses are the eigenvalues of S C / sqrt(det C)
  // times the volume ratio 1 (incompressible: thickness shrinks by sqrt(det C)), i.e. eig(S C).
  const Density d = relaxedDensity(c, material.kappa(), material.band);
  Eigen::Matrix2d S, C;
  S << 2 * d.grad[0], d.grad[2], d.grad[2], 2 * d.grad[1];
  C << c[0], c[2], c[2], c[1];
  const Eigen::Matrix2d SC = S * C;
  const double tr = SC.trace(), det = SC.determinant();
  const double disc = std::sqrt(std::max(0.25 * tr * tr - det, 0.0));
  s.stress = std::max(0.5 * tr + disc, 0.0);
  const double detC = std::max(c[0] * c[1] - c[2] * c[2], 1e-300);
  s.tension = s.stress * material.thickness / std::sqrt(detC);
  return s;
}

}  // namespace billow
