#include "optimize/objectives.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace billow {

PatternObjective::PatternObjective(const ImlsDistance& imls, const BuiltPattern& built, const SewnMesh& mesh,
                                   const std::vector<double>& seamWeights, const OptimizeWeights& weights)
    : imls_(imls), w_(weights), n_(mesh.numVertices) {
  const Vertices& T = imls.target().V;
  D_ = (T.colwise().maxCoeff() - T.colwise().minCoeff()).norm();
  norm_ = 1.0 / (std::max(n_, 1) * D_ * D_);
  edge_ = mesh.meanEdgeLength > 0 ? mesh.meanEdgeLength : D_ / 100;

  // E_target weights: lumped rest area of the outer surface, relative to the mean. Vertices of internal panels
  // only (not on any outer triangle) get none: they are not meant to lie on the target.
  targetWeight_ = Eigen::VectorXd::Zero(n_);
  for (int t = 0; t < mesh.numTriangles(); ++t)
    if (mesh.outer[t])
      for (int c = 0; c < 3; ++c) targetWeight_[mesh.triangles(t, c)] += mesh.rest[t].area / 3;
  const long used = (targetWeight_.array() > 0).count();
  const double mean = used ? targetWeight_.sum() / used : 1;
  targetWeight_ *= w_.target * norm_ / mean;

  // E_seam: one entry per simulation vertex on a seam, s_j averaged over the panels that meet there.
  std::vector<Eigen::Vector3d> sum(n_, Eigen::Vector3d::Zero());
  std::vector<int> count(n_, 0);
  std::vector<double> sigma(n_, 0);
  for (size_t p = 0; p < built.panels.size(); ++p) {
    const BuiltPanel& bp = built.panels[p];
    for (int v = 0; v < bp.boundaryVertices; ++v) {
      const int s = bp.seam[v];
      if (s < 0) continue;
      const int sv = mesh.simVertex(int(p), v);
      sum[sv] += bp.targetPosition.row(v).transpose();
      ++count[sv];
      sigma[sv] = std::max(sigma[sv], s < int(seamWeights.size()) ? seamWeights[s] : 1.0);
    }
  }
  for (int v = 0; v < n_; ++v)
    if (count[v]) seams_.push_back({v, sum[v] / count[v], sigma[v]});

  // E_length: edge k of a piece is sewn to edge N-1-k of its neighbour piece (rows run opposite). Pairs are
  // mutual (counted once) or one-way: an internal panel's piece names the outer piece it is sewn to.
  const auto gid = [&](int p, int v) { return mesh.panelVertexStart[p] + v; };
  for (size_t p = 0; p < built.panels.size(); ++p) {
    const BuiltPanel& bp = built.panels[p];
    for (size_t i = 0; i < bp.pieces.size(); ++i) {
      const PanelPiece& a = bp.pieces[i];
      const int q = a.neighborPanel, j = a.neighborPiece;
      if (q < 0 || j < 0) continue;
      const PanelPiece& b = built.panels[q].pieces[j];
      const bool mutual = b.neighborPanel == int(p) && b.neighborPiece == int(i);
      if (mutual && std::make_pair(int(p), int(i)) >= std::make_pair(q, j)) continue;
      if (b.rows.size() != a.rows.size()) continue;
      PiecePair pp;
      const int N = int(a.rows.size()) - 1;
      for (int k = 0; k <= N; ++k) pp.a.push_back(gid(int(p), a.rows[k])), pp.b.push_back(gid(q, b.rows[N - k]));
      for (int k = 0; k < N; ++k) pairs_.push_back({pp.a[k], pp.a[k + 1], pp.b[k], pp.b[k + 1]});
      piecePairs_.push_back(std::move(pp));
    }
  }

  // E_smooth and E_laplace: boundary loops (the first rows, in order) and interior one-rings.
  for (size_t p = 0; p < built.panels.size(); ++p) {
    const BuiltPanel& bp = built.panels[p];
    const int nb = bp.boundaryVertices;
    for (int j = 0; j < nb; ++j)
      if (!bp.corner[j])
        boundary_.push_back({gid(int(p), (j + nb - 1) % nb), gid(int(p), j), gid(int(p), (j + 1) % nb)});
    const Panel& panel = built.pattern.panels[p];
    std::vector<std::set<int>> ring(panel.vertices.rows());
    for (int t = 0; t < panel.triangles.rows(); ++t)
      for (int c = 0; c < 3; ++c)
        for (int e = 1; e < 3; ++e) ring[panel.triangles(t, c)].insert(panel.triangles(t, (c + e) % 3));
    for (int v = nb; v < panel.vertices.rows(); ++v) {
      if (ring[v].empty()) continue;
      interior_.push_back(gid(int(p), v));
      ringStart_.push_back(int(ring_.size()));
      for (int k : ring[v]) ring_.push_back(gid(int(p), k));
    }
  }
  ringStart_.push_back(int(ring_.size()));
}

