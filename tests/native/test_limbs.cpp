// A target's limbs (suggest/limbs.hpp) and the layouts that seam around and along them (suggest/seam_layouts.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "crease_shapes.hpp"
#include "io/design_json.hpp"
#include "pattern/design_scene.hpp"
#include "suggest/limbs.hpp"
#include "suggest/seam_layouts.hpp"
#include "test_support.hpp"

namespace billow {
namespace {

double meshArea(const TriMesh& m) {
  double area = 0;
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

// Each limb is closed off by its root loop: a loop where its level is zero, every path from the limb's faces to the
// body's crossing the faces the loop passes through; the tip on the limb, the limb a small part of the surface.
void expectLimbsClosedOff(const TriMesh& mesh, const std::vector<Limb>& limbs) {
  const double D = test::boxDiagonal(mesh), total = meshArea(mesh);
  std::vector<std::set<int>> vertexFaces(size_t(mesh.V.rows()));
  for (int f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) vertexFaces[size_t(mesh.F(f, k))].insert(f);
  for (const Limb& limb : limbs) {
    ASSERT_EQ(limb.faces.size(), size_t(mesh.F.rows()));
    EXPECT_GE(limb.elongation, kLimbElongation);
    EXPECT_LT(limb.area, 0.3 * total);
    EXPECT_GT(limb.area, 0);
    EXPECT_GE(limb.rootLoop.size(), 3u);
    for (const SectionPoint& p : limb.rootLoop) {
      EXPECT_NEAR(limbLevel(mesh, limb, p.at.face, p.position), 0, 1e-9 * D);
      EXPECT_EQ(limb.faces[size_t(p.at.face)], 2);
    }
    EXPECT_NEAR(limb.girth, loopLength(limb.rootLoop), 1e-12 * D);
    bool tipOn = false;
    for (int f : vertexFaces[size_t(limb.tip)]) tipOn |= limb.faces[size_t(f)] == 1;
    EXPECT_TRUE(tipOn);
    EXPECT_LT(limb.level[limb.tip], 0);
    // No vertex is shared by a face of the limb and a face of the body: the root loop's faces lie between.
    for (const std::set<int>& faces : vertexFaces) {
      bool limbFace = false, bodyFace = false;
      for (int f : faces) limbFace |= limb.faces[size_t(f)] == 1, bodyFace |= limb.faces[size_t(f)] == 0;
      EXPECT_FALSE(limbFace && bodyFace);
    }
  }
  // No two overlap.
  for (size_t i = 0; i < limbs.size(); ++i)
    for (size_t j = i + 1; j < limbs.size(); ++j)
      for (int f = 0; f < mesh.F.rows(); ++f) EXPECT_FALSE(limbs[i].faces[size_t(f)] && limbs[j].faces[size_t(f)]);
}

TEST(Limbs, TheOctopusHasEightArmsTheBunnyItsEarsAndTheSphereNone) {
  const TriMesh octopus = test::loadShared("octopus.obj");
  const std::vector<Limb> arms = findLimbs(octopus);
  EXPECT_EQ(arms.size(), 8u);
  expectLimbsClosedOff(octopus, arms);
  for (const Limb& arm : arms) EXPECT_GT(arm.elongation, 4);  // long thin tentacles

  const TriMesh bunny = test::loadShared("bunny.obj");
  const std::vector<Limb> ears = findLimbs(bunny);
  ASSERT_EQ(ears.size(), 2u);
  expectLimbsClosedOff(bunny, ears);
  // Both tips in the top fifth of the bunny (it stands Y up).
  const double top = bunny.V.col(1).maxCoeff(), height = top - bunny.V.col(1).minCoeff();
  for (const Limb& ear : ears) EXPECT_GT(bunny.V(ear.tip, 1), top - 0.2 * height);

  EXPECT_TRUE(findLimbs(test::loadShared("sphere.obj")).empty());
}

// A starfish made for the purpose (the unit sphere subdivided, five arms pulled out of its equator, flattened): its
// arms meet in its middle, so each arm's cap overlaps its neighbours' before it stops growing as a tube; each root
// moves back towards its tip until the five are apart.
TEST(Limbs, AStarfishsFiveArmsAreFoundThoughTheyMeetInItsMiddle) {
  TriMesh mesh = test::loadShared("sphere.obj");
  for (int level = 0; level < 2; ++level) {  // each triangle in four, the new points pushed out onto the sphere
    std::map<std::pair<int, int>, int> middle;
    std::vector<Eigen::Vector3d> points;
    for (int v = 0; v < mesh.V.rows(); ++v) points.push_back(mesh.V.row(v).normalized());
    const auto mid = [&](int a, int b) {
      const auto [it, added] = middle.insert({{std::min(a, b), std::max(a, b)}, int(points.size())});
      if (added) points.push_back((points[size_t(a)] + points[size_t(b)]).normalized());
      return it->second;
    };
    std::vector<Eigen::Vector3i> faces;
    for (int f = 0; f < mesh.F.rows(); ++f) {
      const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2), ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      faces.insert(faces.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    mesh.V.resize(Eigen::Index(points.size()), 3), mesh.F.resize(Eigen::Index(faces.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) mesh.V.row(Eigen::Index(i)) = points[i];
    for (size_t i = 0; i < faces.size(); ++i) mesh.F.row(Eigen::Index(i)) = faces[i];
  }
  std::vector<Eigen::Vector3d> arms;
  for (int k = 0; k < 5; ++k) arms.push_back({std::cos(2 * test::kPi * k / 5), 0, std::sin(2 * test::kPi * k / 5)});
  for (int v = 0; v < mesh.V.rows(); ++v) {
    const Eigen::Vector3d u = mesh.V.row(v);
    double r = 1;
    for (const Eigen::Vector3d& d : arms)
      r = std::max(r, 1 + 1.8 * std::exp(-std::pow(std::acos(std::clamp(u.dot(d), -1.0, 1.0)) / 0.28, 2)));
    mesh.V.row(v) = (r * u).cwiseProduct(Eigen::Vector3d(1, 0.45, 1));
  }
  const std::vector<Limb> limbs = findLimbs(mesh);
  ASSERT_EQ(limbs.size(), 5u);
  expectLimbsClosedOff(mesh, limbs);
  std::set<int> found;
  for (const Limb& limb : limbs) {
    const Eigen::Vector3d tip = mesh.V.row(limb.tip);
    for (int k = 0; k < 5; ++k)
      if (Eigen::Vector3d(tip.x(), 0, tip.z()).normalized().dot(arms[size_t(k)]) > std::cos(10 * test::kPi / 180))
        found.insert(k);
  }
  EXPECT_EQ(found.size(), 5u) << "a tip at the end of each arm";
}

// A plush toy's pattern for the octopus: a seam around each arm where it joins the body, each arm halved along its
// curl, the body in two. Plane sections leave its coiled arms tubes the openings cannot make panels of within 24
// (bench/README.md "Suggested seam layouts"), and its front and back along the outline miss most of the arms.
TEST(SeamLayouts, TheOctopusIsPatternedAroundAndAlongEachArmAndComesFarCloserThanItsTwoPieces) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const auto scene = test::sharedScene("octopus.obj");
  LayoutRequest request;
  request.panels = 24;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  std::vector<const LayoutProposal*> limbLayouts;
  const LayoutProposal* outline = nullptr;
  for (const LayoutProposal& p : proposals) {
    if (!p.limbs.empty() && p.bands == 0 && p.outlineView < 0) limbLayouts.push_back(&p);
    if (p.limbs.empty() && p.outlineView == 2 && p.bands == 0) outline = &p;  // the two pieces alone
  }
  ASSERT_EQ(limbLayouts.size(), 3u);  // the body halved across each axis (and in bands: not tried here)
  ASSERT_NE(outline, nullptr);
  EvaluateOptions options;
  LayoutEvaluation best;
  best.distance = INFINITY;
  for (const LayoutProposal* p : limbLayouts) {
    EXPECT_EQ(p->limbs.size(), 8u);
    EXPECT_EQ(p->name.rfind("seams around 8 limbs, each halved along its length, the body in ", 0), 0u) << p->name;
    const std::vector<DesignSeam> seams = proposalSeams(scene->target, *p);
    int around = 0, along = 0;
    for (const DesignSeam& s : seams) {
      around += s.name.rfind("around limb ", 0) == 0 && s.closed;
      along += s.name.rfind("along limb ", 0) == 0;
    }
    EXPECT_EQ(around, 8) << p->name;
    EXPECT_GE(along, 8) << p->name;
    const LayoutEvaluation e = evaluateLayout(*scene, seams, 0, options);
    if (!e.ok) continue;
    EXPECT_TRUE(scene->segmentation.problems.empty());
    EXPECT_LE(e.panels, 24);
    EXPECT_GE(e.panels, 17);  // each arm in two, the body in two or more
    if (e.distance < best.distance) best = e;
  }
  ASSERT_TRUE(best.ok);
  const LayoutEvaluation twoPieces = evaluateLayout(*scene, proposalSeams(scene->target, *outline), 0, options);
  ASSERT_TRUE(twoPieces.ok) << twoPieces.problem;
  EXPECT_LT(best.distance, 0.6 * twoPieces.distance) << best.distance << " against " << twoPieces.distance;
  EXPECT_LT(best.targetToInflated, 0.6 * twoPieces.targetToInflated);
}

// A plush toy's other pattern: each limb seamed at its root, the body a front and a back sealed along its outline.
// The bunny's ears stand out of its outline seen from the front, so the outline is laid on the body only, in pieces
// from ear root to ear root, each meeting the root seams where it ends: six panels, no seam left loose.
TEST(SeamLayouts, ABodyAlongItsOutlineIsLaidFromLimbRootToLimbRoot) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const auto scene = test::sharedScene("bunny.obj");
  LayoutRequest request;
  request.panels = 6;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  const LayoutProposal* layout = nullptr;
  for (const LayoutProposal& p : proposals)
    if (!p.limbs.empty() && p.outlineView == 2 && p.bands == 0) layout = &p;
  ASSERT_NE(layout, nullptr);
  EXPECT_EQ(layout->name,
            "seams around 2 limbs, each halved along its length, the body in two pieces along the "
            "outline seen from the front");
  EXPECT_TRUE(layout->planes.empty());
  const std::vector<DesignSeam> seams = proposalSeams(scene->target, *layout);
  int around = 0, outline = 0;
  for (const DesignSeam& s : seams) {
    around += s.name.rfind("around limb ", 0) == 0 && s.closed;
    if (s.name == "outline") {
      ++outline;
      EXPECT_FALSE(s.closed);  // from root to root: the ears stand out of the outline
    }
  }
  EXPECT_EQ(around, 2);
  EXPECT_GE(outline, 1);  // from one ear round the body to the other (between them too, where the roots lie apart)
  EvaluateOptions options;
  const LayoutEvaluation e = evaluateLayout(*scene, seams, 0, options);
  ASSERT_TRUE(e.ok) << e.problem;
  EXPECT_TRUE(scene->segmentation.problems.empty());
  EXPECT_EQ(e.panels, 6);  // each ear in two, the body's front and back
}

// The body's outline in a limb layout keeps its corners, as the Outline tool's does: a square cushion with one long
// arm, seen from the front, has its four corners on the seam, not cut off by chords between control points.
TEST(SeamLayouts, TheOutlineOnALimbsBodyKeepsItsCorners) {
  const std::vector<Eigen::Vector2d> corners{{-0.25, -0.25}, {0.25, -0.25}, {0.25, -0.04}, {0.65, -0.04},
                                             {0.65, 0.04},   {0.25, 0.04},  {0.25, 0.25},  {-0.25, 0.25}};
  const TriMesh target = test::extrudedOutline(test::polygonOutline(corners, 10), 0.12, 10, 4);
  const std::vector<Limb> limbs = findLimbs(target);
  ASSERT_EQ(limbs.size(), 1u);
  EXPECT_GT(target.V(limbs[0].tip, 0), 0.5) << "the arm's tip";
  LayoutRequest request;
  request.panels = 4;
  const LayoutProposal* layout = nullptr;
  const std::vector<LayoutProposal> proposals = proposeLayouts(target, request);
  for (const LayoutProposal& p : proposals)
    if (!p.limbs.empty() && p.outlineView == 2 && p.bands == 0) layout = &p;
  ASSERT_NE(layout, nullptr);
  const std::vector<DesignSeam> seams = proposalSeams(target, *layout);
  const double diagonal = test::boxDiagonal(target);
  for (const Eigen::Vector2d& corner : {corners[0], corners[1], corners[6], corners[7]}) {
    double nearest = INFINITY;
    for (const DesignSeam& s : seams)
      if (s.name == "outline")
        for (const DesignPoint& p : s.points) {
          const Eigen::Vector3d x = p.onSurface ? position(target, p.surface) : p.position;
          nearest = std::min(nearest, (x.head<2>() - corner).norm());
        }
    EXPECT_LT(nearest, 0.005 * diagonal) << "a control point at the corner " << corner.transpose();
  }
}

// A ring with an arm standing out of its side (a swim ring with a handle bar, a doughnut plush with a tail), seen
// along its axis, has an outline with a hole: the limb layout along that outline cuts its front and back rings open as
// the outline layout does (the hole's rim, two sections across the ring), on the body only.
TEST(SeamLayouts, ARingsBodyAlongItsOutlineIsCutOpenAcrossTheRing) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const double R = 1, r = 0.35;
  const int nu = 120, nv = 40;
  TriMesh target;
  target.V.resize(nu * nv, 3), target.F.resize(2 * nu * nv, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * test::kPi * i / nu, v = 2 * test::kPi * j / nv;
      const Eigen::Vector3d radial(std::cos(u), std::sin(u), 0),
          normal = std::cos(v) * radial + std::sin(v) * Eigen::Vector3d::UnitZ();
      // The arm: a bump on the ring's outer equator at u = 0, pushed out along the surface's normal.
      const double du = std::remainder(u, 2 * test::kPi) * (R + r), dv = std::remainder(v, 2 * test::kPi) * r;
      const double arm = 1.2 * std::exp(-(du * du + dv * dv) / (0.2 * 0.2));
      target.V.row(i * nv + j) = R * radial + (r + arm) * normal;
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
      target.F.row(2 * a) = Eigen::Vector3i(a, b, c);
      target.F.row(2 * a + 1) = Eigen::Vector3i(a, c, d);
    }
  const auto scene = test::sceneOf(target);
  const std::vector<Limb> limbs = findLimbs(scene->target);
  ASSERT_EQ(limbs.size(), 1u);
  LayoutRequest request;
  request.panels = 8;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  const LayoutProposal* layout = nullptr;
  for (const LayoutProposal& p : proposals)
    if (!p.limbs.empty() && p.outlineView == 2 && p.bands == 0) layout = &p;
  ASSERT_NE(layout, nullptr);
  const std::vector<DesignSeam> seams = proposalSeams(scene->target, *layout);
  int holes = 0, across = 0;
  for (const DesignSeam& s : seams) {
    holes += s.name == "hole in the outline";
    across += s.name == "across a ring";
  }
  EXPECT_EQ(holes, 1);
  EXPECT_EQ(across, 2);
  EvaluateOptions options;
  const LayoutEvaluation e = evaluateLayout(*scene, seams, 0, options);
  ASSERT_TRUE(e.ok) << e.problem;
  EXPECT_TRUE(scene->segmentation.problems.empty());
  EXPECT_EQ(e.panels, 6);  // the arm in two, the front and the back rings each in two
}

// Where the symmetry is kept, a layout's limbs come in mirror pairs (the same planes reflected) or stand on the mirror
// plane on their own, halved along it, and the body's halving plane is its own mirror image.
TEST(SeamLayouts, LimbLayoutsThatKeepTheMirrorSymmetryAreTheirOwnMirrorImage) {
  for (const char* name : {"koala.obj", "elephant.obj"}) {
    const TriMesh target = test::loadShared(name);
    const double mid = 0.5 * (target.V.col(0).maxCoeff() + target.V.col(0).minCoeff()), D = test::boxDiagonal(target);
    const auto reflected = [&](const SectionPlane& p) {
      SectionPlane q{p.normal, p.offset - 2 * mid * p.normal.x()};
      q.normal.x() = -q.normal.x();
      return q;
    };
    const auto same = [&](const SectionPlane& a, const SectionPlane& b) {
      return (a.normal - b.normal).norm() < 1e-9 && std::abs(a.offset - b.offset) < 1e-9 * D;
    };
    LayoutRequest request;
    request.panels = 24, request.symmetryAxis = 0;
    int layouts = 0;
    for (const LayoutProposal& p : proposeLayouts(target, request)) {
      if (p.limbs.empty()) continue;
      ++layouts;
      ASSERT_EQ(p.planes.size(), size_t((p.outlineView < 0) + p.bands));  // the halving plane, unless an outline
      for (const SectionPlane& plane : p.planes)
        EXPECT_TRUE(same(reflected(plane), plane) || same(reflected(plane), {-plane.normal, -plane.offset}))
            << name << ": " << p.name;
      const auto mean = [](const SectionLoop& loop) {
        Eigen::Vector3d m = Eigen::Vector3d::Zero();
        for (const SectionPoint& q : loop) m += q.position;
        return Eigen::Vector3d(m / double(loop.size()));
      };
      for (const Limb& limb : p.limbs) {
        const Eigen::Vector3d m = mean(limb.rootLoop);
        if (std::abs(m.x() - mid) < 0.01 * D) {  // on the mirror plane: halved along it
          EXPECT_TRUE(same(limb.along, {Eigen::Vector3d::UnitX(), mid})) << name;
          continue;
        }
        // Its twin's root loop is its mirror image (to within the mesh's own asymmetry), its plane along it reflected.
        int twins = 0;
        for (const Limb& other : p.limbs) {
          Eigen::Vector3d image = mean(other.rootLoop);
          image.x() = 2 * mid - image.x();
          twins += (image - m).norm() < 0.02 * D && same(reflected(limb.along), other.along);
        }
        EXPECT_EQ(twins, 1) << name << ": " << p.name;
      }
    }
    EXPECT_GT(layouts, 0) << name;
  }
}

// A limb is halved by one seam that runs its length round its tip: where the outline that halves it also runs round a
// bump near the tip (a horse's ear on its head), a loop there would cut a panel of its own off, one more than the
// layout counts on (the horse at 12 panels got 13 and none of its limb layouts was kept).
TEST(SeamLayouts, EachHalvedLimbGetsOneSeamAlongIt) {
  for (const char* name : {"octopus.obj", "hand.obj", "stuffedtoy.obj", "goathead.obj", "cat.obj", "penguin.obj"}) {
    const TriMesh target = test::loadShared(name);
    LayoutRequest request;
    request.panels = 24;
    int halvedLimbs = 0;
    for (const LayoutProposal& p : proposeLayouts(target, request)) {
      if (p.limbs.empty()) continue;
      std::map<std::string, int> along;
      for (const DesignSeam& s : proposalSeams(target, p))
        if (s.name.rfind("along limb ", 0) == 0) ++along[s.name];
      for (size_t i = 0; i < p.limbs.size(); ++i) {
        const int seams = along["along limb " + std::to_string(i + 1)];
        EXPECT_LE(seams, 1) << name << ": " << p.name << ", limb " << i + 1;
        halvedLimbs += seams;
      }
    }
    EXPECT_GT(halvedLimbs, 0) << name;
  }
}

}  // namespace
}  // namespace billow
