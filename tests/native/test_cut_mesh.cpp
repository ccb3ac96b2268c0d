// cutAlongSeams (segment/cut_mesh.hpp) on a cube, where the vertices, seam edges and crossings a seam must
// produce are known by hand. Segmentation only sees segments; a seam point registered twice, a crossing
// missed or a triangle left across a seam would show there as a wrong count far from its cause.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cube_fixture.hpp"
#include "segment/cut_mesh.hpp"

using namespace billow;
using test::pointIn;

namespace {

struct Cube {
  TriMesh mesh = test::unitCube();
  MeshTopology topo = buildTopology(mesh);
};

// A seam through these (face, 3D point) pairs; piece i lies in faces[i].
SeamCurve seamThrough(const TriMesh& m, const std::vector<std::pair<int, Eigen::Vector3d>>& points,
                      const std::vector<int>& faces, bool closed = false) {
  SeamCurve c;
  for (const auto& [f, p] : points) {
    PathPoint q;
    q.point = pointIn(m, f, p);
    q.position = p;
    c.points.push_back(q);
  }
  c.faces = faces;
  c.closed = closed;
  return c;
}

Eigen::Vector3d normalOf(const TriMesh& m, int t) {
  const Eigen::Vector3d a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
  return 0.5 * (b - a).cross(c - a);  // length: the area
}

// What every cut must keep: the target's vertices first and unchanged, every vertex where its origin says,
// each target triangle tiled exactly by the triangles that name it as their origin (same area, same side out,
// corners inside it), a closed genus-0 surface (V - E + F = 2, so F = 2 V - 4), and every seam edge an edge.
void expectSound(const Cube& c, const CutMesh& cut) {
  const TriMesh& m = cut.mesh;
  ASSERT_GE(m.numVertices(), 8);
  EXPECT_EQ(m.V.topRows(8), c.mesh.V);
  ASSERT_EQ(cut.vertexOrigin.size(), static_cast<size_t>(m.numVertices()));
  for (int v = 0; v < m.numVertices(); ++v)
    EXPECT_LT((position(c.mesh, cut.vertexOrigin[v]) - m.V.row(v).transpose()).norm(), 1e-12) << "vertex " << v;
  ASSERT_EQ(cut.faceOrigin.size(), static_cast<size_t>(m.numTriangles()));
  std::vector<double> area(c.mesh.numTriangles(), 0);
  for (int t = 0; t < m.numTriangles(); ++t) {
    const int f = cut.faceOrigin[t];
    const Eigen::Vector3d n = normalOf(c.mesh, f), nt = normalOf(m, t);
    EXPECT_GT(nt.dot(n), 0) << "triangle " << t << " faces the way its origin " << f << " does";
    EXPECT_LT(nt.cross(n).norm(), 1e-12) << "triangle " << t << " lies in the plane of " << f;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d w = pointIn(c.mesh, f, m.V.row(m.F(t, k)).transpose()).bary;
      EXPECT_GT(w.minCoeff(), -1e-12) << "corner " << k << " of triangle " << t << " is inside " << f;
    }
    area[f] += nt.norm();
  }
  for (int f = 0; f < c.mesh.numTriangles(); ++f) EXPECT_NEAR(area[f], 0.5, 1e-12) << "target triangle " << f;
  MeshTopology topo;
  ASSERT_NO_THROW(topo = buildTopology(m)) << "the cut mesh stays closed";
  EXPECT_EQ(m.numVertices() - topo.numEdges() + m.numTriangles(), 2);
  EXPECT_EQ(m.numTriangles(), 2 * m.numVertices() - 4);
  for (const auto& [key, seam] : cut.seamEdge)
    EXPECT_GE(topo.edgeBetween(static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)), 0);
  EXPECT_EQ(cut.unrecoveredPieces, 0);
}

// The seam edges of one seam, as sorted (a, b) pairs with a < b.
std::vector<std::pair<int, int>> seamEdgesOf(const CutMesh& cut, int seam) {
  std::vector<std::pair<int, int>> out;
  for (const auto& [key, s] : cut.seamEdge)
    if (s == seam) out.emplace_back(static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu));
  std::sort(out.begin(), out.end());
  return out;
}

