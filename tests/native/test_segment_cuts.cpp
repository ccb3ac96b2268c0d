// Cuts that open a segment that is not a disk (suggest/segment_cuts.hpp): a loop around a handle that goes the short
// way round and leaves the segment whole, and paths through a segment that join all its seam loops; with them a
// suggested layout's segments become panels where plane sections leave a ring or a part with holes.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

#include "handle_shapes.hpp"
#include "pattern/design_scene.hpp"
#include "seams/plane_section.hpp"
#include "suggest/seam_layouts.hpp"
#include "suggest/segment_cuts.hpp"
#include "test_support.hpp"
#include "util/union_find.hpp"

using namespace billow;
using billow::test::ringMesh;
using billow::test::twoHoledSlab;

namespace {

// Consecutive vertices of a path are joined by an edge of the mesh's triangles.
bool joinedByEdges(const TriMesh& m, const std::vector<int>& path, bool closed) {
  std::set<std::pair<int, int>> edges;
  for (int t = 0; t < m.F.rows(); ++t)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(m.F(t, k), m.F(t, (k + 1) % 3)));
  for (size_t i = 0; i + (closed ? 0 : 1) < path.size(); ++i)
    if (!edges.count(std::minmax(path[i], path[(i + 1) % path.size()]))) return false;
  return true;
}

// The length of a path of mesh vertices, closed or not.
double pathLength(const TriMesh& m, const std::vector<int>& path, bool closed) {
  double length = 0;
  for (size_t i = 0; i + (closed ? 0 : 1) < path.size(); ++i)
    length += (m.V.row(path[i]) - m.V.row(path[(i + 1) % path.size()])).norm();
  return length;
}

// A closed seam along a plane section, control points `spacing` apart.
DesignSeam seamAlong(const TriMesh& target, const SectionLoop& loop, double spacing) {
  DesignSeam seam;
  seam.closed = true;
  for (const SurfacePoint& p : sectionSeamPoints(target, loop, spacing)) {
    DesignPoint point;
    point.onSurface = true, point.surface = p;
    seam.points.push_back(point);
  }
  return seam;
}

void segmentWith(DesignScene& scene, const std::vector<DesignSeam>& seams) {
  scene.design.seams = seams;
  traceDesignSeams(scene);
  segmentDesignScene(scene);
}

}  // namespace

TEST(SegmentCuts, TheLoopAroundARingGoesTheShortWayRound) {
  const double R = 1, r = 0.35;
  const TriMesh shape = ringMesh(R, r);
  const auto scene = test::sceneOf(shape);
  segmentWith(*scene, {});
  const Segmentation& sg = scene->segmentation;
  ASSERT_EQ(sg.segments.size(), 1u);
  ASSERT_EQ(sg.segments[0].genus, 1);
  const std::vector<std::vector<int>> loops = loopsAroundHandles(sg, 0);
  ASSERT_EQ(loops.size(), 1u);
  const std::vector<int>& loop = loops[0];
  ASSERT_GE(loop.size(), 3u);
  EXPECT_TRUE(joinedByEdges(sg.mesh, loop, true));
  EXPECT_EQ(std::set<int>(loop.begin(), loop.end()).size(), loop.size()) << "a simple loop";
  // Round the tube (2 pi r, the mesh's 40-gon a little less), not round the hole (2 pi (R - r) and more).
  const double scale = test::boxDiagonal(scene->target) / test::boxDiagonal(shape);
  const double length = pathLength(sg.mesh, loop, true);
  EXPECT_NEAR(length / scale, 2 * test::kPi * r, 0.03 * 2 * test::kPi * r);
  // Where the tube is too thin to seam round, the loop goes round the hole instead (2 pi (R - r) on the inside).
  const std::vector<std::vector<int>> longer = loopsAroundHandles(sg, 0, 1.5 * length);
  ASSERT_EQ(longer.size(), 1u);
  const double around = pathLength(sg.mesh, longer[0], true);
  EXPECT_GE(around, 1.5 * length);
  EXPECT_LT(around / scale, 1.1 * 2 * test::kPi * (R - r));
  // A sphere has no handle.
  const auto ball = test::sharedScene("sphere.obj");
  segmentWith(*ball, {});
  ASSERT_EQ(ball->segmentation.segments.size(), 1u);
  EXPECT_TRUE(loopsAroundHandles(ball->segmentation, 0).empty());
}

