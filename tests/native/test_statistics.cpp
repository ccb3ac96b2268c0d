// exportStatistics and summaryLines (export/statistics.hpp) on a cube of six squares, where the areas, seam
// lengths and sewing time a maker plans with follow from the side length: the numbers in the statistics file
// and the PDF's overview lines are checked against those hand values, in millimetres and in inches.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "export/layout.hpp"
#include "export/statistics.hpp"
#include "simulate/example_patterns.hpp"

using namespace billow;
using nlohmann::json;

namespace {

constexpr double kSide = 200;  // [mm], the cube's edge

// Six squares of side 0.2 m sewn into a cube: 12 seams, one per cube edge, each 200 mm on both panels.
Pattern cube() {
  ExampleOptions eo;
  eo.triangles = 300;
  eo.size = kSide / 1000;
  return examplePattern("cube", eo);
}

// The cube without its last face: an open box whose four rim edges are sewn to nothing.
Pattern openBox() {
  Pattern p = cube();
  const int dropped = static_cast<int>(p.panels.size()) - 1;
  p.panels.pop_back();
  std::vector<Stitch> kept;
  for (const Stitch& s : p.stitches)
    if (s.panelA != dropped && s.panelB != dropped) kept.push_back(s);
  p.stitches = kept;
  return p;
}

json statistics(const Pattern& p, const ExportOptions& o) { return exportStatistics(p, layoutSheet(p, o), o); }

}  // namespace

TEST(Statistics, ACubeOfSixSquaresHasItsAreasSeamsAndSewingTime) {
  ExportOptions o;
  o.grainLock = true;  // 0 or 180 degrees: each 220 mm cut square lies square on the sheet
  const json j = statistics(cube(), o);
  EXPECT_EQ(j["format"], "billow-export-stats");
  EXPECT_EQ(j["joining"], "sewn");
  EXPECT_EQ(j["allowance_mm"], 10.0);
  EXPECT_EQ(j["free_edge_allowance_mm"], 10.0) << "free edges default to the seam allowance";
  EXPECT_EQ(j["units"]["length"], "mm");

  ASSERT_EQ(j["panels"].size(), 6u);
  for (size_t p = 0; p < 6; ++p) {
    const json& panel = j["panels"][p];
    EXPECT_EQ(panel["number"], p + 1);
    EXPECT_EQ(panel["name"], "face " + std::to_string(p + 1));
    EXPECT_EQ(panel["internal"], false);
    EXPECT_NEAR(panel["area_m2"].get<double>(), 0.04, 1e-9);
    // A square offset by 10 mm with mitred corners (a right angle reaches sqrt(2) widths, under the limit of 2)
    // is a 220 mm square.
    EXPECT_NEAR(panel["cut_area_m2"].get<double>(), 0.22 * 0.22, 1e-9);
    EXPECT_NEAR(panel["width_mm"].get<double>(), kSide + 20, 1e-6);
    EXPECT_NEAR(panel["height_mm"].get<double>(), kSide + 20, 1e-6);
    EXPECT_NEAR(panel["perimeter_mm"].get<double>(), 4 * kSide, 1e-6);
    EXPECT_NEAR(std::abs(std::remainder(panel["rotation_deg"].get<double>(), 180.0)), 0, 1e-9);
    // Placed on the sheet with the gap to its edges.
    const double x = panel["position_mm"][0], y = panel["position_mm"][1];
    EXPECT_GE(x, o.gap - 1e-9);
    EXPECT_LE(x + kSide + 20, o.sheetWidth - o.gap + 1e-9);
    EXPECT_GE(y, o.gap - 1e-9);
    EXPECT_LE(y + kSide + 20, j["totals"]["sheet_length_mm"].get<double>() - o.gap + 1e-9);
  }

  ASSERT_EQ(j["seams"].size(), 12u);
  for (size_t k = 0; k < 12; ++k) {
    const json& seam = j["seams"][k];
    EXPECT_EQ(seam["id"], k);
    EXPECT_EQ(seam["label"], "S" + std::to_string(k + 1));
    EXPECT_NE(seam["panels"][0], seam["panels"][1]) << "a cube edge joins two faces";
    EXPECT_NEAR(seam["length_a_mm"].get<double>(), kSide, 1e-6);
    EXPECT_NEAR(seam["length_b_mm"].get<double>(), kSide, 1e-6);
    EXPECT_NEAR(seam["mismatch_mm"].get<double>(), 0, 1e-6);
    EXPECT_EQ(seam["closed"], false);
    EXPECT_EQ(seam["allowance_mm"], 10.0);
  }

  const json& t = j["totals"];
  EXPECT_EQ(t["panels"], 6);
  EXPECT_EQ(t["seams"], 12);
  EXPECT_NEAR(t["panel_area_m2"].get<double>(), 6 * 0.04, 1e-9);
  EXPECT_NEAR(t["material_area_m2"].get<double>(), 6 * 0.22 * 0.22, 1e-9);
  EXPECT_NEAR(t["seam_length_mm"].get<double>(), 12 * kSide, 1e-6);
  EXPECT_EQ(t["free_edge_mm"], 0.0);
  // 2.4 m at 0.5 m per minute, and 2 minutes for each of the 12 seams.
  EXPECT_NEAR(t["sewing_minutes"].get<double>(), 2.4 / 0.5 + 12 * 2, 1e-9);
  EXPECT_EQ(t["sheet_width_mm"], o.sheetWidth);
  EXPECT_NEAR(t["sheet_area_m2"].get<double>(), o.sheetWidth * t["sheet_length_mm"].get<double>() * 1e-6, 1e-12);
  // Utilisation is the cut pieces' share of the sheet used.
  EXPECT_NEAR(t["utilisation"].get<double>(), t["material_area_m2"].get<double>() / t["sheet_area_m2"].get<double>(),
              1e-9);
  EXPECT_TRUE(j["valves"].empty());
}

