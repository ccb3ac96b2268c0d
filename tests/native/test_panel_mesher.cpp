// Panel meshing: boundary resampling with seam correspondence, interior quality, barycentric location.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "remesh/panel_mesher.hpp"
#include "remesh/predicates.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;
using Eigen::Vector2d;
using test::kPi;

namespace {

Points2 toPoints(const std::vector<Vector2d>& v) {
  Points2 P(static_cast<Eigen::Index>(v.size()), 2);
  for (std::size_t i = 0; i < v.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = v[i].transpose();
  return P;
}

double polygonArea(const Points2& P) {
  double a = 0;
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    const Eigen::Index j = (i + 1) % P.rows();
    a += P(i, 0) * P(j, 1) - P(i, 1) * P(j, 0);
  }
  return 0.5 * a;
}

Vector2d xy(const TriMesh& m, int v) { return m.V.row(v).head<2>().transpose(); }

struct Quality {
  double minAngle = 180, area = 0, inBand = 0;
  int edges = 0;
};

// Min angle, area, and the fraction of edges with length in [0.5 h, 1.5 h].
Quality measure(const TriMesh& m, double h) {
  Quality q;
  std::set<std::pair<int, int>> seen;
  int good = 0;
  for (int f = 0; f < m.numTriangles(); ++f) {
    const Vector2d a = xy(m, m.F(f, 0)), b = xy(m, m.F(f, 1)), c = xy(m, m.F(f, 2));
    q.area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    const Vector2d v[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
      const Vector2d e1 = v[(k + 1) % 3] - v[k], e2 = v[(k + 2) % 3] - v[k];
      q.minAngle =
          std::min(q.minAngle, std::acos(std::clamp(e1.normalized().dot(e2.normalized()), -1.0, 1.0)) * 180 / kPi);
      const int i = m.F(f, k), j = m.F(f, (k + 1) % 3);
      if (seen.insert({std::min(i, j), std::max(i, j)}).second) {
        const double len = (xy(m, i) - xy(m, j)).norm();
        ++q.edges;
        if (len >= 0.5 * h && len <= 1.5 * h) ++good;
      }
    }
  }
  q.inBand = static_cast<double>(good) / q.edges;
  return q;
}

void expectGoodPanel(const TriMesh& m, const Points2& boundary, double h, double minAngle = 20) {
  ASSERT_GE(m.numVertices(), boundary.rows());
  for (Eigen::Index i = 0; i < boundary.rows(); ++i) {
    EXPECT_EQ(m.V(i, 0), boundary(i, 0));
    EXPECT_EQ(m.V(i, 1), boundary(i, 1));
  }
  EXPECT_TRUE((m.V.col(2).array() == 0).all());
  for (int f = 0; f < m.numTriangles(); ++f)
    EXPECT_EQ(orient2d(xy(m, m.F(f, 0)), xy(m, m.F(f, 1)), xy(m, m.F(f, 2))), 1) << "flipped triangle " << f;
  // Boundary edges are mesh edges, each used once: the boundary is exactly the given polygon.
  std::set<std::pair<int, int>> directed;
  for (int f = 0; f < m.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) directed.insert({m.F(f, k), m.F(f, (k + 1) % 3)});
  const int n = static_cast<int>(boundary.rows());
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(directed.count({i, (i + 1) % n})) << "boundary edge " << i;
    EXPECT_FALSE(directed.count({(i + 1) % n, i}));
  }
  const Quality q = measure(m, h);
  std::printf("[panel] %d vertices, %d triangles, min angle %.1f deg, %.1f%% edges in [0.5h, 1.5h]\n", m.numVertices(),
              m.numTriangles(), q.minAngle, 100 * q.inBand);
  EXPECT_NEAR(q.area, polygonArea(boundary), 1e-9 * std::abs(polygonArea(boundary)));
  EXPECT_GE(q.minAngle, minAngle);
  EXPECT_GE(q.inBand, 0.9);
}

Points2 disc(int n) {
  std::vector<Vector2d> v;
  for (int i = 0; i < n; ++i) v.emplace_back(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n));
  return toPoints(v);
}

