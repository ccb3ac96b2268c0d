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

bool factorizeNormal(const Eigen::SparseMatrix<double>& J, Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& ldlt) {
  Eigen::SparseMatrix<double> JJt = J * J.transpose();
  for (int k = 0; k < JJt.rows(); ++k) JJt.coeffRef(k, k) += 1e-12;  // pairs that share both edges' vertices
  ldlt.compute(JJt);
  return ldlt.info() == Eigen::Success;
}

// The minimum-norm step that changes J X by b: J^T (J J^T)^-1 b. False when J J^T does not factorize.
bool normalStep(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& b, Eigen::VectorXd& step) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  if (!factorizeNormal(J, ldlt)) return false;
  step = J.transpose() * ldlt.solve(b);
  return step.allFinite();
}

}  // namespace

Eigen::VectorXd tangentToSeamLengths(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& X,
                                     const Eigen::VectorXd& v) {
  return SeamTangent(pairs, X)(v);
}

double projectSeamLengths(const std::vector<PatternObjective::EdgePair>& pairs, Eigen::VectorXd& X, int maxIterations,
                          double tolerance) {
  const int m = static_cast<int>(pairs.size());
  if (m == 0) return 0;
  for (int it = 0; it < maxIterations && maxMismatch(pairs, X) > tolerance; ++it) {
    Eigen::VectorXd r, step;
    Eigen::SparseMatrix<double> J;
    seamLengthResiduals(pairs, X, r, J);
    if (!normalStep(J, r, step)) break;
    X -= step;
  }
  return maxMismatch(pairs, X);
}

SeamTangent::SeamTangent(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& X) {
  if (pairs.empty()) return;
  Eigen::VectorXd r;
  seamLengthResiduals(pairs, X, r, J_);
  ok_ = factorizeNormal(J_, JJt_);
}

Eigen::VectorXd SeamTangent::operator()(const Eigen::VectorXd& v) const {
  if (!ok_) return v;
  const Eigen::VectorXd step = J_.transpose() * JJt_.solve(J_ * v);
  return step.allFinite() ? Eigen::VectorXd(v - step) : v;
}

}  // namespace billow
