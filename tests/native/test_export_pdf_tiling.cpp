// Which tiles of the printable PDF are printed: on a sheet laid out so most of the grid is empty, exactly the
// tiles something is drawn on that no other printed tile shows (plus the tile joining two that meet only at a
// corner), every point drawn lies on a printed page, printed pages keep their grid labels and the overview
// counts the skipped tiles; on a nested sheet, the same coverage.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "export/layout.hpp"
#include "export/pdf_writer.hpp"
#include "simulate/example_patterns.hpp"
#include "test_export_parsers.hpp"

using namespace billow;
using namespace billow::test;

namespace {

using Tile = std::pair<int, int>;  // (row, column) from the top left

Polygon2 rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// A4 tiles show 190 x 221 mm and step 180 x 211 mm (10 mm overlap), so this 1000 x 1000 mm sheet is a grid of
// 5 rows (from the top: y 844-1065, 633-854, 422-643, 211-432, 0-221) by 6 columns (x 0-190, 180-370, ...).
Drawing sparseSheet() {
  Drawing d;
  d.width = 1000, d.length = 1000;
  // Inside tile (1,1) alone.
  d.paths.push_back({Layer::Cut, 0, true, rectangle(20, 880, 150, 1000), {}});
  d.texts.push_back({Layer::Label, 0, {85, 940}, 10, "1  one"});
  // Tile (5,5), reaching 5 mm into the strip it shares with (5,6): (5,6) shows nothing else.
  d.paths.push_back({Layer::Cut, 1, true, rectangle(780, 20, 905, 150), {}});
  d.paths.push_back({Layer::Notch, 1, false, {{902, 80}, {908, 80}}, {}});
  // Only in the strip tiles (3,3) and (3,4) share: one of them, the first.
  d.paths.push_back({Layer::Cut, 2, true, rectangle(542, 520, 548, 540), {}});
  // From tile (1,2) to tile (2,3) through the corner square the four tiles (1-2, 2-3) share: (2,2), which
  // shows more of the line than (1,3), joins them along edges.
  d.paths.push_back({Layer::Cut, 3, false, {{300, 912}, {430, 782}}, {}});
  return d;
}

std::vector<Tile> printedTiles(const PdfTiling& t) {
  std::vector<Tile> out;
  for (int r = 0; r < t.rows; ++r)
    for (int c = 0; c < t.columns; ++c)
      if (t.isPrinted(r, c)) out.push_back({r + 1, c + 1});
  return out;
}

// Printed tiles whose sheet area holds p.
std::vector<Tile> printedTilesShowing(const PdfTiling& t, const Vec2& p) {
  std::vector<Tile> out;
  for (int r = 0; r < t.rows; ++r)
    for (int c = 0; c < t.columns; ++c) {
      const Box2 b = t.tileBox(r, c);
      if (t.isPrinted(r, c) && p.x() >= b.lo.x() - 1e-9 && p.x() <= b.hi.x() + 1e-9 && p.y() >= b.lo.y() - 1e-9 &&
          p.y() <= b.hi.y() + 1e-9)
        out.push_back({r, c});
    }
  return out;
}

// Every point drawn (paths every 0.25 mm, label boxes every 1 mm) is on a printed tile, and never only on two
// tiles that meet at a corner (they could not be aligned by a shared edge's crosshairs).
void expectEverythingPrinted(const Drawing& d, const PdfTiling& t) {
  int failures = 0;
  auto check = [&](const Vec2& p) {
    const std::vector<Tile> tiles = printedTilesShowing(t, p);
    const bool diagonal = tiles.size() == 2 && tiles[0].first != tiles[1].first && tiles[0].second != tiles[1].second;
    if ((tiles.empty() || diagonal) && ++failures <= 5)
      ADD_FAILURE() << "(" << p.x() << ", " << p.y() << ") is on " << tiles.size() << " printed tiles";
  };
  for (const DrawnPath& path : d.paths) {
    const Polygon2& q = path.points;
    for (size_t i = 0; i < q.size(); ++i) {
      if (i + 1 == q.size() && !path.closed) {
        check(q[i]);
        break;
      }
      const Vec2 a = q[i], b = q[(i + 1) % q.size()];
      const int steps = std::max(1, int((b - a).norm() / 0.25));
      for (int k = 0; k < steps; ++k) check(a + (double(k) / steps) * (b - a));
    }
  }
  for (const DrawnText& text : d.texts) {
    const Box2 b = pdfTextBox(text);
    for (double x = b.lo.x(); x <= b.hi.x(); x += 1)
      for (double y = b.lo.y(); y <= b.hi.y(); y += 1) check({x, y});
  }
  EXPECT_EQ(failures, 0);
}

}  // namespace

