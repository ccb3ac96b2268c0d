// Geodesics (seams/geodesic.hpp) and projection (seams/surface_point.hpp): great circles on the sphere,
// never longer than the mesh-edge path on the corpus, fast around thin limbs.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "seams/geodesic.hpp"
#include "seams/seam_curve.hpp"
#include "seams/surface_distance.hpp"
#include "segment/segmentation.hpp"
#include "test_support.hpp"

using namespace billow;

namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The piece faces must hold both ends, and interior points must be on edges or vertices.
void expectWellFormed(const TriMesh& m, const MeshTopology& topo, const GeodesicPath& g) {
  ASSERT_EQ(g.faces.size() + 1, g.points.size());
  for (size_t i = 0; i < g.faces.size(); ++i) {
    SurfacePoint s;
    EXPECT_TRUE(expressInFace(m, topo, g.points[i].point, g.faces[i], s));
    EXPECT_TRUE(expressInFace(m, topo, g.points[i + 1].point, g.faces[i], s));
  }
  for (size_t i = 1; i + 1 < g.points.size(); ++i) EXPECT_TRUE(g.points[i].vertex >= 0 || g.points[i].edge >= 0);
  for (const PathPoint& p : g.points) EXPECT_LT((position(m, p.point) - p.position).norm(), 1e-9);
}

}  // namespace

TEST(SurfaceProjection, MatchesBruteForceAndIsFast) {
  const TriMesh m = test::loadShared("cat.obj");
  const SurfaceProjector projector(m);
  const Eigen::Vector3d lo = m.V.colwise().minCoeff(), hi = m.V.colwise().maxCoeff();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector3d q = lo + (hi - lo).cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng)));
    double d = 0, best = 1e300;
    projector.project(q, &d);
    for (int f = 0; f < m.numTriangles(); ++f) {
      const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
      const Eigen::Vector3d w = closestPointBarycentric(q, a, b, c);
      best = std::min(best, (w[0] * a + w[1] * b + w[2] * c - q).norm());
    }
    EXPECT_NEAR(d, best, 1e-12 * (hi - lo).norm());
  }
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 1000; ++i)
    projector.project(lo + (hi - lo).cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng))));
  const double perQuery = msSince(t0) / 1000;
  std::printf("[timing] projection on cat (%d triangles): %.4f ms per query\n", m.numTriangles(), perQuery);
  EXPECT_LT(perQuery, 1.0);
}

TEST(SurfaceDistance, SignedOutsidePositiveInsideNegativeOnACubeAndOnSpot) {
  // The cube [-1, 1]^3, outward triangles.
  TriMesh cube;
  cube.V.resize(8, 3);
  for (int i = 0; i < 8; ++i) cube.V.row(i) << (i & 1 ? 1 : -1), (i & 2 ? 1 : -1), (i & 4 ? 1 : -1);
  cube.F.resize(12, 3);
  cube.F << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5;
  const SurfaceProjector cubeProjector(cube);
  Vertices q(5, 3);
  q << 0, 0, 1.5, 0, 0, 0.5, 0, 0, 0, 1.5, 1.5, 0, 0.9, 0.95, 0;
  const Eigen::VectorXd d = signedDistances(cube, cubeProjector, q);
  EXPECT_NEAR(d[0], 0.5, 1e-12);
  EXPECT_NEAR(d[1], -0.5, 1e-12);
  EXPECT_NEAR(d[2], -1.0, 1e-12);
  EXPECT_NEAR(d[3], std::sqrt(0.5), 1e-12) << "outside an edge";
  EXPECT_NEAR(d[4], -0.05, 1e-12) << "inside, near an edge";
  // Spot: every vertex pushed out along its area-weighted normal by 0.2 % of the box diagonal is
  // outside by about that much, pushed in is inside.
  const TriMesh spot = test::loadShared("spot.obj");
  const SurfaceProjector projector(spot);
  const double h = 0.002 * (spot.V.colwise().maxCoeff() - spot.V.colwise().minCoeff()).norm();
  Vertices normals = Vertices::Zero(spot.V.rows(), 3);
  for (int f = 0; f < spot.numTriangles(); ++f) {
    const Eigen::Vector3d a = spot.V.row(spot.F(f, 0)), b = spot.V.row(spot.F(f, 1)), c = spot.V.row(spot.F(f, 2));
    for (int k = 0; k < 3; ++k) normals.row(spot.F(f, k)) += (b - a).cross(c - a).transpose();
  }
  normals.rowwise().normalize();
  const Eigen::VectorXd out = signedDistances(spot, projector, spot.V + h * normals);
  const Eigen::VectorXd in = signedDistances(spot, projector, spot.V - h * normals);
  int wrongSide = 0;
  for (int v = 0; v < spot.V.rows(); ++v) wrongSide += (out[v] <= 0) + (in[v] >= 0);
  EXPECT_EQ(wrongSide, 0);
  EXPECT_NEAR(out.mean(), h, 0.2 * h);
  EXPECT_NEAR(in.mean(), -h, 0.2 * h);
}