TEST(SegmentCuts, PathsThroughAPartJoinAllItsLoopsOnce) {
  // The sphere with three caps cut off around three axes: the rest is one part with three seam loops.
  const auto scene = test::sharedScene("sphere.obj");
  const TriMesh& target = scene->target;
  const Eigen::Vector3d center = 0.5 * (target.V.colwise().maxCoeff() + target.V.colwise().minCoeff()).transpose();
  const double radius = 0.5 * (target.V.col(0).maxCoeff() - target.V.col(0).minCoeff());
  std::vector<DesignSeam> seams;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d n = Eigen::Vector3d::Unit(axis);
    const std::vector<SectionLoop> loops = planeSection(target, n, n.dot(center) + 0.8 * radius);
    ASSERT_EQ(loops.size(), 1u);
    seams.push_back(seamAlong(target, loops[0], 0.05 * radius));
  }
  segmentWith(*scene, seams);
  const Segmentation& sg = scene->segmentation;
  int part = -1;
  for (int s = 0; s < int(sg.segments.size()); ++s)
    if (sg.segments[size_t(s)].loops.size() == 3) part = s;
  ASSERT_GE(part, 0);
  const Segment& rest = sg.segments[size_t(part)];
  const std::vector<std::vector<int>> cuts = cutsJoiningLoops(sg, part);
  ASSERT_EQ(cuts.size(), 2u);
  std::vector<int> loopOf(size_t(sg.mesh.V.rows()), -1);
  for (size_t l = 0; l < rest.loops.size(); ++l)
    for (int v : rest.loops[l].vertices) loopOf[size_t(v)] = int(l);
  std::set<int> inside;
  for (int t : rest.triangles)
    for (int k = 0; k < 3; ++k) inside.insert(sg.mesh.F(t, k));
  UnionFind joined(3);
  for (const std::vector<int>& cut : cuts) {
    ASSERT_GE(cut.size(), 2u);
    EXPECT_TRUE(joinedByEdges(sg.mesh, cut, false));
    const int from = loopOf[size_t(cut.front())], to = loopOf[size_t(cut.back())];
    ASSERT_GE(from, 0);
    ASSERT_GE(to, 0);
    EXPECT_NE(joined.find(from), joined.find(to)) << "two cuts between the same loops cut a piece off";
    joined.unite(from, to);
    for (size_t i = 1; i + 1 < cut.size(); ++i) {
      EXPECT_EQ(loopOf[size_t(cut[i])], -1) << "a cut runs through the part, off its seams";
      EXPECT_TRUE(inside.count(cut[i]));
    }
  }
  EXPECT_EQ(joined.find(1), joined.find(0));
  EXPECT_EQ(joined.find(2), joined.find(0));

  // As a suggested layout: the cuts open the part, in one round.
  EvaluateOptions look;
  look.maxIterations = 0;
  look.openingRounds = 1;
  const LayoutEvaluation e = evaluateLayout(*scene, seams, 0, look);
  ASSERT_TRUE(e.ok) << e.problem;
  EXPECT_EQ(e.panels, 4);
  EXPECT_EQ(e.opened.tubeCuts, 2);
}

// A ring with a patch cut off its outside: the rest goes round the hole and is no panel until a seam goes round its
// tube and cuts join that seam's two sides and the patch's seam; the layout says so.
TEST(SegmentCuts, ARingIsOpenedAroundItsHandle) {
  const TriMesh shape = ringMesh(1, 0.35, 90, 30);
  const auto scene = test::sceneOf(shape);
  const TriMesh& target = scene->target;
  const double right = target.V.col(0).maxCoeff(), width = right - target.V.col(0).minCoeff();
  const std::vector<SectionLoop> patch = planeSection(target, Eigen::Vector3d::UnitX(), right - 0.05 * width);
  ASSERT_EQ(patch.size(), 1u);
  const DesignSeam seam = seamAlong(target, patch[0], 0.01 * width);
  EvaluateOptions look;
  look.maxIterations = 0;
  const LayoutEvaluation e = evaluateLayout(*scene, {seam}, 1, look);
  ASSERT_TRUE(e.ok) << e.problem;
  EXPECT_EQ(e.panels, 2);
  EXPECT_EQ(e.opened.handleSeams, 1);
  EXPECT_EQ(e.opened.tubeCuts, 2);
  EXPECT_NE(e.description().find("1 seam around a handle"), std::string::npos) << e.description();
}

