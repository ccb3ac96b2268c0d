// The outline seen from a direction (seams/outline.hpp), its corners kept (sectionSeamPoints), and the suggested
// layouts made along it (suggest/seam_layouts.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>

#include "cube_fixture.hpp"
#include "handle_shapes.hpp"
#include "mesh/validate.hpp"
#include "pattern/design_scene.hpp"
#include "seams/outline.hpp"
#include "suggest/seam_layouts.hpp"
#include "test_support.hpp"

namespace billow {
namespace {

// A torus around the z axis (radii R and r), n x m quads split in two, outward.
TriMesh torus(double R, double r, int n, int m) {
  TriMesh t;
  t.V.resize(n * m, 3), t.F.resize(2 * n * m, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * test::kPi * i / n, v = 2 * test::kPi * j / m;
      t.V.row(i * m + j) << (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v);
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
      t.F.row(2 * (i * m + j)) << a, b, c;
      t.F.row(2 * (i * m + j) + 1) << a, c, d;
    }
  return t;
}

TEST(Outline, TheSphereSeenFromAboveHasItsEquatorForOutline) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  const Eigen::Vector3d middle = 0.5 * (sphere.V.colwise().maxCoeff() + sphere.V.colwise().minCoeff());
  const double r = 0.5 * (sphere.V.col(0).maxCoeff() - sphere.V.col(0).minCoeff());
  const std::optional<Outline> outline = outlineSeenFrom(sphere, Eigen::Vector3d::UnitZ());
  ASSERT_TRUE(outline.has_value());
  EXPECT_TRUE(outline->holes.empty());
  // Where the normal turns away from the viewer: the equator, within a triangle's height of it.
  for (const SectionPoint& p : outline->loop) EXPECT_LT(std::abs(p.position.z() - middle.z()), 0.06 * r);
  EXPECT_NEAR(loopLength(outline->loop), 2 * test::kPi * r, 0.03 * 2 * test::kPi * r);
}

// A letter L extruded along z (n x n cells across, t deep), as the boundary of its cells: side walls t rows deep,
// every wall vertex inside a row seen exactly edge-on from the front.
TriMesh extrudedL(int n, int t) {
  const auto filled = [&](int i, int j, int k) {
    if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= t) return false;
    const double x = (i + 0.5) / n, y = (j + 0.5) / n;
    return (x < 0.35 && y < 0.95) || (x < 0.8 && y < 0.3);
  };
  std::map<std::array<int, 3>, int> index;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> faces;
  const auto vertex = [&](int i, int j, int k) {
    const auto [it, added] = index.try_emplace({i, j, k}, int(points.size()));
    if (added) points.emplace_back(double(i) / n, double(j) / n, double(k) / n);
    return it->second;
  };
  // Each face of a cell that no cell covers, counter-clockwise seen from outside: the corners of the face whose
  // normal is axis a (sign s), in order.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < t; ++k) {
        if (!filled(i, j, k)) continue;
        for (int a = 0; a < 3; ++a)
          for (int s : {-1, 1}) {
            std::array<int, 3> c{i, j, k}, step{0, 0, 0};
            step[a] = s;
            if (filled(i + step[0], j + step[1], k + step[2])) continue;
            const int b = (a + 1) % 3, d = (a + 2) % 3;
            std::array<std::array<int, 3>, 4> q;
            for (int m = 0; m < 4; ++m) {
              q[m] = c;
              if (s > 0) q[m][a] += 1;
              q[m][b] += (m == 1 || m == 2), q[m][d] += (m >= 2);
            }
            if (s < 0) std::swap(q[1], q[3]);
            int v[4];
            for (int m = 0; m < 4; ++m) v[m] = vertex(q[m][0], q[m][1], q[m][2]);
            faces.emplace_back(v[0], v[1], v[2]), faces.emplace_back(v[0], v[2], v[3]);
          }
      }
  TriMesh m;
  m.V.resize(long(points.size()), 3), m.F.resize(long(faces.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) m.V.row(long(v)) = points[v].transpose();
  for (size_t f = 0; f < faces.size(); ++f) m.F.row(long(f)) = faces[f].transpose();
  return m;
}

