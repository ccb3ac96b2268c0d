// SVG, DXF and PDF writers and the one-call export: read the files back with minimal parsers and compare
// with the pattern (true scale to 0.01 mm), check escaping, layers, the PDF's pages, xref and check square.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "export/dxf_writer.hpp"
#include "export/export.hpp"
#include "export/layout.hpp"
#include "export/pdf_writer.hpp"
#include "export/svg_writer.hpp"
#include "simulate/example_patterns.hpp"
#include "test_export_parsers.hpp"
#include "util/error.hpp"

using namespace billow;
using namespace billow::test;

namespace {

const char* kNastyName = "a<b & \"c\" 'd' </text><script>x</script> (1) \\ 100%";

Pattern sphere() {
  ExampleOptions eo;
  eo.triangles = 600;
  eo.size = 0.15;
  Pattern p = examplePattern("sphere3", eo);
  p.panels[1].name = kNastyName;
  return p;
}

// Edge lengths of panel p's outline in mm, in loop order.
std::vector<double> edgeLengths(const Polygon2& poly) {
  std::vector<double> out;
  for (size_t i = 0; i < poly.size(); ++i) out.push_back((poly[(i + 1) % poly.size()] - poly[i]).norm());
  return out;
}

void expectSameOutline(const Polygon2& expected, const ReadPath& read) {
  ASSERT_TRUE(read.closed);
  ASSERT_EQ(read.points.size(), expected.size());
  const auto a = edgeLengths(expected), b = edgeLengths(read.points);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 0.01);
  EXPECT_NEAR(perimeter(expected), perimeter(read.points), 0.01);
}

}  // namespace

TEST(SvgWriter, RoundTripAtTrueScale) {
  const Pattern p = sphere();
  const ExportOptions o;
  const SheetLayout s = layoutSheet(p, o);
  const std::string svg = writeSvg(s.drawing, "test");
  EXPECT_NE(svg.find("width=\"1000mm\""), std::string::npos);
  EXPECT_NE(svg.find("viewBox=\"0 0 1000 "), std::string::npos);
  const auto paths = readSvgPaths(svg);
  std::vector<ReadPath> cut, sew;
  int notches = 0;
  for (const ReadPath& r : paths) {
    if (r.layer == "cut") cut.push_back(r);
    if (r.layer == "sew") sew.push_back(r);
    notches += r.layer == "notches";
  }
  ASSERT_EQ(sew.size(), p.panels.size());
  ASSERT_EQ(cut.size(), p.panels.size());
  EXPECT_EQ(notches, int(s.notches.size()));
  for (size_t k = 0; k < p.panels.size(); ++k) {
    expectSameOutline(s.outlines.panels[k].points(p.panels[k], 1000), sew[k]);
    expectSameOutline(s.panels[k].cut, cut[k]);
    // Placed where the layout says (the reader undoes the y flip).
    EXPECT_NEAR((sew[k].points[0] - s.panels[k].placement.apply(s.panels[k].sew[0])).norm(), 0, 1e-3);
  }
  for (const char* id : {"\"cut\"", "\"sew\"", "\"notches\"", "\"labels\""}) EXPECT_NE(svg.find(id), std::string::npos);
}

TEST(SvgWriter, NamesNeverBecomeMarkup) {
  const std::string svg = writeSvg(layoutSheet(sphere(), {}).drawing, kNastyName);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("<b "), std::string::npos);
  EXPECT_NE(svg.find("a&lt;b &amp; &quot;c&quot; &apos;d&apos; &lt;/text&gt;&lt;script&gt;"), std::string::npos);
  // Every '<' starts one of our own elements.
  for (size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    const std::string tag = svg.substr(at, 6);
    EXPECT_TRUE(tag.rfind("<?xml", 0) == 0 || tag.rfind("<svg", 0) == 0 || tag.rfind("</svg", 0) == 0 ||
                tag.rfind("<g", 0) == 0 || tag.rfind("</g", 0) == 0 || tag.rfind("<path", 0) == 0 ||
                tag.rfind("<text", 0) == 0 || tag.rfind("</text", 0) == 0 || tag.rfind("<title", 0) == 0 ||
                tag.rfind("</titl", 0) == 0)
        << tag;
  }
}