// A lune: two circular arcs between (-1, 0) and (1, 0), bulging up (radius 1.3) and down (radius 2).
Points2 lune(int perArc, std::vector<int>* corners) {
  std::vector<Vector2d> v;
  auto arc = [&](double radius, bool lower) {
    const double c = std::sqrt(radius * radius - 1);  // center at (0, -+c)
    const double half = std::asin(1 / radius);
    for (int i = 0; i < perArc; ++i) {
      const double t = -half + 2 * half * i / perArc;  // from (1, 0) (lower: from (-1, 0))
      if (lower)
        v.emplace_back(-radius * std::sin(-t), c - radius * std::cos(t));
      else
        v.emplace_back(radius * std::sin(-t), -c + radius * std::cos(t));
    }
  };
  arc(2.0, true);   // (-1, 0) -> (1, 0) along the bottom
  arc(1.3, false);  // (1, 0) -> (-1, 0) along the top
  if (corners) *corners = {0, perArc};
  return toPoints(v);
}

}  // namespace

TEST(PanelMesh, ResamplePolylineGivesEqualArcLengthsAndExactEnds) {
  Points2 line(4, 2);
  line << 0, 0, 1, 0, 1, 2, 4, 2;  // length 6
  Eigen::VectorXd params;
  const Points2 r = resamplePolyline(line, 12, &params);
  ASSERT_EQ(r.rows(), 13);
  EXPECT_EQ(r.row(0), line.row(0));
  EXPECT_EQ(r.row(12), line.row(3));
  for (int k = 0; k < 12; ++k) {
    // Straight pieces or corner cuts: each chord is at most the arc step 0.5 and near it.
    const double d = (r.row(k + 1) - r.row(k)).norm();
    EXPECT_LE(d, 0.5 + 1e-12);
    EXPECT_GE(d, 0.5 / std::sqrt(2.0) - 1e-12);
  }
  EXPECT_DOUBLE_EQ(params(2), 1.0);  // arc length 1 is vertex 1
  EXPECT_DOUBLE_EQ(params(3), 1.25);
  EXPECT_DOUBLE_EQ(params(12), 3.0);
}

TEST(PanelMesh, ResampleBoundaryKeepsCornersAndMatchesSeamCounts) {
  std::vector<int> corners;
  const Points2 poly = lune(40, &corners);
  const ResampledBoundary b = resampleBoundary(poly, corners, 0.1);
  ASSERT_EQ(b.cornerRows.size(), 2u);
  EXPECT_EQ(b.points.row(b.cornerRows[0]), poly.row(corners[0]));
  EXPECT_EQ(b.points.row(b.cornerRows[1]), poly.row(corners[1]));
  EXPECT_EQ(b.points.rows(), b.segmentsPerPiece[0] + b.segmentsPerPiece[1]);
  for (Eigen::Index i = 0; i < b.points.rows(); ++i) {
    // Each point lies on the input polygon at its parameter.
    const int e = static_cast<int>(std::floor(b.param(i)));
    const double s = b.param(i) - e;
    const Eigen::RowVector2d p = (1 - s) * poly.row(e) + s * poly.row((e + 1) % poly.rows());
    EXPECT_LT((p - b.points.row(i)).norm(), 1e-12);
  }
  // The partner panel across the bottom seam (the same arc, mirrored, traversed the other way) takes the same
  // count on that piece and gets the mirrored points.
  Points2 mirrored = poly;
  mirrored.col(1) *= -1;
  Points2 partner = mirrored.colwise().reverse();
  const int n = static_cast<int>(poly.rows());
  // partner's corners: reversed indices of 0 and 40.
  std::vector<int> pc = {n - 1 - corners[1], n - 1 - corners[0]};
  const ResampledBoundary bp = resampleBoundary(partner, pc, {b.segmentsPerPiece[0], b.segmentsPerPiece[1]});
  const int seam = b.segmentsPerPiece[0];
  for (int k = 0; k <= seam; ++k) {
    const Eigen::RowVector2d mine = b.points.row(b.cornerRows[0] + k);
    const int j = bp.cornerRows[0] + (seam - k);  // partner piece 0 runs the mirrored bottom arc backwards
    const Eigen::RowVector2d theirs = bp.points.row(j % bp.points.rows());
    EXPECT_LT((mine - Eigen::RowVector2d(theirs.x(), -theirs.y())).norm(), 1e-12) << k;
  }
}

