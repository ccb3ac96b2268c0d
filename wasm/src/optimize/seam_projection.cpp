#include "optimize/seam_projection.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

namespace billow {

namespace {

double maxMismatch(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& X) {
  double m = 0;
  for (const auto& e : pairs) {
    const double La = (X.segment<2>(2 * e.a1) - X.segment<2>(2 * e.a0)).norm();
    const double Lb = (X.segment<2>(2 * e.b1) - X.segment<2>(2 * e.b0)).norm();
    m = std::max(m, std::abs(La - Lb) / (0.5 * (La + Lb)));
  }
  return m;
}

}  // namespace

double projectSeamLengths(const std::vector<PatternObjective::EdgePair>& pairs, Eigen::VectorXd& X, int maxIterations,
                          double tolerance) {
  const int m = static_cast<int>(pairs.size());
  if (m == 0) return 0;
  for (int it = 0; it < maxIterations && maxMismatch(pairs, X) > tolerance; ++it) {
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::VectorXd r(m);
    for (int k = 0; k < m; ++k) {
      const auto& e = pairs[k];
      const Eigen::Vector2d ea = X.segment<2>(2 * e.a1) - X.segment<2>(2 * e.a0);
      const Eigen::Vector2d eb = X.segment<2>(2 * e.b1) - X.segment<2>(2 * e.b0);
      const double La = ea.norm(), Lb = eb.norm();
      r[k] = La - Lb;
      const Eigen::Vector2d ua = ea / La, ub = eb / Lb;
      for (int c = 0; c < 2; ++c) {
        trip.emplace_back(k, 2 * e.a1 + c, ua[c]), trip.emplace_back(k, 2 * e.a0 + c, -ua[c]);
        trip.emplace_back(k, 2 * e.b1 + c, -ub[c]), trip.emplace_back(k, 2 * e.b0 + c, ub[c]);
      }
    }
    Eigen::SparseMatrix<double> J(m, X.size());
    J.setFromTriplets(trip.begin(), trip.end());  // duplicates (shared vertices) are summed
    Eigen::SparseMatrix<double> JJt = J * J.transpose();
    for (int k = 0; k < m; ++k) JJt.coeffRef(k, k) += 1e-12;  // pairs that share both edges' vertices
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(JJt);
    if (ldlt.info() != Eigen::Success) break;
    const Eigen::VectorXd mu = ldlt.solve(r);
    if (!mu.allFinite()) break;
    X -= J.transpose() * mu;
  }
  return maxMismatch(pairs, X);
}

}  // namespace billow
