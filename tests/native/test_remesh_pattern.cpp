// Remeshing during optimization (pattern/remesh_pattern.hpp, paper Sec. 5.3): every panel is meshed again
// from its current outline, seams keep matching samples on both sides, no panel is lost, the panels stay
// disks without flipped triangles, and the target and inflated positions come over.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "io/mesh_file.hpp"
#include "panel_checks.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/remesh_pattern.hpp"
#include "simulate/sewn_pattern.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;
using billow::test::dataPath;
using billow::test::examplesDir;
using billow::test::expectDisk;
using billow::test::panelArea;
using billow::test::signedArea;

namespace {

// The 0.5 m sphere cut into three gores (pole to pole); `connect`: an internal panel between seams 0 and 1.
BuiltPattern gores(bool connect, int triangles = 1500) {
  const std::string path = dataPath("sphere-gores.billow.json");
  const auto scene = makeDesignScene(readDesignJson(readFileBytes(path)), path, {examplesDir()});
  PatternBuildOptions o;
  o.triangles = triangles;
  if (connect) o.connections = {{0, 1}};
  for (const DesignSeam& s : scene->design.seams) o.seamNames.push_back(s.name);
  return buildPattern(scene->target, scene->segmentation, o);
}

// Distance from point q to the closed polygon through the panel's boundary rows 0..n-1.
double distanceToOutline(const Panel& p, int n, const Eigen::Vector2d& q) {
  double best = INFINITY;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = p.vertices.row(i), b = p.vertices.row((i + 1) % n);
    const double t = std::clamp((q - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-30), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - q).norm());
  }
  return best;
}

// Checks shared by the tests: same panels, disks with boundary rows first and no flip, pieces of equal
// counts on both sides, stitched samples at one target point, the outline and area kept.
void expectGoodRemesh(const BuiltPattern& before, const RemeshedPattern& after, double h) {
  const Pattern& p0 = before.pattern;
  const Pattern& p1 = after.built.pattern;
  ASSERT_EQ(p1.panels.size(), p0.panels.size());
  ASSERT_EQ(after.built.panels.size(), before.panels.size());
  ASSERT_EQ(after.inflated.size(), p1.panels.size());
  for (size_t p = 0; p < p1.panels.size(); ++p) {
    SCOPED_TRACE("panel " + std::to_string(p + 1));
    const Panel& panel = p1.panels[p];
    const BuiltPanel& bp = after.built.panels[p];
    EXPECT_EQ(panel.internal, p0.panels[p].internal);
    ASSERT_EQ(after.inflated[p].rows(), panel.vertices.rows());
    ASSERT_EQ(bp.targetPosition.rows(), panel.vertices.rows());
    ASSERT_EQ(bp.seam.size(), size_t(panel.vertices.rows()));
    // A disk whose boundary is exactly the rows 0..n-1, without flipped triangles.
    expectDisk(panel, bp.boundaryVertices);
    for (int t = 0; t < panel.triangles.rows(); ++t)
      EXPECT_GT(signedArea(panel, t), 0) << "triangle " << t << " is flipped or degenerate";
    // The outline is the old one, resampled: every new boundary point lies on it; the area barely changes.
    const Panel& old = p0.panels[p];
    for (int v = 0; v < bp.boundaryVertices; ++v)
      EXPECT_LT(distanceToOutline(old, before.panels[p].boundaryVertices, panel.vertices.row(v).transpose()), 1e-9);
    EXPECT_NEAR(panelArea(panel) / panelArea(old), 1, 0.01);
    // Edges near h (the refinement bound is 1.25 h inside; the boundary is cut at about h).
    for (int t = 0; t < panel.triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k)
        EXPECT_LT(
            (panel.vertices.row(panel.triangles(t, k)) - panel.vertices.row(panel.triangles(t, (k + 1) % 3))).norm(),
            2 * h);
    // Pieces: the same partners, as many samples as the partner's, corners where pieces start.
    ASSERT_EQ(bp.pieces.size(), before.panels[p].pieces.size());
    for (const PanelPiece& piece : bp.pieces) {
      EXPECT_TRUE(bp.corner[piece.rows.front()]);
      if (piece.neighborPanel < 0) continue;
      const PanelPiece& partner = after.built.panels[piece.neighborPanel].pieces[piece.neighborPiece];
      EXPECT_EQ(piece.rows.size(), partner.rows.size());
    }
  }
  // Stitched panel vertices are one point on the target (the seam sampled at the same arc length).
  ASSERT_FALSE(p1.stitches.empty());
  for (const Stitch& s : p1.stitches) {
    const Eigen::Vector3d a = after.built.panels[s.panelA].targetPosition.row(s.vertexA);
    const Eigen::Vector3d b = after.built.panels[s.panelB].targetPosition.row(s.vertexB);
    EXPECT_LT((a - b).norm(), 0.1 * h);
  }
  // It sews into one closed outer surface (sewPattern validates that).
  EXPECT_NO_THROW(sewPattern(p1));
}

}  // namespace