TEST(DxfWriter, R12StructureAndRoundTrip) {
  const Pattern p = sphere();
  const SheetLayout s = layoutSheet(p, {});
  const std::string dxf = writeDxf(s.drawing);
  EXPECT_NE(dxf.find("9\n$ACADVER\n1\nAC1009\n"), std::string::npos);
  EXPECT_NE(dxf.find("9\n$INSUNITS\n70\n4\n"), std::string::npos);
  EXPECT_EQ(dxf.substr(dxf.size() - 7), "\n0\nEOF\n");
  const DxfFile f = readDxf(dxf);
  for (const char* layer : {"CUT", "SEW", "NOTCH", "LABEL"}) EXPECT_TRUE(f.layerColors.count(layer)) << layer;
  EXPECT_EQ(f.layerColors.at("NOTCH"), 1);
  std::vector<ReadPath> sew, cut;
  int lines = 0;
  for (const ReadPath& r : f.paths) {
    if (r.layer == "SEW") sew.push_back(r);
    if (r.layer == "CUT") cut.push_back(r);
    lines += r.layer == "NOTCH";
  }
  ASSERT_EQ(sew.size(), p.panels.size());
  EXPECT_EQ(lines, int(s.notches.size()));
  for (size_t k = 0; k < p.panels.size(); ++k) {
    expectSameOutline(s.outlines.panels[k].points(p.panels[k], 1000), sew[k]);
    expectSameOutline(s.panels[k].cut, cut[k]);
  }
  // Section order: HEADER, TABLES, BLOCKS, ENTITIES.
  const size_t h = dxf.find("2\nHEADER"), t = dxf.find("2\nTABLES"), b = dxf.find("2\nBLOCKS"),
               e = dxf.find("2\nENTITIES");
  EXPECT_TRUE(h < t && t < b && b < e && e != std::string::npos);
  bool named = false;
  for (const auto& [layer, text] : f.texts) named = named || text.find("100%%%") != std::string::npos;
  EXPECT_TRUE(named);
  EXPECT_EQ(escapeDxfText("Rücken\n50%"), "R\\U+00FCcken50%%%");
}

TEST(PdfWriter, PagesXrefAndCheckSquare) {
  const SheetLayout s = layoutSheet(sphere(), {});
  for (PaperSize paper : {PaperSize::A4, PaperSize::Letter}) {
    PdfOptions o;
    o.paper = paper;
    o.title = "t (1) \\ x";
    const std::string pdf = writePdf(s.drawing, o);
    const PdfTiling t = pdfTiling(s.drawing, o);
    EXPECT_EQ(pdf.rfind("%PDF-1.4\n", 0), 0u);
    EXPECT_EQ(countPdfPages(pdf), t.pageCount());
    EXPECT_EQ(t.pageCount(), 1 + t.printedTiles());  // the overview, then the tiles with something to cut
    EXPECT_GT(t.printedTiles(), 0);
    EXPECT_LE(t.printedTiles(), t.rows * t.columns);
    EXPECT_GE((t.columns - 1) * t.stepX + t.contentWidth, s.drawing.width);
    EXPECT_GE(t.height, s.drawing.length);
    EXPECT_NE(pdf.find(paper == PaperSize::A4 ? "/MediaBox [0 0 595.276 841.89]" : "/MediaBox [0 0 612 792]"),
              std::string::npos);
    EXPECT_NE(pdf.find("(t \\(1\\) \\\\ x)"), std::string::npos);
    // xref: every entry points at "N 0 obj", startxref at "xref".
    const size_t sx = pdf.rfind("startxref\n");
    const size_t xref = std::stoul(pdf.substr(sx + 10));
    ASSERT_EQ(pdf.compare(xref, 4, "xref"), 0);
    std::istringstream in(pdf.substr(xref + 5));
    int first = 0, count = 0;
    in >> first >> count;
    std::string offset, gen, kind;
    in >> offset >> gen >> kind;  // the free entry
    for (int i = 1; i < count; ++i) {
      in >> offset >> gen >> kind;
      const std::string head = std::to_string(i) + " 0 obj";
      EXPECT_EQ(pdf.compare(std::stoul(offset), head.size(), head), 0) << i;
    }
    // The 50 mm check square on every page, in points.
    int squares = 0;
    for (size_t at = pdf.find("% scale-check-square\n"); at != std::string::npos;
         at = pdf.find("% scale-check-square\n", at + 1)) {
      std::istringstream q(pdf.substr(at + 21, 80));
      double x, y, w, h;
      std::string op;
      q >> x >> y >> w >> h >> op;
      EXPECT_EQ(op, "re");
      EXPECT_NEAR(w, 50 / 25.4 * 72, 0.01);
      EXPECT_NEAR(h, 50 / 25.4 * 72, 0.01);
      ++squares;
    }
    EXPECT_EQ(squares, t.pageCount());
    EXPECT_NE(pdf.find("(row 1, column 1)"), std::string::npos);
  }
}

