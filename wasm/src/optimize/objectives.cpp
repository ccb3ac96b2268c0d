#include "optimize/objectives.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "export/polygon.hpp"
#include "optimize/rest_derivatives.hpp"
#include "seams/surface_point.hpp"

namespace billow {

namespace {
// The width inside a panel over which E_cover's reach at the seams falls to coverReach, of the target's diagonal.
constexpr double kCoverSeamBand = 0.03;
}  // namespace

OptimizeWeights weightsAtEdgeLength(OptimizeWeights w, double ratio) {
  w.seam /= ratio;
  w.smooth /= std::pow(ratio, 4);
  w.fair /= std::pow(ratio, 4);
  return w;
}

namespace {
// The outline's turning angle at Q_j (Q_l, Q_j, Q_r in order), in (-pi, pi], and its gradients when given.
double turningAngle(const Eigen::Vector2d& l, const Eigen::Vector2d& j, const Eigen::Vector2d& r, Eigen::Vector2d* gl,
                    Eigen::Vector2d* gj, Eigen::Vector2d* gr) {
  const Eigen::Vector2d u = j - l, v = r - j;
  if (gl) {
    const Eigen::Vector2d pu = Eigen::Vector2d(-u.y(), u.x()) / u.squaredNorm(),
                          pv = Eigen::Vector2d(-v.y(), v.x()) / v.squaredNorm();
    *gl = pu, *gr = pv, *gj = -pu - pv;
  }
  return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}
double wrapAngle(double a) { return a - 2 * M_PI * std::round(a / (2 * M_PI)); }
}  // namespace

PatternObjective::PatternObjective(const ImlsDistance& imls, const BuiltPattern& built, const SewnMesh& mesh,
                                   const std::vector<double>& seamWeights, const OptimizeWeights& weights)
    : imls_(imls), w_(weights), n_(mesh.numVertices), targetCache_(size_t(mesh.numVertices)) {
  const Vertices& T = imls.target().V;
  D_ = (T.colwise().maxCoeff() - T.colwise().minCoeff()).norm();
  norm_ = 1.0 / (std::max(n_, 1) * D_ * D_);
  edge_ = mesh.meanEdgeLength > 0 ? mesh.meanEdgeLength : D_ / 100;

  // E_target weights: lumped rest area of the outer surface, relative to the mean. Vertices of internal panels
  // only (not on any outer triangle) get none: they are not meant to lie on the target.
  const auto gid = [&](int p, int v) { return mesh.panelVertexStart[p] + v; };
  int first = 0;
  for (size_t p = 0; p < built.pattern.panels.size(); ++p) {
    const Triangles& F = built.pattern.panels[p].triangles;
    for (int k = 0; k < F.rows(); ++k)
      if (mesh.outer[first + k]) {
        OuterTriangle t;
        for (int c = 0; c < 3; ++c) t.vertex[c] = mesh.triangles(first + k, c), t.pattern[c] = gid(int(p), F(k, c));
        outer_.push_back(t);
      }
    first += static_cast<int>(F.rows());
  }
  std::vector<char> onOuter(n_, 0);
  for (const OuterTriangle& t : outer_)
    for (int c = 0; c < 3; ++c) onOuter[t.vertex[c]] = 1;
  const long used = std::count(onOuter.begin(), onOuter.end(), 1);
  targetScale_ = w_.target * norm_ * double(used);
  targetWeight_ = targetWeights(packPattern(built.pattern));

  // E_cover: the target's vertices by lumped area; on a target with more than twice as many vertices as the
  // outer surface, every k-th of them (their areas renormalized), so it costs about what E_target does.
  const TriMesh& target = imls.target();
  Eigen::VectorXd lumped = Eigen::VectorXd::Zero(target.numVertices());
  for (int f = 0; f < target.numTriangles(); ++f) {
    const Eigen::Vector3d a = target.V.row(target.F(f, 0)).transpose(), b = target.V.row(target.F(f, 1)).transpose(),
                          c = target.V.row(target.F(f, 2)).transpose();
    for (int k = 0; k < 3; ++k) lumped[target.F(f, k)] += (b - a).cross(c - a).norm() / 6;
  }
  const long stride = std::max<long>(1, (target.numVertices() + 2 * used - 1) / std::max<long>(2 * used, 1));
  double sampled = 0;
  for (int v = 0; v < target.numVertices(); v += int(stride)) coverVertex_.push_back(v), sampled += lumped[v];
  coverWeight_.resize(long(coverVertex_.size()));
  coverArea_.resize(long(coverVertex_.size()));
  for (size_t k = 0; k < coverVertex_.size(); ++k) {
    coverWeight_[long(k)] = sampled > 0 ? w_.cover * norm_ * double(used) * lumped[coverVertex_[k]] / sampled : 0;
    coverArea_[long(k)] = lumped[coverVertex_[k]];
  }
  coverTau2_ = (w_.coverReach * D_) * (w_.coverReach * D_);
  if (w_.coverReachAtSeams > 0) {
    // Each panel vertex's distance to its outline in the pattern, as a nearness 1 - distance / band.
    std::vector<double> near(size_t(mesh.panelVertexStart.back()), 0.0);
    const double band = kCoverSeamBand * D_;
    for (size_t p = 0; p < built.panels.size(); ++p) {
      const PanelVertices& Q = built.pattern.panels[p].vertices;
      const int nb = built.panels[p].boundaryVertices;
      Polygon2 outline;
      for (int j = 0; j < nb; ++j) outline.push_back(Q.row(j).transpose());
      for (int v = 0; v < Q.rows(); ++v)
        near[size_t(gid(int(p), v))] =
            v < nb ? 1 : 1 - std::min(distanceToBoundary(Q.row(v).transpose(), outline), band) / band;
    }
    for (const OuterTriangle& t : outer_)
      seamNearness_.push_back((near[size_t(t.pattern[0])] + near[size_t(t.pattern[1])] + near[size_t(t.pattern[2])]) /
                              3);
  }
  std::vector<std::vector<int>> at(n_);
  for (size_t t = 0; t < outer_.size(); ++t)
    for (int c = 0; c < 3; ++c) at[outer_[t].vertex[c]].push_back(int(t));
  aroundStart_.assign(1, 0);
  for (size_t t = 0; t < outer_.size(); ++t) {
    std::set<int> near;
    for (int c = 0; c < 3; ++c) near.insert(at[outer_[t].vertex[c]].begin(), at[outer_[t].vertex[c]].end());
    near.erase(int(t));
    around_.insert(around_.end(), near.begin(), near.end());
    aroundStart_.push_back(int(around_.size()));
  }

  // E_quality: every rest triangle against its flattened shape.
  first = 0;
  double restTotal = 0;
  for (size_t p = 0; p < built.pattern.panels.size(); ++p) {
    const Panel& panel = built.pattern.panels[p];
    for (int k = 0; k < panel.triangles.rows(); ++k) {
      RestTriangle t;
      for (int c = 0; c < 3; ++c) t.pattern[c] = gid(int(p), panel.triangles(k, c));
      const Eigen::Vector2d a = panel.vertices.row(panel.triangles(k, 0)).transpose(),
                            b = panel.vertices.row(panel.triangles(k, 1)).transpose(),
                            c = panel.vertices.row(panel.triangles(k, 2)).transpose();
      Eigen::Matrix2d Dm;
      Dm << b - a, c - a;
      if (!(Dm.determinant() > 0)) continue;
      t.DmInv = Dm.inverse();
      t.weight = 0.5 * Dm.determinant();
      restTotal += t.weight;
      rest_.push_back(t);
    }
  }
  for (RestTriangle& t : rest_) t.weight *= w_.quality * edge_ * edge_ * norm_ * double(rest_.size()) / restTotal;

  const auto sigmaOf = [&](int seam) { return seam < int(seamWeights.size()) ? seamWeights[seam] : 1.0; };

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
      sigma[sv] = std::max(sigma[sv], sigmaOf(s));
    }
  }
  for (int v = 0; v < n_; ++v)
    if (count[v]) seams_.push_back({v, sum[v] / count[v], sigma[v]});

  // E_length: edge k of a piece is sewn to edge N-1-k of its neighbour piece (rows run opposite). Pairs are
  // mutual (counted once) or one-way: an internal panel's piece names the outer piece it is sewn to.
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
    outlines_.emplace_back();
    for (int j = 0; j < nb; ++j) outlines_.back().push_back(gid(int(p), j));
    // E_gap's reach per outline vertex: an edge length, or less at a thin tip or notch of the flattened outline
    // (its distance to the nearest edge not ending at it), so that the barrier is zero on the flattened pattern;
    // half of that let the steps jump the barrier at thin tips (bench/README.md).
    const PanelVertices& Q = built.pattern.panels[p].vertices;
    std::vector<double> reach(nb, edge_);
    for (int j = 0; j < nb; ++j)
      for (int k = 2; k < nb; ++k) {
        const int v = (j + k) % nb;
        const Eigen::Vector2d a = Q.row(j).transpose(), b = Q.row((j + 1) % nb).transpose(), q = Q.row(v).transpose();
        reach[v] = std::min(reach[v], (q - a - closestSegmentParameter(q, a, b) * (b - a)).norm());
      }
    gapReach_.push_back(std::move(reach));
    // E_fair's outlines: those without a corner (pieces.size() > 1 marks where seams meet, as below).
    if (bp.pieces.size() <= 1 && nb > 3) {
      std::vector<double> turn0(nb);
      for (int j = 0; j < nb; ++j)
        turn0[j] = turningAngle(Q.row((j + nb - 1) % nb).transpose(), Q.row(j).transpose(),
                                Q.row((j + 1) % nb).transpose(), nullptr, nullptr, nullptr);
      fairOutlines_.push_back({outlines_.size() - 1, std::move(turn0)});
      fairVertices_ += nb;
    }
    for (int j = 0; j < nb; ++j) {
      // A corner is where seams meet, and the outline may turn there; the one corner of a panel bounded by a
      // single loop is only where the loop starts, and left free there it bent into a hook (58 degrees on the
      // two-disc sphere's Panel 1, its other points 8).
      if (bp.corner[j] && bp.pieces.size() > 1) continue;
      const int seam = bp.seam[j];
      const bool sliding = seam >= 0 && sigmaOf(seam) * w_.seam < w_.slidingBelow;
      const double relative = sliding ? w_.slidingSmooth : 1.0;
      boundary_.push_back({gid(int(p), (j + nb - 1) % nb), gid(int(p), j), gid(int(p), (j + 1) % nb), relative});
    }
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