TEST(Geodesic, FollowsGreatCirclesOnTheSphere) {
  const TriMesh m = test::loadShared("sphere.obj");
  const MeshTopology topo = buildTopology(m);
  const SurfaceProjector projector(m);
  const GeodesicSolver solver(m, topo);
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, 1);
  // One coordinate per statement: the order a constructor's arguments are evaluated in differs between compilers.
  const auto direction = [&] {
    Eigen::Vector3d d;
    for (int k = 0; k < 3; ++k) d[k] = n(rng);
    return d.normalized();
  };
  double edge = 0;
  for (int e = 0; e < topo.numEdges(); ++e)
    edge += (m.V.row(topo.E(e, 0)) - m.V.row(topo.E(e, 1))).norm() / topo.numEdges();
  int tested = 0;
  while (tested < 12) {
    const Eigen::Vector3d p = direction();
    const Eigen::Vector3d q = direction();
    const double arc = std::acos(std::max(-1.0, std::min(1.0, p.dot(q))));
    if (arc > 2.6 || arc < 0.3) continue;  // not antipodal, not trivial
    ++tested;
    const SurfacePoint a = projector.project(p), b = projector.project(q);
    const Eigen::Vector3d pa = position(m, a), pb = position(m, b);
    const double exact = std::acos(std::max(-1.0, std::min(1.0, pa.normalized().dot(pb.normalized()))));
    const GeodesicPath g = solver.path(a, b);
    expectWellFormed(m, topo, g);
    // the icosphere is inscribed in the unit sphere: compare with the arc at the mean radius of the path
    double r = 0;
    for (const PathPoint& x : g.points) r += x.position.norm() / g.points.size();
    EXPECT_NEAR(g.length, exact * r, 0.01 * exact * r) << "arc " << exact;
    // and every path point lies within an edge's length of the great circle's plane: the shortest path over the
    // facets may cross other triangles than the plane does (up to half an edge length in 400 random pairs)
    const Eigen::Vector3d normal = pa.cross(pb).normalized();
    for (const PathPoint& x : g.points) EXPECT_LT(std::abs(x.position.dot(normal)), edge);
  }
}

class CorpusGeodesic : public ::testing::TestWithParam<const char*> {};