double PatternObjective::shapeEnergy(const Vertices& x, Eigen::VectorXd* grad, ObjectiveTerms* terms) const {
  if (grad) grad->setZero(3 * n_);
  double Et = 0, Es = 0;
  Eigen::Vector3d g;
  for (int i = 0; i < n_; ++i) {
    const double w = targetWeight_[i];
    if (w == 0) continue;
    const double d = imls_.distance(x.row(i).transpose(), grad ? &g : nullptr);
    Et += w * d * d;  // Eq. 9, squared
    if (grad) grad->segment<3>(3 * i) += 2 * w * d * g;
  }
  for (const SeamVertex& s : seams_) {
    const double w = seamWeight(s);
    const Eigen::Vector3d r = x.row(s.vertex).transpose() - s.target;
    Es += w * r.squaredNorm();  // Eq. 10
    if (grad) grad->segment<3>(3 * s.vertex) += 2 * w * r;
  }
  if (terms) terms->target = Et, terms->seam = Es;
  return Et + Es;
}

double PatternObjective::patternEnergy(const Eigen::VectorXd& X, Eigen::VectorXd* grad, ObjectiveTerms* terms) const {
  if (grad) grad->setZero(X.size());
  const auto P = [&](int v) { return Eigen::Vector2d(X.segment<2>(2 * v)); };
  double El = 0, Eb = 0, EL = 0;
  const double wl = w_.length * norm_, wb = w_.smooth * norm_, wL = w_.laplace * norm_;
  for (const EdgePair& e : pairs_) {  // Eq. 11
    const Eigen::Vector2d ea = P(e.a1) - P(e.a0), eb = P(e.b1) - P(e.b0);
    const double La = ea.norm(), Lb = eb.norm(), r = La - Lb;
    El += wl * r * r;
    if (!grad) continue;
    const Eigen::Vector2d ga = 2 * wl * r * ea / La, gb = -2 * wl * r * eb / Lb;
    grad->segment<2>(2 * e.a1) += ga, grad->segment<2>(2 * e.a0) -= ga;
    grad->segment<2>(2 * e.b1) += gb, grad->segment<2>(2 * e.b0) -= gb;
  }
  for (const Triple& t : boundary_) {  // Eq. 12
    const Eigen::Vector2d q = P(t.l) - 2 * P(t.j) + P(t.r);
    Eb += wb * q.squaredNorm();
    if (!grad) continue;
    grad->segment<2>(2 * t.l) += 2 * wb * q, grad->segment<2>(2 * t.r) += 2 * wb * q;
    grad->segment<2>(2 * t.j) -= 4 * wb * q;
  }
  for (size_t i = 0; i < interior_.size(); ++i) {  // Eq. 13
    const int b = ringStart_[i], e = ringStart_[i + 1];
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (int k = b; k < e; ++k) mean += P(ring_[k]);
    mean /= (e - b);
    const Eigen::Vector2d L = P(interior_[i]) - mean;
    EL += wL * L.squaredNorm();
    if (!grad) continue;
    grad->segment<2>(2 * interior_[i]) += 2 * wL * L;
    for (int k = b; k < e; ++k) grad->segment<2>(2 * ring_[k]) -= 2 * wL * L / (e - b);
  }
  if (terms) terms->length = El, terms->smooth = Eb, terms->laplace = EL;
  return El + Eb + EL;
}

double PatternObjective::maxEdgeMismatch(const Eigen::VectorXd& X) const {
  double m = 0;
  for (const EdgePair& e : pairs_) {
    const double La = (X.segment<2>(2 * e.a1) - X.segment<2>(2 * e.a0)).norm();
    const double Lb = (X.segment<2>(2 * e.b1) - X.segment<2>(2 * e.b0)).norm();
    m = std::max(m, std::abs(La - Lb) / (0.5 * (La + Lb)));
  }
  return m;
}

double PatternObjective::maxPieceMismatch(const Eigen::VectorXd& X) const {
  double m = 0;
  for (const PiecePair& pp : piecePairs_) {
    double La = 0, Lb = 0;
    for (size_t k = 0; k + 1 < pp.a.size(); ++k) {
      La += (X.segment<2>(2 * pp.a[k + 1]) - X.segment<2>(2 * pp.a[k])).norm();
      Lb += (X.segment<2>(2 * pp.b[k + 1]) - X.segment<2>(2 * pp.b[k])).norm();
    }
    if (La + Lb > 0) m = std::max(m, std::abs(La - Lb) / (0.5 * (La + Lb)));
  }
  return m;
}

}  // namespace billow