TEST(Outline, AnExtrudedLetterSeenFromTheFrontIsOutlinedRoundTheMiddleOfItsSideWalls) {
  TriMesh letter = extrudedL(24, 4);
  const ValidationReport check = validateTarget(letter);
  ASSERT_TRUE(check.ok && !check.modified && check.stats.genus == 0);
  const std::optional<Outline> outline = outlineSeenFrom(letter, Eigen::Vector3d::UnitZ());
  ASSERT_TRUE(outline.has_value());
  EXPECT_TRUE(outline->holes.empty());
  // The walls are 4 rows deep (z 0 to 1/6): the seal runs round their middle, not along the front edge's next row
  // (z = 1/8, where the rows' exact zeros put it), so the front and the back are mirror images.
  double mean = 0;
  for (const SectionPoint& p : outline->loop) {
    EXPECT_GT(p.position.z(), 0.25 / 6) << p.position.transpose();
    EXPECT_LT(p.position.z(), 0.75 / 6) << p.position.transpose();
    mean += p.position.z() / double(outline->loop.size());
  }
  EXPECT_NEAR(mean, 0.5 / 6, 0.01);
}

TEST(Outline, ARingSeenThroughItsHoleHasTwoLoopsAndTwoCutsAcrossIt) {
  const TriMesh ring = torus(1.0, 0.3, 48, 16);
  const Eigen::Vector3d towards = Eigen::Vector3d::UnitZ();
  const std::optional<Outline> outline = outlineSeenFrom(ring, towards);
  ASSERT_TRUE(outline.has_value());
  ASSERT_EQ(outline->holes.size(), 1u);
  // The rim goes round the outside (radius R + r), the hole's round the inside (R - r).
  for (const SectionPoint& p : outline->loop) EXPECT_NEAR(p.position.head<2>().norm(), 1.3, 0.02);
  for (const SectionPoint& p : outline->holes[0]) EXPECT_NEAR(p.position.head<2>().norm(), 0.7, 0.02);
  // Two cuts across the ring, each a section along the view around the ring's tube (about 2 pi r).
  const std::vector<SectionLoop> across = acrossHandles(ring, outline->loop, outline->holes, towards);
  ASSERT_EQ(across.size(), 2u);
  for (const SectionLoop& cut : across) EXPECT_NEAR(loopLength(cut), 2 * test::kPi * 0.3, 0.1);
}

TEST(Outline, ASeamAlongASquareLoopKeepsItsCorners) {
  const TriMesh cube = test::unitCube();
  const std::vector<SectionLoop> loops = planeSection(cube, Eigen::Vector3d::UnitZ(), 0.5);
  ASSERT_EQ(loops.size(), 1u);
  const auto hits = [&](const std::vector<SurfacePoint>& controls) {
    int corners = 0;
    for (double x : {0.0, 1.0})
      for (double y : {0.0, 1.0}) {
        bool hit = false;
        for (const SurfacePoint& p : controls) hit |= (position(cube, p) - Eigen::Vector3d(x, y, 0.5)).norm() < 1e-9;
        corners += hit;
      }
    return corners;
  };
  // 13 points on a perimeter of 4: only the loop's first point can fall on a corner by arc length alone.
  const double spacing = 4.0 / 13;
  EXPECT_LT(hits(sectionSeamPoints(cube, loops[0], spacing)), 4);
  EXPECT_EQ(hits(sectionSeamPoints(cube, loops[0], spacing, true)), 4);
  // An open piece of it from the middle of a side, past two corners (a crease from junction to junction round a
  // letter's turns): those corners kept too, its ends as they are.
  const SectionLoop& loop = loops[0];
  size_t start = 0;
  for (size_t i = 0; i < loop.size(); ++i)
    if ((loop[i].position - Eigen::Vector3d(0.5, 0, 0.5)).norm() <
        (loop[start].position - Eigen::Vector3d(0.5, 0, 0.5)).norm())
      start = i;
  SectionLoop path;
  for (size_t k = 0; path.empty() || loopLength(path) < 2.9; ++k) path.push_back(loop[(start + k) % loop.size()]);
  const std::vector<SurfacePoint> plain = sectionPathPoints(cube, path, 3.0 / 7),
                                  kept = sectionPathPoints(cube, path, 3.0 / 7, true);
  EXPECT_LT(hits(plain), 2);
  EXPECT_EQ(hits(kept), 2);
  EXPECT_LT((position(cube, kept.front()) - path.front().position).norm(), 1e-12);
  EXPECT_LT((position(cube, kept.back()) - path.back().position).norm(), 1e-12);
}