TEST(PanelMesh, DiscIsWellShaped) {
  const double h = 0.08;
  const ResampledBoundary b = resampleBoundary(disc(400), {}, h);
  const TriMesh m = meshPanel(b.points, h);
  expectGoodPanel(m, b.points, h);
}

TEST(PanelMesh, LShapeIsWellShaped) {
  std::vector<Vector2d> v = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const double h = 0.1;
  const ResampledBoundary b = resampleBoundary(toPoints(v), {0, 1, 2, 3, 4, 5}, h);
  EXPECT_EQ(b.points.rows(), 80);
  const TriMesh m = meshPanel(b.points, h);
  expectGoodPanel(m, b.points, h);
}

TEST(PanelMesh, LuneIsWellShaped) {
  std::vector<int> corners;
  const Points2 poly = lune(200, &corners);
  for (double h : {0.2, 0.05}) {
    const ResampledBoundary b = resampleBoundary(poly, corners, h);
    const TriMesh m = meshPanel(b.points, h);
    expectGoodPanel(m, b.points, h);
  }
}

// A ring panel (a letter O, a number 8): the outline and a clockwise hole, both kept exactly, nothing meshed
// inside the hole; a hole that is not inside the outline is refused.
TEST(PanelMesh, RingIsWellShapedAroundItsHole) {
  const double h = 0.08;
  const ResampledBoundary outer = resampleBoundary(disc(400), {}, h);
  Points2 hole = resampleBoundary(disc(200) * 0.4, {}, h).points.colwise().reverse();
  hole.col(0).array() += 0.2;  // off centre
  const TriMesh m = meshPanel(outer.points, h, {}, {hole});
  Points2 both(outer.points.rows() + hole.rows(), 2);
  both << outer.points, hole;
  for (Eigen::Index i = 0; i < both.rows(); ++i) EXPECT_EQ(m.V.row(i).head<2>(), both.row(i));
  std::set<std::pair<int, int>> directed;
  for (int f = 0; f < m.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) directed.insert({m.F(f, k), m.F(f, (k + 1) % 3)});
  const int n = static_cast<int>(outer.points.rows()), k = static_cast<int>(hole.rows());
  for (int i = 0; i < k; ++i) {  // each hole edge borders the panel on its left, as the outline's do
    EXPECT_TRUE(directed.count({n + i, n + (i + 1) % k})) << "hole edge " << i;
    EXPECT_FALSE(directed.count({n + (i + 1) % k, n + i}));
  }
  const Quality q = measure(m, h);
  EXPECT_NEAR(q.area, polygonArea(outer.points) + polygonArea(hole), 1e-9);
  EXPECT_GE(q.minAngle, 20);
  EXPECT_GE(q.inBand, 0.9);
  // The hole moved out of the outline, or the outline given as a hole of itself.
  Points2 outside = hole;
  outside.col(0).array() += 3;
  for (const Points2& bad : {outside, Points2(0.5 * hole)}) {
    try {
      meshPanel(outer.points, h, {}, {hole, bad});
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_TRUE(e.code == "panel.bad-hole" || e.code == "panel.self-intersecting") << e.code;
    }
  }
  EXPECT_THROW(meshPanel(outer.points, h, {}, {Points2(hole.colwise().reverse())}), Error);  // counter-clockwise
}

TEST(PanelMesh, RejectsBadOutlines) {
  Points2 cw = disc(20).colwise().reverse();
  EXPECT_THROW(meshPanel(cw, 0.1), Error);
  Points2 bow(4, 2);
  bow << 0, 0, 1, 1, 1, 0, 0, 1;  // self-intersecting
  try {
    meshPanel(bow, 0.1);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(e.code == "panel.self-intersecting" || e.code == "panel.clockwise") << e.code;
  }
}

