// The adjoint of the equilibrium constraint for the reduced-space method (DESIGN.md "Pattern optimization"):
// with g(x, X) = dPi/dx = 0 (Eq. 7, g = -f) and K = dg/dx, the inflated shape x(X) has
// dx/dX = -K^-1 dg/dX, so the reduced gradient of E(x(X), X) is
//     dE/dX = dE/dX|_x - lambda^T dg/dX,   K lambda = dE/dx.
// K is singular along the six rigid motions; they are pinned (3-2-1 on three far-apart vertices). Which
// pins does not matter when dE/dx has no rigid component: x is rigidly aligned to minimize E first
// (rigid_align.hpp), and what an alignment stopped short of its minimum leaves is removed (removeRigidPart).
#pragma once
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "simulate/block_cholesky.hpp"

namespace billow {

// Six DOF indices (3 v + axis) that remove the rigid motions of x: all of vertex a, two coordinates of the
// farthest vertex b, one of the vertex c farthest from the line ab.
std::vector<int> rigidPins(const Vertices& x);

// Removes from b (3 per vertex of x) its least-squares rigid part: the net force and the net torque about the
// centroid. At the alignment's minimum there is none; an alignment stopped early leaves some, and pinned, it
// would enter the gradient through whichever pins were chosen.
void removeRigidPart(const Vertices& x, Eigen::VectorXd& b);

// Solves K lambda = b with lambda = 0 at the pins and at DOFs without any stiffness (zero rows of K: the
// inside of a slack internal panel) (the supernodal Cholesky, K being positive definite at a stable
// equilibrium; LDL^T when it is not, because of the pressure term; sparse LU when LDL^T fails or is
// inaccurate; last, the smallest diagonal shift that factorizes, for nearly singular K).
// Returns the relative residual |K lambda - b| / |b| on free DOFs (INFINITY, lambda = 0: no solve).
double solveAdjoint(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& b, const std::vector<int>& pins,
                    Eigen::VectorXd& lambda);

// solveAdjoint that keeps its factorization for further right-hand sides with the same K (K is symmetric, so
// it also gives the equilibrium's first-order change dx = -K^-1 dg/dX dX: PatternOptimizer's prediction), and the
// supernodal Cholesky's analysis for further K of the same pattern (the optimizer's iterates on one mesh).
class PinnedStiffness {
 public:
  // As solveAdjoint.
  double solve(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& b, const std::vector<int>& pins,
               Eigen::VectorXd& lambda);
  // K y = b with the last factorization (y = 0 at pins and stiffness-free DOFs); false when there is none.
  bool solveAgain(const Eigen::VectorXd& b, Eigen::VectorXd& y) const;

 private:
  enum class Kind { None, Cholesky, Ldlt, Lu, Shifted };
  Kind kind_ = Kind::None;
  std::vector<char> pinned_;
  BlockCholesky cholesky_;
  std::vector<int> analyzedOuter_, analyzedInner_;  // the lower-triangle pattern cholesky_ was analyzed for
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
};

}  // namespace billow