using test::sharedScene;

// The octopus's coiled arms leave a tube under every plane; the outline seen from the front still makes two panels
// that inflate.
TEST(Outline, TheOctopusGetsAFrontAndBackLayoutWherePlanesLeaveTubes) {
  const auto scene = sharedScene("octopus.obj");
  LayoutRequest request;
  request.panels = 6;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  int outlines = 0, usable = 0;
  for (const LayoutProposal& p : proposals) {
    if (p.outlineView < 0 || p.bands > 0 || !p.limbs.empty()) continue;  // the front and back alone
    ++outlines;
    const LayoutEvaluation look = lookAtLayout(*scene, p, {}, request.panels, {});
    if (!look.ok) continue;
    ++usable;
    EXPECT_EQ(look.panels, 2) << p.name;
    EXPECT_TRUE(scene->segmentation.problems.empty()) << p.name;
    EXPECT_LT(look.distance, 0.15) << p.name;  // relative to the diagonal: a first look, not optimized
  }
  EXPECT_EQ(outlines, 3);
  EXPECT_GE(usable, 2);
}

// A pillow bulges where a flat shape is thin: the hand along its outline from the front, its bands' loops held together
// inside by internal connections, comes far closer than without them (bench/README.md "Suggested seam layouts").
TEST(SeamLayouts, AFlatShapeHeldTogetherInsideComesCloserThanItsPillow) {
  const auto scene = sharedScene("hand.obj");
  LayoutRequest request;
  request.panels = 12;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  // Three bands across the side-to-side axis along the outline seen from the front, with and without.
  const auto find = [&](bool connected) {
    const auto p = std::find_if(proposals.begin(), proposals.end(), [&](const LayoutProposal& q) {
      return q.outlineView == 2 && q.axis == 0 && q.bands == 2 && q.connected == connected;
    });
    EXPECT_NE(p, proposals.end());
    return *p;
  };
  const LayoutProposal pillow = find(false), held = find(true);
  EXPECT_NE(held.name.find("held together inside"), std::string::npos) << held.name;
  const LayoutEvaluation plain = lookAtLayout(*scene, pillow, {}, request.panels, {});
  const LayoutEvaluation look = lookAtLayout(*scene, held, {}, request.panels, {});
  ASSERT_TRUE(plain.ok) << plain.problem;
  ASSERT_TRUE(look.ok) << look.problem;
  // One per loop of a band's plane that crosses the rim twice: the palm, and a finger one plane cuts on its own.
  ASSERT_GE(look.connections.size(), 2u);
  EXPECT_NE(look.description().find(std::to_string(look.connections.size()) + " internal connections"),
            std::string::npos)
      << look.description();
  EXPECT_TRUE(plain.connections.empty());
  // Each band's loop is two seams from crossing to crossing of the rim, which passes through both: they meet it there
  // exactly, as a seam drawn to another's point is snapped to it.
  const auto same = [](const DesignPoint& a, const DesignPoint& b) {
    return a.surface.face == b.surface.face && a.surface.bary == b.surface.bary;
  };
  const DesignSeam& rim = look.seams[0];
  ASSERT_TRUE(rim.closed);
  for (const DesignConnection& c : look.connections) {
    ASSERT_EQ(c.seams.size(), 2u);
    const DesignSeam& front = look.seams[size_t(c.seams[0])];
    const DesignSeam& back = look.seams[size_t(c.seams[1])];
    ASSERT_FALSE(front.closed || back.closed);
    EXPECT_TRUE(same(front.points.front(), back.points.back()) && same(front.points.back(), back.points.front()));
    for (const DesignPoint& end : {front.points.front(), front.points.back()})
      EXPECT_TRUE(
          std::any_of(rim.points.begin(), rim.points.end(), [&](const DesignPoint& p) { return same(p, end); }));
  }
  // The connections are panels to cut, inside.
  const auto connections = long(look.connections.size());
  EXPECT_EQ(look.panels, long(scene->segmentation.segments.size()) + connections);
  EXPECT_EQ(
      std::count_if(look.pattern.panels.begin(), look.pattern.panels.end(), [](const Panel& p) { return p.internal; }),
      connections);
  // The first looks, both ways: the connections hold front and back at the hand's thickness.
  EXPECT_LT(look.distance, 0.8 * plain.distance) << look.distance << " against " << plain.distance;
}