// A part with two handles gets a loop around each in one round, apart from each other; sewn along both it keeps no
// handle, and the cuts join its four loops.
TEST(SegmentCuts, APartWithTwoHandlesGetsALoopAroundEach) {
  const auto scene = test::sceneOf(twoHoledSlab());
  segmentWith(*scene, {});
  const Segmentation& sg = scene->segmentation;
  ASSERT_EQ(sg.segments.size(), 1u);
  ASSERT_EQ(sg.segments[0].genus, 2);
  const std::vector<std::vector<int>> loops = loopsAroundHandles(sg, 0);
  ASSERT_EQ(loops.size(), 2u);
  std::set<int> seen;
  std::vector<DesignSeam> seams;
  for (const std::vector<int>& loop : loops) {
    EXPECT_TRUE(joinedByEdges(sg.mesh, loop, true));
    DesignSeam seam;
    seam.closed = true;
    for (int v : loop) {
      EXPECT_TRUE(seen.insert(v).second) << "the loops are apart";
      DesignPoint point;
      point.onSurface = true, point.surface = sg.vertexOrigin[size_t(v)];
      seam.points.push_back(point);
    }
    seams.push_back(seam);
  }
  segmentWith(*scene, seams);
  const Segmentation& sewn = scene->segmentation;
  ASSERT_EQ(sewn.segments.size(), 1u) << "the loops cut nothing off";
  EXPECT_EQ(sewn.segments[0].genus, 0);
  EXPECT_EQ(sewn.segments[0].loops.size(), 4u);
  EXPECT_EQ(cutsJoiningLoops(sewn, 0).size(), 3u);
}

namespace {

// An apple peel on the shared sphere: a cap round each pole and a seam that spirals `turns` times from one to the
// other.
std::vector<DesignSeam> peelSeams(const DesignScene& scene, int turns) {
  const TriMesh& target = scene.target;
  // A design's points are in the mesh's own units.
  const Eigen::Vector3d center =
      0.5 * (target.V.colwise().maxCoeff() + target.V.colwise().minCoeff()).transpose() / scene.scale;
  const double radius = 0.5 * (target.V.col(0).maxCoeff() - target.V.col(0).minCoeff()) / scene.scale;
  const auto at = [&](double polar, double around) {
    DesignPoint point;
    point.position = center + radius * Eigen::Vector3d(std::sin(polar) * std::cos(around), std::cos(polar),
                                                       std::sin(polar) * std::sin(around));
    return point;
  };
  // From a cap round one pole to a cap round the other.
  std::vector<DesignSeam> seams(3);
  const int n = 30 * turns;
  for (int k = 0; k < 12; ++k)
    for (int cap : {0, 1}) seams[size_t(cap)].points.push_back(at(cap ? test::kPi - 0.3 : 0.3, 2 * test::kPi * k / 12));
  seams[0].closed = seams[1].closed = true;
  DesignSeam& peel = seams[2];
  for (int k = 0; k <= n; ++k) {
    const double t = double(k) / n;
    peel.points.push_back(at(0.3 + t * (test::kPi - 0.6), 2 * test::kPi * turns * t));
  }
  return seams;
}

}  // namespace

