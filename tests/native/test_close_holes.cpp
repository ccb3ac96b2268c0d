// Holes closed (mesh/close_holes.hpp): a sphere with caps cut off is closed again by caps of triangles about its rim's
// size, facing out, every face kept; holes that touch at a vertex are left; a design says it and is loaded closed.
#include <gtest/gtest.h>

#include <map>

#include "io/design_json.hpp"
#include "mesh/close_holes.hpp"
#include "mesh/validate.hpp"
#include "pattern/design_scene.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;

namespace {

// The shared sphere without the triangles whose centroid c (from its centre, in units of its radius) is `open(c)`.
template <class Open>
TriMesh sphereOpenWhere(Open open) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  const Eigen::RowVector3d middle = 0.5 * (sphere.V.colwise().maxCoeff() + sphere.V.colwise().minCoeff());
  const double radius = 0.5 * (sphere.V.col(1).maxCoeff() - sphere.V.col(1).minCoeff());
  std::vector<Eigen::Vector3i> kept;
  for (int f = 0; f < sphere.numTriangles(); ++f) {
    const Eigen::RowVector3d c =
        ((sphere.V.row(sphere.F(f, 0)) + sphere.V.row(sphere.F(f, 1)) + sphere.V.row(sphere.F(f, 2))) / 3 - middle) /
        radius;
    if (!open(c)) kept.push_back(sphere.F.row(f));
  }
  TriMesh m{sphere.V, Triangles(int(kept.size()), 3)};
  for (size_t f = 0; f < kept.size(); ++f) m.F.row(int(f)) = kept[f].transpose();
  return m;
}

// Open above `top` and below `bottom` (along y).
TriMesh openSphere(double top, double bottom = -2) {
  return sphereOpenWhere([&](const Eigen::RowVector3d& c) { return c(1) > top || c(1) < bottom; });
}

double longestEdge(const TriMesh& m, int firstFace) {
  double longest = 0;
  for (int f = firstFace; f < m.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (m.V.row(m.F(f, k)) - m.V.row(m.F(f, (k + 1) % 3))).norm());
  return longest;
}

}  // namespace

TEST(CloseHoles, ASphereOpenAtTheTopIsClosedByACapFacingOut) {
  TriMesh m = openSphere(0.8);
  {
    TriMesh checked = m;
    const ValidationReport open = validateTarget(checked);
    ASSERT_FALSE(open.ok);
    ASSERT_EQ(open.stats.holes, 1);
  }
  const TriMesh before = m;
  EXPECT_EQ(closeHoles(m), 1);
  // Every face kept where it was; the cap appended.
  ASSERT_GT(m.numTriangles(), before.numTriangles());
  EXPECT_EQ(m.F.topRows(before.numTriangles()), before.F);
  EXPECT_EQ(m.V.topRows(before.numVertices()), before.V);
  const ValidationReport report = test::expectClosedSurface(m, 0);
  // The sphere less the segment above its rim (about 0.78 of its radius up: 3-4 % of the ball), closed flat.
  const double r = 0.5 * (before.V.col(1).maxCoeff() - before.V.col(1).minCoeff()),
               sphere = 4.0 / 3 * test::kPi * r * r * r;
  EXPECT_GT(report.stats.volume, 0.95 * sphere);
  EXPECT_LT(report.stats.volume, sphere);
  // The cap's triangles about the rim's own edges, not long slivers to a middle.
  double rim = 0;
  for (int f = 0; f < before.numTriangles(); ++f)
    rim = std::max(rim, (before.V.row(before.F(f, 0)) - before.V.row(before.F(f, 1))).norm());
  EXPECT_LT(longestEdge(m, before.numTriangles()), 2.0 * rim);
}

