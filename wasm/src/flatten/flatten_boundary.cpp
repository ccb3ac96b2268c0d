// Newton's method with a Levenberg-Marquardt shift and an Armijo line search on Eq. 14 (Skouras et al. 2014,
// Sec. 5.2, after Wang 2008). The exact Hessian is indefinite away from the minimum and singular along the
// rigid motions, so mu * I is added and raised until the LDL^T factorization has positive pivots. It starts
// from a closed polygon with exactly the target's edge lengths (SQP on the edge directions), with targets made
// consistent (turns summing to 2 pi), on the boundary without its very short edges.
#include "flatten/flatten_boundary.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

#include "util/vec2.hpp"

namespace billow {
namespace {

// Closed segments p0p1 and q0q1 share a point (touching counts).
bool segmentsMeet(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const double d1 = cross2(p1 - p0, q0 - p0), d2 = cross2(p1 - p0, q1 - p0);
  const double d3 = cross2(q1 - q0, p0 - q0), d4 = cross2(q1 - q0, p1 - q0);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto onSegment = [](const Vec2& a, const Vec2& b, const Vec2& p) {
    return p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) && p.y() >= std::min(a.y(), b.y()) &&
           p.y() <= std::max(a.y(), b.y());
  };
  return (d1 == 0 && onSegment(p0, p1, q0)) || (d2 == 0 && onSegment(p0, p1, q1)) ||
         (d3 == 0 && onSegment(q0, q1, p0)) || (d4 == 0 && onSegment(q0, q1, p1));
}

// lbar_j: the mean of the target lengths of the two edges at vertex j.
Eigen::VectorXd meanAdjacentLengths(const BoundaryTargets& t) {
  const int n = static_cast<int>(t.length.size());
  Eigen::VectorXd lbar(n);
  for (int j = 0; j < n; ++j) lbar[j] = 0.5 * (t.length[(j + n - 1) % n] + t.length[j]);
  return lbar;
}

Points2 fromVector(const Eigen::VectorXd& x) { return Eigen::Map<const Points2>(x.data(), x.size() / 2, 2); }
Eigen::VectorXd toVector(const Points2& Q) { return Eigen::Map<const Eigen::VectorXd>(Q.data(), Q.size()); }

// Newton direction from (H + mu I) d = -g, raising mu until the factorization is positive definite.
bool newtonDirection(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& g, double& mu, Eigen::VectorXd& d) {
  Eigen::SparseMatrix<double> I(H.rows(), H.cols());
  I.setIdentity();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  ldlt.analyzePattern(H);
  for (int attempt = 0; attempt < 40; ++attempt, mu *= 10) {
    ldlt.factorize(H + mu * I);
    if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0) {
      d = -ldlt.solve(g);
      return d.allFinite();
    }
  }
  return false;
}

}  // namespace

bool isSimpleCcwPolygon(const Points2& Q) {
  const int n = static_cast<int>(Q.rows());
  if (n < 3 || !Q.allFinite() || signedArea(Q) <= 0) return false;
  auto P = [&](int j) -> Vec2 { return Q.row(j % n).transpose(); };
  for (int i = 0; i < n; ++i) {
    // Adjacent edges only meet at their shared vertex, unless the polygon folds back on itself there.
    const Vec2 a = P(i + 1) - P(i), b = P(i + 2) - P(i + 1);
    if (cross2(a, b) == 0 && a.dot(b) < 0) return false;
  }
  // Two edges can meet only where their boxes overlap, and then they share a cell of a grid each edge is binned into
  // the cells its box covers: about n cells, so a panel's outline of a thousand edges is not checked pair by pair.
  const Vec2 lo = Q.colwise().minCoeff().transpose(), size = Q.colwise().maxCoeff().transpose() - lo;
  const double cell = std::max(std::sqrt(size.x() * size.y() / n), 1e-300);
  const int nx = std::clamp(int(size.x() / cell) + 1, 1, n), ny = std::clamp(int(size.y() / cell) + 1, 1, n);
  const auto cellOf = [&](double x, double lower, int count) {
    return std::clamp(int((x - lower) / cell), 0, count - 1);
  };
  const auto box = [&](int i) {
    const Vec2 p = P(i), q = P(i + 1);
    return std::array<int, 4>{cellOf(std::min(p.x(), q.x()), lo.x(), nx), cellOf(std::max(p.x(), q.x()), lo.x(), nx),
                              cellOf(std::min(p.y(), q.y()), lo.y(), ny), cellOf(std::max(p.y(), q.y()), lo.y(), ny)};
  };
  std::vector<int> start(size_t(nx) * ny + 1, 0), edges;
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < n; ++i) {
      const std::array<int, 4> b = box(i);
      for (int x = b[0]; x <= b[1]; ++x)
        for (int y = b[2]; y <= b[3]; ++y) {
          const size_t c = size_t(x) * ny + y;
          if (pass == 0)
            ++start[c + 1];
          else
            edges[size_t(start[c]++)] = i;
        }
    }
    if (pass == 0) {
      std::partial_sum(start.begin(), start.end(), start.begin());
      edges.resize(size_t(start.back()));
    } else {  // each cell's start moved to the next's: back by one cell
      std::rotate(start.rbegin(), start.rbegin() + 1, start.rend());
      start[0] = 0;
    }
  }
  for (size_t c = 0; c + 1 < start.size(); ++c)
    for (int u = start[c]; u < start[c + 1]; ++u)
      for (int v = u + 1; v < start[c + 1]; ++v) {
        const int i = std::min(edges[size_t(u)], edges[size_t(v)]), k = std::max(edges[size_t(u)], edges[size_t(v)]);
        if (k == i + 1 || (i == 0 && k == n - 1)) continue;  // neighbours meet at their shared vertex
        const Vec2 p0 = P(i), p1 = P(i + 1), q0 = P(k), q1 = P(k + 1);
        if (std::max(p0.x(), p1.x()) < std::min(q0.x(), q1.x()) ||
            std::max(q0.x(), q1.x()) < std::min(p0.x(), p1.x()) ||
            std::max(p0.y(), p1.y()) < std::min(q0.y(), q1.y()) || std::max(q0.y(), q1.y()) < std::min(p0.y(), p1.y()))
          continue;
        if (segmentsMeet(p0, p1, q0, q1)) return false;
      }
  return true;
}