TEST_P(CorpusGeodesic, NeverLongerThanTheEdgePathAndFast) {
  const TriMesh m = test::loadShared(GetParam());
  const MeshTopology topo = buildTopology(m);
  const GeodesicSolver solver(m, topo);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> pick(0, m.numVertices() - 1);
  double worstMs = 0, totalMs = 0;
  int improved = 0;
  const int pairs = 12;
  for (int i = 0; i < pairs; ++i) {
    const int v0 = pick(rng), v1 = pick(rng);
    const auto t0 = std::chrono::steady_clock::now();
    const GeodesicPath g = solver.path(vertexPoint(m, topo, v0), vertexPoint(m, topo, v1));
    const double ms = msSince(t0);
    worstMs = std::max(worstMs, ms), totalMs += ms;
    const double edge = solver.edgeGraphDistance(v0, v1);
    expectWellFormed(m, topo, g);
    EXPECT_LE(g.length, edge * (1 + 1e-12)) << v0 << " -> " << v1;
    if (g.length < 0.99 * edge) ++improved;
    EXPECT_LT(g.iterations, GeodesicOptions().maxIterations + 1);
  }
  EXPECT_GE(improved, pairs / 2) << "straightening should shorten most edge paths";
  std::printf("[timing] geodesic on %s (%d triangles): mean %.2f ms, worst %.2f ms\n", GetParam(), m.numTriangles(),
              totalMs / pairs, worstMs);
  EXPECT_LT(worstMs, 500.0);
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusGeodesic,
                         ::testing::Values("sphere.obj", "spot.obj", "bunny.obj", "blub.obj", "penguin.obj",
                                           "elephant.obj", "koala.obj", "cat.obj", "octopus.obj", "hand.obj",
                                           "stuffedtoy.obj", "goathead.obj"));

// A loop of points around a thin limb (the octopus' tentacles, the cat's tail): every piece ends fast.
TEST(Geodesic, LoopsAroundThinLimbsTerminateFast) {
  for (const char* name : {"octopus.obj", "cat.obj"}) {
    const TriMesh m = test::loadShared(name);
    const MeshTopology topo = buildTopology(m);
    const GeodesicSolver solver(m, topo);
    // the thinnest part: the vertex whose neighbourhood has the smallest bounding radius is not robust;
    // instead walk loops around many random vertices (one ring at a few hops) and time all of them.
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> pick(0, m.numVertices() - 1);
    double worst = 0;
    for (int i = 0; i < 30; ++i) {
      const int v = pick(rng);
      std::vector<int> ring;
      for (const auto& [u, e] : topo.neighbors[v]) ring.push_back(u);
      const auto t0 = std::chrono::steady_clock::now();
      for (size_t k = 0; k < ring.size(); ++k) {
        const GeodesicPath g =
            solver.path(vertexPoint(m, topo, ring[k]), vertexPoint(m, topo, ring[(k + 1) % ring.size()]));
        EXPECT_LE(g.length, solver.edgeGraphDistance(ring[k], ring[(k + 1) % ring.size()]) * (1 + 1e-12));
      }
      worst = std::max(worst, msSince(t0));
    }
    std::printf("[timing] ring loops on %s: worst %.2f ms\n", name, worst);
    EXPECT_LT(worst, 200.0);
  }
}

