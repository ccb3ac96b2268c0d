// Relaxed membrane energy of constant-strain triangles (Skouras et al. 2014, Sec. 4, Eqs. 1-5).
//
// Per triangle: rest 2D triangle X0..X2 (from the panel), deformed 3D triangle x0..x2;
// F = Ds Dm^-1 (3x2), C = F^T F (2x2) with eigenvalues lambda1 >= lambda2 (squared stretches, Eq. 1).
// psi = kappa (lambda1 + lambda2 + 1/(lambda1 lambda2) - 3) (Eq. 3), kappa = E/6; the tension-field relaxed
// density (Eq. 4) is 0 when slack (lambda1 < 1), kappa (lambda1 + 2/sqrt(lambda1) - 3) when wrinkled
// (lambda2 < 1/sqrt(lambda1), Eq. 5), psi when taut.
//
// Smoothing (the paper's supplementary material is lost; this is our own design). The relaxed density is
// psi evaluated at clamped stretches: psi(l1*, l2*) with l1* = max(l1, 1) and l2* = max(l2, 1/sqrt(l1*)).
// Replacing both max() by a C2 "soft max" over a band of half-width `band` gives
//     l1* = 1 + soft(l1 - 1),   t = 1/sqrt(l1*),   l2* = t + soft(l2 - t),
// soft(u) = 0 for u <= -band, u for u >= band, with soft'' a quartic bump in between. Outside the bands
// this is exactly Eq. 4 (slack: l1* = 1, l2* = 1, psi(1,1) = 0; wrinkled: l2* = t). Inside the bands the
// energy is C2, so Newton and the optimizer see a continuous Hessian. Stresses stay non-negative since
// soft' >= 0 and psi is non-decreasing in l2 for l2 >= t. The density is not guaranteed convex in C
// inside the bands, so the element Hessian is projected (see ElementOptions::projectHessian).
// One measure-zero exception: at an isotropic C (lambda1 == lambda2) inside a band the eigenvalue map is
// not differentiable; there the unsmoothed Eq. 4 is used (its energy there is O(band^2)).
#pragma once
#include <Eigen/Dense>

namespace billow {

struct MembraneMaterial {
  double youngsModulus = 3.0e9;  // E [Pa], metallized nylon foil
  double thickness = 25e-6;      // h [m]
  double band = 1e-4;            // soft-max half-width, in squared stretch (strains of interest are ~1e-3)
  double kappa() const { return youngsModulus / 6.0; }  // incompressible neo-Hookean, kappa = mu/2 = E/6
};

enum class Regime : int { Slack = 0, Wrinkled = 1, Taut = 2 };

// Relaxed density psi~ and its derivatives with respect to c = (C11, C22, C12), C12 counted once.
struct Density {
  double psi = 0;
  Eigen::Vector3d grad = Eigen::Vector3d::Zero();
  Eigen::Matrix3d hess = Eigen::Matrix3d::Zero();
};
Density relaxedDensity(const Eigen::Vector3d& c, double kappa, double band);
// relaxedDensity(c, kappa, band).psi, without the derivatives (the line search's energies).
double relaxedEnergyDensity(const Eigen::Vector3d& c, double kappa, double band);

// Rest data of one triangle: Dm^-1 (Dm = [X1-X0, X2-X0]) and rest area A_e.
struct ElementRest {
  Eigen::Matrix2d DmInv = Eigen::Matrix2d::Identity();
  double area = 0;
};
// Throws nothing; a degenerate triangle gives area 0 (callers validate first).
ElementRest makeElementRest(const Eigen::Vector2d& X0, const Eigen::Vector2d& X1, const Eigen::Vector2d& X2);

using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;

struct ElementOptions {
  bool wantHessian = true;
  // Clamp the negative eigenvalues of d2psi/dc2 (3x3) and of the stress dpsi/dC (2x2) at zero, so the
  // 9x9 element Hessian is positive semi-definite. Off: the exact Hessian (for finite-difference tests).
  bool projectHessian = true;
};

// Element energy h A_e psi~ with gradient (9) and Hessian (9x9) in (x0, x1, x2). Returns the energy.
double membraneElement(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                       const Eigen::Vector3d& x2, const MembraneMaterial& material, const ElementOptions& options,
                       Vector9d* grad, Matrix9d* hess);

// The same element's gradient (3) and diagonal Hessian block (3x3) in one corner (0, 1 or 2) only: the
// vertex-by-vertex Gauss-Seidel sweeps (gauss_seidel.hpp). Equal to the corner's parts of membraneElement.
double membraneElementCorner(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                             const Eigen::Vector3d& x2, const MembraneMaterial& material, int corner,
                             const ElementOptions& options, Eigen::Vector3d* grad, Eigen::Matrix3d* hess);

// Energy only (line search).
double membraneElementEnergy(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                             const Eigen::Vector3d& x2, const MembraneMaterial& material);

// What a designer sees per triangle: the compression field (wrinkles) and the stress.
struct ElementState {
  Regime regime = Regime::Taut;
  double lambda1 = 1, lambda2 = 1;  // eigenvalues of C
  // Wrinkled: 1 - sqrt(lambda2 sqrt(lambda1)), the share of material that must fold away across N2.
  // Slack: 1 - sqrt(lambda2) (the sheet is loose in every direction). Taut: 0.
  double compression = 0;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // F N2 normalized: across the wrinkles' crests
  double stress = 0;   // max principal Cauchy stress [Pa] (incompressible: thickness h / sqrt(det C))
  double tension = 0;  // max principal membrane tension [N/m] = stress x deformed thickness
};
ElementState membraneElementState(const ElementRest& rest, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                                  const Eigen::Vector3d& x2, const MembraneMaterial& material);

}  // namespace billow