int trianglesFrom(const CutMesh& cut, int f) {
  return static_cast<int>(std::count(cut.faceOrigin.begin(), cut.faceOrigin.end(), f));
}

}  // namespace

TEST(CutMesh, AStraightSeamAcrossASquareFaceAddsItsThreePointsAndTwoSeamEdges) {
  // x = 0.5 across the bottom square: it starts on edge 0-1, crosses the diagonal 0-3 at its middle and ends
  // on edge 2-3. Three new vertices, 8, 9 and 10, in seam order. Both bottom triangles are cut in three, the
  // side triangles holding edges 0-1 and 2-3 (2 and 9) in two: 11 vertices, 12 + 2 * 2 + 2 * 1 = 18 triangles.
  const Cube c;
  const SeamCurve s = seamThrough(c.mesh, {{0, {0.5, 0, 0}}, {0, {0.5, 0.5, 0}}, {1, {0.5, 1, 0}}}, {0, 1});
  const CutMesh cut = cutAlongSeams(c.mesh, c.topo, {s});
  expectSound(c, cut);
  ASSERT_EQ(cut.mesh.numVertices(), 11);
  EXPECT_EQ(cut.mesh.numTriangles(), 18);
  EXPECT_LT((cut.mesh.V.row(8) - Eigen::RowVector3d(0.5, 0, 0)).norm(), 1e-12);
  EXPECT_LT((cut.mesh.V.row(9) - Eigen::RowVector3d(0.5, 0.5, 0)).norm(), 1e-12);
  EXPECT_LT((cut.mesh.V.row(10) - Eigen::RowVector3d(0.5, 1, 0)).norm(), 1e-12);
  EXPECT_EQ(cut.seamVertices, (std::vector<std::vector<int>>{{8, 9, 10}}));
  EXPECT_EQ(seamEdgesOf(cut, 0), (std::vector<std::pair<int, int>>{{8, 9}, {9, 10}}));
  EXPECT_EQ(cut.seamEdge.size(), 2u);
  EXPECT_EQ(trianglesFrom(cut, 0), 3);
  EXPECT_EQ(trianglesFrom(cut, 1), 3);
  EXPECT_EQ(trianglesFrom(cut, 2), 2);
  EXPECT_EQ(trianglesFrom(cut, 9), 2);
  // No triangle of the bottom square reaches across x = 0.5.
  for (int t = 0; t < cut.mesh.numTriangles(); ++t) {
    if (cut.faceOrigin[t] > 1) continue;
    double lo = 1, hi = 0;
    for (int k = 0; k < 3; ++k)
      lo = std::min(lo, cut.mesh.V(cut.mesh.F(t, k), 0)), hi = std::max(hi, cut.mesh.V(cut.mesh.F(t, k), 0));
    EXPECT_TRUE(hi <= 0.5 + 1e-12 || lo >= 0.5 - 1e-12) << "triangle " << t << " spans x " << lo << ".." << hi;
  }
  EXPECT_TRUE(cut.selfCrossings.empty());
}

TEST(CutMesh, TwoSeamsCrossingInsideATriangleShareANewVertexThere) {
  // x = 0.25 and y = 0.75 across the bottom square cross at (0.25, 0.75), inside triangle 1 (y > x): after the
  // six seam points (8..13) the crossing is vertex 14, on two edges of each seam. Not a self-crossing.
  const Cube c;
  const SeamCurve a = seamThrough(c.mesh, {{0, {0.25, 0, 0}}, {0, {0.25, 0.25, 0}}, {1, {0.25, 1, 0}}}, {0, 1});
  const SeamCurve b = seamThrough(c.mesh, {{1, {0, 0.75, 0}}, {1, {0.75, 0.75, 0}}, {0, {1, 0.75, 0}}}, {1, 0});
  const CutMesh cut = cutAlongSeams(c.mesh, c.topo, {a, b});
  expectSound(c, cut);
  ASSERT_EQ(cut.mesh.numVertices(), 15);
  EXPECT_LT((cut.mesh.V.row(14) - Eigen::RowVector3d(0.25, 0.75, 0)).norm(), 1e-12);
  EXPECT_EQ(cut.vertexOrigin[14].face, 1);
  EXPECT_EQ(cut.seamVertices, (std::vector<std::vector<int>>{{8, 9, 10}, {11, 12, 13}}));
  EXPECT_EQ(seamEdgesOf(cut, 0), (std::vector<std::pair<int, int>>{{8, 9}, {9, 14}, {10, 14}}));
  EXPECT_EQ(seamEdgesOf(cut, 1), (std::vector<std::pair<int, int>>{{11, 14}, {12, 13}, {12, 14}}));
  EXPECT_TRUE(cut.selfCrossings.empty());
}

