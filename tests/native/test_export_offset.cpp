// Seam allowance: the cut line is at distance w from the sewing line everywhere (up to the miter), has no
// self-intersections and contains the panel, also on concave curves tighter than the allowance.
#include <gtest/gtest.h>

#include <cmath>

#include "export/offset.hpp"

using namespace billow;

namespace {

Polygon2 regular(int n, double r, double phase = 0) {
  Polygon2 p;
  for (int k = 0; k < n; ++k)
    p.push_back(r * Vec2(std::cos(phase + 2 * M_PI * k / n), std::sin(phase + 2 * M_PI * k / n)));
  return p;
}

// A square with a semicircular bite of radius r out of its top side: a concave curve of radius r.
Polygon2 bitten(double side, double r, int n) {
  Polygon2 p = {{0, 0}, {side, 0}, {side, side}};
  for (int k = 0; k <= n; ++k) {
    const double a = M_PI * k / n;  // from the right end of the bite, under it, to the left end
    p.push_back(Vec2(side / 2 + r * std::cos(a), side - r * std::sin(a)));
  }
  p.push_back({0, side});
  return p;
}

Polygon2 star(int points, double r1, double r2) {
  Polygon2 p;
  for (int k = 0; k < 2 * points; ++k) {
    const double a = M_PI * k / points, r = k % 2 ? r2 : r1;
    p.push_back(r * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

// Samples the cut line and checks distance bounds, simplicity and containment.
void expectAllowance(const Polygon2& sew, const Polygon2& cut, double w, double maxFactor) {
  ASSERT_GE(cut.size(), 3u);
  EXPECT_GT(signedArea(cut), signedArea(sew));
  EXPECT_FALSE(selfIntersects(cut));
  double lo = 1e300, hi = 0;
  for (size_t i = 0; i < cut.size(); ++i)
    for (int k = 0; k < 10; ++k) {
      const Vec2 q = cut[i] + (k / 10.0) * (cut[(i + 1) % cut.size()] - cut[i]);
      const double d = distanceToBoundary(q, sew);
      lo = std::min(lo, d), hi = std::max(hi, d);
      EXPECT_FALSE(insidePolygon(q, sew));
    }
  EXPECT_GT(lo, w * (1 - 1e-9));
  EXPECT_LT(hi, w * maxFactor);
  for (const Vec2& v : sew) EXPECT_TRUE(insidePolygon(v, cut));
  double t, u;  // the sewing line never touches the cut line
  for (size_t i = 0; i < sew.size(); ++i)
    for (size_t j = 0; j < cut.size(); ++j)
      EXPECT_FALSE(segmentIntersection(sew[i], sew[(i + 1) % sew.size()], cut[j], cut[(j + 1) % cut.size()], t, u));
}

}  // namespace

TEST(Offset, SquareGetsMiteredCorners) {
  const Polygon2 sq = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  const Polygon2 cut = offsetPolygon(sq, 10);
  ASSERT_EQ(cut.size(), 4u);
  EXPECT_NEAR(signedArea(cut), 120 * 120, 1e-9);
  expectAllowance(sq, cut, 10, std::sqrt(2.0) + 1e-9);
}

TEST(Offset, CircleStaysAtTheWidth) {
  const Polygon2 disc = regular(200, 300);
  expectAllowance(disc, offsetPolygon(disc, 12), 12, 1.001);
}

TEST(Offset, ZeroWidthIsTheSewingLine) {
  const Polygon2 disc = regular(20, 50);
  const Polygon2 cut = offsetPolygon(disc, 0);
  ASSERT_EQ(cut.size(), disc.size());
  for (size_t i = 0; i < cut.size(); ++i) EXPECT_EQ(cut[i], disc[i]);
}

TEST(Offset, ConcaveCurveTighterThanTheAllowanceLeavesNoLoops) {
  // Inner curve radius ~ 15 < allowance 25: the raw offset folds over; the clipped one must not.
  const Polygon2 bite = bitten(200, 15, 40);
  ASSERT_GT(signedArea(bite), 0);
  for (double w : {2.0, 10.0, 25.0, 60.0}) {
    SCOPED_TRACE(w);
    expectAllowance(bite, offsetPolygon(bite, w), w, std::sqrt(2.0) + 1e-9);  // the square's corners
  }
}

TEST(Offset, StarSharpCornersAreBevelledNotShort) {
  const Polygon2 s = star(5, 100, 30);  // 26-degree tips: the miter would reach 4.4 w
  const Polygon2 cut = offsetPolygon(s, 10);
  expectAllowance(s, cut, 10, 2.0 + 1e-6);
  const Polygon2 mitered = offsetPolygon(s, 10, {5.0});
  expectAllowance(s, mitered, 10, 5.0);
  EXPECT_GT(signedArea(mitered), signedArea(cut));
}

TEST(Offset, PerEdgeWidthsIncludingZero) {
  const Polygon2 sq = {{0, 0}, {50, 0}, {100, 0}, {100, 100}, {0, 100}};
  const std::vector<double> widths = {5, 15, 0, 10, 10};  // a step along the bottom, a heat-sealed side
  const Polygon2 cut = offsetPolygon(sq, widths);
  EXPECT_FALSE(selfIntersects(cut));
  EXPECT_NEAR(distanceToBoundary(Vec2(25, -5), cut), 0, 1e-9);
  EXPECT_NEAR(distanceToBoundary(Vec2(75, -15), cut), 0, 1e-9);
  EXPECT_NEAR(distanceToBoundary(Vec2(100, 50), cut), 0, 1e-9);  // heat sealed: cut on the line
  EXPECT_NEAR(distanceToBoundary(Vec2(50, 110), cut), 0, 1e-9);
  // square + bottom strips (5 and 15) + top and left strips (10) + the top-left and bottom-left miters
  EXPECT_NEAR(signedArea(cut), 10000 + 250 + 750 + 1000 + 1000 + 100 + 50, 1e-6);
}

TEST(Offset, RandomWigglyPolygons) {
  // Star-shaped polygons with random radii: many small concave and convex corners.
  unsigned seed = 7;
  auto rnd = [&] { return (seed = seed * 1103515245u + 12345u) / 4294967296.0; };
  for (int trial = 0; trial < 20; ++trial) {
    Polygon2 p;
    const int n = 40 + trial * 3;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * M_PI * k / n, r = 100 + 40 * rnd();
      p.push_back(r * Vec2(std::cos(a), std::sin(a)));
    }
    const double w = 1 + 20 * rnd();
    SCOPED_TRACE(trial);
    expectAllowance(p, offsetPolygon(p, w), w, 2.0 + 1e-6);
  }
}