// Two proposals that end with the same seams are one layout to the designer: the second is not shown.
TEST(SeamLayouts, ALayoutEndingWithTheSeamsOfOneBeforeItIsNotShownAgain) {
  const auto scene = sharedScene("sphere.obj");
  LayoutRequest request;
  request.panels = 2;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  ASSERT_FALSE(proposals.empty());
  const LayoutEvaluation first = lookAtLayout(*scene, proposals[0], {}, 2, {});
  ASSERT_TRUE(first.ok) << first.problem;
  LayoutProposal again = proposals[0];
  again.name = "the same, named otherwise";
  const LayoutEvaluation second = lookAtLayout(*scene, again, {}, 2, {first.seams});
  EXPECT_FALSE(second.ok);
  EXPECT_NE(second.problem.find("same seams"), std::string::npos) << second.problem;
  // Another layout is still shown beside it.
  const LayoutEvaluation other = lookAtLayout(*scene, proposals[1], {}, 2, {first.seams});
  EXPECT_TRUE(other.ok) << other.problem;
  // Told apart before its panels are built and inflated.
  EXPECT_TRUE(second.pattern.panels.empty());
  EXPECT_EQ(second.balloon.positions.rows(), 0);
}

}  // namespace
}  // namespace billow

// A slab with two holes seen from its edge: the view looks through neither, so the outline alone leaves the front and
// the back holding the handles, not panels. openIntoPanels (what the app's Outline tool adds on a shape with handles)
// keeps the outline seam as it was and adds the seams that make every part a panel.
TEST(Outline, ASlabWithTwoHandlesSeenFromItsEdgeIsOpenedIntoPanels) {
  const auto scene = test::sceneOf(test::twoHoledSlab());
  const std::optional<Outline> outline = outlineSeenFrom(scene->target, Eigen::Vector3d::UnitY());
  ASSERT_TRUE(outline.has_value());
  EXPECT_TRUE(outline->holes.empty()) << "the holes are not seen from the edge";
  DesignSeam seam;
  seam.closed = true;
  for (const SurfacePoint& p : sectionSeamPoints(scene->target, outline->loop, 0.02, true))
    seam.points.push_back(DesignPoint{true, p, Eigen::Vector3d::Zero()});
  scene->design.seams = {seam};
  traceDesignSeams(*scene);
  segmentDesignScene(*scene);
  const auto notPanel = [](const Segmentation& s) {
    return std::count_if(s.segments.begin(), s.segments.end(), [](const Segment& g) { return !g.isDisk; });
  };
  ASSERT_GT(notPanel(scene->segmentation), 0) << "the outline alone leaves a part that is not a panel";

  const LayoutEvaluation opened = openIntoPanels(*scene, {seam}, 1, {}, 1000);
  ASSERT_TRUE(opened.ok) << opened.problem;
  ASSERT_GT(opened.seams.size(), 1u);
  ASSERT_EQ(opened.seams[0].points.size(), seam.points.size()) << "the designer's seam stays as it was";
  for (size_t k = 0; k < seam.points.size(); ++k) {
    EXPECT_EQ(opened.seams[0].points[k].surface.face, seam.points[k].surface.face);
    EXPECT_EQ(opened.seams[0].points[k].surface.bary, seam.points[k].surface.bary);
  }
  EXPECT_FALSE(opened.description().empty());
  EXPECT_EQ(notPanel(scene->segmentation), 0);
  EXPECT_TRUE(scene->segmentation.problems.empty());
  EXPECT_GE(scene->segmentation.segments.size(), 2u);
}

