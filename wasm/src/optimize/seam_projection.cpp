#include "optimize/seam_projection.hpp"

#include <Eigen/Dense>
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

// r = L_a - L_b per pair and J = dr/dX.
void seamLengthResiduals(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& X,
                         Eigen::VectorXd& r, Eigen::SparseMatrix<double>& J) {
  const int m = static_cast<int>(pairs.size());
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(size_t(m) * 8);
  r.resize(m);
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
  J.resize(m, X.size());
  J.setFromTriplets(trip.begin(), trip.end());  // duplicates (shared vertices) are summed
}

// The minimum-norm step that changes J X by b: J^T (J J^T)^-1 b, or with a metric M^-1 J^T (J M^-1 J^T)^-1 b
// (M^-1 J^T column by column). False when the normal matrix does not factorize.
bool normalStep(const Eigen::SparseMatrix<double>& J, const SeamMetric& metric, const Eigen::VectorXd& b,
                Eigen::VectorXd& step) {
  if (!metric) {
    Eigen::SparseMatrix<double> JJt = J * J.transpose();
    for (int k = 0; k < JJt.rows(); ++k) JJt.coeffRef(k, k) += 1e-12;  // pairs that share both edges' vertices
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(JJt);
    if (ldlt.info() != Eigen::Success) return false;
    step = J.transpose() * ldlt.solve(b);
    return step.allFinite();
  }
  const Eigen::SparseMatrix<double> Jt = J.transpose();
  Eigen::MatrixXd Z(J.cols(), J.rows());
  for (int k = 0; k < J.rows(); ++k) Z.col(k) = metric(Eigen::VectorXd(Jt.col(k)));
  Eigen::MatrixXd G = J * Z;
  G.diagonal().array() += 1e-12 * std::max(G.diagonal().cwiseAbs().maxCoeff(), 1e-300);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(G);
  if (ldlt.info() != Eigen::Success) return false;
  step = Z * ldlt.solve(b);
  return step.allFinite();
}

}  // namespace

Eigen::VectorXd tangentToSeamLengths(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& X,
                                     const Eigen::VectorXd& v, const SeamMetric& metric) {
  if (pairs.empty()) return v;
  Eigen::VectorXd r, step;
  Eigen::SparseMatrix<double> J;
  seamLengthResiduals(pairs, X, r, J);
  return normalStep(J, metric, J * v, step) ? Eigen::VectorXd(v - step) : v;
}

double projectSeamLengths(const std::vector<PatternObjective::EdgePair>& pairs, Eigen::VectorXd& X, int maxIterations,
                          double tolerance, const SeamMetric& metric) {
  const int m = static_cast<int>(pairs.size());
  if (m == 0) return 0;
  for (int it = 0; it < maxIterations && maxMismatch(pairs, X) > tolerance; ++it) {
    Eigen::VectorXd r, step;
    Eigen::SparseMatrix<double> J;
    seamLengthResiduals(pairs, X, r, J);
    if (!normalStep(J, metric, r, step)) break;
    X -= step;
  }
  return maxMismatch(pairs, X);
}

}  // namespace billow
