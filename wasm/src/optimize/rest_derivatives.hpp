// Derivatives of the equilibrium equations (Skouras et al. 2014, Eq. 7) that the simulator does not export:
// the exact (unprojected) stiffness K = d2 Pi / dx2 and the mixed derivative dg/dX of the gradient
// g = dPi/dx = -f with respect to the rest (pattern) positions X. The adjoint (adjoint.hpp) needs both.
//
// Per element W = h A(X) psi~(c(x, X)), c = (C11, C22, C12), C = M^T Ds^T Ds M, M = Dm^-1. Its gradient
// g_e = dW/dx is evaluated with first-order dual numbers over the six rest coordinates (X0, X1, X2), using
// psi~'s own gradient and Hessian in c (membrane_energy.hpp relaxedDensity), so dg_e/dX is exact.
#pragma once
#include <Eigen/Sparse>
#include <vector>

#include "simulate/membrane_energy.hpp"
#include "simulate/seam_rods.hpp"
#include "simulate/sewn_pattern.hpp"

namespace billow {

using Matrix96d = Eigen::Matrix<double, 9, 6>;

// Element gradient dW/d(x0, x1, x2) (9) and, when given, its derivative in (X0x, X0y, X1x, X1y, X2x, X2y).
Vector9d membraneElementRestJacobian(const Eigen::Vector2d& X0, const Eigen::Vector2d& X1, const Eigen::Vector2d& X2,
                                     const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                                     const MembraneMaterial& material, Matrix96d* dGradDX);

// Pattern coordinates X: 2 per panel vertex, in the sewn order (panel p's vertex v at panelVertexStart[p] + v).
Eigen::VectorXd packPattern(const Pattern& pattern);
void unpackPattern(const Eigen::VectorXd& X, Pattern& pattern);
// First sewn triangle of every panel (#panels + 1).
std::vector<int> panelTriangleStart(const Pattern& pattern);

// Exact K = sum_e d2W_e/dx2 + d2E_seams/dx2 - p d2V/dx2 (3 #V square, vertex-major DOFs), rest data from
// mesh.rest; the seam rods' constant Hessian when given.
Eigen::SparseMatrix<double> assembleStiffness(const SewnMesh& mesh, const Vertices& x, const MembraneMaterial& material,
                                              double pressure, const SeamRods* rods = nullptr);

// g = dPi/dx (3 #V) with the rest data of X (tests; the simulator keeps its own).
Eigen::VectorXd equilibriumGradient(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X,
                                    const Vertices& x, const MembraneMaterial& material, double pressure);

// out += lambda^T dg/dX (2 per panel vertex), lambda 3 #V. The pressure term does not depend on X.
void addRestGradientProduct(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, const Vertices& x,
                            const Eigen::VectorXd& lambda, const MembraneMaterial& material, Eigen::VectorXd& out);

// out += dg/dX dX (3 #V), dX 2 per panel vertex: how the equilibrium forces change with the panels.
void addRestJacobianProduct(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, const Vertices& x,
                            const Eigen::VectorXd& dX, const MembraneMaterial& material, Eigen::VectorXd& out);

// dg/dX at one (X, x) with each element's 9 x 6 block kept, for many products there: the Gauss-Newton direction's
// CG takes two per iteration, and the functions above evaluate every element's dual-number gradient anew each time.
class RestJacobian {
 public:
  RestJacobian(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, const Vertices& x,
               const MembraneMaterial& material);
  // out += lambda^T dg/dX, as addRestGradientProduct.
  void addTransposedProduct(const Eigen::VectorXd& lambda, Eigen::VectorXd& out) const;
  // out += dg/dX dX, as addRestJacobianProduct.
  void addProduct(const Eigen::VectorXd& dX, Eigen::VectorXd& out) const;

 private:
  struct Element {
    int vertex[3];   // sewn vertices (3 DOFs each)
    int pattern[3];  // panel vertices (2 DOFs each)
    Matrix96d J;
  };
  std::vector<Element> elements_;
};

// The seam rods' coefficient of the panels X: seamRodCoefficient of the mesh sewn from them (its outer panels' rest
// area, its mean rest edge length), and when given its derivative in X (2 per panel vertex). The pattern optimizer's
// rods follow the panels so, as the cut panels' own rods do: the optimized panels must balance with the rods they
// will be sewn with, not the flattened panels' (what a frozen stiffness did: bench/README.md).
double seamRodCoefficientAt(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, double pressure,
                            double beta, Eigen::VectorXd* dcdX = nullptr);

// The rods' part of dg/dX when their coefficient follows the panels: g_rods = c(X) dS/dx, S the rods' energy per
// unit coefficient, so dg_rods/dX = dS/dx dc/dX^T. out += lambda^T dg_rods/dX (2 per panel vertex), and
// out += dg_rods/dX dX (3 #V).
void addRodGradientProduct(const SeamRods& rods, const Vertices& x, const Eigen::VectorXd& dcdX,
                           const Eigen::VectorXd& lambda, Eigen::VectorXd& out);
void addRodJacobianProduct(const SeamRods& rods, const Vertices& x, const Eigen::VectorXd& dcdX,
                           const Eigen::VectorXd& dX, Eigen::VectorXd& out);

}  // namespace billow