TEST(Statistics, AnOpenBoxHasItsRimAsFreeEdgeWithItsOwnAllowance) {
  // Five faces: the four rim edges of the missing face (200 mm on each of four panels) are sewn to nothing.
  ExportOptions o;
  o.freeEdgeAllowance = 30;
  const json j = statistics(openBox(), o);
  const json& t = j["totals"];
  EXPECT_EQ(t["panels"], 5);
  EXPECT_EQ(t["seams"], 8);
  EXPECT_NEAR(t["free_edge_mm"].get<double>(), 4 * kSide, 1e-6);
  EXPECT_NEAR(t["seam_length_mm"].get<double>(), 8 * kSide, 1e-6);
  EXPECT_EQ(j["free_edge_allowance_mm"], 30.0);
  EXPECT_EQ(summaryLines(j, o)[0], "5 panels, 8 seams, seam allowance 10 mm, free edges 30 mm");
}

TEST(Statistics, ASeamWhoseSidesDifferCountsTheirMeanAndTheMismatch) {
  // A pillow of two 300 mm squares sewn all around (one closed seam), its back panel scaled by 1.01: the sides
  // are 1200 and 1212 mm long, so the seam counts 1206 mm, 12 mm of mismatch, and 1.206 / 0.5 + 2 minutes.
  Pattern p = examplePattern("pillow", {});
  ASSERT_EQ(p.panels.size(), 2u);
  p.panels[1].vertices *= 1.01;
  ExportOptions o;
  const json j = statistics(p, o);
  ASSERT_EQ(j["seams"].size(), 1u);
  const json& seam = j["seams"][0];
  EXPECT_EQ(seam["closed"], true);
  EXPECT_NEAR(seam["length_a_mm"].get<double>(), 1200, 1e-6);
  EXPECT_NEAR(seam["length_b_mm"].get<double>(), 1212, 1e-6);
  EXPECT_NEAR(seam["mismatch_mm"].get<double>(), 12, 1e-6);
  const json& t = j["totals"];
  EXPECT_NEAR(t["seam_length_mm"].get<double>(), 1206, 1e-6);
  EXPECT_NEAR(t["max_seam_mismatch_mm"].get<double>(), 12, 1e-6);
  EXPECT_NEAR(t["sewing_minutes"].get<double>(), 1.206 / 0.5 + 2, 1e-9);
  EXPECT_NEAR(t["panel_area_m2"].get<double>(), 0.09 * (1 + 1.01 * 1.01), 1e-9);
  EXPECT_EQ(summaryLines(j, o)[3], "seams 1206 mm in total, largest mismatch 12 mm; sewing about 4 min");
}

