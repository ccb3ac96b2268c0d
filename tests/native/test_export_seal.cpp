// Heat-sealed patterns and fill valves: with joining "sealed" the allowance is a seal band, drawn as a band
// between the sealing line and the cut line and named so in every cut file; a fill valve is a gap left open
// at the same place on both pieces of its seam, as wide as asked, reported when its seam is gone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "export/export.hpp"
#include "export/layout.hpp"
#include "io/export_options_json.hpp"
#include "io/pattern_json.hpp"
#include "simulate/example_patterns.hpp"
#include "test_export_parsers.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;
using namespace billow::test;
using nlohmann::json;

namespace {

// The Mylar balloon: two discs sealed along their rim, the foil balloon this class of design is made of.
Pattern mylar() {
  ExampleOptions eo;
  eo.triangles = 600;
  eo.size = 0.3;
  return examplePattern("mylar", eo);
}

ExportOptions sealed(double band) {
  ExportOptions o;
  o.sealed = true;
  o.allowance = band;
  return o;
}

// Arc length [mm] of point q along a closed polyline, from its first point (q lies on it).
double arcOf(const Polygon2& loop, const Vec2& q) {
  double along = 0, best = 1e300, bestArc = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
    const double len = (b - a).norm();
    const double t = len > 0 ? std::clamp((q - a).dot(b - a) / (len * len), 0.0, 1.0) : 0.0;
    const double d = (a + t * (b - a) - q).norm();
    if (d < best) best = d, bestArc = along + t * len;
    along += len;
  }
  return bestArc;
}

}  // namespace

TEST(SealBand, SealedPatternDrawsABandInsteadOfASewingLine) {
  const Pattern pattern = mylar();
  const ExportBundle bundle = exportPattern(pattern, sealed(5));
  const std::vector<ReadPath> svg = readSvgPaths(bundle.svg);
  int bands = 0, sew = 0;
  for (const ReadPath& p : svg) bands += p.layer == "seal-band", sew += p.layer == "sew";
  EXPECT_EQ(sew, 0);
  EXPECT_EQ(bands, 2 * int(pattern.panels.size()));  // per piece: the tinted band, then its sealing line
  EXPECT_NE(bundle.svg.find("fill-rule=\"evenodd\""), std::string::npos);
  EXPECT_NE(bundle.svg.find("inkscape:label=\"seal-band\""), std::string::npos);
  // The band is as wide as asked: the cut line lies 5 mm outside the sealing line all round.
  const SheetLayout layout = layoutSheet(pattern, sealed(5));
  for (const PanelLayout& pl : layout.panels)
    for (size_t i = 0; i < pl.sew.size(); i += 7) {
      const Vec2 mid = 0.5 * (pl.sew[i] + pl.sew[(i + 1) % pl.sew.size()]);
      EXPECT_NEAR(distanceToBoundary(mid, pl.cut), 5.0, 0.05);
    }
  const DxfFile dxf = readDxf(bundle.dxf);
  EXPECT_TRUE(dxf.layerColors.count("SEAL_BAND"));
  EXPECT_EQ(std::count_if(dxf.paths.begin(), dxf.paths.end(), [](const ReadPath& p) { return p.layer == "SEAL_BAND"; }),
            int(pattern.panels.size()));
  EXPECT_NE(bundle.pdf.find("h f*"), std::string::npos);  // the band filled even-odd on the printed tiles
  const json stats = json::parse(bundle.statistics);
  EXPECT_EQ(stats["joining"], "sealed");
  // A sewn pattern keeps its sewing line and has no band.
  const ExportBundle sewn = exportPattern(pattern, ExportOptions{});
  EXPECT_EQ(sewn.svg.find("seal-band"), std::string::npos);
  EXPECT_EQ(json::parse(sewn.statistics)["joining"], "sewn");
  EXPECT_EQ(sewn.pdf.find("h f*"), std::string::npos);
}