double PatternObjective::restArea(const OuterTriangle& t, const Eigen::VectorXd& X) const {
  const Eigen::Vector2d a = X.segment<2>(2 * t.pattern[0]), b = X.segment<2>(2 * t.pattern[1]),
                        c = X.segment<2>(2 * t.pattern[2]);
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

Eigen::VectorXd PatternObjective::targetWeights(const Eigen::VectorXd& X) const {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(n_);
  double total = 0;
  for (const OuterTriangle& t : outer_) {
    const double a = restArea(t, X);
    total += a;
    for (int c = 0; c < 3; ++c) w[t.vertex[c]] += a / 3;
  }
  return total > 0 ? Eigen::VectorXd(w * (targetScale_ / total)) : w;
}

double PatternObjective::coverKernel(double d2, double tau2, double* irls) {
  const double s = tau2 / (d2 + tau2);  // rho = tau^2 d^2 / (d^2 + tau^2) = s d^2
  if (irls) *irls = s * s;              // rho'(d) / (2 d) = tau^4 / (d^2 + tau^2)^2
  return s * d2;
}

void PatternObjective::trackCover(const Vertices& x) const {
  const std::vector<int> last = std::move(coverTriangle_);  // search hints
  coverTriangle_.clear();
  if (!(w_.cover > 0) || coverVertex_.empty() || outer_.empty()) return;
  TriMesh surface;
  surface.V = x;
  surface.F.resize(long(outer_.size()), 3);
  for (size_t t = 0; t < outer_.size(); ++t)
    for (int c = 0; c < 3; ++c) surface.F(long(t), c) = outer_[t].vertex[c];
  const SurfaceProjector projector(surface);
  const Vertices& T = imls_.target().V;
  const double seamReach = w_.coverReachAtSeams * D_;
  coverTau2Sample_.assign(coverVertex_.size(), coverTau2_);
  for (size_t k = 0; k < coverVertex_.size(); ++k) {
    coverTriangle_.push_back(
        projector.project(T.row(coverVertex_[k]).transpose(), nullptr, k < last.size() ? last[k] : -1).face);
    if (!seamNearness_.empty()) {
      const double b = seamNearness_[size_t(coverTriangle_.back())];
      coverTau2Sample_[k] = (1 - b) * coverTau2_ + b * seamReach * seamReach;
    }
  }
}

void PatternObjective::coverPoints(const Vertices& x, std::vector<CoverPoint>& out) const {
  out.clear();
  if (!(w_.cover > 0) || coverVertex_.empty() || outer_.empty()) return;
  if (coverTriangle_.size() != coverVertex_.size()) trackCover(x);  // the first evaluation
  const Vertices& T = imls_.target().V;
  const auto closest = [&](int t, const Eigen::Vector3d& q, CoverPoint& p) {
    const OuterTriangle& o = outer_[t];
    const Eigen::Vector3d a = x.row(o.vertex[0]).transpose(), b = x.row(o.vertex[1]).transpose(),
                          c = x.row(o.vertex[2]).transpose();
    p.bary = closestPointBarycentric(q, a, b, c);
    p.closest = p.bary[0] * a + p.bary[1] * b + p.bary[2] * c;
    p.triangle = t;
    return (p.closest - q).squaredNorm();
  };
  out.resize(coverVertex_.size());
  for (size_t k = 0; k < coverVertex_.size(); ++k) {
    CoverPoint& best = out[k];
    best.target = T.row(coverVertex_[k]).transpose();
    best.weight = coverWeight_[long(k)];
    best.tau2 = coverTau2Sample_[k];
    double d2 = closest(coverTriangle_[k], best.target, best);
    // Walk to a neighbouring triangle while one is closer (a bounded number of steps: the shape moved little). A
    // closest point inside its triangle is a local minimum over the surface already: the walk ends there without
    // looking at the neighbours (most samples, most evaluations; the rigid alignment evaluates this many times).
    for (int step = 0; step < 64; ++step) {
      if ((best.bary.array() > 0).all()) break;
      CoverPoint trial = best;
      int next = -1;
      for (int i = aroundStart_[best.triangle]; i < aroundStart_[best.triangle + 1]; ++i) {
        CoverPoint p = best;
        const double e = closest(around_[i], best.target, p);
        if (e < d2) d2 = e, trial = p, next = around_[i];
      }
      if (next < 0) break;
      best = trial;
    }
  }
}

double PatternObjective::shapeEnergy(const Vertices& x, const Eigen::VectorXd& X, Eigen::VectorXd* gradx,
                                     Eigen::VectorXd* gradX, ObjectiveTerms* terms) const {
  if (gradx) gradx->setZero(3 * n_);
  if (gradX) gradX->setZero(X.size());
  double Et = 0, Es = 0;
  Eigen::Vector3d g;
  const Eigen::VectorXd weight = targetWeights(X);
  Eigen::VectorXd d2 = Eigen::VectorXd::Zero(n_);
  for (int i = 0; i < n_; ++i) {
    if (weight[i] == 0) continue;
    const double d = targetDistance(i, x.row(i).transpose(), gradx ? &g : nullptr);
    d2[i] = d * d;
    Et += weight[i] * d * d;  // Eq. 9, squared
    if (gradx) gradx->segment<3>(3 * i) += 2 * weight[i] * d * g;
  }
  if (gradX) {
    // E_t = s sum_t a_t q_t / A, q_t the mean d^2 of its corners: dE_t/da_t = (s q_t - E_t) / A.
    double total = 0;
    for (const OuterTriangle& t : outer_) total += restArea(t, X);
    for (const OuterTriangle& t : outer_) {
      const double q = (d2[t.vertex[0]] + d2[t.vertex[1]] + d2[t.vertex[2]]) / 3;
      const double dEda = (targetScale_ * q - Et) / total;
      for (int c = 0; c < 3; ++c) {
        // d a_t / d P_c = (P_{c+1} - P_{c+2}) rotated by -90 degrees, halved.
        const Eigen::Vector2d p1 = X.segment<2>(2 * t.pattern[(c + 1) % 3]),
                              p2 = X.segment<2>(2 * t.pattern[(c + 2) % 3]);
        gradX->segment<2>(2 * t.pattern[c]) += dEda * 0.5 * Eigen::Vector2d(p1.y() - p2.y(), p2.x() - p1.x());
      }
    }
  }
  double Ec = 0;
  std::vector<CoverPoint> cover;
  coverPoints(x, cover);
  for (const CoverPoint& c : cover) {
    const Eigen::Vector3d r = c.closest - c.target;
    double irls = 1;
    Ec += c.weight * coverKernel(r.squaredNorm(), c.tau2, gradx ? &irls : nullptr);
    if (gradx)
      for (int k = 0; k < 3; ++k)
        gradx->segment<3>(3 * outer_[c.triangle].vertex[k]) += 2 * c.weight * irls * c.bary[k] * r;
  }
  for (const SeamVertex& s : seams_) {
    const double w = seamWeight(s);
    const Eigen::Vector3d r = x.row(s.vertex).transpose() - s.target;
    Es += w * r.squaredNorm();  // Eq. 10
    if (gradx) gradx->segment<3>(3 * s.vertex) += 2 * w * r;
  }
  if (terms) terms->target = Et, terms->cover = Ec, terms->seam = Es;
  return Et + Ec + Es;
}

void PatternObjective::residualRows(const Vertices& x, const Eigen::VectorXd& X, std::vector<ResidualRow>& rows) const {
  rows.clear();
  const Eigen::VectorXd weight = targetWeights(X);
  Eigen::Vector3d n;
  for (int i = 0; i < n_; ++i) {
    if (weight[i] == 0) continue;
    ResidualRow r;
    targetDistance(i, x.row(i).transpose(), &n);
    r.count = 1, r.vertex[0] = i, r.grad[0] = n, r.weight = weight[i];
    rows.push_back(r);
  }
  std::vector<CoverPoint> cover;
  coverPoints(x, cover);
  for (const CoverPoint& c : cover) {
    const Eigen::Vector3d d = c.closest - c.target;
    const double len = d.norm();
    if (!(len > 0)) continue;
    double irls = 1;
    coverKernel(len * len, c.tau2, &irls);
    ResidualRow r;
    r.count = 3, r.weight = c.weight * irls;
    for (int k = 0; k < 3; ++k) r.vertex[k] = outer_[c.triangle].vertex[k], r.grad[k] = c.bary[k] * d / len;
    rows.push_back(r);
  }
  for (const SeamVertex& s : seams_)
    for (int axis = 0; axis < 3; ++axis) {
      ResidualRow r;
      r.count = 1, r.vertex[0] = s.vertex, r.grad[0] = Eigen::Vector3d::Unit(axis), r.weight = seamWeight(s);
      rows.push_back(r);
    }
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
    const double w = wb * t.weight;
    Eb += w * q.squaredNorm();
    if (!grad) continue;
    grad->segment<2>(2 * t.l) += 2 * w * q, grad->segment<2>(2 * t.r) += 2 * w * q;
    grad->segment<2>(2 * t.j) -= 4 * w * q;
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
  double Eq = 0;
  if (w_.quality > 0)
    for (const RestTriangle& t : rest_) {
      const Eigen::Vector2d p0 = P(t.pattern[0]);
      Eigen::Matrix2d Ds;
      Ds << P(t.pattern[1]) - p0, P(t.pattern[2]) - p0;
      const Eigen::Matrix2d J = Ds * t.DmInv;
      const double det = J.determinant(), norm2 = J.squaredNorm();
      if (!(det > 0)) {
        Eq = INFINITY;
        continue;
      }
      Eq += t.weight * (norm2 / (2 * det) - 1);  // MIPS: (s1 / s2 + s2 / s1) / 2 - 1
      if (!grad) continue;
      Eigen::Matrix2d cof;
      cof << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
      const Eigen::Matrix2d G = t.weight * (J / det - norm2 / (2 * det * det) * cof) * t.DmInv.transpose();
      grad->segment<2>(2 * t.pattern[1]) += G.col(0), grad->segment<2>(2 * t.pattern[2]) += G.col(1);
      grad->segment<2>(2 * t.pattern[0]) -= G.col(0) + G.col(1);
    }
  const double Eg = w_.gap > 0 ? gapEnergy(X, grad) : 0;
  const double Ef = w_.fair > 0 ? fairEnergy(X, grad) : 0;
  if (terms)
    terms->length = El, terms->smooth = Eb, terms->laplace = EL, terms->quality = Eq, terms->gap = Eg, terms->fair = Ef;
  return El + Eb + EL + Eq + Eg + Ef;
}

double PatternObjective::fairEnergy(const Eigen::VectorXd& X, Eigen::VectorXd* grad) const {
  const double w = w_.fair / std::max(fairVertices_, 1);
  double E = 0;
  for (const FairOutline& f : fairOutlines_) {
    const std::vector<int>& loop = outlines_[f.outline];
    const int nb = int(loop.size());
    const auto P = [&](int j) { return Eigen::Vector2d(X.segment<2>(2 * loop[size_t((j + nb) % nb)])); };
    std::vector<double> change(nb), dEdChange(nb, 0.0);
    std::vector<Eigen::Vector2d> gl(nb), gj(nb), gr(nb);
    for (int j = 0; j < nb; ++j) {
      const double turn = turningAngle(P(j - 1), P(j), P(j + 1), grad ? &gl[j] : nullptr, grad ? &gj[j] : nullptr,
                                       grad ? &gr[j] : nullptr);
      change[j] = wrapAngle(turn - f.turn0[size_t(j)]);
    }
    for (int j = 0; j < nb; ++j) {
      const int l = (j + nb - 1) % nb, r = (j + 1) % nb;
      const double d = change[l] - 2 * change[j] + change[r];
      E += w * d * d;
      dEdChange[l] += 2 * w * d, dEdChange[r] += 2 * w * d, dEdChange[j] -= 4 * w * d;
    }
    if (!grad) continue;
    for (int j = 0; j < nb; ++j) {
      grad->segment<2>(2 * loop[size_t((j + nb - 1) % nb)]) += dEdChange[j] * gl[j];
      grad->segment<2>(2 * loop[size_t(j)]) += dEdChange[j] * gj[j];
      grad->segment<2>(2 * loop[size_t((j + 1) % nb)]) += dEdChange[j] * gr[j];
    }
  }
  return E;
}

double PatternObjective::gapEnergy(const Eigen::VectorXd& X, Eigen::VectorXd* grad) const {
  const double kappa = w_.gap * edge_ * edge_ * norm_;
  double E = 0;
  // Each edge meets only the outline vertices within an edge length of it: found among the loop sorted by x,
  // then taken in loop order as the all-pairs sum took them, so that E and its gradient are the same to the bit.
  std::vector<int> byX;
  std::vector<double> xs;
  std::vector<int> near;  // an edge's candidates, as offsets k along the loop from its first vertex
  for (size_t p = 0; p < outlines_.size(); ++p) {
    const std::vector<int>& loop = outlines_[p];
    const int n = int(loop.size());
    byX.resize(n), xs.resize(n);
    for (int i = 0; i < n; ++i) {
      if (!std::isfinite(X[2 * loop[i]]) || !std::isfinite(X[2 * loop[i] + 1])) return INFINITY;
      byX[i] = i;
    }
    std::sort(byX.begin(), byX.end(), [&](int u, int v) { return X[2 * loop[u]] < X[2 * loop[v]]; });
    for (int i = 0; i < n; ++i) xs[i] = X[2 * loop[byX[i]]];
    for (int j = 0; j < n; ++j) {
      const int ia = loop[j], ib = loop[(j + 1) % n];
      const Eigen::Vector2d a = X.segment<2>(2 * ia), b = X.segment<2>(2 * ib), ab = b - a;
      const Eigen::Vector2d lo = a.cwiseMin(b).array() - edge_, hi = a.cwiseMax(b).array() + edge_;
      near.clear();
      const auto first = std::lower_bound(xs.begin(), xs.end(), lo.x());
      const auto last = std::upper_bound(first, xs.end(), hi.x());
      for (auto it = first; it != last; ++it) {
        const int at = byX[it - xs.begin()];
        const double y = X[2 * loop[at] + 1];
        const int k = (at - j + n) % n;
        if (k >= 2 && !(y < lo.y()) && !(y > hi.y())) near.push_back(k);  // every vertex but the edge's own two
      }
      std::sort(near.begin(), near.end());
      for (const int k : near) {
        const int at = (j + k) % n, iv = loop[at];
        const Eigen::Vector2d v = X.segment<2>(2 * iv);
        const double h = gapReach_[p][at];
        const double t = closestSegmentParameter(v, a, b);
        const Eigen::Vector2d r = v - (a + t * ab);
        const double d = r.norm(), s = d / h;
        if (!(s < 1)) continue;
        if (!(s > 0)) return INFINITY;
        E += kappa * -(s - 1) * (s - 1) * std::log(s);
        if (!grad) continue;
        // d d / d v = r / d; d d / d a = -(1 - t) r / d, d d / d b = -t r / d (t minimizes, so its change drops out).
        const Eigen::Vector2d f = kappa * (-2 * (s - 1) * std::log(s) - (s - 1) * (s - 1) / s) / h * r / d;
        grad->segment<2>(2 * iv) += f;
        grad->segment<2>(2 * ia) -= (1 - t) * f;
        grad->segment<2>(2 * ib) -= t * f;
      }
    }
  }
  return E;
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