// An apple peel: the sphere cut along a seam that spirals six times from a cap round one pole to a cap round the other
// is one long strip, and laid flat it curls. The layout cuts it across where its outline crosses itself, until its
// pieces lie flat.
TEST(SegmentCuts, APeelThatWouldOverlapItselfFlatIsCutAcross) {
  const auto scene = test::sharedScene("sphere.obj");
  const int turns = 6;
  const std::vector<DesignSeam> seams = peelSeams(*scene, turns);
  const double radius = 0.5 * (scene->target.V.col(0).maxCoeff() - scene->target.V.col(0).minCoeff()) / scene->scale;
  segmentWith(*scene, seams);
  const Segmentation& sg = scene->segmentation;
  ASSERT_TRUE(sg.problems.empty()) << sg.problems[0].message;
  ASSERT_EQ(sg.segments.size(), 3u);
  int stripIndex = 0;
  for (int s = 1; s < 3; ++s)
    if (sg.segments[size_t(s)].area > sg.segments[size_t(stripIndex)].area) stripIndex = s;
  // Looked at with 150 triangles, the flattened coil's outline, resampled at that edge length, crosses itself; each cut
  // across shortens the coil, and it takes several.
  EvaluateOptions look;
  look.maxIterations = 0;
  look.triangles = 150;
  look.openingRounds = 8;
  {
    const BuiltPattern built = buildDesignPattern(*scene, look.triangles);
    ASSERT_FALSE(built.ok());
    EXPECT_EQ(built.problems[0].code, "pattern.overlaps") << built.problems[0].message;
  }

  // The cut: from the peel's edge through its inside to the next turn, straight across.
  const Segment& strip = sg.segments[size_t(stripIndex)];
  ASSERT_EQ(strip.loops.size(), 1u);
  const std::vector<int>& loop = strip.loops[0].vertices;
  const std::vector<int> path = cutAcross(sg, stripIndex, sg.mesh.V.row(loop[loop.size() / 3]).transpose());
  ASSERT_GE(path.size(), 2u);
  EXPECT_TRUE(joinedByEdges(sg.mesh, path, false));
  const std::set<int> onLoop(loop.begin(), loop.end());
  EXPECT_TRUE(onLoop.count(path.front()) && onLoop.count(path.back()));
  for (size_t i = 1; i + 1 < path.size(); ++i) EXPECT_FALSE(onLoop.count(path[i])) << "through the inside";
  const double length = pathLength(sg.mesh, path, false);
  double loopLength = 0, from = 0, apart = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    if (loop[i] == path.front()) from = loopLength;
    if (loop[i] == path.back()) apart = loopLength;
    loopLength += (sg.mesh.V.row(loop[i]) - sg.mesh.V.row(loop[(i + 1) % loop.size()])).norm();
  }
  apart = std::abs(apart - from);
  EXPECT_GE(std::min(apart, loopLength - apart), 2 * length) << "across, not round a corner";
  // A turn apart: (pi - 0.6) / 6 of the sphere's radius along a meridian, give or take the mesh.
  const double turn = (test::kPi - 0.6) / turns * radius * scene->scale;
  EXPECT_LT(length, 1.3 * turn);

  const LayoutEvaluation e = evaluateLayout(*scene, seams, 3, look);
  ASSERT_TRUE(e.ok) << e.problem << " (" << e.description() << ")";
  EXPECT_GE(e.opened.acrossCuts, 1);
  EXPECT_EQ(e.panels, 3 + e.opened.acrossCuts);
  EXPECT_EQ(int(e.seams.size()), 3 + e.opened.acrossCuts);
  EXPECT_NE(e.description().find(std::to_string(e.opened.acrossCuts) + " cut"), std::string::npos) << e.description();
  EXPECT_NE(e.description().find("would overlap"), std::string::npos) << e.description();
}

// What the Outline tool adds on a shape with handles (openIntoPanels) cuts a panel that would overlap itself across
// too, as the builder's message advises: a boot seen from its front left its back in one piece that curled. A peel of
// six turns, looked at with 150 triangles.
TEST(SegmentCuts, ThePanelsTheOutlineOpensAreCutAcrossWhereTheyWouldOverlap) {
  const auto scene = test::sharedScene("sphere.obj");
  const std::vector<DesignSeam> seams = peelSeams(*scene, 6);
  segmentWith(*scene, seams);
  ASSERT_TRUE(scene->segmentation.problems.empty()) << scene->segmentation.problems[0].message;
  ASSERT_FALSE(buildDesignPattern(*scene, 150).ok()) << "the peel curls over itself, laid flat";
  const LayoutEvaluation opened = openIntoPanels(*scene, seams, 3, {}, 150);
  ASSERT_TRUE(opened.ok) << opened.problem;
  EXPECT_GE(opened.opened.acrossCuts, 1);
  ASSERT_EQ(int(opened.seams.size()), 3 + opened.opened.acrossCuts);
  EXPECT_EQ(opened.seams[2].points.size(), seams[2].points.size()) << "the seams given stay";
  EXPECT_NE(opened.description().find("would overlap"), std::string::npos) << opened.description();
  EXPECT_TRUE(buildDesignPattern(*scene, 150).ok()) << "the scene is left with the cut panels, which lie flat";
}

