// straightenInStrip (seams/funnel.hpp), the funnel algorithm inside the geodesic solver, on a cube where every
// answer is known: a straight line across a face or over a fold unfolds to a segment, and a strip that goes
// the long way around a corner (270 degrees of faces) is shortest through the corner, bending there by the
// angle by which the unfolded wedge exceeds pi. The solver only flips out of such wraps if they are reported.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cube_fixture.hpp"
#include "seams/funnel.hpp"
#include "test_support.hpp"

using namespace billow;
using test::kPi;
using test::pointIn;

namespace {

// Pieces hold both their ends, interior points lie on mesh edges or vertices, and the length is the sum.
void expectWellFormed(const TriMesh& m, const MeshTopology& topo, const GeodesicPath& g) {
  ASSERT_EQ(g.faces.size() + 1, g.points.size());
  double length = 0;
  for (size_t i = 0; i < g.faces.size(); ++i) {
    SurfacePoint s;
    EXPECT_TRUE(expressInFace(m, topo, g.points[i].point, g.faces[i], s)) << "piece " << i;
    EXPECT_TRUE(expressInFace(m, topo, g.points[i + 1].point, g.faces[i], s)) << "piece " << i;
    length += (g.points[i + 1].position - g.points[i].position).norm();
  }
  for (size_t i = 1; i + 1 < g.points.size(); ++i) EXPECT_TRUE(g.points[i].vertex >= 0 || g.points[i].edge >= 0);
  for (const PathPoint& p : g.points) EXPECT_LT((position(m, p.point) - p.position).norm(), 1e-12);
  EXPECT_NEAR(g.length, length, 1e-12);
}

struct Cube {
  TriMesh mesh = test::unitCube();
  MeshTopology topo = buildTopology(mesh);
};

}  // namespace

TEST(Funnel, WithinOneFaceThePathIsTheSegmentAndAVertexEndIsNamed) {
  const Cube c;
  const SurfacePoint a = pointIn(c.mesh, 1, {1, 1, 0}), b = pointIn(c.mesh, 1, {0.2, 0.7, 0});
  const StripPath s = straightenInStrip(c.mesh, c.topo, {1}, a, b);
  expectWellFormed(c.mesh, c.topo, s.path);
  ASSERT_EQ(s.path.points.size(), 2u);
  EXPECT_EQ(s.path.points[0].vertex, 3) << "the start is cube vertex 3, (1, 1, 0)";
  EXPECT_EQ(s.path.points[1].vertex, -1);
  EXPECT_EQ(s.path.faces, std::vector<int>{1});
  EXPECT_NEAR(s.path.length, std::sqrt(0.8 * 0.8 + 0.3 * 0.3), 1e-14);
  EXPECT_TRUE(s.wraps.empty());
}

TEST(Funnel, AcrossAFaceDiagonalThePathCrossesItWhereTheSegmentDoes) {
  // (0.2, 0.6) to (0.8, 0.4) on the bottom face crosses the diagonal y = x halfway, at (0.5, 0.5).
  const Cube c;
  const StripPath s =
      straightenInStrip(c.mesh, c.topo, {1, 0}, pointIn(c.mesh, 1, {0.2, 0.6, 0}), pointIn(c.mesh, 0, {0.8, 0.4, 0}));
  expectWellFormed(c.mesh, c.topo, s.path);
  ASSERT_EQ(s.path.points.size(), 3u);
  const PathPoint& x = s.path.points[1];
  EXPECT_EQ(x.edge, c.topo.edgeBetween(0, 3));
  EXPECT_NEAR(x.t, 0.5, 1e-12);
  EXPECT_LT((x.position - Eigen::Vector3d(0.5, 0.5, 0)).norm(), 1e-12);
  EXPECT_NEAR(s.path.length, std::sqrt(0.4), 1e-12);
  EXPECT_TRUE(s.wraps.empty());
}

TEST(Funnel, OverACubeEdgeThePathIsStraightInTheUnfolding) {
  // (0.5, 0.2, 0) on the bottom to (0.7, 0, 0.4) on the front face: unfolded about the x axis the start is at
  // (0.5, -0.2), so the segment meets the edge a third of the way, at x = 0.5 + 0.2 / 3, and is sqrt(0.4) long.
  const Cube c;
  const StripPath s =
      straightenInStrip(c.mesh, c.topo, {0, 2}, pointIn(c.mesh, 0, {0.5, 0.2, 0}), pointIn(c.mesh, 2, {0.7, 0, 0.4}));
  expectWellFormed(c.mesh, c.topo, s.path);
  ASSERT_EQ(s.path.points.size(), 3u);
  const PathPoint& x = s.path.points[1];
  EXPECT_EQ(x.edge, c.topo.edgeBetween(0, 1));
  EXPECT_NEAR(x.t, 0.5 + 0.2 / 3, 1e-12) << "from vertex 0 towards vertex 1";
  EXPECT_LT((x.position - Eigen::Vector3d(0.5 + 0.2 / 3, 0, 0)).norm(), 1e-12);
  EXPECT_NEAR(s.path.length, std::sqrt(0.4), 1e-12);
  EXPECT_TRUE(s.wraps.empty());
}

