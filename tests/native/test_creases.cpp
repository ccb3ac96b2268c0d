// A target's creases (suggest/creases.hpp) and the layouts that seam along them (suggest/seam_layouts.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "crease_shapes.hpp"
#include "io/design_json.hpp"
#include "pattern/design_scene.hpp"
#include "suggest/creases.hpp"
#include "suggest/seam_layouts.hpp"
#include "test_support.hpp"

namespace billow {
namespace {

size_t countClosed(const Creases& set) {
  return size_t(std::count_if(set.creases.begin(), set.creases.end(), [](const Crease& c) { return c.closed; }));
}

// Every crease runs along edges that turn sharply, an open one from junction to junction.
void expectAlongSharpEdges(const TriMesh& mesh, const Creases& set) {
  const MeshTopology topology = buildTopology(mesh);
  for (const Crease& c : set.creases) {
    ASSERT_GE(c.vertices.size(), 2u);
    const SectionLoop path = creasePath(mesh, topology, c);
    // A chain from a junction round to itself is a loop through it.
    const bool round = !c.closed && c.vertices.front() == c.vertices.back();
    const bool loop = c.closed || round;
    ASSERT_EQ(path.size(), c.vertices.size() - round);
    for (size_t k = 0; k < path.size(); ++k) {
      EXPECT_LT((position(mesh, path[k].at) - mesh.V.row(c.vertices[k]).transpose()).norm(), 1e-12);
      // The point's face holds the edge from the point before (the first point of a path: to the one after).
      const int other = k == 0 ? (loop ? c.vertices[path.size() - 1] : c.vertices[1]) : c.vertices[k - 1];
      const auto has = [&](int v) { return (mesh.F.row(path[k].at.face).array() == v).any(); };
      EXPECT_TRUE(has(other) && has(c.vertices[k]));
    }
  }
}

TEST(Creases, ABoxHasTwelveADrumItsTwoRimsAndRoundShapesNone) {
  const TriMesh box = test::boxShape(0.6, 0.4, 0.2);
  const std::vector<Creases> boxSets = findCreases(box);
  ASSERT_FALSE(boxSets.empty());
  EXPECT_EQ(boxSets[0].creases.size(), 12u);
  EXPECT_EQ(boxSets[0].panels, 6);
  EXPECT_EQ(countClosed(boxSets[0]), 0u);
  for (const Crease& c : boxSets[0].creases) {
    const double l = c.length;
    EXPECT_TRUE(std::abs(l - 0.6) < 1e-9 || std::abs(l - 0.4) < 1e-9 || std::abs(l - 0.2) < 1e-9) << l;
  }
  expectAlongSharpEdges(box, boxSets[0]);
  // Fewer creases, fewer panels each time, the longest kept: down to one loop round the box (2 panels).
  for (size_t i = 1; i < boxSets.size(); ++i) EXPECT_LT(boxSets[i].panels, boxSets[i - 1].panels);
  EXPECT_EQ(boxSets.back().panels, 2);
  EXPECT_EQ(countClosed(boxSets.back()), 1u);

  const std::vector<Creases> drumSets = findCreases(test::drumShape(0.25, 0.3));
  ASSERT_FALSE(drumSets.empty());
  EXPECT_EQ(drumSets[0].creases.size(), 2u);
  EXPECT_EQ(countClosed(drumSets[0]), 2u);
  EXPECT_EQ(drumSets[0].panels, 3);  // the top, the bottom and the side (a tube the layout opens)
  EXPECT_NEAR(drumSets[0].creases[0].length, 64 * 2 * 0.25 * std::sin(M_PI / 64), 1e-9);

  // A star cushion: its front and back outlines, and a crease across its side at each tip and notch; with one of those
  // kept, front, back and one gusset strip.
  const TriMesh star = test::starShape(0.3, 0.1);
  const std::vector<Creases> starSets = findCreases(star);
  ASSERT_FALSE(starSets.empty());
  EXPECT_EQ(starSets[0].creases.size(), 30u);
  EXPECT_EQ(starSets[0].panels, 12);
  const auto three = std::find_if(starSets.begin(), starSets.end(), [](const Creases& s) { return s.panels == 3; });
  ASSERT_NE(three, starSets.end());
  EXPECT_EQ(three->creases.size(), 3u);
  expectAlongSharpEdges(star, *three);

  // Round and organic shapes: no crease (their sharpest edges turn as much as those beside them), but the hand's wrist,
  // where its mesh is cut off flat.
  for (const char* name :
       {"sphere.obj", "bunny.obj", "spot.obj", "octopus.obj", "koala.obj", "blub.obj", "penguin.obj", "stuffedtoy.obj"})
    EXPECT_TRUE(findCreases(test::loadShared(name)).empty()) << name;
  const std::vector<Creases> hand = findCreases(test::loadShared("hand.obj"));
  ASSERT_EQ(hand.size(), 1u);
  EXPECT_EQ(hand[0].creases.size(), 1u);
  EXPECT_TRUE(hand[0].creases[0].closed);
}

// A remeshed part's fold is not sharp all along: where a face beside it is skewed, an edge beside turns too (the wing
// nut of odedstein/meshes had its sharp edges in 30 chains with loose ends, peeled away). A drum with faces so
// disturbed at a few places along both rims still has its two rims, each closed, along the edges that turn.
TEST(Creases, AFoldBrokenWhereAFaceBesideItIsSkewedIsOneCrease) {
  TriMesh drum = test::drumShape(0.25, 0.3);
  const auto faceRing = [](bool top, int ring, int i) { return (top ? 0 : 1 + 10 * 64) + 1 + (ring - 1) * 64 + i; };
  // A face beside the rim tilted: the vertex a ring in from the rim lifted off the face.
  drum.V(faceRing(true, 9, 5), 2) += 0.012;
  drum.V(faceRing(false, 9, 40), 2) -= 0.012;
  // A rim vertex moved 6 mm in across the corner: the rim edge beside it still turns 86 degrees, a face beside it too.
  for (const auto& [top, i] : {std::pair{true, 30}, std::pair{false, 12}}) {
    const int v = faceRing(top, 10, i);
    drum.V.row(v).head<2>() *= (0.25 - 0.006) / 0.25, drum.V(v, 2) += top ? -0.006 : 0.006;
  }
  const std::vector<Creases> sets = findCreases(drum);
  ASSERT_FALSE(sets.empty());
  EXPECT_EQ(sets[0].creases.size(), 2u);
  EXPECT_EQ(countClosed(sets[0]), 2u);
  EXPECT_EQ(sets[0].panels, 3);
  expectAlongSharpEdges(drum, sets[0]);
  for (const Crease& c : sets[0].creases) EXPECT_NEAR(c.length, 2 * M_PI * 0.25, 0.03) << c.length;
}

// A modeller's bevel spreads a crease over a few rows of edges, each turning too little to be one: the crease runs
// along the bevel's middle row, so a box whose rims are rounded (in 2 to 6 rows, as a bevel tool makes them) has the
// same 12 creases as a sharp one, and a rounded drum its two rims. A chamfer (one row) stays a strip between two
// creases.
TEST(Creases, ABevelledEdgeIsOneCreaseAlongItsMiddle) {
  const double r = 0.02, wall = 0.08;  // the box 0.6 x 0.4 x 0.2, its rims rounded to radius r
  for (int rows = 2; rows <= 6; ++rows) {
    const TriMesh box = test::extrudedOutline(
        test::polygonOutline({{-0.3, -0.2}, {0.3, -0.2}, {0.3, 0.2}, {-0.3, 0.2}}, 12), 0.2, 8, 6, r, rows);
    const std::vector<Creases> sets = findCreases(box);
    ASSERT_FALSE(sets.empty()) << rows;
    EXPECT_EQ(sets[0].creases.size(), 12u) << rows;
    EXPECT_EQ(sets[0].panels, 6) << rows;
    EXPECT_EQ(sets.back().panels, 2) << rows;
    expectAlongSharpEdges(box, sets[0]);
    // Each crease point on a vertical corner (up its mitre through the bevel), or on a rim between a third and two
    // thirds round its quarter circle.
    for (const Crease& c : sets[0].creases)
      for (int v : c.vertices) {
        const Eigen::Vector3d p = box.V.row(v);
        const bool corner = std::abs((0.3 - std::abs(p.x())) - (0.2 - std::abs(p.y()))) < 1e-9;
        const double z = std::abs(p.z()) - wall;
        EXPECT_TRUE(corner || (z > r * std::sin(M_PI / 6) - 1e-9 && z < r * std::sin(M_PI / 3) + 1e-9))
            << rows << " rows: " << p.transpose();
      }
  }
  std::vector<Eigen::Vector2d> circle;
  for (int i = 0; i < 64; ++i)
    circle.emplace_back(0.3 * std::cos(2 * M_PI * i / 64), 0.3 * std::sin(2 * M_PI * i / 64));
  const std::vector<Creases> drum = findCreases(test::extrudedOutline(circle, 0.15, 10, 8, r, 3));
  ASSERT_FALSE(drum.empty());
  EXPECT_EQ(drum[0].creases.size(), 2u);
  EXPECT_EQ(countClosed(drum[0]), 2u);
  EXPECT_EQ(drum[0].panels, 3);
  // A bevelled star cushion keeps a set of front, back and one gusset strip.
  std::vector<Eigen::Vector2d> star;
  for (int k = 0; k < 10; ++k) {
    const double radius = k % 2 == 0 ? 0.3 : 0.135, angle = M_PI / 2 + M_PI * k / 5;
    star.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  const std::vector<Creases> stars =
      findCreases(test::extrudedOutline(test::polygonOutline(star, 8), 0.1, 10, 3, 0.01, 3));
  EXPECT_TRUE(std::any_of(stars.begin(), stars.end(), [](const Creases& s) { return s.panels == 3; }));
  // A chamfer: two creases, the strip between them a panel of its own.
  const std::vector<Creases> chamfered = findCreases(test::extrudedOutline(
      test::polygonOutline({{-0.3, -0.2}, {0.3, -0.2}, {0.3, 0.2}, {-0.3, 0.2}}, 12), 0.2, 8, 6, r, 1));
  ASSERT_FALSE(chamfered.empty());
  EXPECT_EQ(chamfered[0].panels, 14);
}

// A star cushion sewn along its creases (front, back and a gusset strip round its side) comes far closer than its two
// pieces, halves or sealed along its outline: two flat pieces cannot make its flat sides and sharp rims.
TEST(SeamLayouts, AStarCushionIsSewnAlongItsCreasesAndComesCloserThanItsTwoPieces) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const auto scene = test::sceneOf(test::starShape(0.3, 0.1));
  LayoutRequest request;
  request.panels = 3;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  const LayoutProposal *creases = nullptr, *outline = nullptr, *halves = nullptr;
  for (const LayoutProposal& p : proposals) {
    if (!p.creases.empty()) creases = &p;
    if (p.outlineView == 2 && p.bands == 0) outline = &p;
    if (p.creases.empty() && p.outlineView < 0 && p.gores == 2 && p.bands == 0 && p.planes[0].normal.z() == 1)
      halves = &p;
  }
  ASSERT_NE(creases, nullptr);
  ASSERT_NE(outline, nullptr);
  ASSERT_NE(halves, nullptr);
  EXPECT_EQ(creases->name, "along 3 of its 30 creases");
  const std::vector<DesignSeam> seams = proposalSeams(scene->target, *creases);
  ASSERT_EQ(seams.size(), 3u);
  // The outlines are loops through where the crease across the side meets them, exactly.
  const DesignSeam& across = seams[2];
  EXPECT_FALSE(across.closed);
  for (int k = 0; k < 2; ++k) {
    EXPECT_TRUE(seams[size_t(k)].closed);
    EXPECT_EQ(seams[size_t(k)].name, "crease " + std::to_string(k + 1));
    const Eigen::Vector3d start = position(scene->target, seams[size_t(k)].points.front().surface);
    const double toEnd = std::min((start - position(scene->target, across.points.front().surface)).norm(),
                                  (start - position(scene->target, across.points.back().surface)).norm());
    EXPECT_LT(toEnd, 1e-12);
  }
  for (const DesignSeam& seam : seams)
    for (const DesignPoint& p : seam.points) {
      EXPECT_GE(p.surface.bary.minCoeff(), 0) << seam.name;
      EXPECT_NEAR(p.surface.bary.sum(), 1, 1e-12) << seam.name;
    }
  const EvaluateOptions options;
  const LayoutEvaluation e = evaluateLayout(*scene, seams, 0, options);
  ASSERT_TRUE(e.ok) << e.problem;
  EXPECT_TRUE(scene->segmentation.problems.empty());
  EXPECT_EQ(e.panels, 3);
  for (const LayoutProposal* other : {outline, halves}) {
    const LayoutEvaluation o = evaluateLayout(*scene, proposalSeams(scene->target, *other), 0, options);
    ASSERT_TRUE(o.ok) << o.problem;
    EXPECT_LT(e.distance, 0.8 * o.distance) << other->name << ": " << o.distance << " against " << e.distance;
  }
}

// Where the symmetry is kept, only crease sets that are their own mirror image are laid: the box without one of its
// four short creases is not.
TEST(SeamLayouts, CreaseLayoutsThatKeepTheMirrorSymmetryAreTheirOwnMirrorImage) {
  const TriMesh box = test::boxShape(0.6, 0.4, 0.2);
  const std::vector<Creases> sets = findCreases(box);
  ASSERT_GE(sets.size(), 2u);
  EXPECT_TRUE(mirrorSymmetric(box, sets[0].creases, 0, 0.0, 0.01));
  EXPECT_FALSE(mirrorSymmetric(box, sets[1].creases, 0, 0.0, 0.01));  // one short crease left out
  LayoutRequest request;
  request.panels = 5, request.symmetryAxis = 0;
  int laid = 0;
  for (const LayoutProposal& p : proposeLayouts(box, request)) {
    if (p.creases.empty()) continue;
    ++laid;
    EXPECT_TRUE(mirrorSymmetric(box, p.creases, 0, 0.0, 0.01)) << p.name;
  }
  EXPECT_GE(laid, 1);
  // A star cushion kept its own mirror image across x = 0, where the plane runs through its top tip and its bottom
  // notch: the creases across its side are left out in mirror pairs, and its front, its back and one strip keep the
  // crease at a tip or notch the plane runs through.
  const TriMesh star = test::starShape(0.3, 0.1);
  const std::vector<Creases> starSets = findCreases(star, 0, 0.0);
  const auto three = std::find_if(starSets.begin(), starSets.end(), [](const Creases& s) { return s.panels == 3; });
  ASSERT_NE(three, starSets.end());
  EXPECT_TRUE(mirrorSymmetric(star, three->creases, 0, 0.0, 0.01));
  request.panels = 3;
  bool laidThree = false;
  for (const LayoutProposal& p : proposeLayouts(star, request))
    laidThree = laidThree || p.name == "along 3 of its 30 creases";
  EXPECT_TRUE(laidThree);
  request.panels = 5, request.symmetryAxis = -1;
  bool asymmetric = false;
  for (const LayoutProposal& p : proposeLayouts(box, request))
    asymmetric = asymmetric || (!p.creases.empty() && !mirrorSymmetric(box, p.creases, 0, 0.0, 0.01));
  EXPECT_TRUE(asymmetric);  // without the symmetry, the five-panel set is laid
}

// A box cushion held together inside: its front, its back and the strip round it, the front and the back each cut by a
// band whose two pieces an internal panel joins (a mattress's baffle). Its flat sides bulge least so: closer than the
// same creases without the baffle and than its pillow along the outline held together inside.
TEST(SeamLayouts, ABoxCushionAlongItsCreasesIsHeldTogetherInsideByABaffle) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const auto scene = test::sceneOf(test::boxShape(0.6, 0.4, 0.2));
  LayoutRequest request;
  request.panels = 6;
  const std::vector<LayoutProposal> proposals = proposeLayouts(scene->target, request);
  const LayoutProposal *baffled = nullptr, *pillow = nullptr;
  for (const LayoutProposal& p : proposals) {
    if (!p.creases.empty() && p.connected && p.bands == 1 && p.axis == 1) baffled = &p;
    if (p.outlineView == 2 && p.connected && p.bands == 1 && p.axis == 1) pillow = &p;
  }
  ASSERT_NE(baffled, nullptr);
  ASSERT_NE(pillow, nullptr);
  EXPECT_EQ(baffled->name, "along 3 of its 12 creases, held together inside along 1 band across the vertical axis");
  std::vector<DesignConnection> connections;
  const std::vector<DesignSeam> seams = proposalSeams(scene->target, *baffled, &connections);
  ASSERT_EQ(seams.size(), 5u);  // three creases, the band's front and back pieces
  ASSERT_EQ(connections.size(), 1u);
  EXPECT_EQ(connections[0].seams, (std::vector<int>{3, 4}));
  EXPECT_EQ(seams[3].name, "band 1, front");
  EXPECT_EQ(seams[4].name, "band 1, back");
  // Each piece runs from crease to crease, its ends control points of the creases there: the seams meet exactly.
  for (const DesignSeam& piece : {seams[3], seams[4]}) {
    EXPECT_FALSE(piece.closed);
    for (const DesignPoint* end : {&piece.points.front(), &piece.points.back()}) {
      const Eigen::Vector3d p = position(scene->target, end->surface);
      double nearest = INFINITY;
      for (size_t c = 0; c < 3; ++c)
        for (const DesignPoint& q : seams[c].points)
          nearest = std::min(nearest, (position(scene->target, q.surface) - p).norm());
      EXPECT_LT(nearest, 1e-12) << piece.name;
    }
  }
  const EvaluateOptions options;
  const LayoutEvaluation e = evaluateLayout(*scene, seams, 0, options, connections);
  ASSERT_TRUE(e.ok) << e.problem;
  EXPECT_TRUE(scene->segmentation.problems.empty());
  EXPECT_EQ(e.panels, 6);  // the front and the back in two each, the strip, the baffle
  const LayoutEvaluation plain =
      evaluateLayout(*scene, std::vector<DesignSeam>(seams.begin(), seams.begin() + 3), 0, options);
  std::vector<DesignConnection> pillowConnections;
  const std::vector<DesignSeam> pillowSeams = proposalSeams(scene->target, *pillow, &pillowConnections);
  const LayoutEvaluation outlined = evaluateLayout(*scene, pillowSeams, 0, options, pillowConnections);
  ASSERT_TRUE(outlined.ok) << outlined.problem;
  EXPECT_LT(e.distance, 0.8 * outlined.distance) << e.distance << " against " << outlined.distance;
  ASSERT_TRUE(plain.ok) << plain.problem;
  EXPECT_LT(e.distance, plain.distance) << e.distance << " against " << plain.distance;
}

}  // namespace
}  // namespace billow