TEST(CutMesh, SeamsThroughOneEdgePointShareItsVertex) {
  // x = 0.5 and y = 0.5 both cross the diagonal 0-3 at its middle, one given in triangle 0, the other in
  // triangle 1 and a hair (1e-12, under the merge tolerance) off the edge: one vertex, 9, on both seams.
  const Cube c;
  const SeamCurve a = seamThrough(c.mesh, {{0, {0.5, 0, 0}}, {0, {0.5, 0.5, 0}}, {1, {0.5, 1, 0}}}, {0, 1});
  SeamCurve b = seamThrough(c.mesh, {{1, {0, 0.5, 0}}, {1, {0.5, 0.5, 0}}, {0, {1, 0.5, 0}}}, {1, 0});
  b.points[1].point.bary += Eigen::Vector3d(-1e-12, 1e-12, 0);  // towards corner 1 of triangle 1 (vertex 2)
  const CutMesh cut = cutAlongSeams(c.mesh, c.topo, {a, b});
  expectSound(c, cut);
  EXPECT_EQ(cut.mesh.numVertices(), 8 + 5);
  EXPECT_EQ(cut.seamVertices, (std::vector<std::vector<int>>{{8, 9, 10}, {11, 9, 12}}));
  EXPECT_EQ(seamEdgesOf(cut, 1), (std::vector<std::pair<int, int>>{{9, 11}, {9, 12}}));
  EXPECT_TRUE(cut.selfCrossings.empty()) << "two seams meeting is a junction, not a self-crossing";
}

TEST(CutMesh, ASeamCrossingItselfInsideATriangleIsReportedWhereItCrosses) {
  // A zig-zag inside triangle 1: (0.1, 0.5) -> (0.4, 0.8) -> (0.4, 0.5) -> (0.1, 0.8). Its first and last
  // pieces cross halfway along both, at (0.25, 0.65): one new vertex (12) on four edges of the seam.
  const Cube c;
  const SeamCurve s =
      seamThrough(c.mesh, {{1, {0.1, 0.5, 0}}, {1, {0.4, 0.8, 0}}, {1, {0.4, 0.5, 0}}, {1, {0.1, 0.8, 0}}}, {1, 1, 1});
  const CutMesh cut = cutAlongSeams(c.mesh, c.topo, {s});
  expectSound(c, cut);
  ASSERT_EQ(cut.selfCrossings.size(), 1u);
  EXPECT_EQ(cut.selfCrossings[0].seam, 0);
  EXPECT_LT((cut.selfCrossings[0].position - Eigen::Vector3d(0.25, 0.65, 0)).norm(), 1e-12);
  ASSERT_EQ(cut.mesh.numVertices(), 13);
  EXPECT_LT((cut.mesh.V.row(12) - Eigen::RowVector3d(0.25, 0.65, 0)).norm(), 1e-12);
  EXPECT_EQ(seamEdgesOf(cut, 0), (std::vector<std::pair<int, int>>{{8, 12}, {9, 10}, {9, 12}, {10, 12}, {11, 12}}));
}

