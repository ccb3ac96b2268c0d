// labelSegments (segment/segment_topology.hpp) on meshes whose cut-open topology is known: a cube and a torus
// with seams along their edges, and an open square. Whether a segment is a disk decides if it can be
// flattened, so its Euler characteristic, boundary loops and genus are checked against hand counts here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cube_fixture.hpp"
#include "segment/segment_topology.hpp"
#include "test_support.hpp"

using namespace billow;
using test::kPi;

namespace {

// Labels mesh m with these seam edges (seam id per edge), as the segmentation does after cutting.
Segmentation labelled(const TriMesh& m, const std::vector<std::pair<std::pair<int, int>, int>>& seamEdges) {
  CutMesh cut;
  cut.mesh = m;
  for (const auto& [edge, seam] : seamEdges) cut.seamEdge[edgeKey(edge.first, edge.second)] = seam;
  Segmentation out;
  out.mesh = m;
  labelSegments(cut, out);
  return out;
}

// A closed loop of edges through these vertices, all of one seam.
std::vector<std::pair<std::pair<int, int>, int>> loop(const std::vector<int>& vertices, int seam) {
  std::vector<std::pair<std::pair<int, int>, int>> out;
  for (size_t i = 0; i < vertices.size(); ++i)
    out.push_back({{vertices[i], vertices[(i + 1) % vertices.size()]}, seam});
  return out;
}

// The loop's vertices as a cycle starting at its smallest vertex, for comparing loops that start anywhere.
std::vector<int> fromSmallest(std::vector<int> v) {
  std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
  return v;
}

// A torus of n x n vertices (n >= 3): vertex (i, j) = i + n j, i around the tube's axis, j around the tube;
// every grid cell split along the same diagonal, outward triangles.
TriMesh torus(int n) {
  TriMesh m;
  m.V.resize(n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / n;
      m.V.row(i + n * j) << (2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v);
    }
  m.F.resize(2 * n * n, 3);
  const auto id = [n](int i, int j) { return (i % n) + n * (j % n); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.F.row(2 * (i + n * j)) << id(i, j), id(i + 1, j), id(i + 1, j + 1);
      m.F.row(2 * (i + n * j) + 1) << id(i, j), id(i + 1, j + 1), id(i, j + 1);
    }
  return m;
}

}  // namespace

TEST(SegmentTopology, WithoutSeamsTheCubeIsOneClosedSphere) {
  // V - E + F = 8 - 18 + 12 = 2, no boundary: genus (2 - 2 - 0) / 2 = 0, and not a disk.
  const Segmentation s = labelled(test::unitCube(), {});
  ASSERT_EQ(s.segments.size(), 1u);
  const Segment& g = s.segments[0];
  EXPECT_EQ(g.triangles.size(), 12u);
  EXPECT_NEAR(g.area, 6.0, 1e-12);
  EXPECT_EQ(g.eulerCharacteristic, 2);
  EXPECT_TRUE(g.loops.empty());
  EXPECT_EQ(g.genus, 0);
  EXPECT_FALSE(g.isDisk);
  EXPECT_EQ(s.faceSegment, std::vector<int>(12, 0));
}

TEST(SegmentTopology, ALoopAroundTheBottomSquareCutsItOffAsADisk) {
  // The seam 0-1-3-2 around the bottom face: the square (triangles 0 and 1, segment 0 as it holds triangle 0)
  // and the other five faces, both disks. Each loop keeps its segment on its left, so they run opposite ways:
  // the square's boundary half-edges are 0->2, 2->3, 3->1, 1->0.
  const Segmentation s = labelled(test::unitCube(), loop({0, 1, 3, 2}, 0));
  ASSERT_EQ(s.segments.size(), 2u);
  EXPECT_EQ(s.segments[0].triangles, (std::vector<int>{0, 1}));
  EXPECT_EQ(s.segments[1].triangles.size(), 10u);
  EXPECT_NEAR(s.segments[0].area, 1.0, 1e-12);
  EXPECT_NEAR(s.segments[1].area, 5.0, 1e-12);
  for (const Segment& g : s.segments) {
    EXPECT_EQ(g.eulerCharacteristic, 1);
    ASSERT_EQ(g.loops.size(), 1u);
    EXPECT_EQ(g.loops[0].seams, std::vector<int>(4, 0));
    EXPECT_EQ(g.genus, 0);
    EXPECT_TRUE(g.isDisk);
  }
  EXPECT_EQ(fromSmallest(s.segments[0].loops[0].vertices), (std::vector<int>{0, 2, 3, 1}));
  EXPECT_EQ(fromSmallest(s.segments[1].loops[0].vertices), (std::vector<int>{0, 1, 3, 2}));
}

