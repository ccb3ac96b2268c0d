// Nesting: no two placed pieces overlap (exact polygon test), all lie within the sheet width, rotation
// options are honoured, and a piece too wide for the sheet is refused by name.
#include <gtest/gtest.h>

#include <cmath>

#include "export/layout.hpp"
#include "export/nesting.hpp"
#include "simulate/example_patterns.hpp"
#include "util/error.hpp"

using namespace billow;

namespace {

void expectValid(const std::vector<Polygon2>& pieces, const NestResult& r, const NestOptions& o) {
  std::vector<Polygon2> placed;
  for (size_t i = 0; i < pieces.size(); ++i) placed.push_back(transformed(pieces[i], r.placements[i]));
  for (size_t i = 0; i < placed.size(); ++i) {
    const Box2 b = boundingBox(placed[i]);
    EXPECT_GE(b.lo.x(), -1e-9);
    EXPECT_LE(b.hi.x(), o.sheetWidth + 1e-9);
    EXPECT_GE(b.lo.y(), -1e-9);
    EXPECT_LE(b.hi.y(), r.length + 1e-9);
    for (size_t j = i + 1; j < placed.size(); ++j)
      EXPECT_FALSE(polygonsIntersect(placed[i], placed[j])) << i << " " << j;
  }
  EXPECT_GT(r.utilisation, 0);
  EXPECT_LE(r.utilisation, 1);
}

std::vector<Polygon2> randomPieces(int count, unsigned seed) {
  auto rnd = [&] { return (seed = seed * 1103515245u + 12345u) / 4294967296.0; };
  std::vector<Polygon2> out;
  for (int i = 0; i < count; ++i) {
    Polygon2 p;
    const double sx = 30 + 200 * rnd(), sy = 30 + 200 * rnd();
    const int n = 5 + int(10 * rnd());
    for (int k = 0; k < n; ++k) {
      const double a = 2 * M_PI * k / n, r = 0.6 + 0.4 * rnd();
      p.push_back(Vec2(sx * r * std::cos(a), sy * r * std::sin(a)));
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace

TEST(Nesting, RandomPiecesDoNotOverlapAndStayOnTheSheet) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto pieces = randomPieces(25, seed);
    for (bool rotate : {false, true}) {
      NestOptions o;
      o.sheetWidth = 800;
      o.allowRotation = rotate;
      const NestResult r = nestPieces(pieces, o);
      expectValid(pieces, r, o);
      if (!rotate) {
        for (const Placement2& pl : r.placements) EXPECT_EQ(pl.angle, 0);
      }
    }
  }
}

TEST(Nesting, GrainLockKeepsTheAxisAlongTheRoll) {
  const auto pieces = randomPieces(12, 9);
  NestOptions o;
  o.sheetWidth = 700;
  o.grainLock = true;
  const NestResult r = nestPieces(pieces, o);
  expectValid(pieces, r, o);
  for (const Placement2& pl : r.placements) EXPECT_NEAR(std::sin(pl.angle), 0, 1e-12);
}

TEST(Nesting, RotationHelpsLongPieces) {
  // Long thin strips across a narrow roll only fit turned along it.
  std::vector<Polygon2> strips(4, Polygon2{{0, 0}, {600, 0}, {600, 40}, {0, 40}});
  NestOptions o;
  o.sheetWidth = 300;
  const NestResult r = nestPieces(strips, o);
  expectValid(strips, r, o);
  EXPECT_LT(r.length, 700);
  o.allowRotation = false;
  try {
    nestPieces(strips, o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "export.sheet-too-narrow");
  }
}

TEST(Nesting, ExamplePatternsWithAllowance) {
  for (const char* name : {"mylar", "pillow", "sphere3", "sphere3-internal"}) {
    SCOPED_TRACE(name);
    ExampleOptions eo;
    eo.triangles = 800;
    eo.size = 0.2;
    ExportOptions xo;
    xo.sheetWidth = 900;
    const SheetLayout s = layoutSheet(examplePattern(name, eo), xo);
    std::vector<Polygon2> cuts;
    for (const PanelLayout& pl : s.panels) cuts.push_back(pl.cut);
    expectValid(cuts, s.nest, {xo.sheetWidth, xo.gap, true, false});
  }
}

TEST(Nesting, TooNarrowSheetNamesThePanel) {
  ExampleOptions eo;
  eo.triangles = 200;
  ExportOptions xo;
  xo.sheetWidth = 200;  // the Mylar discs are 600 mm across
  try {
    layoutSheet(examplePattern("mylar", eo), xo);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "export.sheet-too-narrow");
    EXPECT_NE(std::string(e.what()).find("'front'"), std::string::npos);
    // The width offered instead fits: the same pattern lays out on it, and 10 mm less would not.
    EXPECT_GT(e.sheetWidth, 600);
    EXPECT_LT(e.sheetWidth, 700);
    xo.sheetWidth = e.sheetWidth;
    EXPECT_NO_THROW(layoutSheet(examplePattern("mylar", eo), xo));
    xo.sheetWidth = e.sheetWidth - 10;
    EXPECT_THROW(layoutSheet(examplePattern("mylar", eo), xo), Error);
  }
}
