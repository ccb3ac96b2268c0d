// Pattern files: exact round trip, every error with its code, warnings for unequal seams, sewing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/pattern_json.hpp"
#include "simulate/example_patterns.hpp"
#include "simulate/sewn_pattern.hpp"
#include "util/error.hpp"

using namespace billow;
using nlohmann::json;

namespace {

// Two triangles sewn at their three corners: the smallest closed pattern.
json tinyPattern() {
  return json::parse(R"({
    "format": "billow-pattern", "version": 1, "units": "m", "pressure": 1000.0,
    "material": { "name": "foil", "thickness": 2.5e-5, "youngs_modulus": 3.0e9 },
    "panels": [
      { "name": "front", "internal": false, "vertices": [[0, 0], [0.1, 0], [0, 0.1]], "triangles": [[0, 1, 2]] },
      { "name": "back", "internal": false, "vertices": [[0, 0], [0.1, 0], [0, -0.1]], "triangles": [[0, 2, 1]] } ],
    "stitches": [[0, 0, 1, 0], [0, 1, 1, 1], [0, 2, 1, 2]],
    "a-field-from-the-future": { "ignored": true } })");
}

// The error reading j gives ("no error" as its code when there is none).
Error errorOf(const json& j) {
  try {
    readPatternJson(j.dump());
  } catch (const Error& e) {
    return e;
  }
  return Error("no error", "");
}

std::string codeOf(const json& j) { return errorOf(j).code; }

}  // namespace

TEST(PatternJson, ReadsTheTinyPatternAndIgnoresUnknownFields) {
  std::vector<PatternWarning> warnings;
  const Pattern p = readPatternJson(tinyPattern().dump(), &warnings);
  ASSERT_EQ(p.panels.size(), 2u);
  EXPECT_EQ(p.panels[0].name, "front");
  EXPECT_EQ(p.stitches.size(), 3u);
  EXPECT_DOUBLE_EQ(p.material.youngsModulus, 3e9);
  EXPECT_TRUE(warnings.empty());
  const SewnMesh m = sewPattern(p);
  EXPECT_EQ(m.numVertices, 3);
  EXPECT_EQ(m.simVertex(0, 2), m.simVertex(1, 2));
}

TEST(PatternJson, RoundTripIsExact) {
  ExampleOptions eo;
  eo.triangles = 300;
  for (const std::string& name : exampleNames()) {
    Pattern p = examplePattern(name, eo);
    p.material.density = 1390;
    p.panels[0].seamCorners = seamCorners(sewPattern(p), 0);  // marked (perhaps none); the others not
    p.pressure = 1234.5678901234567;
    const std::string text = writePatternJson(p);
    const Pattern q = readPatternJson(text);
    EXPECT_EQ(writePatternJson(q), text) << name;
    ASSERT_EQ(q.panels.size(), p.panels.size());
    for (size_t i = 0; i < p.panels.size(); ++i) {
      EXPECT_TRUE(q.panels[i].vertices == p.panels[i].vertices) << name;  // bitwise equal doubles
      EXPECT_TRUE(q.panels[i].triangles == p.panels[i].triangles) << name;
      EXPECT_EQ(q.panels[i].seamCorners, p.panels[i].seamCorners) << name;
    }
    EXPECT_EQ(q.pressure, p.pressure);
    EXPECT_EQ(q.material.density, 1390);
  }
}

TEST(PatternJson, InflatedStartAndUnitsAreRead) {
  json j = tinyPattern();
  j["units"] = "mm";
  j["inflated"] = {{{0, 0, 1}, {100, 0, 0}, {0, 100, 0}}, {{0, 0, -1}, {100, 0, 0}, {0, 100, 0}}};
  const Pattern p = readPatternJson(j.dump());
  EXPECT_DOUBLE_EQ(p.panels[0].vertices(1, 0), 1e-4);
  ASSERT_EQ(p.inflated.size(), 2u);
  EXPECT_DOUBLE_EQ(p.inflated[0](1, 0), 0.1);
}

