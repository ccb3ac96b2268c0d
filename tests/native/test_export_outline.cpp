// Outlines and seams: loops are counterclockwise, seam ids are shared by both panels, runs break where the
// partner panel changes, free edges stay free, lengths and mismatch are measured.
#include <gtest/gtest.h>

#include "export/outline.hpp"
#include "simulate/example_patterns.hpp"
#include "util/error.hpp"

using namespace billow;

namespace {

ExampleOptions small() {
  ExampleOptions o;
  o.triangles = 400;
  return o;
}

// Every seam's edges carry its id on side a (and on side b when shared), and sides have equal edge counts.
void expectConsistent(const Pattern& p, const Outlines& out) {
  for (size_t k = 0; k < p.panels.size(); ++k) EXPECT_GT(signedArea(out.panels[k].points(p.panels[k])), 0);
  for (const Seam& s : out.seams) {
    ASSERT_EQ(s.a.edges.size(), s.b.edges.size());
    for (int e : s.a.edges) EXPECT_EQ(out.panels[s.a.panel].edgeSeam[e], s.id);
    if (s.shared) {
      for (int e : s.b.edges) EXPECT_EQ(out.panels[s.b.panel].edgeSeam[e], s.id);
    }
  }
}

}  // namespace

TEST(ExportOutline, MylarIsOneClosedSeam) {
  const Pattern p = examplePattern("mylar", small());
  const Outlines out = buildOutlines(p);
  expectConsistent(p, out);
  ASSERT_EQ(out.seams.size(), 1u);
  EXPECT_TRUE(out.seams[0].closed);
  EXPECT_TRUE(out.seams[0].shared);
  EXPECT_FALSE(out.seams[0].b.forward);  // the back is mirrored: it runs the other way round its loop
  EXPECT_NEAR(out.seams[0].a.length, out.seams[0].b.length, 1e-12);
  EXPECT_LT(out.maxMismatch, 1e-12);
  for (const PanelOutline& po : out.panels)
    for (int id : po.edgeSeam) EXPECT_EQ(id, 0);
}

TEST(ExportOutline, Sphere3HasThreeSharedSeamsBetweenGores) {
  const Pattern p = examplePattern("sphere3", small());
  const Outlines out = buildOutlines(p);
  expectConsistent(p, out);
  ASSERT_EQ(out.seams.size(), 3u);
  for (const Seam& s : out.seams) {
    EXPECT_FALSE(s.closed);
    EXPECT_TRUE(s.shared);
    EXPECT_NE(s.a.panel, s.b.panel);
    EXPECT_NEAR(s.a.length, s.b.length, 1e-9);
    // Each gore is sewn along both of its sides: each side is half its outline.
    EXPECT_NEAR(2 * s.a.length, perimeter(out.panels[s.a.panel].points(p.panels[s.a.panel])), 1e-9);
  }
  for (const PanelOutline& po : out.panels)
    for (int id : po.edgeSeam) EXPECT_GE(id, 0);  // a closed sphere has no free edge
}

TEST(ExportOutline, InternalPanelOnASeamGetsItsOwnSeams) {
  const Pattern p = examplePattern("sphere3-internal", small());
  const Outlines out = buildOutlines(p);
  expectConsistent(p, out);
  ASSERT_EQ(out.seams.size(), 5u);
  int internalSeams = 0;
  for (const Seam& s : out.seams) {
    if (s.a.panel != 3) continue;
    ++internalSeams;
    EXPECT_FALSE(s.shared);
    EXPECT_GT(s.mismatch(), 0.01);
  }
  EXPECT_EQ(internalSeams, 2);
  EXPECT_GT(out.maxMismatch, 0.01);
}

TEST(ExportOutline, UnstitchedSideIsAFreeEdgeAndSeamsBreakThere) {
  Pattern p = examplePattern("pillow", small());
  // Unpick the stitches of the top side (y = +size/2): that side becomes an opening.
  std::vector<Stitch> kept;
  for (const Stitch& s : p.stitches)
    if (p.panels[0].vertices(s.vertexA, 1) < 0.15 - 1e-9) kept.push_back(s);
  p.stitches = kept;
  const Outlines out = buildOutlines(p);
  expectConsistent(p, out);
  ASSERT_EQ(out.seams.size(), 1u);
  EXPECT_FALSE(out.seams[0].closed);
  // Three sides of 0.3 m, less the last edge of each side next to the unpicked corners.
  EXPECT_GT(out.seams[0].a.length, 0.8);
  EXPECT_LT(out.seams[0].a.length, 0.9 - 1e-3);
  EXPECT_EQ(out.seams[0].mismatch(), 0);
  int free = 0;
  for (int id : out.panels[0].edgeSeam) free += id < 0;
  EXPECT_GT(free, 0);
  // The loop starts at a junction: edge 0 and the last edge belong to different runs.
  EXPECT_NE(out.panels[0].edgeSeam.front(), out.panels[0].edgeSeam.back());
}

TEST(ExportOutline, ConeSewnToItselfFoldsAtTheApex) {
  // A fan (sector) whose two straight sides are sewn together: a cone, one panel, one seam onto itself.
  Pattern p;
  Panel fan;
  fan.name = "cone";
  const int n = 8;
  fan.vertices.resize(2 * n + 2, 2);
  fan.vertices.row(0) << 0, 0;
  for (int k = 0; k <= 2 * n; ++k) {
    const double a = M_PI / 2 * k / (2 * n), r = 0.2;
    fan.vertices.row(k + 1) << r * std::cos(a), r * std::sin(a);
  }
  // Rows of the fan: centre 0, rim 1..2n+1. Add intermediate points on the two straight sides.
  fan.triangles.resize(2 * n, 3);
  for (int k = 0; k < 2 * n; ++k) fan.triangles.row(k) << 0, k + 1, k + 2;
  p.panels.push_back(fan);
  p.stitches.push_back({0, 1, 0, 2 * n + 1});  // the two rim ends meet; with the apex: two sides sewn
  const Outlines out = buildOutlines(p);
  ASSERT_EQ(out.seams.size(), 1u);
  EXPECT_EQ(out.seams[0].a.panel, 0);
  EXPECT_EQ(out.seams[0].b.panel, 0);
  EXPECT_EQ(out.seams[0].a.edges.size(), 1u);
  EXPECT_NE(out.seams[0].a.edges[0], out.seams[0].b.edges[0]);
  EXPECT_NEAR(out.seams[0].a.length, 0.2, 1e-12);
}

TEST(ExportOutline, PanelWithAHoleIsRefused) {
  Pattern p;
  Panel ring;
  ring.name = "washer";
  ring.vertices.resize(8, 2);
  ring.vertices << -2, -2, 2, -2, 2, 2, -2, 2, -1, -1, 1, -1, 1, 1, -1, 1;
  ring.triangles.resize(8, 3);
  ring.triangles << 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7;
  p.panels.push_back(ring);
  try {
    buildOutlines(p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "export.panel-shape");
  }
}