BoundaryTargets consistentTargets(const BoundaryTargets& t) {
  const int n = static_cast<int>(t.length.size());
  const Eigen::VectorXd lbar = meanAdjacentLengths(t);
  BoundaryTargets c = t;
  const double curvature = t.angle.sum() - (n - 2) * M_PI;  // K: the turning angles sum to 2 pi - K
  c.angle -= curvature * lbar / lbar.sum();
  return c;
}

Eigen::VectorXd blendedTurning(const BoundaryTargets& consistent, double convexBlend) {
  const Eigen::VectorXd lbar = meanAdjacentLengths(consistent);
  const Eigen::VectorXd target = M_PI - consistent.angle.array(), circle = 2 * M_PI * lbar / lbar.sum();
  return (1 - convexBlend) * target + convexBlend * circle;
}

Points2 closedLengthStart(const BoundaryTargets& t, const Eigen::VectorXd& turning, int maxIterations) {
  const int n = static_cast<int>(t.length.size());
  const Eigen::VectorXd w = meanAdjacentLengths(t);
  const double perimeter = t.length.sum();
  // Edge directions phi_j; the turn at vertex j is phi_j - phi_j-1 (plus 2 pi at vertex 0), so they sum to 2 pi.
  Eigen::VectorXd phi(n);
  phi[0] = 0;
  for (int j = 1; j < n; ++j) phi[j] = phi[j - 1] + turning[j];
  const auto residual = [&](const Eigen::VectorXd& f) {
    Eigen::VectorXd r(n);
    r[0] = f[0] - f[n - 1] + 2 * M_PI - turning[0];
    for (int j = 1; j < n; ++j) r[j] = f[j] - f[j - 1] - turning[j];
    return r;
  };
  const auto objective = [&](const Eigen::VectorXd& f) { return w.dot(residual(f).cwiseAbs2()); };
  const auto gap = [&](const Eigen::VectorXd& f) {
    Vec2 c = Vec2::Zero();
    for (int j = 0; j < n; ++j) c += t.length[j] * Vec2(std::cos(f[j]), std::sin(f[j]));
    return c;
  };
  // Hessian of the objective: a cyclic second difference weighted by w, singular along rotations (a constant
  // shift of phi), regularized by a small multiple of the identity.
  std::vector<Eigen::Triplet<double>> triplets;
  for (int j = 0; j < n; ++j) {
    const int a = j, b = (j + n - 1) % n;
    triplets.emplace_back(a, a, 2 * w[j] * (1 + 1e-9));
    triplets.emplace_back(b, b, 2 * w[j]);
    triplets.emplace_back(a, b, -2 * w[j]);
    triplets.emplace_back(b, a, -2 * w[j]);
  }
  Eigen::SparseMatrix<double> H(n, n), I(n, n);
  H.setFromTriplets(triplets.begin(), triplets.end());
  I.setIdentity();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  ldlt.analyzePattern(H);
  Eigen::Vector2d lambda = Eigen::Vector2d::Zero();
  double rho = 0;
  for (int it = 0; it < maxIterations; ++it) {
    const Eigen::VectorXd r = residual(phi);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
    for (int j = 0; j < n; ++j) {
      g[j] += 2 * w[j] * r[j];
      g[(j + n - 1) % n] -= 2 * w[j] * r[j];
    }
    const Vec2 c = gap(phi);
    Eigen::MatrixXd J(2, n);
    for (int j = 0; j < n; ++j) J.col(j) << -t.length[j] * std::sin(phi[j]), t.length[j] * std::cos(phi[j]);
    // Hessian of the Lagrangian f + lambda . c (the closing constraints curve: d2c/dphi_j2 = -l_j e_j), shifted
    // until positive definite.
    Eigen::SparseMatrix<double> HL = H;
    for (int j = 0; j < n; ++j)
      HL.coeffRef(j, j) -= t.length[j] * (lambda.x() * std::cos(phi[j]) + lambda.y() * std::sin(phi[j]));
    double mu = 0;
    for (int attempt = 0; attempt < 30; ++attempt, mu = mu == 0 ? 1e-6 * w.mean() : 10 * mu) {
      ldlt.factorize(HL + mu * I);
      if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0) break;
    }
    if (ldlt.info() != Eigen::Success) break;
    // SQP step: min 1/2 d^T HL d + g^T d subject to c + J d = 0.
    const Eigen::MatrixXd HiJt = ldlt.solve(J.transpose());
    const Eigen::VectorXd Hig = ldlt.solve(g);
    lambda = (J * HiJt).ldlt().solve(c - J * Hig);
    const Eigen::VectorXd d = -Hig - HiJt * lambda;
    if (!d.allFinite()) break;
    // Backtracking on the exact penalty merit f + rho |c|_1, rho never lowered.
    rho = std::max(rho, 2 * lambda.cwiseAbs().maxCoeff());
    const double merit = objective(phi) + rho * c.lpNorm<1>();
    double step = 1;
    for (int k = 0; k < 30; ++k, step *= 0.5) {
      const Eigen::VectorXd trial = phi + step * d;
      if (objective(trial) + rho * gap(trial).lpNorm<1>() < merit - 1e-4 * step * rho * c.lpNorm<1>()) break;
    }
    phi += step * d;
    if (gap(phi).norm() < 1e-9 * perimeter && step * d.cwiseAbs().maxCoeff() < 1e-8) break;
  }
  // What gap is left is taken up by every edge in proportion to its length (not by the last edge alone).
  const Vec2 c = gap(phi);
  Points2 Q(n, 2);
  Q.row(0).setZero();
  for (int j = 0; j + 1 < n; ++j) {
    const Vec2 e = t.length[j] * Vec2(std::cos(phi[j]), std::sin(phi[j])) - c * (t.length[j] / perimeter);
    Q.row(j + 1) = Q.row(j) + e.transpose();
  }
  return Q;
}