TEST(CloseHoles, TwoHolesAreBothClosedAndTouchingOnesAreLeft) {
  TriMesh m = openSphere(0.7, -0.7);
  EXPECT_EQ(closeHoles(m), 2);
  test::expectClosedSurface(m, 0);

  // Two triangles off a closed sphere that share one corner: their holes touch there, and neither is closed.
  TriMesh pinched = test::loadShared("sphere.obj");
  const int v = pinched.F(0, 0);
  int other = -1;
  for (int f = 1; f < pinched.numTriangles() && other < 0; ++f) {
    bool touchesOnlyAtV = false, sharesEdge = false;
    for (int k = 0; k < 3; ++k) {
      const int a = pinched.F(f, k);
      touchesOnlyAtV = touchesOnlyAtV || a == v;
      sharesEdge = sharesEdge || (a != v && (a == pinched.F(0, 1) || a == pinched.F(0, 2)));
    }
    if (touchesOnlyAtV && !sharesEdge) other = f;
  }
  ASSERT_GE(other, 0);
  Triangles kept(pinched.numTriangles() - 2, 3);
  for (int f = 0, row = 0; f < pinched.numTriangles(); ++f)
    if (f != 0 && f != other) kept.row(row++) = pinched.F.row(f);
  pinched.F = kept;
  EXPECT_EQ(closeHoles(pinched), 0);
  EXPECT_FALSE(validateTarget(pinched).ok);
}

TEST(CloseHoles, ADesignThatHasThemClosedIsLoadedClosedAndOneThatHasNotSaysHow) {
  Design design;
  design.target.kind = DesignTarget::Inline;
  design.target.mesh = openSphere(0.8);
  try {
    loadDesignTargetScene(design, "", {});
    FAIL() << "an open target is refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "design.bad-target");
    EXPECT_NE(std::string(e.what()).find("\"closeHoles\": true"), std::string::npos) << e.what();
  }
  design.target.closeHoles = true;
  const Design back = readDesignJson(writeDesignJson(design));
  EXPECT_TRUE(back.target.closeHoles);
  const std::unique_ptr<DesignScene> scene = loadDesignTargetScene(back, "", {});
  TriMesh target = scene->target;
  EXPECT_TRUE(validateTarget(target).ok);

  // A seam point on the cap is written as the 3D point it is (in the mesh's own units), one on the file's own faces
  // as it was: a later version may cap the hole otherwise, the file's faces stay.
  EXPECT_EQ(scene->facesRead, design.target.mesh.numTriangles());
  DesignSeam seam;
  const SurfacePoint own{3, Eigen::Vector3d(0.2, 0.3, 0.5)},
      cap{scene->facesRead + 1, Eigen::Vector3d(0.5, 0.25, 0.25)};
  for (const SurfacePoint& p : {own, cap}) seam.points.push_back(DesignPoint{true, p, Eigen::Vector3d::Zero()});
  std::vector<DesignSeam> seams{seam};
  addedFacePointsAsPositions(*scene, seams);
  ASSERT_TRUE(seams[0].points[0].onSurface);
  EXPECT_EQ(seams[0].points[0].surface.face, 3);
  ASSERT_FALSE(seams[0].points[1].onSurface);
  EXPECT_LT((seams[0].points[1].position * scene->scale - position(scene->target, cap)).norm(), 1e-12);
}

namespace {

// The shared sphere open along a C: the triangles above 0.3 of its radius whose centroid, seen from above, lies
// in a ring between 0.3 and 0.75 of the radius from the axis, three quarters round. The hole's middle is outside it.
TriMesh sphereOpenAlongAC() {
  return sphereOpenWhere([](const Eigen::RowVector3d& c) {
    const double r = std::hypot(c(0), c(2)), angle = std::atan2(c(2), c(0));
    return c(1) > 0.3 && r > 0.3 && r < 0.75 && angle > -M_PI / 2;
  });
}

}  // namespace

TEST(CloseHoles, AHoleWhoseMiddleLiesOutsideItGetsACapThatDoesNotFoldOverItself) {
  TriMesh m = sphereOpenAlongAC();
  const int before = m.numTriangles();
  ASSERT_EQ(closeHoles(m), 1);
  test::expectClosedSurface(m, 0);
  // Seen from above, along the axis the C's rim lies across, the cap's triangles all turn one way and cover the
  // hole once: their areas' sum is the sum of their sizes.
  double sum = 0, sizes = 0;
  for (int f = before; f < m.numTriangles(); ++f) {
    const Eigen::RowVector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const double area = 0.5 * ((b(2) - a(2)) * (c(0) - a(0)) - (b(0) - a(0)) * (c(2) - a(2)));
    sum += area, sizes += std::abs(area);
  }
  EXPECT_GT(sizes, 0);
  EXPECT_NEAR(std::abs(sum), sizes, 1e-9 * sizes) << "cap triangles fold over each other";
}

