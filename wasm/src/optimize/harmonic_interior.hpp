// Interior pattern vertices that follow the panel boundary (DESIGN.md "Pattern optimization", bench/README.md).
// A panel is cut along its boundary only: where its interior vertices lie is discretization, not design. Left
// free (the paper's X with E_laplace, Eq. 13, against sliding), the optimizer used them to lower E through
// the discretization, collapsing rest triangles until the fold check stopped every step. Here the interior
// displacement is the harmonic extension of the boundary displacement from a reference pattern X0,
//     U_i = -L_ii^-1 L_ib U_b,   U = X - X0,
// with the cotangent Laplacian L of X0 (exact for affine motions: a panel that is moved, turned or stretched
// uniformly keeps its triangles' shapes). Optimization variables are then the boundary coordinates; the
// reduced gradient in them is g_b + (dX_i/dX_b)^T g_i = g_b - L_bi L_ii^-1 g_i.
#pragma once
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <vector>

#include "pattern/pattern.hpp"

namespace billow {

class HarmonicInterior {
 public:
  // X0: reference pattern coordinates (2 per panel vertex, sewn order); panelVertexStart[p]: first row of
  // panel p in X; boundaryVertices[p]: its first rows that are boundary (the rest are interior).
  HarmonicInterior(const Pattern& pattern, const std::vector<int>& panelVertexStart,
                   const std::vector<int>& boundaryVertices, const Eigen::VectorXd& X0);

  // Sets X's interior rows from its boundary rows.
  void extend(Eigen::VectorXd& X) const;
  // Gradient in all of X -> gradient in the boundary rows (interior rows set to zero).
  void reduce(Eigen::VectorXd& g) const;
  bool ok() const { return ok_; }  // false when the Laplacian could not be factorized (then both do nothing)
  bool interior(int row) const { return index_[row] >= 0; }

 private:
  Eigen::VectorXd X0_;
  std::vector<int> index_;           // panel-vertex row -> interior index, -1 on the boundary
  std::vector<int> rows_;            // interior index -> panel-vertex row
  Eigen::SparseMatrix<double> Lib_;  // #interior by #rows (boundary columns only)
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> Lii_;
  bool ok_ = false;
};

}  // namespace billow