TEST(SegmentTopology, TwoLoopsLeaveABandBetweenThemThatIsNoDisk) {
  // Bottom and top squares cut off: the four sides between them form an annulus. Cut open, every one of its
  // 8 vertices is one wedge, its 16 edges include the 8 seam edges once, and V - E + F = 8 - 16 + 8 = 0: with
  // two loops, genus (2 - 0 - 2) / 2 = 0, but not a disk.
  auto seams = loop({0, 1, 3, 2}, 0);
  for (const auto& e : loop({4, 5, 7, 6}, 1)) seams.push_back(e);
  const Segmentation s = labelled(test::unitCube(), seams);
  ASSERT_EQ(s.segments.size(), 3u);
  const Segment& band = s.segments[s.faceSegment[2]];
  EXPECT_EQ(band.triangles, (std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_NEAR(band.area, 4.0, 1e-12);
  EXPECT_EQ(band.eulerCharacteristic, 0);
  ASSERT_EQ(band.loops.size(), 2u);
  EXPECT_EQ(band.genus, 0);
  EXPECT_FALSE(band.isDisk);
  std::vector<int> loopSeams;
  for (const BoundaryLoop& l : band.loops) {
    EXPECT_EQ(l.vertices.size(), 4u);
    ASSERT_FALSE(l.seams.empty());
    EXPECT_TRUE(std::all_of(l.seams.begin(), l.seams.end(), [&](int x) { return x == l.seams[0]; }));
    loopSeams.push_back(l.seams[0]);
  }
  std::sort(loopSeams.begin(), loopSeams.end());
  EXPECT_EQ(loopSeams, (std::vector<int>{0, 1}));
  EXPECT_TRUE(s.segments[s.faceSegment[0]].isDisk);
  EXPECT_TRUE(s.segments[s.faceSegment[10]].isDisk);
}

TEST(SegmentTopology, AnOpenSlitMakesTheClosedCubeADisk) {
  // A seam 0-1-3 that does not close: opened, vertex 1 in the middle of the slit splits in two (9 wedges) and
  // the slit's two edges are doubled (20 edges): 9 - 20 + 12 = 1, with one loop 0, 1, 3, 1 around the slit.
  const Segmentation s = labelled(test::unitCube(), {{{0, 1}, 0}, {{1, 3}, 0}});
  ASSERT_EQ(s.segments.size(), 1u);
  const Segment& g = s.segments[0];
  EXPECT_EQ(g.eulerCharacteristic, 1);
  ASSERT_EQ(g.loops.size(), 1u);
  EXPECT_TRUE(g.isDisk);
  std::vector<int> v = g.loops[0].vertices;
  ASSERT_EQ(v.size(), 4u);
  for (size_t i = 0; i < v.size(); ++i) {
    const int a = v[i], b = v[(i + 1) % v.size()];
    EXPECT_TRUE(std::min(a, b) == 0 ? std::max(a, b) == 1 : (std::min(a, b) == 1 && std::max(a, b) == 3))
        << "loop edge " << a << "-" << b << " is on the slit";
  }
  std::sort(v.begin(), v.end());
  EXPECT_EQ(v, (std::vector<int>{0, 1, 1, 3}));
}

TEST(SegmentTopology, AnOpenSquareIsADiskBoundedByItsRim) {
  // Two triangles of a square, no seams: the rim is a boundary of no seam (-1), counterclockwise.
  TriMesh m;
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 2, 3;
  const Segmentation s = labelled(m, {});
  ASSERT_EQ(s.segments.size(), 1u);
  const Segment& g = s.segments[0];
  EXPECT_EQ(g.eulerCharacteristic, 1);  // 4 - 5 + 2
  ASSERT_EQ(g.loops.size(), 1u);
  EXPECT_EQ(fromSmallest(g.loops[0].vertices), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(g.loops[0].seams, std::vector<int>(4, -1));
  EXPECT_TRUE(g.isDisk);
  EXPECT_NEAR(g.area, 1.0, 1e-12);
}

TEST(SegmentTopology, ATorusHasGenusOneUntilCutAlongBothOfItsCircles) {
  // 4 x 4 torus: 16 - 48 + 32 = 0, genus 1. Cut along one meridian (i = 0) it is an annulus: 0 with two
  // loops. Cut along a meridian and a longitude (j = 0) it opens into a square: the 6 vertices on one circle
  // only split in two, the crossing vertex in four: 16 + 6 + 3 wedges, 48 + 8 edges, 25 - 56 + 32 = 1.
  const int n = 4;
  const TriMesh m = torus(n);
  const Segmentation whole = labelled(m, {});
  ASSERT_EQ(whole.segments.size(), 1u);
  EXPECT_EQ(whole.segments[0].eulerCharacteristic, 0);
  EXPECT_TRUE(whole.segments[0].loops.empty());
  EXPECT_EQ(whole.segments[0].genus, 1);
  EXPECT_FALSE(whole.segments[0].isDisk);

  std::vector<int> meridian, longitude;
  for (int k = 0; k < n; ++k) meridian.push_back(n * k), longitude.push_back(k);
  const Segmentation annulus = labelled(m, loop(meridian, 0));
  ASSERT_EQ(annulus.segments.size(), 1u);
  EXPECT_EQ(annulus.segments[0].eulerCharacteristic, 0);
  EXPECT_EQ(annulus.segments[0].loops.size(), 2u);
  EXPECT_EQ(annulus.segments[0].genus, 0);
  EXPECT_FALSE(annulus.segments[0].isDisk);

  auto both = loop(meridian, 0);
  for (const auto& e : loop(longitude, 1)) both.push_back(e);
  const Segmentation square = labelled(m, both);
  ASSERT_EQ(square.segments.size(), 1u);
  const Segment& g = square.segments[0];
  EXPECT_EQ(g.eulerCharacteristic, 1);
  ASSERT_EQ(g.loops.size(), 1u);
  EXPECT_EQ(g.loops[0].vertices.size(), 16u) << "each of the 8 seam edges twice";
  EXPECT_EQ(std::count(g.loops[0].vertices.begin(), g.loops[0].vertices.end(), 0), 4) << "the square's 4 corners";
  EXPECT_EQ(g.genus, 0);
  EXPECT_TRUE(g.isDisk);
}