TEST(PatternJson, EveryErrorHasItsCode) {
  EXPECT_EQ(codeOf(json::parse("[1, 2]")), "pattern.unknown-format");
  json j = tinyPattern();
  j["format"] = "something-else";
  EXPECT_EQ(codeOf(j), "pattern.unknown-format");
  j = tinyPattern();
  j["version"] = 2;
  EXPECT_EQ(codeOf(j), "pattern.version");
  j = tinyPattern();
  j["panels"][0]["triangles"][0][2] = 7;
  EXPECT_EQ(codeOf(j), "pattern.bad-index");
  j = tinyPattern();
  j["panels"][0]["triangles"][0][2] = -1;
  EXPECT_EQ(codeOf(j), "pattern.bad-index");
  j = tinyPattern();
  j["stitches"][1] = {0, 1, 5, 1};
  EXPECT_EQ(codeOf(j), "pattern.bad-index");
  j = tinyPattern();
  j["panels"][0]["seam_corners"] = {1, 3};  // the panel has three vertices
  EXPECT_EQ(codeOf(j), "pattern.bad-index");
  EXPECT_NE(std::string(errorOf(j).what()).find("seam corner"), std::string::npos) << errorOf(j).what();
  j["panels"][0]["seam_corners"] = {0.5};
  EXPECT_EQ(codeOf(j), "pattern.bad-index");
  j["panels"][0]["seam_corners"] = 1;
  EXPECT_EQ(codeOf(j), "pattern.bad-value");
  j["panels"][0]["seam_corners"] = {1};
  EXPECT_EQ(codeOf(j), "no error");
  j = tinyPattern();
  j["stitches"].erase(2);
  EXPECT_EQ(codeOf(j), "pattern.open");
  j = tinyPattern();
  j["panels"][0]["vertices"][2] = {0.2, 0};  // collinear: zero area
  EXPECT_EQ(codeOf(j), "pattern.degenerate");
  j = tinyPattern();
  j["panels"][0]["triangles"][0] = {0, 2, 1};  // clockwise
  EXPECT_EQ(codeOf(j), "pattern.degenerate");
  j = tinyPattern();
  j["material"]["thickness"] = -1;
  EXPECT_EQ(codeOf(j), "pattern.bad-value");
  j = tinyPattern();
  j.erase("pressure");
  EXPECT_EQ(codeOf(j), "pattern.bad-value");
  j = tinyPattern();
  j["panels"][1]["vertices"][0] = {"x", 0};
  EXPECT_EQ(codeOf(j), "pattern.bad-value");
  EXPECT_EQ(codeOf(json::parse("{\"format\": \"billow-pattern\", \"version\": 1}")), "pattern.bad-value");
  try {
    readPatternJson("{ not json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "pattern.json");
  }
  PatternLimits small;
  small.maxTriangles = 1;
  try {
    readPatternJson(tinyPattern().dump(), nullptr, small);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "pattern.too-large");
  }
}

TEST(PatternJson, SewingErrorsSayWhichPanelAndVertex) {
  // The front's corners 0 and 1 both sewn to the back's corner 0: its triangle has two corners sewn together.
  json j = tinyPattern();
  j["stitches"] = json::parse("[[0, 0, 1, 0], [0, 1, 1, 0], [0, 2, 1, 2], [0, 1, 1, 1]]");
  const Error sewnTogether = errorOf(j);
  EXPECT_EQ(sewnTogether.code, "pattern.degenerate");
  EXPECT_EQ(sewnTogether.panel, 0);
  EXPECT_EQ(sewnTogether.vertex, 0);
  // An edge sewn to nothing: its panel and one of its ends.
  j = tinyPattern();
  j["stitches"].erase(2);
  const Error open = errorOf(j);
  EXPECT_EQ(open.code, "pattern.open");
  EXPECT_GE(open.panel, 0);
  EXPECT_LT(open.panel, 2);
  EXPECT_GE(open.vertex, 0);
  EXPECT_LT(open.vertex, 3);
}