namespace {

// A tail: a tube of radius r whose axis curls round a circle of radius R through `turn` radians, each end rounded by
// a half sphere; `rings` rings of `around` vertices along the curl, `capRings` over each half sphere.
TriMesh curledTail(double R, double r, double turn, int rings = 60, int around = 24, int capRings = 6) {
  const auto axis = [&](double s) { return Eigen::Vector3d(R * std::sin(s / R), R * (1 - std::cos(s / R)), 0); };
  const auto tangent = [&](double s) { return Eigen::Vector3d(std::cos(s / R), std::sin(s / R), 0); };
  const auto normal = [&](double s) { return Eigen::Vector3d(-std::sin(s / R), std::cos(s / R), 0); };
  const double length = R * turn;
  // Each ring: its centre on the axis, pushed out along the tangent over the caps, and its radius.
  std::vector<std::pair<Eigen::Vector3d, double>> centers;
  std::vector<Eigen::Vector3d> normals;
  for (int k = 1; k < capRings; ++k) {
    const double phi = 0.5 * test::kPi * k / capRings;
    centers.push_back({axis(0) - r * std::cos(phi) * tangent(0), r * std::sin(phi)}), normals.push_back(normal(0));
  }
  for (int k = 0; k <= rings; ++k) {
    const double s = length * k / rings;
    centers.push_back({axis(s), r}), normals.push_back(normal(s));
  }
  for (int k = capRings - 1; k >= 1; --k) {
    const double phi = 0.5 * test::kPi * k / capRings;
    centers.push_back({axis(length) + r * std::cos(phi) * tangent(length), r * std::sin(phi)});
    normals.push_back(normal(length));
  }
  const int n = int(centers.size());
  TriMesh m;
  m.V.resize(n * around + 2, 3), m.F.resize(2 * (n - 1) * around + 2 * around, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < around; ++j) {
      const double v = 2 * test::kPi * j / around;
      m.V.row(i * around + j) =
          centers[size_t(i)].first +
          centers[size_t(i)].second * (std::cos(v) * normals[size_t(i)] + std::sin(v) * Eigen::Vector3d::UnitZ());
    }
  const int first = n * around, last = first + 1;
  m.V.row(first) = axis(0) - r * tangent(0);
  m.V.row(last) = axis(length) + r * tangent(length);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j < around; ++j) {
      const int a = i * around + j, b = (i + 1) * around + j, c = (i + 1) * around + (j + 1) % around,
                d = i * around + (j + 1) % around;
      m.F.row(f++) = Eigen::Vector3i(a, d, c), m.F.row(f++) = Eigen::Vector3i(a, c, b);
    }
  for (int j = 0; j < around; ++j) {
    m.F.row(f++) = Eigen::Vector3i(first, (j + 1) % around, j);
    m.F.row(f++) = Eigen::Vector3i(last, (n - 1) * around + j, (n - 1) * around + (j + 1) % around);
  }
  return m;
}

