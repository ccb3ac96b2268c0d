// Exact equal seam lengths (Eq. 11 as a hard constraint, DESIGN.md: fabrication needs it exactly). The
// optimizer keeps E_length as a penalty (so its objective stays one smooth function and decreases
// monotonically); at the end the pattern is projected onto the constraint set r_e(X) = L_a - L_b = 0 by
// Gauss-Newton minimum-norm steps dX = -J^T (J J^T)^-1 r, which move the panel boundaries the least.
#pragma once
#include <Eigen/SparseCholesky>
#include <vector>

#include "optimize/objectives.hpp"

namespace billow {

// Projects X in place; returns the max relative edge mismatch afterwards.
double projectSeamLengths(const std::vector<PatternObjective::EdgePair>& pairs, Eigen::VectorXd& X,
                          int maxIterations = 10, double tolerance = 1e-12);

// v minus its part normal to the constraint set at X: v - J^T (J J^T)^-1 J v with J = dr/dX, so that
// J (result) = 0 (to first order a move along the result keeps the seam lengths equal). Zero rows of v
// (interior vertices, which J never touches) stay zero.
Eigen::VectorXd tangentToSeamLengths(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& X,
                                     const Eigen::VectorXd& v);

// tangentToSeamLengths at one X for many v: J and the factorization of J J^T made once.
class SeamTangent {
 public:
  SeamTangent(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& X);
  Eigen::VectorXd operator()(const Eigen::VectorXd& v) const;

 private:
  Eigen::SparseMatrix<double> J_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> JJt_;
  bool ok_ = false;
};

}  // namespace billow