TEST(PdfTiling, PrintsOnlyTilesWithSomethingToCut) {
  const Drawing d = sparseSheet();
  PdfOptions o;
  const PdfTiling t = pdfTiling(d, o);
  ASSERT_EQ(t.rows, 5);
  ASSERT_EQ(t.columns, 6);
  EXPECT_EQ(printedTiles(t), (std::vector<Tile>{{1, 1}, {1, 2}, {2, 2}, {2, 3}, {3, 3}, {5, 5}}));
  EXPECT_EQ(t.skippedTiles(), 24);
  EXPECT_EQ(t.pageCount(), 7);  // 31 when every tile was printed
  expectEverythingPrinted(d, t);

  const std::string pdf = writePdf(d, o);
  EXPECT_EQ(countPdfPages(pdf), 7);
  EXPECT_NE(pdf.find("(24 of 30 tiles have nothing to cut and are not printed"), std::string::npos);
  // Printed tiles keep their place in the grid; the skipped ones have no page.
  EXPECT_NE(pdf.find("(row 5, column 5)"), std::string::npos);
  EXPECT_EQ(pdf.find("(row 5, column 6)"), std::string::npos);
  EXPECT_NE(pdf.find("page 7 of 7"), std::string::npos);
  EXPECT_EQ(pdf.find("page 8 of"), std::string::npos);
}

TEST(PdfTiling, EveryTileOfAFullSheetIsPrinted) {
  Drawing d;
  d.width = 500, d.length = 400;
  for (double x = 10; x < 490; x += 20) d.paths.push_back({Layer::Cut, 0, false, {{x, 0}, {x, 400}}, {}});
  PdfOptions o;
  o.paper = PaperSize::Letter;
  const PdfTiling t = pdfTiling(d, o);
  EXPECT_EQ(t.printedTiles(), t.rows * t.columns);
  EXPECT_GT(t.tiles(), 1);
  const std::string pdf = writePdf(d, o);
  EXPECT_EQ(countPdfPages(pdf), 1 + t.rows * t.columns);
  EXPECT_EQ(pdf.find("have nothing to cut"), std::string::npos);
}

TEST(PdfTiling, NestedPiecesOnAWideSheetAreAllPrinted) {
  ExampleOptions eo;
  eo.triangles = 600;
  eo.size = 0.15;
  ExportOptions eopt;
  eopt.sheetWidth = 2000;  // the pieces fill the left of a roll much wider than they need
  const SheetLayout s = layoutSheet(examplePattern("sphere3", eo), eopt);
  for (PaperSize paper : {PaperSize::A4, PaperSize::Letter}) {
    PdfOptions o;
    o.paper = paper;
    const PdfTiling t = pdfTiling(s.drawing, o);
    EXPECT_LT(t.printedTiles(), t.tiles());
    EXPECT_GT(t.printedTiles(), 0);
    expectEverythingPrinted(s.drawing, t);
    const std::string pdf = writePdf(s.drawing, o);
    EXPECT_EQ(countPdfPages(pdf), t.pageCount());
    EXPECT_NE(pdf.find("(" + std::to_string(t.skippedTiles()) + " of " + std::to_string(t.tiles()) + " tiles"),
              std::string::npos);
  }
}