// The pieces a path cuts a segment into: each one's area and the length of its outline (its part of the segment's loops
// and of the path).
std::vector<std::pair<double, double>> piecesCutBy(const Segmentation& sg, int segment, const std::vector<int>& path) {
  const TriMesh& m = sg.mesh;
  std::set<std::pair<int, int>> cutEdges, loopEdges;
  for (size_t i = 0; i + 1 < path.size(); ++i) cutEdges.insert(std::minmax(path[i], path[i + 1]));
  for (const BoundaryLoop& loop : sg.segments[size_t(segment)].loops)
    for (size_t i = 0; i < loop.vertices.size(); ++i)
      loopEdges.insert(std::minmax(loop.vertices[i], loop.vertices[(i + 1) % loop.vertices.size()]));
  const std::vector<int>& triangles = sg.segments[size_t(segment)].triangles;
  std::map<std::pair<int, int>, int> firstBeside;
  UnionFind parts(int(triangles.size()));
  for (int i = 0; i < int(triangles.size()); ++i)
    for (int k = 0; k < 3; ++k) {
      const auto edge = std::minmax(m.F(triangles[size_t(i)], k), m.F(triangles[size_t(i)], (k + 1) % 3));
      if (cutEdges.count(edge) || loopEdges.count(edge)) continue;
      const auto [it, added] = firstBeside.emplace(edge, i);
      if (!added) parts.unite(i, it->second);
    }
  std::map<int, std::pair<double, double>> sizes;
  for (int i = 0; i < int(triangles.size()); ++i) {
    const int t = triangles[size_t(i)];
    const Eigen::Vector3d p0 = m.V.row(m.F(t, 0)), p1 = m.V.row(m.F(t, 1)), p2 = m.V.row(m.F(t, 2));
    auto& [area, outline] = sizes[parts.find(i)];
    area += 0.5 * (p1 - p0).cross(p2 - p0).norm();
    for (int k = 0; k < 3; ++k) {
      const auto edge = std::minmax(m.F(t, k), m.F(t, (k + 1) % 3));
      if (cutEdges.count(edge) || loopEdges.count(edge)) outline += (m.V.row(edge.first) - m.V.row(edge.second)).norm();
    }
  }
  std::vector<std::pair<double, double>> out;
  for (const auto& [part, size] : sizes) out.push_back(size);
  return out;
}

}  // namespace

// A curled tail sewn round near its root: the rest, a long curled tube closed at its tip, is too big for its seam. A
// section across it would leave a tube, its end still too big; cut along its length through its tip, from its seam to
// the seam's far side, it is two pieces.
TEST(SegmentCuts, ALimbsEndTooBigForItsSeamIsCutAlongThroughItsTip) {
  const TriMesh shape = curledTail(0.5, 0.1, 4.0, 80);
  test::expectClosedSurface(shape, 0);
  const auto scene = test::sceneOf(shape);
  const TriMesh& target = scene->target;
  const double size = test::boxDiagonal(target);
  // The tail as the scene stands it (0.6 m tall): its root end, and the tangent there.
  const Eigen::Vector3d rootTip = target.V.row(shape.V.rows() - 2), farTip = target.V.row(shape.V.rows() - 1);
  const Eigen::Vector3d along = (target.V.row(0) - target.V.row(shape.V.rows() - 2)).normalized();
  const std::vector<SectionLoop> root = planeSection(target, along, along.dot(rootTip) + 0.05 * size);
  ASSERT_EQ(root.size(), 1u);
  const DesignSeam seam = seamAlong(target, root[0], 0.01 * size);
  segmentWith(*scene, {seam});
  const Segmentation& sg = scene->segmentation;
  ASSERT_EQ(sg.segments.size(), 2u);
  const int tail = sg.segments[0].area > sg.segments[1].area ? 0 : 1;
  ASSERT_FALSE(sg.problems.empty());
  EXPECT_EQ(sg.problems[0].code, "segment.too-big-for-seam");
  EXPECT_EQ(sg.problems[0].segment, tail);

  const std::vector<int> path = cutAlong(sg, tail, SegmentationOptions{}.minFlatShare);
  ASSERT_GE(path.size(), 3u);
  EXPECT_TRUE(joinedByEdges(sg.mesh, path, false));
  const std::vector<int>& loop = sg.segments[size_t(tail)].loops[0].vertices;
  const std::set<int> onLoop(loop.begin(), loop.end());
  EXPECT_TRUE(onLoop.count(path.front()) && onLoop.count(path.back()));
  std::set<int> visited;
  double nearestTip = INFINITY;
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    EXPECT_FALSE(onLoop.count(path[i])) << "through the inside";
    EXPECT_TRUE(visited.insert(path[i]).second) << "the path does not cross itself";
    nearestTip = std::min(nearestTip, (sg.mesh.V.row(path[i]).transpose() - farTip).norm());
  }
  EXPECT_LT(nearestTip, 0.02 * size) << "it runs round the tip";
  // Its ends half the loop apart, on either side of the tail.
  double loopLength = 0, from = 0, to = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    if (loop[i] == path.front()) from = loopLength;
    if (loop[i] == path.back()) to = loopLength;
    loopLength += (sg.mesh.V.row(loop[i]) - sg.mesh.V.row(loop[(i + 1) % loop.size()])).norm();
  }
  const double apart = std::min(std::abs(to - from), loopLength - std::abs(to - from));
  EXPECT_GT(apart, 0.4 * loopLength);
  // Two halves of about equal area (a path down the curl's shorter inner side and back round near the seam would cut a
  // strip off).
  const std::vector<std::pair<double, double>> halves = piecesCutBy(sg, tail, path);
  ASSERT_EQ(halves.size(), 2u);
  const double tailArea = halves[0].first + halves[1].first;
  for (const auto& [area, outline] : halves) EXPECT_GT(area, 0.4 * tailArea);

  // As a suggested layout, in one round: three panels, none too big for its seam, and no tube left.
  EvaluateOptions look;
  look.maxIterations = 0;
  look.openingRounds = 1;
  const LayoutEvaluation e = evaluateLayout(*scene, {seam}, 1, look);
  ASSERT_TRUE(e.ok) << e.problem;
  EXPECT_EQ(e.panels, 3);
  EXPECT_EQ(e.opened.limbEndCuts, 1);
  EXPECT_EQ(e.opened.tubeCuts, 0);
  EXPECT_NE(e.description().find("1 cut along a limb's end"), std::string::npos) << e.description();
}