// The Outline tool's seams on a slab with two holes seen through them: the rim, each hole's rim, and the sections
// across the rings (acrossHandles), opened into panels as the app's tool does on a shape with handles.
LayoutEvaluation outlineOpened(DesignScene& scene, const Eigen::Vector3d& towards, std::vector<SectionLoop>& across) {
  const std::optional<Outline> outline = outlineSeenFrom(scene.target, towards);
  if (!outline) return {};
  across = acrossHandles(scene.target, outline->loop, outline->holes, towards);
  std::vector<DesignSeam> seams;
  const auto lay = [&](const SectionLoop& loop, bool corners) {
    DesignSeam seam;
    seam.closed = true;
    for (const SurfacePoint& p : sectionSeamPoints(scene.target, loop, 0.02, corners))
      seam.points.push_back(DesignPoint{true, p, Eigen::Vector3d::Zero()});
    seams.push_back(seam);
  };
  lay(outline->loop, true);
  for (const SectionLoop& hole : outline->holes) lay(hole, true);
  for (const SectionLoop& loop : across) lay(loop, false);
  return openIntoPanels(scene, seams, 1, {}, 1000);
}

// Seen face on, each ring is cut across its bars, where they are narrowest and opposite: through a hole's corner the
// section ran along its wall and around the whole slab (the far one, once), and cut slivers off.
TEST(Outline, TheCutsAcrossASlabsRingsRunAcrossItsBarsNotAlongTheHolesWalls) {
  const auto scene = test::sceneOf(test::twoHoledSlab());
  std::vector<SectionLoop> across;
  const LayoutEvaluation opened = outlineOpened(*scene, Eigen::Vector3d::UnitZ(), across);
  ASSERT_EQ(across.size(), 4u) << "two per hole";
  const double cube = (scene->target.V.col(0).maxCoeff() - scene->target.V.col(0).minCoeff()) / 5;
  for (const SectionLoop& cut : across) {
    EXPECT_NEAR(loopLength(cut), 4 * cube, 1e-9) << "around one bar";
    // Across x or y, away from every wall (the cubes' faces).
    const Eigen::Vector3d spread = [&] {
      Eigen::Vector3d lo = cut[0].position, hi = lo;
      for (const SectionPoint& p : cut) lo = lo.cwiseMin(p.position), hi = hi.cwiseMax(p.position);
      return Eigen::Vector3d(hi - lo);
    }();
    const int along = spread.x() < 1e-9 ? 0 : 1;
    ASSERT_LT(spread[along], 1e-9) << "a plane across x or y";
    const double at = (cut[0].position[along] - scene->target.V.col(along).minCoeff()) / cube;
    EXPECT_GT(std::abs(at - std::round(at)), 0.2) << "across a bar, not along a wall";
  }
  ASSERT_TRUE(opened.ok) << opened.problem;
  EXPECT_EQ(opened.opened.grazingLoops, 0);
  EXPECT_TRUE(scene->segmentation.problems.empty());
  for (const Segment& segment : scene->segmentation.segments) EXPECT_TRUE(segment.isDisk);
}

