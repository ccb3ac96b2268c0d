// triangulateFace (segment/face_triangulation.hpp), which re-triangulates each target triangle a seam crosses:
// it must tile the triangle exactly (counterclockwise, no gap, no overlap), be Delaunay where it is free to, and
// keep every seam piece as an edge even where Delaunay would cross it, or the seam is not cut.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "segment/face_triangulation.hpp"

using namespace billow;

namespace {

using Vec2 = Eigen::Vector2d;
using Tris = std::vector<std::array<int, 3>>;

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool hasEdge(const Tris& tris, int a, int b) {
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k)
      if (std::minmax(t[k], t[(k + 1) % 3]) == std::minmax(a, b)) return true;
  return false;
}

// A triangulation of pts inside their first three points: every triangle counterclockwise and the areas adding
// up to the outer triangle's, every interior edge held by two triangles in opposite directions and every
// boundary piece by one, every point used, and (Euler) 2 i + b - 2 triangles for i interior and b boundary points.
void expectTiles(const std::vector<Vec2>& p, const Tris& tris, int interior) {
  const int boundary = static_cast<int>(p.size()) - interior;
  EXPECT_EQ(static_cast<int>(tris.size()), 2 * interior + boundary - 2);
  double area = 0;
  std::set<std::pair<int, int>> directed;
  std::set<int> used;
  for (const auto& t : tris) {
    const double a = orient(p[t[0]], p[t[1]], p[t[2]]);
    EXPECT_GT(a, 0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
    area += a;
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(directed.insert({t[k], t[(k + 1) % 3]}).second) << "half-edge used twice";
      used.insert(t[k]);
    }
  }
  EXPECT_NEAR(area, orient(p[0], p[1], p[2]), 1e-12 * orient(p[0], p[1], p[2]));
  EXPECT_EQ(used.size(), p.size());
  int unpaired = 0;
  for (const auto& [a, b] : directed) unpaired += directed.count({b, a}) == 0;
  EXPECT_EQ(unpaired, boundary) << "the outline: one half-edge per boundary piece";
}

// No point strictly inside the circumcircle of a triangle across any edge not in `fixed` (the empty-circle
// property, checked locally over each interior edge).
void expectDelaunay(const std::vector<Vec2>& p, const Tris& tris, const std::set<std::pair<int, int>>& fixed = {}) {
  for (const auto& t : tris)
    for (const auto& s : tris)
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) {
          const int a = t[k], b = t[(k + 1) % 3];
          if (s[j] != b || s[(j + 1) % 3] != a || fixed.count(std::minmax(a, b))) continue;
          const Vec2 &A = p[a], &B = p[b], &C = p[t[(k + 2) % 3]], &D = p[s[(j + 2) % 3]];
          const Vec2 ad = A - D, bd = B - D, cd = C - D;
          const double det = ad.squaredNorm() * (bd.x() * cd.y() - cd.x() * bd.y()) -
                             bd.squaredNorm() * (ad.x() * cd.y() - cd.x() * ad.y()) +
                             cd.squaredNorm() * (ad.x() * bd.y() - bd.x() * ad.y());
          EXPECT_LE(det, 1e-9) << "edge " << a << "-" << b << " is not locally Delaunay";
        }
}

}  // namespace

TEST(FaceTriangulation, ATriangleAloneIsReturnedAsItIs) {
  const std::vector<Vec2> p{{0, 0}, {1, 0}, {0, 1}};
  int unrecovered = -1;
  EXPECT_EQ(triangulateFace(p, {}, &unrecovered), (Tris{{0, 1, 2}}));
  EXPECT_EQ(unrecovered, 0);
}

TEST(FaceTriangulation, AnInteriorPointMakesAFanOfThree) {
  // The only triangulation of a triangle with one point inside joins the point to the three corners.
  const std::vector<Vec2> p{{0, 0}, {1, 0}, {0, 1}, {0.25, 0.25}};
  const Tris t = triangulateFace(p, {});
  expectTiles(p, t, 1);
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(hasEdge(t, c, 3)) << c;
}

