// Newton's method with a Levenberg-Marquardt shift and an Armijo line search on Eq. 14 (Skouras et al. 2014,
// Sec. 5.2, after Wang 2008). The exact Hessian is indefinite away from the minimum and singular along the
// rigid motions, so mu * I is added and raised until the LDL^T factorization has positive pivots.
#include "flatten/flatten_boundary.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

namespace billow {
namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double signedArea(const Points2& Q) {
  double a = 0;
  for (int j = 0, n = static_cast<int>(Q.rows()); j < n; ++j)
    a += cross(Q.row(j).transpose(), Q.row((j + 1) % n).transpose());
  return 0.5 * a;
}

// Closed segments p0p1 and q0q1 share a point (touching counts).
bool segmentsMeet(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
  const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto onSegment = [](const Vec2& a, const Vec2& b, const Vec2& p) {
    return p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) && p.y() >= std::min(a.y(), b.y()) &&
           p.y() <= std::max(a.y(), b.y());
  };
  return (d1 == 0 && onSegment(p0, p1, q0)) || (d2 == 0 && onSegment(p0, p1, q1)) ||
         (d3 == 0 && onSegment(q0, q1, p0)) || (d4 == 0 && onSegment(q0, q1, p1));
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
    if (cross(a, b) == 0 && a.dot(b) < 0) return false;
    for (int k = i + 2; k < n; ++k) {
      if (i == 0 && k == n - 1) continue;
      const Vec2 p0 = P(i), p1 = P(i + 1), q0 = P(k), q1 = P(k + 1);
      if (std::max(p0.x(), p1.x()) < std::min(q0.x(), q1.x()) || std::max(q0.x(), q1.x()) < std::min(p0.x(), p1.x()) ||
          std::max(p0.y(), p1.y()) < std::min(q0.y(), q1.y()) || std::max(q0.y(), q1.y()) < std::min(p0.y(), p1.y()))
        continue;
      if (segmentsMeet(p0, p1, q0, q1)) return false;
    }
  }
  return true;
}

Points2 turningAngleStart(const BoundaryTargets& t) {
  const int n = static_cast<int>(t.length.size());
  Eigen::VectorXd turn = M_PI - t.angle.array(), inv(n);
  for (int j = 0; j < n; ++j) inv[j] = 2.0 / (t.length[(j + n - 1) % n] + t.length[j]);
  turn += (2 * M_PI - turn.sum()) * inv / inv.sum();
  Points2 Q(n + 1, 2);
  Q.row(0).setZero();
  double heading = 0;
  for (int j = 0; j < n; ++j) {
    if (j > 0) heading += turn[j];
    Q.row(j + 1) = Q.row(j) + t.length[j] * Eigen::RowVector2d(std::cos(heading), std::sin(heading));
  }
  // Close the polygon: remove the gap in proportion to the arc length travelled.
  const Eigen::RowVector2d gap = Q.row(n) - Q.row(0);
  double s = 0;
  const double perimeter = t.length.sum();
  for (int j = 0; j < n; ++j) {
    Q.row(j) -= gap * (s / perimeter);
    s += t.length[j];
  }
  return Q.topRows(n);
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

BoundaryFlattening flattenBoundary(const BoundaryTargets& t, const BoundaryNewtonOptions& o) {
  BoundaryFlattening r = minimizeBoundaryEnergy(t, turningAngleStart(t), false, o);
  if (r.simple) return r;
  const int used = r.iterations;
  r = minimizeBoundaryEnergy(t, circleStart(t), true, o);
  r.iterations += used;
  return r;
}

}  // namespace billow
