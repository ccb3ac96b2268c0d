// Thin handles (suggest/thin_handles.hpp): a tube too thin for a panel to follow is found by the loop around it, and
// cut through: the target stays one closed surface, a handle fewer, every face where it was; a thick handle is left.
#include <gtest/gtest.h>

#include "handle_shapes.hpp"
#include "io/design_json.hpp"
#include "mesh/validate.hpp"
#include "pattern/design_scene.hpp"
#include "suggest/thin_handles.hpp"
#include "test_support.hpp"

using namespace billow;
using billow::test::ringMesh;
using billow::test::twoHoledSlab;

namespace {

// The target as the app takes it: checked (and turned outward where it was inside out).
TriMesh checkedTarget(TriMesh m) {
  const ValidationReport report = validateTarget(m);
  EXPECT_TRUE(report.ok);
  return m;
}

}  // namespace

TEST(ThinHandles, AThinRingsTubeIsFoundByTheLoopAroundIt) {
  const TriMesh ring = checkedTarget(ringMesh(1.0, 0.03, 120, 16));
  const std::vector<ThinHandle> handles = thinHandles(ring);
  ASSERT_EQ(handles.size(), 1u);
  // Round the tube, not round the hole: 2 pi r, as the 16-gon's perimeter gives it.
  EXPECT_NEAR(handles[0].length, 2 * 16 * 0.03 * std::sin(test::kPi / 16), 1e-9);
  EXPECT_EQ(handles[0].loop.size(), 16u);
}

TEST(ThinHandles, AThickHandleIsNotThin) {
  EXPECT_TRUE(thinHandles(checkedTarget(ringMesh(1.0, 0.4, 60, 24))).empty());  // its tube 2.5 m around, 3.8 m across
  EXPECT_TRUE(thinHandles(checkedTarget(twoHoledSlab())).empty());              // bars 4 of 23.6 quarter-cubes around
  // A shape without handles has none.
  EXPECT_TRUE(thinHandles(checkedTarget(test::loadShared("sphere.obj"))).empty());
}

TEST(ThinHandles, CuttingAThinRingLeavesOneClosedSurfaceWithEveryFaceWhereItWas) {
  TriMesh ring = checkedTarget(ringMesh(1.0, 0.03, 120, 16));
  const TriMesh before = ring;
  const std::vector<ThinHandle> handles = thinHandles(ring);
  ASSERT_EQ(handles.size(), 1u);
  cutThinHandles(ring, handles);
  // Two ends of 16 triangles each, around a new vertex in their middle; a copy of each loop vertex.
  EXPECT_EQ(ring.numTriangles(), before.numTriangles() + 32);
  EXPECT_EQ(ring.numVertices(), before.numVertices() + 16 + 2);
  const ValidationReport report = test::expectClosedSurface(ring, 0);
  EXPECT_GT(report.stats.volume, 0.9 * 2 * test::kPi * test::kPi * 1.0 * 0.03 * 0.03);
  // Every face keeps its index and its place: its corners move by at most 0.3 of their longest edge (the loop's,
  // drawn back), the diagonal of a quad up to 2 pi 1.03 / 120 along the ring and 2 pi 0.03 / 16 round the tube.
  const double edge = std::hypot(2 * test::kPi * 1.03 / 120, 2 * test::kPi * 0.03 / 16);
  for (int f = 0; f < before.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k)
      ASSERT_LT((ring.V.row(ring.F(f, k)) - before.V.row(before.F(f, k))).norm(), 0.3 * edge + 1e-12) << f;
  // The two ends do not touch: the loop's two copies lie apart.
  const std::vector<int>& loop = handles[0].loop;
  EXPECT_GT((ring.V.row(loop[0]) - ring.V.row(before.numVertices())).norm(), 0.3 * edge);
  // No thin handle is left to cut.
  EXPECT_TRUE(thinHandles(ring).empty());
}

TEST(ThinHandles, EveryHandleTakenAsThinIsCutAndTheShapeStaysWhole) {
  // The slab's two bars are not thin; taken as thin (any loop shorter than the diagonal), both are cut.
  TriMesh slab = checkedTarget(twoHoledSlab());
  const std::vector<ThinHandle> handles = thinHandles(slab, 1.0);
  ASSERT_EQ(handles.size(), 2u);
  EXPECT_LE(handles[0].length, handles[1].length);
  cutThinHandles(slab, handles);
  test::expectClosedSurface(slab, 0);
}

TEST(ThinHandles, ADesignThatHasThemCutIsLoadedCutAndSaysSo) {
  Design design;
  design.target.kind = DesignTarget::Inline;
  design.target.mesh = checkedTarget(ringMesh(1.0, 0.03, 120, 16));
  design.target.cutThinHandles = true;
  const Design back = readDesignJson(writeDesignJson(design));
  EXPECT_TRUE(back.target.cutThinHandles);
  const auto scene = loadDesignTargetScene(back, "", {});
  TriMesh target = scene->target;
  const ValidationReport report = validateTarget(target);
  EXPECT_EQ(report.stats.genus, 0);
  // Without the flag the ring keeps its handle.
  design.target.cutThinHandles = false;
  EXPECT_EQ(writeDesignJson(design).find("cutThinHandles"), std::string::npos);
  TriMesh uncut = loadDesignTargetScene(design, "", {})->target;
  EXPECT_EQ(validateTarget(uncut).stats.genus, 1);
}