// Seen askew, a section through a hole's narrowest place runs along the slab and across both holes: it is not laid,
// and the cuts that open a tube open that ring instead. Laid, such sections cut slivers off a statue's legs and base.
TEST(Outline, ASectionThatDoesNotRunAroundItsRingIsLeftToTheCutsThatOpenATube) {
  const auto scene = test::sceneOf(test::twoHoledSlab());
  std::vector<SectionLoop> across;
  const LayoutEvaluation opened = outlineOpened(*scene, Eigen::Vector3d(0.2, 0.3, 1).normalized(), across);
  EXPECT_LT(across.size(), 4u);
  ASSERT_TRUE(opened.ok) << opened.problem;
  EXPECT_GT(opened.opened.tubeCuts, 0);
  EXPECT_EQ(opened.opened.grazingLoops, 0);
  EXPECT_TRUE(scene->segmentation.problems.empty());
  for (const Segment& segment : scene->segmentation.segments) EXPECT_TRUE(segment.isDisk);
}

// The cuts openIntoPanels adds end on the lines of the seams they join, and the app keeps them there only if it knows
// which (a point's "on"): openSeamEndHosts names them from the traced lines. A seam around a handle has few control
// points, and its line bows far from the chords between them: by the chords the app once put both ends of a short cut
// that opened a boot's tube on the outline, and the tube stayed shut.
TEST(Outline, TheCutsThatOpenIntoPanelsNameTheSeamsTheyEndOn) {
  const auto scene = test::sceneOf(test::twoHoledSlab());
  const std::optional<Outline> outline = outlineSeenFrom(scene->target, Eigen::Vector3d::UnitY());
  ASSERT_TRUE(outline.has_value());
  DesignSeam seam;
  seam.closed = true;
  for (const SurfacePoint& p : sectionSeamPoints(scene->target, outline->loop, 0.02, true))
    seam.points.push_back(DesignPoint{true, p, Eigen::Vector3d::Zero()});
  const LayoutEvaluation opened = openIntoPanels(*scene, {seam}, 1, {}, 1000);
  ASSERT_TRUE(opened.ok) << opened.problem;
  std::vector<DesignSeam> seams = opened.seams;
  // One more open seam whose ends lie on no seam: across the slab's middle, away from every line.
  const DesignSeam& first = seams[0];
  DesignSeam loose;
  loose.points = {first.points[first.points.size() / 4], first.points[3 * first.points.size() / 4]};
  for (DesignPoint& p : loose.points) {
    const Eigen::Vector3d x = position(scene->target, p.surface);
    p.surface = scene->projector->project(0.5 * x + 0.5 * scene->target.V.colwise().mean().transpose());
  }
  seams.push_back(loose);
  const std::vector<std::array<int, 2>> hosts = openSeamEndHosts(seams, *scene, 1);
  ASSERT_EQ(hosts.size(), seams.size());
  int cuts = 0;
  for (size_t i = 1; i + 1 < seams.size(); ++i) {
    if (seams[i].closed) {
      EXPECT_EQ(hosts[i], (std::array<int, 2>{-1, -1})) << "a loop has no ends";
      continue;
    }
    ++cuts;
    for (const int host : hosts[i]) {
      EXPECT_GE(host, 0) << seams[i].name << " ends on a seam";
      EXPECT_NE(host, int(i)) << "not on itself";
    }
    EXPECT_NE(hosts[i][0], hosts[i][1]) << seams[i].name << " joins two seams";
  }
  EXPECT_GT(cuts, 0) << opened.description();
  EXPECT_EQ(hosts.back(), (std::array<int, 2>{-1, -1})) << "ends that lie on no seam";
}