namespace {

// Around cube vertex 0 the long way, from a = (0.3, 0.6, 0) in triangle 1 to b in triangle 2 on the y = 0 face,
// through triangles 5, 4 and 3. Unfolded around vertex 0, a sits at angle atan2(0.6, 0.3) - 45 degrees from the
// edge to vertex 3 and b at 225 degrees - atan2(b.z, b.x); both at their distance from vertex 0.
const std::vector<int> kLongWay{1, 5, 4, 3, 2};
const Eigen::Vector3d kA(0.3, 0.6, 0);

double unfoldedAngle(const Eigen::Vector3d& b) {
  return 5 * kPi / 4 - std::atan2(b.z(), b.x()) - (std::atan2(kA.y(), kA.x()) - kPi / 4);
}

}  // namespace

TEST(Funnel, TheLongWayAroundACubeCornerWrapsTheCornerWithTheAngleOverPi) {
  // b = (0.6, 0, 0.2): the wedge from a to b is 3 pi / 2 - atan(1/3) - atan(2) > pi, so no segment fits in the
  // strip; the shortest path runs a -> vertex 0 -> b and turns there by the excess, atan(3) - atan(2) = atan(1/7).
  const Cube c;
  const Eigen::Vector3d b(0.6, 0, 0.2);
  ASSERT_GT(unfoldedAngle(b), kPi);
  const StripPath s = straightenInStrip(c.mesh, c.topo, kLongWay, pointIn(c.mesh, 1, kA), pointIn(c.mesh, 2, b));
  expectWellFormed(c.mesh, c.topo, s.path);
  ASSERT_EQ(s.path.points.size(), 3u);
  EXPECT_EQ(s.path.points[1].vertex, 0);
  EXPECT_NEAR(s.path.length, kA.norm() + b.norm(), 1e-12);
  ASSERT_EQ(s.wraps.size(), 1u);
  EXPECT_EQ(s.wraps[0].vertex, 0);
  EXPECT_NEAR(s.wraps[0].turn, unfoldedAngle(b) - kPi, 1e-12);
  EXPECT_NEAR(s.wraps[0].turn, std::atan(1.0 / 7), 1e-12);
  EXPECT_GE(s.wraps[0].portal, 1);
  EXPECT_LE(s.wraps[0].portal, static_cast<int>(kLongWay.size()) - 1);
}

TEST(Funnel, TheSameCornerWalkedBackwardsWrapsItTheSameWay) {
  const Cube c;
  const Eigen::Vector3d b(0.6, 0, 0.2);
  const std::vector<int> back(kLongWay.rbegin(), kLongWay.rend());
  const StripPath s = straightenInStrip(c.mesh, c.topo, back, pointIn(c.mesh, 2, b), pointIn(c.mesh, 1, kA));
  expectWellFormed(c.mesh, c.topo, s.path);
  ASSERT_EQ(s.path.points.size(), 3u);
  EXPECT_EQ(s.path.points[1].vertex, 0);
  EXPECT_NEAR(s.path.length, kA.norm() + b.norm(), 1e-12);
  ASSERT_EQ(s.wraps.size(), 1u);
  EXPECT_EQ(s.wraps[0].vertex, 0);
  EXPECT_NEAR(s.wraps[0].turn, std::atan(1.0 / 7), 1e-12);
}

TEST(Funnel, AWedgeUnderPiAroundTheCornerIsCrossedStraight) {
  // b = (0.6, 0, 0.45): the unfolded wedge is under pi, so the path is the third side of the triangle
  // (vertex 0, a, b) in the unfolding and crosses each of the four fan edges between the triangles.
  const Cube c;
  const Eigen::Vector3d b(0.6, 0, 0.45);
  const double wedge = unfoldedAngle(b);
  ASSERT_LT(wedge, kPi);
  const StripPath s = straightenInStrip(c.mesh, c.topo, kLongWay, pointIn(c.mesh, 1, kA), pointIn(c.mesh, 2, b));
  expectWellFormed(c.mesh, c.topo, s.path);
  const double ra = kA.norm(), rb = b.norm();
  EXPECT_NEAR(s.path.length, std::sqrt(ra * ra + rb * rb - 2 * ra * rb * std::cos(wedge)), 1e-12);
  ASSERT_EQ(s.path.points.size(), 6u);
  const int ends[4] = {2, 6, 4, 5};  // the fan edges from vertex 0, in strip order
  for (int k = 0; k < 4; ++k) {
    const PathPoint& p = s.path.points[k + 1];
    EXPECT_EQ(p.vertex, -1);
    EXPECT_EQ(p.edge, c.topo.edgeBetween(0, ends[k])) << "crossing " << k;
  }
  EXPECT_TRUE(s.wraps.empty());
}