// The hand with a seam round its wrist: the rest, five fingers on a palm, is too big for that seam. A cut along it is
// made only where it leaves no piece too big for its seam (else the section across opens it): given the share a flat
// panel must cover, it is refused just above the smaller of its pieces' shares.
TEST(SegmentCuts, ACutAlongLeavesNoPieceTooBigForItsSeam) {
  const auto scene = test::sharedScene("hand.obj");
  const TriMesh& target = scene->target;
  const Eigen::Vector3d low = target.V.colwise().minCoeff(), high = target.V.colwise().maxCoeff();
  Eigen::Index axis = 0;
  (high - low).maxCoeff(&axis);
  const Eigen::Vector3d n = Eigen::Vector3d::Unit(axis);
  std::vector<DesignSeam> seams;
  for (const double at : {0.06, 0.94}) {
    const std::vector<SectionLoop> loops = planeSection(target, n, low[axis] + at * (high - low)[axis]);
    if (loops.size() == 1) seams.push_back(seamAlong(target, loops[0], 0.01 * test::boxDiagonal(target)));
  }
  ASSERT_EQ(seams.size(), 1u) << "one end of the hand is the wrist, cut in one loop";
  segmentWith(*scene, seams);
  const Segmentation& sg = scene->segmentation;
  ASSERT_EQ(sg.segments.size(), 2u);
  const int hand = sg.segments[0].area > sg.segments[1].area ? 0 : 1;
  ASSERT_TRUE(std::any_of(sg.problems.begin(), sg.problems.end(), [&](const SegmentationProblem& p) {
    return p.code == "segment.too-big-for-seam" && p.segment == hand;
  }));
  const std::vector<int> path = cutAlong(sg, hand, 0);
  ASSERT_FALSE(path.empty());
  const std::vector<std::pair<double, double>> pieces = piecesCutBy(sg, hand, path);
  ASSERT_EQ(pieces.size(), 2u);
  double smallest = INFINITY;
  for (const auto& [area, outline] : pieces) smallest = std::min(smallest, outline * outline / (4 * test::kPi * area));
  EXPECT_GE(smallest, SegmentationOptions{}.minFlatShare) << "the hand's halves fit their seams";
  EXPECT_EQ(cutAlong(sg, hand, 0.99 * smallest), path);
  EXPECT_TRUE(cutAlong(sg, hand, 1.01 * smallest).empty());
}