TEST(PatternJson, StitchesMustJoinBoundaryVertices) {
  ExampleOptions eo;
  eo.triangles = 32;  // pillow: 2 x 2 cells per side, vertex 4 is inside the panel
  Pattern p = examplePattern("pillow", eo);
  ASSERT_EQ(p.panels[0].vertices.rows(), 9);
  p.stitches.push_back({0, 4, 1, 4});
  try {
    sewPattern(p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "pattern.not-boundary");
  }
}

TEST(PatternJson, UnequalSeamsAreWarnedAboutNotRejected) {
  json j = tinyPattern();
  j["panels"][1]["vertices"][1] = {0.11, 0};  // the back's bottom edge is 10 % longer
  std::vector<PatternWarning> warnings;
  readPatternJson(j.dump(), &warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_EQ(warnings[0].code, "pattern.seam-length");
  EXPECT_NEAR(warnings[0].mismatch, 0.01 / 0.11, 1e-3);
}

TEST(PatternJson, ExamplesSewIntoClosedSurfacesOfAboutTheRequestedSize) {
  for (const std::string name : {"mylar", "pillow", "sphere3"}) {
    for (int n : {700, 3000}) {
      ExampleOptions eo;
      eo.triangles = n;
      const SewnMesh m = sewPattern(examplePattern(name, eo));
      EXPECT_NEAR(m.numTriangles(), n, 0.25 * n) << name;
      EXPECT_TRUE(m.warnings.empty()) << name << ": " << m.warnings[0].message;
      // Closed genus-0 surface: V - E + F = 2 with E = 3F/2.
      EXPECT_EQ(m.numVertices - m.numTriangles() / 2, 2) << name;
      // Well-shaped: the smallest angle stays reasonable.
      double minSine = 1;
      for (const ElementRest& r : m.rest) {
        const Eigen::Matrix2d Dm = r.DmInv.inverse();
        const double a = Dm.col(0).norm(), b = Dm.col(1).norm(), c = (Dm.col(1) - Dm.col(0)).norm();
        const double twiceArea = 2 * r.area;
        minSine = std::min({minSine, twiceArea / (a * b), twiceArea / (b * c), twiceArea / (a * c)});
      }
      EXPECT_GT(minSine, std::sin(15 * M_PI / 180)) << name;
    }
  }
}

TEST(PatternJson, LongPillowsHaveTheirAspectAndSquareCells) {
  for (const double aspect : {4.0, 10.0, 20.0}) {
    ExampleOptions eo;
    eo.triangles = 4000;
    eo.size = 0.1;
    eo.aspect = aspect;
    const Pattern p = examplePattern("pillow", eo);
    const Eigen::Vector2d size = p.panels[0].vertices.colwise().maxCoeff() - p.panels[0].vertices.colwise().minCoeff();
    EXPECT_NEAR(size.x(), 0.1, 1e-12);
    EXPECT_NEAR(size.y(), aspect * 0.1, 1e-12);
    const SewnMesh m = sewPattern(p);
    // About the count: both cell counts are even (a diagonal through every corner), so a narrow pillow of
    // few cells across rounds it by up to a third.
    EXPECT_NEAR(m.numTriangles(), 4000, 0.35 * 4000) << aspect;
    EXPECT_EQ(m.numVertices - m.numTriangles() / 2, 2) << aspect;
    // Square cells.
    const Eigen::Vector2d a = p.panels[0].vertices.row(1), b = p.panels[0].vertices.row(0);
    const double across = (a - b).norm();
    const int nx = int(std::lround(0.1 / across));
    const double along = (Eigen::Vector2d(p.panels[0].vertices.row(nx + 1)) - b).norm();
    EXPECT_NEAR(along / across, 1.0, 0.05) << aspect;
  }
  ExampleOptions bad;
  bad.aspect = 0.5;
  EXPECT_THROW(examplePattern("pillow", bad), Error);
}