TEST(Statistics, ValvesSaySeamByLabelWhetherThePatternHasTheirSeam) {
  ExportOptions o;
  o.valves = {{0, 0.5, 20}, {40, 0.25, 15}};  // S1 exists; S41 does not
  const json j = statistics(cube(), o);
  ASSERT_EQ(j["valves"].size(), 2u);
  EXPECT_EQ(j["valves"][0]["label"], "S1");
  EXPECT_EQ(j["valves"][0]["placed"], true);
  EXPECT_EQ(j["valves"][0]["width_mm"], 20.0);
  EXPECT_EQ(j["valves"][1]["label"], "S41");
  EXPECT_EQ(j["valves"][1]["at"], 0.25);
  EXPECT_EQ(j["valves"][1]["placed"], false);
  const std::vector<std::string> lines = summaryLines(j, o);
  int valveLines = 0;
  for (const std::string& l : lines) valveLines += l.rfind("fill valve on ", 0) == 0;
  EXPECT_EQ(valveLines, 1) << "only a placed valve gets a line";
  EXPECT_EQ(lines[1], "fill valve on S1: leave 20 mm open at the marks on both pieces");
}

TEST(Statistics, SummaryLinesSayTheCubesFiguresInMillimetres) {
  ExportOptions o;
  const json j = statistics(cube(), o);
  const std::vector<std::string> lines = summaryLines(j, o);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "6 panels, 12 seams, seam allowance 10 mm");
  char sheet[200];
  std::snprintf(sheet, sizeof sheet, "sheet 1000 mm wide x %.0f mm long, material used %.0f %%",
                j["totals"]["sheet_length_mm"].get<double>(), 100 * j["totals"]["utilisation"].get<double>());
  EXPECT_EQ(lines[1], sheet);
  char area[200];
  std::snprintf(area, sizeof area, "panel area 0.240 m2, cut pieces 0.290 m2, sheet %.3f m2",
                j["totals"]["sheet_area_m2"].get<double>());
  EXPECT_EQ(lines[2], area) << "6 x 0.04 m2 sewn, 6 x 0.0484 m2 cut";
  EXPECT_EQ(lines[3], "seams 2400 mm in total, largest mismatch 0 mm; sewing about 29 min") << "4.8 + 24 minutes";
}

TEST(Statistics, SummaryLinesInInchesAndSquareFeet) {
  ExportOptions o;
  o.units = DisplayUnits::Inches;
  const std::vector<std::string> lines = summaryLines(statistics(cube(), o), o);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "6 panels, 12 seams, seam allowance 0.4 in") << "10 mm = 0.39 in";
  EXPECT_EQ(lines[1].rfind("sheet 39.4 in wide x ", 0), 0u) << lines[1];  // 1000 mm = 39.37 in
  // 0.24 m2 = 2.58 sq ft (1 sq ft = 0.09290304 m2), 0.2904 m2 = 3.13 sq ft.
  EXPECT_EQ(lines[2].rfind("panel area 2.58 sq ft, cut pieces 3.13 sq ft, sheet ", 0), 0u) << lines[2];
  EXPECT_EQ(lines[3], "seams 94.5 in in total, largest mismatch 0.0 in; sewing about 29 min") << "2400 mm = 94.49 in";
}

TEST(Statistics, SeamsWithTheirOwnAllowanceAreNamedUpToFour) {
  ExportOptions o;
  o.seamAllowance = {{1, 0.0}, {2, 25.0}};
  json j = statistics(cube(), o);
  EXPECT_EQ(j["seams"][1]["allowance_mm"], 0.0);
  EXPECT_EQ(j["seams"][2]["allowance_mm"], 25.0);
  EXPECT_EQ(summaryLines(j, o)[0], "6 panels, 12 seams, seam allowance 10 mm, S2 0 mm, S3 25 mm");
  o.seamAllowance = {{0, 5.0}, {3, 5.0}, {5, 5.0}, {7, 5.0}, {9, 5.0}};
  j = statistics(cube(), o);
  EXPECT_EQ(summaryLines(j, o)[0], "6 panels, 12 seams, seam allowance 10 mm (5 seams their own)");
  // An override equal to the default is not an exception worth naming.
  o.seamAllowance = {{4, 10.0}};
  j = statistics(cube(), o);
  EXPECT_EQ(summaryLines(j, o)[0], "6 panels, 12 seams, seam allowance 10 mm");
}

TEST(Statistics, HeatSealedPatternsSayTheSealBand) {
  ExportOptions o;
  o.sealed = true;
  o.allowance = 6;
  const json j = statistics(cube(), o);
  EXPECT_EQ(j["joining"], "sealed");
  EXPECT_EQ(summaryLines(j, o)[0], "6 panels, 12 seams, heat sealed, seal band 6 mm");
  EXPECT_EQ(summaryLines(j, o)[3], "seams 2400 mm in total, largest mismatch 0 mm") << "no sewing time: it is not sewn";
}
