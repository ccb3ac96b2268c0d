#include "optimize/harmonic_interior.hpp"

#include <algorithm>
#include <cmath>

namespace billow {

HarmonicInterior::HarmonicInterior(const Pattern& pattern, const std::vector<int>& panelVertexStart,
                                   const std::vector<int>& boundaryVertices, const Eigen::VectorXd& X0)
    : X0_(X0), index_(X0.size() / 2, -1) {
  for (size_t p = 0; p < pattern.panels.size(); ++p)
    for (int v = boundaryVertices[p]; v < pattern.panels[p].vertices.rows(); ++v) {
      index_[panelVertexStart[p] + v] = static_cast<int>(rows_.size());
      rows_.push_back(panelVertexStart[p] + v);
    }
  const int ni = static_cast<int>(rows_.size());
  if (ni == 0) return;
  // Cotangent weights: w_jk += cot(angle at the third corner) / 2 per triangle.
  std::vector<Eigen::Triplet<double>> ii, ib;
  for (size_t p = 0; p < pattern.panels.size(); ++p) {
    const Triangles& F = pattern.panels[p].triangles;
    for (int t = 0; t < F.rows(); ++t)
      for (int c = 0; c < 3; ++c) {
        const int a = panelVertexStart[p] + F(t, c), j = panelVertexStart[p] + F(t, (c + 1) % 3),
                  k = panelVertexStart[p] + F(t, (c + 2) % 3);
        const Eigen::Vector2d u = X0.segment<2>(2 * j) - X0.segment<2>(2 * a),
                              v = X0.segment<2>(2 * k) - X0.segment<2>(2 * a);
        const double cross = u.x() * v.y() - u.y() * v.x();
        if (!(std::abs(cross) > 0)) continue;
        const double w = 0.5 * u.dot(v) / std::abs(cross);  // edge j-k, opposite corner a
        for (const auto& [r, s] : {std::pair<int, int>{j, k}, std::pair<int, int>{k, j}}) {
          if (index_[r] < 0) continue;
          ii.emplace_back(index_[r], index_[r], w);
          if (index_[s] >= 0)
            ii.emplace_back(index_[r], index_[s], -w);
          else
            ib.emplace_back(index_[r], s, -w);
        }
      }
  }
  Eigen::SparseMatrix<double> L(ni, ni);
  L.setFromTriplets(ii.begin(), ii.end());
  Lib_.resize(ni, static_cast<int>(index_.size()));
  Lib_.setFromTriplets(ib.begin(), ib.end());
  Lii_.compute(L);
  ok_ = Lii_.info() == Eigen::Success && Lii_.vectorD().minCoeff() > 0;
}

void HarmonicInterior::extend(Eigen::VectorXd& X) const {
  if (!ok_) return;
  const int n = static_cast<int>(index_.size());
  Eigen::MatrixXd Ub = Eigen::MatrixXd::Zero(n, 2);
  for (int v = 0; v < n; ++v)
    if (index_[v] < 0) Ub.row(v) = (X.segment<2>(2 * v) - X0_.segment<2>(2 * v)).transpose();
  const Eigen::MatrixXd Ui = Lii_.solve(Eigen::MatrixXd(-(Lib_ * Ub)));
  for (size_t i = 0; i < rows_.size(); ++i)
    X.segment<2>(2 * rows_[i]) = X0_.segment<2>(2 * rows_[i]) + Ui.row(i).transpose();
}

void HarmonicInterior::reduce(Eigen::VectorXd& g) const {
  if (!ok_) return;
  Eigen::MatrixXd gi(rows_.size(), 2);
  for (size_t i = 0; i < rows_.size(); ++i) gi.row(i) = g.segment<2>(2 * rows_[i]).transpose();
  const Eigen::MatrixXd gb = Lib_.transpose() * Lii_.solve(gi);
  for (int v = 0; v < gb.rows(); ++v)
    if (index_[v] < 0) g.segment<2>(2 * v) -= gb.row(v).transpose();
  for (int r : rows_) g.segment<2>(2 * r).setZero();
}

}  // namespace billow
