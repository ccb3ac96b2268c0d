// Per-seam seam allowance (0 on a heat-sealed seam, wider on another), the allowance of free edges, the
// export options as JSON (the embind module's options and the design's "fabrication" object), and the
// CLI's --seam-allowance / --free-edge-allowance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "export/export.hpp"
#include "export/layout.hpp"
#include "export/offset.hpp"
#include "io/export_options_json.hpp"
#include "io/pattern_json.hpp"
#include "simulate/example_patterns.hpp"
#include "test_export_parsers.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;
using nlohmann::json;

namespace {

Pattern gores() {
  ExampleOptions eo;
  eo.triangles = 900;
  eo.size = 0.2;
  return examplePattern("sphere3", eo);
}

// Distance [mm] from the middle of outline edge e of panel p to its cut line.
double cutDistance(const SheetLayout& s, int p, int e) {
  const Polygon2& sew = s.panels[p].sew;
  const Vec2 mid = 0.5 * (sew[e] + sew[(e + 1) % sew.size()]);
  return distanceToBoundary(mid, s.panels[p].cut);
}

// Edges well inside one seam (or free run): their four neighbours on each side belong to it too, so where
// two widths meet (the cut line steps there) does not count.
bool inside(const PanelOutline& o, int e) {
  const int n = int(o.edgeSeam.size());
  for (int k = -4; k <= 4; ++k)
    if (o.edgeSeam[(e + k + n) % n] != o.edgeSeam[e]) return false;
  return true;
}

// For every inner edge of every panel: the expected allowance of its seam, and the measured one.
void expectWidths(const SheetLayout& s, double (*expected)(int seam)) {
  int checked = 0;
  for (size_t p = 0; p < s.panels.size(); ++p) {
    const PanelOutline& o = s.outlines.panels[p];
    for (int e = 0; e < int(o.edgeSeam.size()); ++e) {
      if (!inside(o, e)) continue;
      EXPECT_NEAR(cutDistance(s, int(p), e), expected(o.edgeSeam[e]), 0.05)
          << "panel " << p << " edge " << e << " of seam " << o.edgeSeam[e];
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

}  // namespace

TEST(SeamAllowance, AnOverrideChangesOnlyThatSeamOnBothPanels) {
  const Pattern p = gores();
  ExportOptions o;
  const SheetLayout plain = layoutSheet(p, o);
  ASSERT_EQ(plain.outlines.seams.size(), 3u);
  expectWidths(plain, [](int) { return 10.0; });

  o.seamAllowance = {{1, 0.0}, {2, 25.0}};  // S2 heat sealed, S3 wide
  const SheetLayout mixed = layoutSheet(p, o);
  expectWidths(mixed, [](int seam) { return seam == 1 ? 0.0 : seam == 2 ? 25.0 : 10.0; });
  // Both panels of S2 are cut on the sewing line there; the statistics say which seam has what.
  const Seam& s2 = mixed.outlines.seams[1];
  EXPECT_NE(s2.a.panel, s2.b.panel);
  const json stats = json::parse(exportPattern(p, o).statistics);
  EXPECT_EQ(stats["seams"][0]["allowance_mm"], 10.0);
  EXPECT_EQ(stats["seams"][1]["allowance_mm"], 0.0);
  EXPECT_EQ(stats["seams"][2]["allowance_mm"], 25.0);
  EXPECT_EQ(stats["allowance_mm"], 10.0);

  // An override of a seam the pattern does not have (the designer redrew the seams) changes nothing.
  o.seamAllowance = {{7, 0.0}};
  const SheetLayout stale = layoutSheet(p, o);
  for (size_t k = 0; k < plain.panels.size(); ++k) EXPECT_TRUE(stale.panels[k].cut == plain.panels[k].cut);
}

TEST(SeamAllowance, WidthsThatChangeOnAGentleCurveStayAtTheirDistance) {
  // A circle of radius 100 mm in 72 edges: where 10 mm meets 25 mm the corner turns by only 5 degrees, so
  // the two offset lines meet far away; the cut line must step from one width to the other there, not reach
  // out to that point (it did: a 5-point cut line 480 mm away on the sphere's internal panel).
  const int n = 72;
  Polygon2 circle;
  std::vector<double> widths;
  for (int k = 0; k < n; ++k) {
    circle.push_back(100 * Vec2(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)));
    widths.push_back(k < n / 3 ? 10 : k < n / 2 ? 25 : k < 2 * n / 3 ? 0 : 10.5);
  }
  const Polygon2 cut = offsetPolygon(circle, widths);
  EXPECT_GE(cut.size(), size_t(n));
  const Box2 box = boundingBox(cut);
  EXPECT_LT(box.size().maxCoeff(), 2 * (100 + 25) + 1);
  for (const Vec2& v : circle) EXPECT_TRUE(insidePolygon(v, cut) || distanceToBoundary(v, cut) < 1e-9);
  // Away from where the width changes (the cut line steps there, perpendicular to the sewing line, so the
  // wider seam keeps its allowance to its end), each edge has its width.
  int checked = 0;
  for (int k = 0; k < n; ++k) {
    bool away = true;
    for (int j = -4; j <= 4; ++j) away = away && widths[(k + j + n) % n] == widths[k];
    if (!away) continue;
    const Vec2 mid = 0.5 * (circle[k] + circle[(k + 1) % n]);
    EXPECT_NEAR(distanceToBoundary(mid, cut), widths[k], 0.05) << "edge " << k;
    ++checked;
  }
  EXPECT_GT(checked, n / 2);
  // At the step from 10 to 25 mm (vertex 24, 120 degrees) the cut line runs out along the wide edge's end.
  const Vec2 end24 = circle[24] + 25 * Vec2(std::cos(2 * M_PI * 24.5 / n), std::sin(2 * M_PI * 24.5 / n));
  EXPECT_LT(distanceToBoundary(end24, cut), 0.5);
  // Every cut vertex lies within the widest allowance (times the miter limit) of the sewing line.
  for (const Vec2& v : cut) EXPECT_LT(distanceToBoundary(v, circle), 2 * 25 + 1e-6);
}

TEST(SeamAllowance, FreeEdgesHaveTheirOwnAllowance) {
  // A pillow with its top side left open: the stitches along y = max are dropped.
  Pattern p = examplePattern("pillow", {});
  const double top = p.panels[0].vertices.col(1).maxCoeff();
  std::vector<Stitch> kept;
  for (const Stitch& s : p.stitches)
    if (p.panels[s.panelA].vertices(s.vertexA, 1) < top - 1e-9) kept.push_back(s);
  ASSERT_LT(kept.size(), p.stitches.size());
  p.stitches = kept;
  ExportOptions o;
  o.freeEdgeAllowance = 30;
  const SheetLayout s = layoutSheet(p, o);
  expectWidths(s, [](int seam) { return seam < 0 ? 30.0 : 10.0; });
  const json stats = json::parse(exportPattern(p, o).statistics);
  EXPECT_EQ(stats["free_edge_allowance_mm"], 30.0);
  EXPECT_NEAR(stats["totals"]["free_edge_mm"].get<double>(), 2 * 1000 * 0.3, 0.3 * 1000 * 0.25);  // top sides
  o.freeEdgeAllowance = 250;
  EXPECT_THROW(layoutSheet(p, o), Error);
}

TEST(SeamAllowance, JsonOptionsAreReadAndCheckedWithAMessage) {
  const ExportOptions o = readExportOptionsJson(json::parse(
      R"({"allowance": 12, "seam_allowance": {"5": 15, "3": 0}, "free_edge_allowance": 4, "grain_lock": true,
          "rotate": false, "sheet_width": 1400, "units": "in", "paper": "letter"})"));
  EXPECT_EQ(o.allowance, 12);
  ASSERT_EQ(o.seamAllowance.size(), 2u);
  EXPECT_EQ(o.seamAllowance[0], std::make_pair(3, 0.0));
  EXPECT_EQ(o.seamAllowance[1], std::make_pair(5, 15.0));
  EXPECT_EQ(o.freeEdgeAllowance, 4);
  EXPECT_TRUE(o.grainLock);
  EXPECT_FALSE(o.allowRotation);
  EXPECT_EQ(o.sheetWidth, 1400);
  EXPECT_EQ(o.units, DisplayUnits::Inches);
  EXPECT_EQ(o.paper, PaperSize::Letter);
  EXPECT_EQ(readExportOptionsJson(json::object()).freeEdgeAllowance, -1);  // free edges as the seams

  const auto message = [](const char* text) {
    try {
      readExportOptionsJson(json::parse(text));
    } catch (const Error& e) {
      EXPECT_EQ(e.code, "export.bad-value");
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(R"({"seam_allowance": {"3": 101}})").find("seam S4"), std::string::npos);
  EXPECT_NE(message(R"({"seam_allowance": {"3": -1}})").find("from 0 to 100 mm"), std::string::npos);
  EXPECT_NE(message(R"({"seam_allowance": {"3": "wide"}})").find("seam S4"), std::string::npos);
  EXPECT_NE(message(R"({"seam_allowance": {"S4": 3}})").find("\"S4\""), std::string::npos);
  EXPECT_NE(message(R"({"seam_allowance": {"-1": 3}})").find("whole number"), std::string::npos);
  EXPECT_NE(message(R"({"seam_allowance": {"1.5": 3}})").find("whole number"), std::string::npos);
  EXPECT_NE(message(R"({"seam_allowance": [[3, 0]]})").find("seam ids"), std::string::npos);
  EXPECT_NE(message(R"({"free_edge_allowance": 120})").find("free edges"), std::string::npos);
  EXPECT_NE(message(R"({"grain_lock": "yes"})").find("grain_lock"), std::string::npos);
  EXPECT_NE(message(R"({"allowance": "10"})").find("allowance"), std::string::npos);
  EXPECT_NE(message(R"({"paper": "a3"})").find("Letter"), std::string::npos);
}

// ---- The CLI (native only: it runs the billow executable next to this test binary) ----

TEST(CliExport, SeamAllowanceOptions) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  const std::string pattern = testing::TempDir() + "billow-allowance-gores.json";
  std::ofstream(pattern) << writePatternJson(gores());
  const std::string dir = testing::TempDir() + "billow-allowance-out";
  std::string out;
  ASSERT_EQ(test::runCapture(test::cliPath() + " export " + pattern + " --out-dir " + dir +
                                 " --seam-allowance S2=0 --seam-allowance 2=25 --grain-lock",
                             out),
            0)
      << out;
  const json stats = json::parse(readFileBytes(dir + "/stats.json"));
  EXPECT_EQ(stats["seams"][0]["allowance_mm"], 10.0);
  EXPECT_EQ(stats["seams"][1]["allowance_mm"], 0.0);  // S2 is id 1
  EXPECT_EQ(stats["seams"][2]["allowance_mm"], 25.0);
  for (const auto& panel : stats["panels"]) {
    const double r = std::abs(panel["rotation_deg"].get<double>());
    EXPECT_TRUE(r < 1e-9 || std::abs(r - 180) < 1e-9) << r;  // grain lock: turned 0 or 180 degrees only
  }

  // Mistakes are refused (exit code 1) with a message that says what is expected.
  const auto refused = [&](const std::string& options, const std::string& words) {
    std::string output;
    EXPECT_EQ(test::runCapture(test::cliPath() + " export " + pattern + " --out-dir " + dir + " " + options, output), 1)
        << options;
    EXPECT_NE(output.find(words), std::string::npos) << options << ": " << output;
  };
  refused("--seam-allowance S2", "needs SEAM=MM");
  refused("--seam-allowance S2=wide", "a length in mm");
  refused("--seam-allowance X2=3", "its label S1, S2");
  refused("--seam-allowance S0=3", "start at S1");
  refused("--seam-allowance =3", "its label S1, S2");
  refused("--seam-allowance S2=3 --seam-allowance 1=4", "given two allowances");
  refused("--seam-allowance S2=300", "seam S2 from 0 to 200 mm");
  refused("--free-edge-allowance -3", "0 mm or more");
  refused("--seam-allowance", "needs a value");
  std::string help;
  ASSERT_EQ(test::runCapture(test::cliPath() + " export --help", help), 0);
  EXPECT_NE(help.find("--seam-allowance SEAM=MM"), std::string::npos);
  EXPECT_NE(help.find("--free-edge-allowance MM"), std::string::npos);
#endif
}

TEST(CliDesign, CutFileUsesTheDesignsSeamAllowancesAndGrain) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  json doc = json::parse(readFileBytes(test::dataPath("sphere-gores.billow.json")));
  doc["target"] = {{"obj", test::examplesDir() + "/sphere.obj"}};
  doc["fabrication"] = {{"allowance", 20}, {"seam_allowance", {{"1", 0}}}, {"grain_lock", true}};
  const std::string design = testing::TempDir() + "billow-allowance.billow.json";
  std::ofstream(design) << doc.dump();
  const std::string dir = testing::TempDir() + "billow-allowance-design";
  std::string out;
  ASSERT_EQ(test::runCapture(test::cliPath() + " design " + design + " --out-dir " + dir +
                                 " --no-optimize --resolution 1000 --quiet",
                             out),
            0)
      << out;
  // The cut lines of the SVG are those of the written pattern with S2 cut on its sewing line.
  const Pattern pattern = readPatternJson(readFileBytes(dir + "/pattern.json"));
  const auto perimeters = [](std::vector<Polygon2> cuts) {
    std::vector<double> lengths;
    for (const Polygon2& c : cuts) lengths.push_back(perimeter(c));
    std::sort(lengths.begin(), lengths.end());
    return lengths;
  };
  std::vector<Polygon2> svgCuts;
  for (const test::ReadPath& r : test::readSvgPaths(readFileBytes(dir + "/pattern.svg")))
    if (r.layer == "cut") svgCuts.push_back(r.points);
  ExportOptions o;
  o.allowance = 20;
  const std::vector<double> plain = perimeters(exportPattern(pattern, o).cutLines);
  o.seamAllowance = {{1, 0.0}};
  const std::vector<double> expected = perimeters(exportPattern(pattern, o).cutLines), got = perimeters(svgCuts);
  ASSERT_EQ(got.size(), expected.size());
  for (size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], expected[k], 0.01);
  double shorter = 0;  // S2 has no allowance: both of its panels' cut lines are shorter
  for (size_t k = 0; k < got.size(); ++k) shorter += plain[k] - expected[k];
  EXPECT_GT(shorter, 20);
  // Grain kept along the roll: each piece lies on the sheet turned 0 or 180 degrees, so its size there is
  // its size in the pattern (turned freely, the nesting turns them).
  o.grainLock = false;
  const SheetLayout free = layoutSheet(pattern, o);
  o.grainLock = true;
  const SheetLayout kept = layoutSheet(pattern, o);
  bool turned = false;
  for (size_t p = 0; p < free.panels.size(); ++p) {
    turned = turned || std::abs(std::remainder(free.panels[p].placement.angle, M_PI)) > 1e-6;
    EXPECT_NEAR(std::abs(std::remainder(kept.panels[p].placement.angle, M_PI)), 0.0, 1e-9);
  }
  EXPECT_TRUE(turned) << "turned freely, some piece is turned";
  for (const Polygon2& cut : svgCuts) {
    const Vec2 size = boundingBox(cut).size();
    const auto same = std::find_if(kept.panels.begin(), kept.panels.end(), [&](const PanelLayout& pl) {
      return std::abs(perimeter(pl.cut) - perimeter(cut)) < 0.01;
    });
    ASSERT_NE(same, kept.panels.end());
    EXPECT_NEAR(size.x(), boundingBox(same->cut).size().x(), 0.01);
    EXPECT_NEAR(size.y(), boundingBox(same->cut).size().y(), 0.01);
  }