TEST(Export, BundleAndStatistics) {
  ExampleOptions eo;
  eo.triangles = 600;
  const Pattern p = examplePattern("sphere3", eo);
  ExportOptions o;
  o.sheetWidth = 1200;
  o.seamAllowance = {{1, 0.0}};  // heat-seal seam S2
  const ExportBundle b = exportPattern(p, o);
  EXPECT_FALSE(b.svg.empty());
  EXPECT_FALSE(b.dxf.empty());
  EXPECT_FALSE(b.pdf.empty());
  const auto j = nlohmann::json::parse(b.statistics);
  const auto& t = j["totals"];
  EXPECT_EQ(t["panels"], 3);
  EXPECT_EQ(t["seams"], 3);
  double perimeters = 0;  // every outline edge is sewn once, to one other edge
  for (const auto& panel : j["panels"]) perimeters += panel["perimeter_mm"].get<double>();
  EXPECT_NEAR(t["seam_length_mm"].get<double>(), perimeters / 2, 1e-6);
  EXPECT_NEAR(t["panel_area_m2"].get<double>(), 4 * M_PI * 0.09, 0.05);
  EXPECT_GT(t["material_area_m2"].get<double>(), t["panel_area_m2"].get<double>());
  EXPECT_NEAR(t["sewing_minutes"].get<double>(), t["seam_length_mm"].get<double>() / 1000 / 0.5 + 3 * 2, 1e-9);
  EXPECT_LT(t["max_seam_mismatch_mm"].get<double>(), 1e-6);
  EXPECT_GT(t["utilisation"].get<double>(), 0.2);
  EXPECT_EQ(j["seams"][1]["allowance_mm"], 0.0);
  EXPECT_EQ(j["panels"][0]["name"], "gore 1");
}

// The bundle's sheet (placements, size, notch ticks in each panel's frame) is the sheet the cut files draw:
// the placed cut lines and ticks are the drawing's cut and notch paths, and no placed piece leaves the sheet.
TEST(Export, SheetViewMatchesTheDrawing) {
  ExampleOptions eo;
  eo.triangles = 600;
  const Pattern p = examplePattern("sphere3", eo);
  ExportOptions o;
  o.sheetWidth = 700;
  const ExportBundle b = exportPattern(p, o);
  const SheetLayout s = layoutSheet(p, o);
  ASSERT_EQ(b.placements.size(), p.panels.size());
  ASSERT_EQ(b.notchTicks.size(), p.panels.size());
  EXPECT_EQ(b.sheetWidth, 700);
  EXPECT_NEAR(b.sheetLength, s.drawing.length, 1e-9);
  std::vector<Polygon2> drawnTicks(p.panels.size());
  size_t cutPaths = 0;
  for (const DrawnPath& path : s.drawing.paths) {
    if (path.layer == Layer::Notch)
      drawnTicks[path.panel].insert(drawnTicks[path.panel].end(), path.points.begin(), path.points.end());
    if (path.layer != Layer::Cut) continue;
    ++cutPaths;
    const Polygon2 placed = transformed(b.cutLines[path.panel], b.placements[path.panel]);
    ASSERT_EQ(placed.size(), path.points.size());
    for (size_t i = 0; i < placed.size(); ++i) EXPECT_LT((placed[i] - path.points[i]).norm(), 1e-9);
    for (const Vec2& v : placed) {
      EXPECT_GE(v.x(), -1e-9);
      EXPECT_LE(v.x(), b.sheetWidth + 1e-9);
      EXPECT_GE(v.y(), -1e-9);
      EXPECT_LE(v.y(), b.sheetLength + 1e-9);
    }
  }
  EXPECT_EQ(cutPaths, p.panels.size());
  size_t ticks = 0;
  for (size_t panel = 0; panel < p.panels.size(); ++panel) {
    const Polygon2 placed = transformed(b.notchTicks[panel], b.placements[panel]);
    ASSERT_EQ(placed.size(), drawnTicks[panel].size());
    for (size_t i = 0; i < placed.size(); ++i) EXPECT_LT((placed[i] - drawnTicks[panel][i]).norm(), 1e-9);
    ticks += placed.size() / 2;
  }
  EXPECT_EQ(ticks, s.notches.size());
  EXPECT_GT(ticks, 3u);  // junctions at least
}

TEST(Export, BadOptionsAreRefusedWithAMessage) {
  const Pattern p = examplePattern("pillow", {});
  ExportOptions o;
  o.allowance = -1;
  EXPECT_THROW(exportPattern(p, o), Error);
  o = {};
  o.sheetWidth = 0;
  EXPECT_THROW(exportPattern(p, o), Error);
  EXPECT_THROW(exportPattern(Pattern{}, {}), Error);
}