TEST(FillValve, GapAtTheSamePlaceOnBothPiecesAsWideAsAsked) {
  const Pattern pattern = mylar();
  for (const double at : {0.1, 0.5, 0.85}) {
    ExportOptions o = sealed(6);
    o.valves = {{0, at, 25}};
    const SheetLayout layout = layoutSheet(pattern, o);
    ASSERT_EQ(layout.outlines.seams.size(), 1u);
    const Seam& seam = layout.outlines.seams[0];
    ASSERT_EQ(layout.valveGaps.size(), 2u);
    double centres[2];
    int k = 0;
    for (const ValveGap& gap : layout.valveGaps) {
      const SeamSide& side = gap.panel == seam.a.panel ? seam.a : seam.b;
      const PanelLayout& pl = layout.panels[gap.panel];
      // The mark starts and ends on the sealing line, 25 mm apart along it, and reaches the cut line.
      const Polygon2& mark = gap.mark;
      const size_t half = mark.size() / 2;
      double along = 0;
      for (size_t i = 0; i + 1 < half; ++i) along += (mark[i + 1] - mark[i]).norm();
      EXPECT_NEAR(along, 25.0, 0.5) << "at " << at;
      EXPECT_LT(distanceToBoundary(mark.front(), pl.sew), 1e-6);
      EXPECT_LT(distanceToBoundary(mark[half - 1], pl.sew), 1e-6);
      EXPECT_NEAR(distanceToBoundary(mark.back(), pl.cut), 0.0, 0.1);
      // Where along its side of the seam the gap's middle sits, as a share of the side.
      const SidePoint start = pointAlongSide(pattern, layout.outlines, side, 0);
      double s = arcOf(pl.sew, 0.5 * (mark[half / 2] + mark[(half - 1) / 2])) - arcOf(pl.sew, 1000 * start.point);
      const double perimeter = 1000 * side.length;
      s = std::fmod(s + perimeter, perimeter);
      if (!side.forward) s = std::fmod(perimeter - s, perimeter);
      centres[k++] = s / perimeter;
    }
    EXPECT_NEAR(centres[0], at, 0.01);
    EXPECT_NEAR(centres[1], at, 0.01);
    const ExportBundle bundle = exportPattern(pattern, o);
    const std::vector<ReadPath> svg = readSvgPaths(bundle.svg);
    EXPECT_EQ(std::count_if(svg.begin(), svg.end(), [](const ReadPath& p) { return p.layer == "valves"; }), 2);
    EXPECT_NE(bundle.svg.find("valve 25 mm"), std::string::npos);
    EXPECT_EQ(bundle.valveMarks[0].size() + bundle.valveMarks[1].size(), 2u);
    const json stats = json::parse(bundle.statistics);
    EXPECT_TRUE(stats["valves"][0]["placed"].get<bool>());
  }
}

TEST(FillValve, AValveOnASeamThatIsGoneIsReportedNotDrawn) {
  ExportOptions o = sealed(5);
  o.valves = {{7, 0.5, 20}};
  const ExportBundle bundle = exportPattern(mylar(), o);
  const json stats = json::parse(bundle.statistics);
  ASSERT_EQ(stats["valves"].size(), 1u);
  EXPECT_FALSE(stats["valves"][0]["placed"].get<bool>());
  EXPECT_EQ(stats["valves"][0]["label"], "S8");
  EXPECT_EQ(bundle.svg.find("id=\"valves\""), std::string::npos);
}

TEST(FillValve, JsonJoiningAndValvesAreReadAndCheckedWithAMessage) {
  const ExportOptions o = readExportOptionsJson(
      json::parse(R"({"joining": "sealed", "allowance": 4, "valves": [{"seam": 2, "at": 0.25, "width": 18}]})"));
  EXPECT_TRUE(o.sealed);
  ASSERT_EQ(o.valves.size(), 1u);
  EXPECT_EQ(o.valves[0].seam, 2);
  EXPECT_DOUBLE_EQ(o.valves[0].at, 0.25);
  EXPECT_DOUBLE_EQ(o.valves[0].width, 18);
  EXPECT_FALSE(readExportOptionsJson(json::parse(R"({"joining": "sewn"})")).sealed);
  const auto refused = [](const char* text, const char* words) {
    try {
      readExportOptionsJson(json::parse(text));
      ADD_FAILURE() << text << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code, "export.bad-value");
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused(R"({"joining": "glued"})", "sewn");
  refused(R"({"valves": {"seam": 1}})", "list");
  refused(R"({"valves": [{"at": 0.5}]})", "names no seam");
  refused(R"({"valves": [{"seam": 1, "at": 1.5}]})", "S2");
  refused(R"({"valves": [{"seam": 0, "width": 0}]})", "wider than 0");
}

TEST(CliExport, SealedAndValveOptions) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  const std::string pattern = testing::TempDir() + "billow-seal-mylar.json";
  std::ofstream(pattern) << writePatternJson(mylar());
  const std::string dir = testing::TempDir() + "billow-seal-out";
  std::string out;
  ASSERT_EQ(test::runCapture(test::cliPath() + " export " + pattern + " --out-dir " + dir +
                                 " --sealed --allowance 4 --valve S1=22@0.3",
                             out),
            0)
      << out;
  const json stats = json::parse(readFileBytes(dir + "/stats.json"));
  EXPECT_EQ(stats["joining"], "sealed");
  EXPECT_EQ(stats["allowance_mm"], 4.0);
  ASSERT_EQ(stats["valves"].size(), 1u);
  EXPECT_EQ(stats["valves"][0]["seam"], 0);
  EXPECT_DOUBLE_EQ(stats["valves"][0]["at"].get<double>(), 0.3);
  EXPECT_EQ(stats["valves"][0]["width_mm"], 22.0);
  EXPECT_TRUE(stats["valves"][0]["placed"].get<bool>());
  EXPECT_NE(readFileBytes(dir + "/pattern.svg").find("valve 22 mm"), std::string::npos);
  const auto refused = [&](const std::string& options, const std::string& words) {
    std::string output;
    EXPECT_EQ(test::runCapture(test::cliPath() + " export " + pattern + " --out-dir " + dir + " " + options, output), 1)
        << options;
    EXPECT_NE(output.find(words), std::string::npos) << options << ": " << output;
  };
  refused("--valve S1", "needs SEAM=MM");
  refused("--valve S1=wide", "a length in mm");
  refused("--valve S1=20@2", "from 0 to 1");
  refused("--valve S0=20", "its label S1, S2");
  refused("--valve S1=300", "at most 200 mm");
#endif
}