Points2 circleStart(const BoundaryTargets& t) {
  const int n = static_cast<int>(t.length.size());
  const double perimeter = t.length.sum(), radius = perimeter / (2 * M_PI);
  Points2 Q(n, 2);
  double s = 0;
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * M_PI * s / perimeter;
    Q.row(j) << radius * std::cos(phi), radius * std::sin(phi);
    s += t.length[j];
  }
  return Q;
}

BoundaryFlattening minimizeBoundaryEnergy(const BoundaryTargets& t, const Points2& start, bool keepSimple,
                                          const BoundaryNewtonOptions& o) {
  BoundaryFlattening r;
  Eigen::VectorXd x = toVector(start), g, d;
  Eigen::SparseMatrix<double> H;
  double mu = 1e-10;
  r.energy = boundaryEnergy(start, t, &g, &H);
  for (; r.iterations < o.maxIterations && g.lpNorm<Eigen::Infinity>() > o.gradientTolerance; ++r.iterations) {
    mu = std::max(mu, 1e-12 * H.diagonal().cwiseAbs().maxCoeff());
    if (!newtonDirection(H, g, mu, d)) break;
    const double slope = g.dot(d);
    double step = 1, trial = 0;
    int halvings = 0;
    for (; halvings < o.maxHalvings; ++halvings, step *= 0.5) {
      const Points2 Q = fromVector(x + step * d);
      trial = boundaryEnergy(Q, t);
      if (std::isfinite(trial) && trial <= r.energy + o.armijo * step * slope && (!keepSimple || isSimpleCcwPolygon(Q)))
        break;
    }
    if (halvings == o.maxHalvings) break;
    x += step * d;
    mu = halvings == 0 ? mu * 0.1 : mu * 10;
    const double previous = r.energy;
    r.energy = boundaryEnergy(fromVector(x), t, &g, &H);
    if (previous - r.energy <= 1e-15 * previous) break;
  }
  r.Q = fromVector(x);
  r.simple = isSimpleCcwPolygon(r.Q);
  return r;
}