// A smoothed seam (cubic Hermite through the control points, DESIGN.md) through six points on a circle of
// latitude follows that circle; the plain seam through the same points is the geodesic hexagon, which cuts
// the corners. Both are well formed, pass through every control point, and close exactly.
TEST(SeamCurve, SmoothSeamFollowsTheCircleThroughItsPointsWhereGeodesicsCutCorners) {
  const TriMesh m = test::loadShared("sphere.obj");
  const MeshTopology topo = buildTopology(m);
  const SurfaceProjector projector(m);
  const GeodesicSolver solver(m, topo);
  const double latitude = 0.5;  // the circle z = sin(0.5) on the unit sphere, radius cos(0.5)
  SeamSpec spec;
  spec.closed = true;
  for (int k = 0; k < 6; ++k) {
    const double a = 2 * M_PI * k / 6 + 0.1;
    spec.controls.push_back(projector.project(
        Eigen::Vector3d(std::cos(latitude) * std::cos(a), std::cos(latitude) * std::sin(a), std::sin(latitude))));
  }
  const double circle = 2 * M_PI * std::cos(latitude);
  // Worst distance of the curve's points from the cone of the circle (angle from the equator plane).
  auto worstLatitudeError = [&](const SeamCurve& c) {
    double worst = 0;
    for (const PathPoint& p : c.points)
      worst = std::max(worst, std::abs(std::asin(p.position.normalized().z()) - latitude));
    return worst;
  };
  spec.smooth = false;
  const SeamCurve plain = buildSeamCurve(solver, projector, spec);
  spec.smooth = true;
  const SeamCurve smooth = buildSeamCurve(solver, projector, spec);
  for (const SeamCurve* c : {&plain, &smooth}) {
    ASSERT_EQ(c->faces.size() + 1, c->points.size());
    for (size_t i = 0; i < c->faces.size(); ++i) {
      SurfacePoint s;
      EXPECT_TRUE(expressInFace(m, topo, c->points[i].point, c->faces[i], s));
      EXPECT_TRUE(expressInFace(m, topo, c->points[i + 1].point, c->faces[i], s));
    }
    ASSERT_EQ(c->controlIndices.size(), 6u);
    for (int k = 0; k < 6; ++k)
      EXPECT_LT((c->points[c->controlIndices[k]].position - position(m, spec.controls[k])).norm(), 1e-12);
    EXPECT_EQ((c->points.front().position - c->points.back().position).norm(), 0.0);
  }
  const double plainError = worstLatitudeError(plain), smoothError = worstLatitudeError(smooth);
  std::printf(
      "[seams] latitude circle: plain length %.4f, smooth %.4f, circle %.4f; worst latitude error %.4f vs %.4f\n",
      plain.length, smooth.length, circle, plainError, smoothError);
  EXPECT_LT(smoothError, 0.5 * plainError) << "the spline keeps to the circle";
  EXPECT_LT(smoothError, 0.03);
  EXPECT_NEAR(smooth.length, circle, 0.02 * circle);
  EXPECT_LT(plain.length, smooth.length) << "the geodesic hexagon is shorter than the circle";
}

TEST(SeamCurve, SmoothSpansThatWouldCrossTheSeamFallBackToTheSurfacePath) {
  // A square loop with a deep, narrow notch: the spline through the notch's three points overshoots, and its
  // two sides crossed each other (a self-crossing seam and sliver segments). Those spans keep the surface
  // path; the square's sides stay smooth.
  const TriMesh m = test::loadShared("sphere.obj");
  const MeshTopology topo = buildTopology(m);
  const SurfaceProjector projector(m);
  const GeodesicSolver solver(m, topo);
  SeamSpec spec;
  spec.closed = true;
  const double uv[7][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {0.03, 0.5}, {0, 0}, {-0.03, 0.5}, {-0.5, 0.5}};
  for (const auto& p : uv) spec.controls.push_back(projector.project(Eigen::Vector3d(p[0], p[1], 1).normalized()));
  spec.smooth = false;
  const SeamCurve plain = buildSeamCurve(solver, projector, spec);
  spec.smooth = true;
  const SeamCurve smooth = buildSeamCurve(solver, projector, spec);
  for (const SeamCurve* c : {&plain, &smooth}) {
    const Segmentation s = segmentTarget(m, topo, {*c});
    int crossings = 0;
    for (const SegmentationProblem& p : s.problems) crossings += p.code == "seam.self-crossing";
    EXPECT_EQ(crossings, 0) << (c == &plain ? "plain" : "smooth");
    EXPECT_EQ(s.segments.size(), 2u);
    EXPECT_TRUE(s.ok());
  }
  ASSERT_EQ(smooth.controlIndices.size(), 7u);
  // The notch's spans are the plain ones; a side of the square is not.
  const auto spanLength = [](const SeamCurve& c, int k) {
    const int end = k + 1 < int(c.controlIndices.size()) ? c.controlIndices[k + 1] : int(c.points.size()) - 1;
    double length = 0;
    for (int i = c.controlIndices[k]; i < end; ++i) length += (c.points[i + 1].position - c.points[i].position).norm();
    return length;
  };
  EXPECT_NEAR(spanLength(smooth, 3), spanLength(plain, 3), 1e-12);
  EXPECT_NEAR(spanLength(smooth, 4), spanLength(plain, 4), 1e-12);
  EXPECT_GT(std::abs(spanLength(smooth, 0) - spanLength(plain, 0)), 1e-4) << "the square's sides stay smoothed";
}