TEST(RemeshPattern, MinimumAngle) {
  Pattern p;
  Panel panel;
  panel.vertices.resize(3, 2);
  panel.vertices << 0, 0, 1, 0, 0, 1;
  panel.triangles.resize(1, 3);
  panel.triangles << 0, 1, 2;
  p.panels.push_back(panel);
  EXPECT_NEAR(minPanelAngleDeg(p), 45, 1e-9);
  p.panels[0].vertices.row(2) << 0.5, 0.01;
  EXPECT_NEAR(minPanelAngleDeg(p), std::atan(0.02) * 180 / M_PI, 1e-6);
}

TEST(RemeshPattern, GoresFinerAndCoarserKeepSeamsAndPanels) {
  const BuiltPattern built = gores(false);
  ASSERT_TRUE(built.ok());
  const double h = built.figures.edgeLength;
  for (const double factor : {0.7, 1.5}) {
    SCOPED_TRACE("h x " + std::to_string(factor));
    const RemeshedPattern r = remeshPattern(built, built.pattern.inflated, factor * h);
    expectGoodRemesh(built, r, factor * h);
    // Triangle count goes as 1 / h^2.
    const double ratio = double(r.built.figures.triangles) / built.figures.triangles;
    EXPECT_NEAR(ratio * factor * factor, 1, 0.25);
    // The carried target positions of inside vertices lie on the 0.5 m sphere (chords of h: within h^2 / R).
    for (const Vertices& x : r.inflated)
      for (int v = 0; v < x.rows(); ++v) EXPECT_NEAR(x.row(v).norm(), 0.25, factor * factor * h * h / 0.25 + 1e-3);
  }
}

TEST(RemeshPattern, PanelsMovedByTheOptimizerAreMeshedFromTheirNewOutline) {
  BuiltPattern built = gores(false);
  const double h = built.figures.edgeLength;
  // As optimization steps do: every panel grows a little (seams keep equal lengths on both sides) and its
  // inside vertices slide, so its triangles degrade.
  for (size_t p = 0; p < built.pattern.panels.size(); ++p) {
    Panel& panel = built.pattern.panels[p];
    panel.vertices *= 1.03;
    for (int v = built.panels[p].boundaryVertices; v < panel.vertices.rows(); ++v)
      panel.vertices(v, 0) += 0.35 * h * std::sin(panel.vertices(v, 1) / h);
  }
  const double before = minPanelAngleDeg(built.pattern);
  const RemeshedPattern r = remeshPattern(built, built.pattern.inflated, h);
  expectGoodRemesh(built, r, h);
  EXPECT_GT(minPanelAngleDeg(r.built.pattern), before) << "remeshing restores the triangles' quality";
  EXPECT_GT(minPanelAngleDeg(r.built.pattern), 15);
}