TEST(PanelMesh, BarycentricLocationRoundTrips) {
  const double h = 0.05;
  const ResampledBoundary b = resampleBoundary(disc(300), {}, h);
  const TriMesh m = meshPanel(b.points, h);
  const TriangleLocator loc(m);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  int inside = 0;
  for (int k = 0; k < 5000; ++k) {
    const Vector2d p(u(rng), u(rng));
    const BarycentricPoint bp = loc.locate(p);
    ASSERT_GE(bp.triangle, 0);
    const Vector2d back = bp.weights(0) * xy(m, m.F(bp.triangle, 0)) + bp.weights(1) * xy(m, m.F(bp.triangle, 1)) +
                          bp.weights(2) * xy(m, m.F(bp.triangle, 2));
    EXPECT_NEAR(bp.weights.sum(), 1.0, 1e-12);
    EXPECT_GE(bp.weights.minCoeff(), -1e-12);
    if (bp.inside) {
      ++inside;
      EXPECT_LT((back - p).norm(), 1e-12);
    } else {
      EXPECT_NEAR((back - p).norm(), bp.distance, 1e-12);
      EXPECT_GT(p.norm(), 0.99);  // only points off the (polygonal) disc are outside
      if (k % 10 != 0) continue;
      // The brute-force closest distance over all triangles agrees.
      double best = 1e300;
      for (int f = 0; f < m.numTriangles(); ++f) {
        const BarycentricPoint one = barycentricLocate(TriMesh{m.V, m.F.row(f)}, p);
        best = std::min(best, one.distance);
      }
      EXPECT_NEAR(bp.distance, best, 1e-12);
    }
  }
  EXPECT_GT(inside, 3500);
  // Mesh vertices locate to themselves (a weight of 1 at that vertex).
  for (int v = 0; v < m.numVertices(); v += 7) {
    const BarycentricPoint bp = loc.locate(xy(m, v));
    ASSERT_TRUE(bp.inside);
    const Vector2d back = bp.weights(0) * xy(m, m.F(bp.triangle, 0)) + bp.weights(1) * xy(m, m.F(bp.triangle, 1)) +
                          bp.weights(2) * xy(m, m.F(bp.triangle, 2));
    EXPECT_LT((back - xy(m, v)).norm(), 1e-12);
  }
}

TEST(PanelMeshTiming, TenAndHundredThousandTriangles) {
  for (double h : {0.03, 0.0095}) {
    const auto t0 = std::chrono::steady_clock::now();
    const ResampledBoundary b = resampleBoundary(disc(2000), {}, h);
    const TriMesh m = meshPanel(b.points, h);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const auto t1 = std::chrono::steady_clock::now();
    const TriangleLocator loc(m);
    int found = 0;
    for (int v = 0; v < m.numVertices(); ++v) found += loc.locate(xy(m, v) * 0.999).inside ? 1 : 0;
    const double ms2 = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
    std::printf(
        "[timing] panel mesh of the unit disc at h = %g: %d triangles in %.1f ms; locator + %d queries %.1f ms\n", h,
        m.numTriangles(), ms, m.numVertices(), ms2);
    EXPECT_EQ(found, m.numVertices());
    expectGoodPanel(m, b.points, h);
  }
}

TEST(OutlineCrossing, SaysWhereAPolygonMeetsItself) {
  Points2 square(4, 2);
  square << 0, 0, 1, 0, 1, 1, 0, 1;
  EXPECT_EQ(outlineCrossing(square), -1);
  // A bow tie: edge 0 (bottom) is fine, edge 1 crosses edge 3.
  Points2 bowTie(4, 2);
  bowTie << 0, 0, 1, 0, 0, 1, 1, 1;
  EXPECT_EQ(outlineCrossing(bowTie), 1);
  // A C shape whose tips touch: edges meeting at a point count.
  Points2 touching(8, 2);
  touching << 0, 0, 3, 0, 3, 1, 1, 1, 1, 2, 3, 2, 3, 3, 0, 3;
  EXPECT_EQ(outlineCrossing(touching), -1);
  touching.row(2) << 3, 2;  // the lower arm's tip reaches the upper arm's: edge 1 ends on edge (4, 5)
  EXPECT_EQ(outlineCrossing(touching), 1);
  // The lower arm bent up across the upper one: the mesher refuses it, and the crossing is found.
  touching.row(2) << 2, 2.5;
  EXPECT_EQ(outlineCrossing(touching), 1);
  EXPECT_THROW(meshPanel(touching, 0.5), Error);
}