namespace {

// The boundary without its very short edges: where the seams cross the target's triangles near their
// corners they leave edges a thousand times shorter than the others, whose direction (and so the angles
// at their ends) means nothing, and whose 1 / l_j weight makes Eq. 14 stiff. Vertex k is kept when the
// arc length from the previous kept vertex is at least minLength; a dropped vertex's turn goes to the kept
// vertex before it (so the turns still sum as before) and its edge's length to that vertex's edge.
struct CoarseBoundary {
  std::vector<int> kept;  // fine vertex of each coarse vertex, increasing, kept[0] = 0
  BoundaryTargets targets;
};

CoarseBoundary dropShortEdges(const BoundaryTargets& t, double minLength) {
  const int n = static_cast<int>(t.length.size());
  CoarseBoundary c;
  c.kept.push_back(0);
  double run = t.length[0];
  for (int k = 1; k < n; ++k) {
    if (run >= minLength) {
      c.kept.push_back(k);
      run = 0;
    }
    run += t.length[k];
  }
  while (c.kept.size() > 3 && run < minLength) {  // the closing edge is short: drop the last kept vertex
    c.kept.pop_back();
    run = t.length.segment(c.kept.back(), n - c.kept.back()).sum();
  }
  if (c.kept.size() < 3) {  // a few edges hold nearly all the length: keep every vertex
    c.kept.resize(n);
    std::iota(c.kept.begin(), c.kept.end(), 0);
  }
  const int m = static_cast<int>(c.kept.size());
  c.targets.length = Eigen::VectorXd::Zero(m);
  c.targets.angle = Eigen::VectorXd::Zero(m);
  for (int i = 0; i < m; ++i) {
    const int end = i + 1 < m ? c.kept[i + 1] : n;
    c.targets.angle[i] = t.angle[c.kept[i]];
    for (int k = c.kept[i]; k < end; ++k) {
      c.targets.length[i] += t.length[k];
      if (k > c.kept[i]) c.targets.angle[i] += t.angle[k] - M_PI;
    }
  }
  return c;
}

// The fine polygon: dropped vertices on their coarse edge, in proportion to the target arc length, moved out
// (to the right of the CCW edge) on a parabola of height bulge / 4 times the edge length, so that no three of
// them are collinear.
Points2 refineBoundary(const CoarseBoundary& c, const BoundaryTargets& t, const Points2& coarse, double bulge) {
  const int n = static_cast<int>(t.length.size()), m = static_cast<int>(c.kept.size());
  Points2 Q(n, 2);
  for (int i = 0; i < m; ++i) {
    const int end = i + 1 < m ? c.kept[i + 1] : n;
    const Eigen::RowVector2d a = coarse.row(i), b = coarse.row((i + 1) % m), out(b.y() - a.y(), a.x() - b.x());
    double s = 0;
    for (int k = c.kept[i]; k < end; ++k) {
      const double f = s / c.targets.length[i];
      Q.row(k) = (1 - f) * a + f * b + bulge * f * (1 - f) * out;
      s += t.length[k];
    }
  }
  return Q;
}

}  // namespace

BoundaryFlattening flattenBoundary(const BoundaryTargets& fine, const BoundaryNewtonOptions& o, double convexBlend) {
  const CoarseBoundary coarse = dropShortEdges(fine, 0.1 * fine.length.mean());
  const BoundaryTargets& t = coarse.targets;
  const BoundaryTargets consistent = consistentTargets(t);
  double blend = convexBlend;
  Points2 start = closedLengthStart(t, blendedTurning(consistent, blend));
  for (const double b : {0.25, 0.5, 0.75, 1.0}) {
    if (b <= blend || isSimpleCcwPolygon(start)) continue;
    blend = b;
    start = closedLengthStart(t, blendedTurning(consistent, blend));
  }
  if (!isSimpleCcwPolygon(start)) start = circleStart(t);  // only when an edge is longer than the rest together
  if (convexBlend > 0) {
    // Asked for a blended boundary: no Newton (it would undo the blend); the dropped vertices bulge out a little
    // so that no triangle along a coarse edge is flat.
    BoundaryFlattening r;
    r.Q = refineBoundary(coarse, fine, start, 1e-3);
    r.energy = boundaryEnergy(r.Q, consistentTargets(fine));
    r.simple = isSimpleCcwPolygon(r.Q);
    r.convexBlend = blend;
    return r;
  }
  BoundaryFlattening r = minimizeBoundaryEnergy(consistent, start, true, o);
  r.Q = refineBoundary(coarse, fine, r.Q, 1e-3);
  r.energy = boundaryEnergy(r.Q, consistentTargets(fine));
  r.simple = isSimpleCcwPolygon(r.Q);
  r.convexBlend = blend;
  return r;
}

}  // namespace billow