// The seam corners a pattern marks (the optimizer's: the seam rods it optimized with) stay where they were on the
// outline, at the nearest new outline vertex; a pattern that marks none still marks none.
TEST(RemeshPattern, MarkedSeamCornersStayWhereTheyWere) {
  BuiltPattern built = gores(false);
  const double h = built.figures.edgeLength;
  EXPECT_FALSE(remeshPattern(built, built.pattern.inflated, h).built.pattern.panels[0].seamCorners);
  const SewnMesh sewn = sewPattern(built.pattern);
  for (size_t p = 0; p < built.pattern.panels.size(); ++p) {
    Panel& panel = built.pattern.panels[p];
    panel.seamCorners = seamCorners(sewn, int(p));
    const std::vector<int> outline = outlineVertices(panel);
    for (size_t k = 3; k < outline.size(); k += 7) panel.seamCorners->push_back(outline[k]);
  }
  for (const double factor : {0.7, 1.5}) {
    SCOPED_TRACE("h x " + std::to_string(factor));
    const RemeshedPattern r = remeshPattern(built, built.pattern.inflated, factor * h);
    for (size_t p = 0; p < built.pattern.panels.size(); ++p) {
      const Panel &before = built.pattern.panels[p], &after = r.built.pattern.panels[p];
      ASSERT_TRUE(after.seamCorners);
      EXPECT_GE(after.seamCorners->size(), before.seamCorners->size() / 2);
      EXPECT_LE(after.seamCorners->size(), before.seamCorners->size());
      const auto nearest = [](const Panel& from, int v, const Panel& to) {
        double d = INFINITY;
        for (int u : *to.seamCorners) d = std::min(d, (to.vertices.row(u) - from.vertices.row(v)).norm());
        return d;
      };
      const std::vector<int> outline = outlineVertices(after);
      for (int v : *after.seamCorners) {
        EXPECT_TRUE(std::binary_search(outline.begin(), outline.end(), v)) << "on the outline";
        EXPECT_LT(nearest(after, v, before), std::max(1.0, factor) * h);
      }
      for (int v : *before.seamCorners) EXPECT_LT(nearest(before, v, after), std::max(1.0, factor) * h);
    }
  }
}

TEST(RemeshPattern, InternalPanelsStaySewnToBothSeams) {
  const BuiltPattern built = gores(true);
  ASSERT_TRUE(built.ok());
  ASSERT_EQ(built.figures.internalPanels, 1);
  const RemeshedPattern r = remeshPattern(built, built.pattern.inflated, built.figures.edgeLength);
  expectGoodRemesh(built, r, built.figures.edgeLength);
  // The internal panel's seam samples are sewn to the outer panels' samples on both seams.
  int internal = -1;
  for (size_t p = 0; p < r.built.pattern.panels.size(); ++p)
    if (r.built.pattern.panels[p].internal) internal = int(p);
  ASSERT_GE(internal, 0);
  std::set<int> sewnTo;
  for (const Stitch& s : r.built.pattern.stitches) {
    if (s.panelA == internal) sewnTo.insert(s.panelB);
    if (s.panelB == internal) sewnTo.insert(s.panelA);
  }
  EXPECT_GE(sewnTo.size(), 2u);
}

TEST(RemeshPattern, AFoldedOutlineIsRefusedWithAMessage) {
  BuiltPattern built = gores(false);
  Panel& panel = built.pattern.panels[0];
  const int n = built.panels[0].boundaryVertices;
  // Mirror half of the boundary across the panel's middle: the outline crosses itself.
  const double mid = 0.5 * (panel.vertices.col(0).minCoeff() + panel.vertices.col(0).maxCoeff());
  for (int v = 0; v < n / 3; ++v) panel.vertices(v, 0) = 2 * mid - panel.vertices(v, 0);
  try {
    remeshPattern(built, built.pattern.inflated, built.figures.edgeLength);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "pattern.remesh-failed");
    EXPECT_NE(std::string(e.what()).find("Panel 1"), std::string::npos) << e.what();
  }
}