TEST(CutMesh, ASeamAlongEdgesAddsNothingAndAPassTwiceThroughAVertexIsATouch) {
  // Along cube edges 1 -> 3 -> 2 -> 0 and back up the diagonal to 3: no new vertex or triangle, four seam
  // edges, and vertex 3 (1, 1, 0) visited twice, which the seam touches itself at.
  const Cube c;
  const SeamCurve s = seamThrough(
      c.mesh, {{0, {1, 0, 0}}, {0, {1, 1, 0}}, {1, {0, 1, 0}}, {1, {0, 0, 0}}, {0, {1, 1, 0}}}, {0, 1, 1, 0});
  const CutMesh cut = cutAlongSeams(c.mesh, c.topo, {s});
  expectSound(c, cut);
  EXPECT_EQ(cut.mesh.numVertices(), 8);
  EXPECT_EQ(cut.mesh.F, c.mesh.F) << "untouched triangles are kept as they are";
  EXPECT_EQ(cut.seamVertices, (std::vector<std::vector<int>>{{1, 3, 2, 0, 3}}));
  EXPECT_EQ(seamEdgesOf(cut, 0), (std::vector<std::pair<int, int>>{{0, 2}, {0, 3}, {1, 3}, {2, 3}}));
  ASSERT_EQ(cut.selfCrossings.size(), 1u);
  EXPECT_LT((cut.selfCrossings[0].position - Eigen::Vector3d(1, 1, 0)).norm(), 1e-12);
}

TEST(CutMesh, APointRepeatedInARowIsNoTouchAndAReturnIsReportedOnce) {
  // Zero-length pieces (a control point doubled where a geodesic ends on it) do not pass through a point twice.
  const Cube c;
  const SeamCurve still = seamThrough(
      c.mesh, {{0, {0, 0, 0}}, {0, {1, 0, 0}}, {0, {1, 0, 0}}, {0, {1, 0, 0}}, {0, {1, 1, 0}}}, {0, 0, 0, 0});
  const CutMesh a = cutAlongSeams(c.mesh, c.topo, {still});
  expectSound(c, a);
  EXPECT_EQ(a.seamVertices, (std::vector<std::vector<int>>{{0, 1, 1, 1, 3}}));
  EXPECT_EQ(seamEdgesOf(a, 0), (std::vector<std::pair<int, int>>{{0, 1}, {1, 3}}));
  EXPECT_TRUE(a.selfCrossings.empty());
  // 1 -> 3 -> 2 -> 0 -> 3 with its last point doubled: vertex 3 is passed through twice, which is one touch.
  const SeamCurve back = seamThrough(
      c.mesh, {{0, {1, 0, 0}}, {0, {1, 1, 0}}, {1, {0, 1, 0}}, {1, {0, 0, 0}}, {0, {1, 1, 0}}, {0, {1, 1, 0}}},
      {0, 1, 1, 0, 0});
  const CutMesh b = cutAlongSeams(c.mesh, c.topo, {back});
  expectSound(c, b);
  EXPECT_EQ(b.selfCrossings.size(), 1u);
}

TEST(CutMesh, AClosedLoopReturningToItsStartIsNoSelfCrossingAlsoAHairBesideTheVertices) {
  // Around the bottom square 0 -> 1 -> 3 -> 2 -> 0, closed: the repeated first point closes the loop. The same loop
  // laid a hair (1e-6) beside the corners, as the Outline tool's seam follows the zero set of a field past the
  // vertices a rim lies on, closed on a point beside its start: cut there, the corners would stay inside one side
  // behind sliver triangles and give it the rim's curvature. It runs along the edges as well and adds nothing.
  const Cube c;
  const double e = 1e-6;
  const SeamCurve exact = seamThrough(
      c.mesh, {{0, {0, 0, 0}}, {0, {1, 0, 0}}, {0, {1, 1, 0}}, {1, {0, 1, 0}}, {1, {0, 0, 0}}}, {0, 0, 1, 1}, true);
  const SeamCurve beside = seamThrough(
      c.mesh,
      {{0, {2 * e, e, 0}}, {0, {1 - 2 * e, e, 0}}, {0, {1 - e, 1 - 2 * e, 0}}, {1, {e, 1 - e, 0}}, {1, {e, 2 * e, 0}}},
      {0, 0, 1, 1}, true);
  for (const SeamCurve& s : {exact, beside}) {
    const CutMesh cut = cutAlongSeams(c.mesh, c.topo, {s});
    expectSound(c, cut);
    EXPECT_EQ(cut.mesh.numVertices(), 8);
    EXPECT_EQ(cut.seamVertices, (std::vector<std::vector<int>>{{0, 1, 3, 2, 0}}));
    EXPECT_EQ(seamEdgesOf(cut, 0), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 3}, {2, 3}}));
    EXPECT_TRUE(cut.selfCrossings.empty());
  }
}