TEST(FaceTriangulation, PointsOnTheEdgesSplitThem) {
  // A point on every edge (none inside): 6 boundary points, so 4 triangles, and no edge of the outer triangle
  // survives whole.
  const std::vector<Vec2> p{{0, 0}, {4, 0}, {1, 3}, {2, 0}, {2.5, 1.5}, {0.5, 1.5}};
  const Tris t = triangulateFace(p, {});
  expectTiles(p, t, 0);
  EXPECT_FALSE(hasEdge(t, 0, 1));
  EXPECT_FALSE(hasEdge(t, 1, 2));
  EXPECT_FALSE(hasEdge(t, 2, 0));
  for (const auto& [a, b] : {std::pair<int, int>{0, 3}, {3, 1}, {1, 4}, {4, 2}, {2, 5}, {5, 0}})
    EXPECT_TRUE(hasEdge(t, a, b)) << a << "-" << b;
}

TEST(FaceTriangulation, WithoutConstraintsItIsDelaunay) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(0, 1);
  for (int round = 0; round < 10; ++round) {
    std::vector<Vec2> p{{0, 0}, {10, 0}, {3, 8}};
    for (int i = 0; i < 12; ++i) {  // uniform in the triangle
      double s = u(rng), r = u(rng);
      if (s + r > 1) s = 1 - s, r = 1 - r;
      p.push_back(p[0] + s * (p[1] - p[0]) + r * (p[2] - p[0]));
    }
    const Tris t = triangulateFace(p, {});
    expectTiles(p, t, 12);
    expectDelaunay(p, t);
  }
}

TEST(FaceTriangulation, AShortEdgeWinsUntilASeamPieceIsConstrainedAcrossIt) {
  // Points 5 and 6 are 0.6 apart, 3 and 4 are 6 apart on the line y = 1 between them. The circle with 5-6 as
  // its diameter is empty, so every Delaunay triangulation has the edge 5-6; a seam piece 3-4 must win over it.
  const std::vector<Vec2> p{{0, 0}, {10, 0}, {5, 10}, {2, 1}, {8, 1}, {5, 1.3}, {5, 0.7}};
  const Tris free = triangulateFace(p, {});
  expectTiles(p, free, 4);
  EXPECT_TRUE(hasEdge(free, 5, 6));
  EXPECT_FALSE(hasEdge(free, 3, 4));

  int unrecovered = -1;
  const Tris cut = triangulateFace(p, {{3, 4}}, &unrecovered);
  EXPECT_EQ(unrecovered, 0);
  expectTiles(p, cut, 4);
  EXPECT_TRUE(hasEdge(cut, 3, 4));
  EXPECT_FALSE(hasEdge(cut, 5, 6));
  expectDelaunay(p, cut, {{3, 4}});
}

TEST(FaceTriangulation, ASeamAcrossTheFaceLeavesNoTriangleStraddlingIt) {
  // A seam from edge 0-1 to edge 0-2, with points on both sides: every triangle lies on one side of it.
  const std::vector<Vec2> p{{0, 0}, {6, 0}, {0, 6}, {4, 0}, {0, 4}, {1, 1}, {2.5, 2.5}, {1.9, 2.0}};
  int unrecovered = -1;
  const Tris t = triangulateFace(p, {{3, 4}}, &unrecovered);
  EXPECT_EQ(unrecovered, 0);
  expectTiles(p, t, 3);
  EXPECT_TRUE(hasEdge(t, 3, 4));
  for (const auto& tri : t) {
    double lo = 0, hi = 0;
    for (int k : tri) lo = std::min(lo, orient(p[3], p[4], p[k])), hi = std::max(hi, orient(p[3], p[4], p[k]));
    EXPECT_FALSE(lo < 0 && hi > 0) << "triangle " << tri[0] << " " << tri[1] << " " << tri[2];
  }
}

TEST(FaceTriangulation, CrossingConstraintsBreakTheRulesAndTheSecondIsCounted) {
  // Two pieces crossing at (5, 1): once 3-4 is an edge, 5-6 cannot be one. The caller (cutAlongSeams) splits
  // crossing pieces first; here the count tells it that it did not.
  const std::vector<Vec2> p{{0, 0}, {10, 0}, {5, 10}, {2, 1}, {8, 1}, {5, 1.3}, {5, 0.7}};
  int unrecovered = -1;
  const Tris t = triangulateFace(p, {{3, 4}, {5, 6}}, &unrecovered);
  EXPECT_EQ(unrecovered, 1);
  expectTiles(p, t, 4);
  EXPECT_TRUE(hasEdge(t, 3, 4));
}