TEST(CloseHoles, AHoleWhoseRimCrossesItselfSeenFromEverySideIsClosedByAFilmThatSeldomFolds) {
  // A slot around the sphere's middle, 300 degrees round: its rim's two long sides lie one over the other seen
  // along the plane that fits it, and across its vector area the slot's ends overlap. Laid on a circle, the rim is
  // spanned by a soap film's cap, whose neighbouring triangles seldom turn sharply back on each other (1 % of its
  // edges by more than 120 degrees, at the slot's narrow ends; the rings drawn towards the centroid, 8 %).
  const TriMesh sphere = test::loadShared("sphere.obj");
  TriMesh m = sphereOpenWhere(
      [](const Eigen::RowVector3d& c) { return std::abs(c(1)) < 0.2 && std::atan2(c(2), c(0)) > -2 * M_PI / 3; });
  const int before = m.numTriangles();
  ASSERT_EQ(closeHoles(m), 1);
  test::expectClosedSurface(m, 0);
  std::map<std::pair<int, int>, Eigen::Vector3d> normalAlong;  // each cap edge's first triangle's normal
  int folds = 0, edges = 0;
  for (int f = before; f < m.numTriangles(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    for (int k = 0; k < 3; ++k) {
      const auto edge = std::minmax(m.F(f, k), m.F(f, (k + 1) % 3));
      const auto [it, first] = normalAlong.emplace(std::pair{edge.first, edge.second}, normal);
      if (!first) edges += 1, folds += it->second.dot(normal) < -0.5;
    }
  }
  EXPECT_GT(edges, 0);
  EXPECT_LT(folds, 0.02 * edges);
  EXPECT_LT(longestEdge(m, before), 3 * longestEdge(sphere, 0));
}

TEST(CloseHoles, ARimVertexWithOneTriangleGetsACapThatDoesNotRepeatThatTrianglesInnerEdge) {
  // A flap on the rim, folded back over the surface (as at the libigl snail's opening): its tip is a rim vertex with
  // one triangle, whose edge across the tip's neighbours already has two triangles. Seen across the hole the flap
  // lies inside the rim, so a cap laid there without points on its rim takes the flap's triangle as an ear, and the
  // flap's inner edge would have four triangles.
  TriMesh m = openSphere(0.8);
  std::map<std::pair<int, int>, int> uses;
  for (int f = 0; f < m.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(m.F(f, k), m.F(f, (k + 1) % 3))];
  int a = -1, b = -1;  // a rim edge a -> b as its triangle runs
  for (int f = 0; f < m.numTriangles() && a < 0; ++f)
    for (int k = 0; k < 3 && a < 0; ++k)
      if (uses[std::minmax(m.F(f, k), m.F(f, (k + 1) % 3))] == 1) a = m.F(f, k), b = m.F(f, (k + 1) % 3);
  ASSERT_GE(a, 0);
  // The tip in the rim's plane, away from the axis.
  const Eigen::RowVector3d middle = 0.5 * (m.V.row(a) + m.V.row(b)),
                           inward = Eigen::RowVector3d(-middle(0), 0, -middle(2)).normalized();
  const int tip = m.numVertices();
  m.V.conservativeResize(tip + 1, 3);
  m.V.row(tip) = middle - 0.5 * (m.V.row(a) - m.V.row(b)).norm() * inward;
  m.F.conservativeResize(m.numTriangles() + 1, 3);
  m.F.row(m.numTriangles() - 1) << b, a, tip;
  {
    TriMesh checked = m;
    const ValidationReport open = validateTarget(checked);
    ASSERT_EQ(open.stats.holes, 1);
    ASSERT_FALSE(open.modified) << "the tip's triangle faces as the others do";
  }
  ASSERT_EQ(closeHoles(m), 1);
  test::expectClosedSurface(m, 0);
}