  // A bad value in the fabrication settings stops the command with a message that says where.
  doc["fabrication"]["seam_allowance"]["1"] = 500;
  std::ofstream(design) << doc.dump();
  EXPECT_EQ(
      test::runCapture(test::cliPath() + " design " + design + " --out-dir " + dir + " --no-optimize --quiet", out), 1);
  EXPECT_NE(out.find("fabrication settings"), std::string::npos) << out;
  EXPECT_NE(out.find("seam S2"), std::string::npos) << out;
#endif
}

// A sheet narrower than a piece: billow design still writes the pattern, the inflated shape and the report,
// says why the cut file is missing, and ends with a non-zero status.
TEST(CliDesign, ASheetTooNarrowLosesNothingElse) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  json doc = json::parse(readFileBytes(test::dataPath("sphere-gores.billow.json")));
  doc["target"] = {{"obj", test::examplesDir() + "/sphere.obj"}};
  doc["fabrication"] = {{"sheet_width", 100}};
  const std::string design = testing::TempDir() + "billow-narrow.billow.json";
  std::ofstream(design) << doc.dump();
  const std::string dir = testing::TempDir() + "billow-narrow-design";
  std::filesystem::remove_all(dir);
  std::string out;
  EXPECT_EQ(
      test::runCapture(
          test::cliPath() + " design " + design + " --out-dir " + dir + " --no-optimize --resolution 600 --quiet", out),
      1);
  EXPECT_NE(out.find("cut file (pattern.svg) was not written"), std::string::npos) << out;
  EXPECT_NE(out.find("Choose a wider sheet"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/pattern.svg"));
  EXPECT_NO_THROW(readPatternJson(readFileBytes(dir + "/pattern.json")));
  EXPECT_TRUE(std::filesystem::exists(dir + "/inflated.obj"));
  const json report = json::parse(readFileBytes(dir + "/report.json"));
  EXPECT_EQ(report["cut_file"]["written"], false);
  EXPECT_NE(report["cut_file"]["message"].get<std::string>().find("sheet"), std::string::npos);
#endif
}
