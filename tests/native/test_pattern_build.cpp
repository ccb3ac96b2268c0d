// The pattern builder (pattern/build_pattern.hpp): panels are disks with no flipped triangle, both sides of
// every seam have the same samples and are stitched k <-> N - k, corners of three panels are chained, the
// sewn outer surface is closed, and every panel vertex starts on the target.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "io/mesh_file.hpp"
#include "panel_checks.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/panel_stages.hpp"
#include "pattern/segment_pieces.hpp"
#include "remesh/panel_mesher.hpp"
#include "test_support.hpp"
#include "util/union_find.hpp"

using namespace billow;
using billow::test::dataPath;
using billow::test::examplesDir;
using billow::test::expectDisk;
using billow::test::panelArea;
using billow::test::signedArea;

namespace {

std::unique_ptr<DesignScene> fixture(const std::string& name) {
  const std::string path = dataPath(name);
  return makeDesignScene(readDesignJson(readFileBytes(path)), path, {examplesDir()});
}

// Properties every built pattern of a closed target must have.
void expectSound(const DesignScene& scene, const BuiltPattern& bp) {
  const Pattern& pat = bp.pattern;
  ASSERT_EQ(pat.panels.size(), bp.panels.size());
  ASSERT_EQ(pat.inflated.size(), pat.panels.size());
  std::vector<std::set<int>> stitched(pat.panels.size());
  for (const Stitch& s : pat.stitches) stitched[s.panelA].insert(s.vertexA), stitched[s.panelB].insert(s.vertexB);
  const double diag = (scene.target.V.colwise().maxCoeff() - scene.target.V.colwise().minCoeff()).norm();
  for (size_t p = 0; p < pat.panels.size(); ++p) {
    const Panel& panel = pat.panels[p];
    const BuiltPanel& built = bp.panels[p];
    const std::string what = panel.name;
    expectDisk(panel, built.boundaryVertices, what);
    for (int t = 0; t < panel.triangles.rows(); ++t) EXPECT_GT(signedArea(panel, t), 0) << what << " triangle " << t;
    // Every boundary vertex is stitched, but the tip of a slit: there both sides of the slit meet in one vertex.
    std::set<int> tips;
    for (const PanelPiece& a : built.pieces) {
      if (a.neighborPanel != static_cast<int>(p)) continue;
      const PanelPiece& b = built.pieces[a.neighborPiece];
      if (a.rows.back() == b.rows.front()) tips.insert(a.rows.back());
    }
    for (int v = 0; v < built.boundaryVertices; ++v)
      EXPECT_TRUE(stitched[p].count(v) || tips.count(v)) << what << " vertex " << v;
    for (int v = built.boundaryVertices; v < panel.vertices.rows(); ++v) EXPECT_EQ(built.seam[v], -1);
    // Exact: the same number of samples on both sides of a piece, and the partner's partner is the piece.
    for (size_t k = 0; k < built.pieces.size(); ++k) {
      const PanelPiece& a = built.pieces[k];
      ASSERT_GE(a.neighborPanel, 0) << what;
      const PanelPiece& b = bp.panels[a.neighborPanel].pieces[a.neighborPiece];
      EXPECT_EQ(a.rows.size(), b.rows.size());
      EXPECT_EQ(b.neighborPanel, static_cast<int>(p));
      EXPECT_EQ(b.neighborPiece, static_cast<int>(k));
      EXPECT_EQ(a.seam, b.seam);
      EXPECT_NEAR(a.targetLength, b.targetLength, 1e-12);
    }
    // Start positions on the target, and the surface points give the same positions.
    for (int v = 0; v < panel.vertices.rows(); ++v) {
      double d = 0;
      scene.projector->project(built.targetPosition.row(v).transpose(), &d);
      EXPECT_LT(d, 1e-9 * diag) << what << " vertex " << v;
      EXPECT_LT((position(scene.target, built.targetPoint[v]) - built.targetPosition.row(v).transpose()).norm(),
                1e-9 * diag);
    }
  }
  const SewnMesh sewn = sewPattern(pat);  // throws pattern.open when the outer surface does not close
  EXPECT_EQ(static_cast<int>(outerTriangles(sewn).rows()), bp.figures.triangles);
}

// Groups of stitched panel vertices (one simulation vertex each), by size.
std::map<int, int> groupSizes(const BuiltPattern& bp) {
  const SewnMesh sewn = sewPattern(bp.pattern);
  std::map<int, int> sizes;
  for (int c : sewn.stitchedCount) ++sizes[c];
  return sizes;
}

// A capsule along x: a tube of radius r, `length` long, closed by hemispheres; `around` vertices to a ring, the rings
// staggered, triangles facing out.
TriMesh capsule(int around, double r, double length) {
  const double h = 2 * M_PI * r / around;
  const int rings = static_cast<int>(length / h), cap = around / 4;
  std::vector<std::pair<double, double>> profile;  // (x, radius) of each ring
  for (int i = 1; i < cap; ++i) {
    const double phi = M_PI / 2 * (1 - static_cast<double>(i) / cap);
    profile.emplace_back(-length / 2 - r * std::sin(phi), r * std::cos(phi));
  }
  for (int i = 0; i <= rings; ++i) profile.emplace_back(-length / 2 + length * i / rings, r);
  for (int i = 1; i < cap; ++i) {
    const double phi = M_PI / 2 * i / cap;
    profile.emplace_back(length / 2 + r * std::sin(phi), r * std::cos(phi));
  }
  const int n = static_cast<int>(profile.size());
  TriMesh m;
  m.V.resize(n * around + 2, 3);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < around; ++j) {
      const double a = 2 * M_PI * (j + 0.5 * (k % 2)) / around;
      m.V.row(k * around + j) << profile[k].first, profile[k].second * std::cos(a), profile[k].second * std::sin(a);
    }
  const int tip0 = n * around, tip1 = tip0 + 1;
  m.V.row(tip0) << -length / 2 - r, 0, 0;
  m.V.row(tip1) << length / 2 + r, 0, 0;
  const auto id = [&](int k, int j) { return k * around + (j % around); };
  std::vector<Eigen::Vector3i> F;
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j < around; ++j) {
      if (k % 2 == 0) {
        F.emplace_back(id(k, j), id(k, j + 1), id(k + 1, j));
        F.emplace_back(id(k, j + 1), id(k + 1, j + 1), id(k + 1, j));
      } else {
        F.emplace_back(id(k, j), id(k, j + 1), id(k + 1, j + 1));
        F.emplace_back(id(k, j), id(k + 1, j + 1), id(k + 1, j));
      }
    }
  for (int j = 0; j < around; ++j) {
    F.emplace_back(tip0, id(0, j + 1), id(0, j));
    F.emplace_back(tip1, id(n - 1, j), id(n - 1, j + 1));
  }
  m.F.resize(static_cast<int>(F.size()), 3);
  for (size_t f = 0; f < F.size(); ++f) m.F.row(static_cast<int>(f)) = F[f].transpose();
  return m;
}

}  // namespace

TEST(PatternBuild, SphereEquatorGivesTwoStitchedHemispheres) {
  const auto scene = fixture("sphere-equator.billow.json");
  ASSERT_TRUE(scene->segmentation.ok());
  const auto t0 = std::chrono::steady_clock::now();
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(bp.ok()) << (bp.problems.empty() ? "" : bp.problems[0].message);
  ASSERT_EQ(bp.pattern.panels.size(), 2u);
  expectSound(*scene, bp);
  EXPECT_EQ(bp.pattern.panels[0].name, "Panel 1");
  EXPECT_FALSE(bp.pattern.panels[0].internal);
  EXPECT_DOUBLE_EQ(bp.pattern.material.thickness, 25e-6);
  EXPECT_DOUBLE_EQ(bp.pattern.material.youngsModulus, 3e9);
  EXPECT_DOUBLE_EQ(bp.pattern.pressure, 1000.0);
  // The equator is one closed piece per panel: one corner each, N equal on both sides.
  EXPECT_EQ(bp.panels[0].pieces.size(), 1u);
  EXPECT_EQ(bp.panels[0].boundaryVertices, bp.panels[1].boundaryVertices);
  // ~3k triangles by default on a 0.5 m sphere.
  EXPECT_GT(bp.figures.triangles, 2400);
  EXPECT_LT(bp.figures.triangles, 4000);
  // Area: Eq. 14 keeps the boundary length L and the interior is harmonic, so a hemisphere flattens to
  // about a disc: by the isoperimetric inequality its area is at most L^2 / (4 pi) (+2 % for boundary length
  // error), about half the segment's (the traced equator is not exactly in the middle: we check from 0.45 of
  // it), and the remeshed panels keep the flattened area within 1 % (chords of the resampled boundary).
  for (size_t p = 0; p < 2; ++p) {
    const double segArea = scene->segmentation.segments[bp.panels[p].segment].area;
    const double a = panelArea(bp.pattern.panels[p]);
    double L = 0;
    for (const PanelPiece& piece : bp.panels[p].pieces) L += piece.targetLength;
    EXPECT_GT(a / segArea, 0.45);
    EXPECT_LT(a, 1.02 * L * L / (4 * M_PI));
    EXPECT_LT(a / segArea, 0.53);
    EXPECT_NEAR(a, bp.panels[p].flattenAreaRatio * segArea, 0.01 * a);
  }
  // The start positions lie on the sphere of radius 0.25: never outside it, and inside by at most the sag of
  // the 1280-triangle icosphere's flat triangles (edge ~0.1 r: sag < 0.5 %).
  for (const BuiltPanel& b : bp.panels)
    for (int v = 0; v < b.targetPosition.rows(); ++v) {
      const double r = b.targetPosition.row(v).norm();
      EXPECT_LT(r, 0.25 * (1 + 1e-6));
      EXPECT_GT(r, 0.25 * (1 - 5e-3));
    }
  // Seam vertices: seam 0, on the traced seam curve (a polyline over the faces, not exactly y = 0).
  const SeamCurve& equator = scene->curves[0];
  for (const BuiltPanel& b : bp.panels)
    for (int v = 0; v < b.boundaryVertices; ++v) {
      EXPECT_EQ(b.seam[v], 0);
      double best = 1e300;
      const Eigen::Vector3d x = b.targetPosition.row(v).transpose();
      for (size_t i = 0; i + 1 < equator.points.size(); ++i) {
        const Eigen::Vector3d a = equator.points[i].position, d = equator.points[i + 1].position - a;
        const double t = std::clamp((x - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
        best = std::min(best, (a + t * d - x).norm());
      }
      EXPECT_LT(best, 1e-9) << "seam vertex " << v << " is off the seam";
    }
  // Not exact before optimization: the two flattened boundaries differ. Reported, and small here by symmetry.
  EXPECT_LT(bp.figures.maxSeamLengthMismatch, 0.02);
  EXPECT_LT(bp.figures.maxStitchTargetDistance, 0.5 * bp.figures.edgeLength);
  std::printf(
      "[figures] sphere equator: %d panels, %d triangles, %d stitches, h %.4f m, seam mismatch %.2e "
      "(edges %.2e), stitch target distance %.2e m, area ratio %.3f / %.3f, build %.1f ms (flatten %.1f, "
      "mesh %.1f)\n",
      bp.figures.panels, bp.figures.triangles, bp.figures.stitches, bp.figures.edgeLength,
      bp.figures.maxSeamLengthMismatch, bp.figures.maxEdgeLengthMismatch, bp.figures.maxStitchTargetDistance,
      bp.panels[0].flattenAreaRatio, bp.panels[1].flattenAreaRatio, ms, bp.figures.flattenMs, bp.figures.meshMs);
}

TEST(PatternBuild, ThreeGoresChainThePoles) {
  const auto scene = fixture("sphere-gores.billow.json");
  ASSERT_TRUE(scene->segmentation.ok());
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation);
  ASSERT_TRUE(bp.ok()) << (bp.problems.empty() ? "" : bp.problems[0].message);
  ASSERT_EQ(bp.pattern.panels.size(), 3u);
  expectSound(*scene, bp);
  for (const BuiltPanel& b : bp.panels) {
    EXPECT_EQ(b.pieces.size(), 2u);  // pole to pole along two meridians
    EXPECT_EQ(std::count(b.corner.begin(), b.corner.end(), 1), 2);
  }
  // Two junction vertices (the poles), each one simulation vertex for three panels, i.e. two stitches.
  const std::map<int, int> sizes = groupSizes(bp);
  EXPECT_EQ(sizes.count(3) ? sizes.at(3) : 0, 2);
  EXPECT_EQ(sizes.count(4), 0u);
  int poleStitches = 0;
  for (const Stitch& s : bp.pattern.stitches) {
    const double y = bp.panels[s.panelA].targetPosition(s.vertexA, 1);
    poleStitches += std::abs(std::abs(y) - 0.25) < 1e-9;
  }
  EXPECT_EQ(poleStitches, 4);
  std::printf("[figures] three gores: %d triangles, seam mismatch %.2e, area ratios %.3f %.3f %.3f\n",
              bp.figures.triangles, bp.figures.maxSeamLengthMismatch, bp.panels[0].flattenAreaRatio,
              bp.panels[1].flattenAreaRatio, bp.panels[2].flattenAreaRatio);
}

TEST(PatternBuild, EdgeLengthOptionSetsTheResolution) {
  const auto scene = fixture("sphere-equator.billow.json");
  PatternBuildOptions o;
  o.triangles = 800;
  const BuiltPattern coarse = buildPattern(scene->target, scene->segmentation, o);
  o.edgeLength = 0.01;
  const BuiltPattern fine = buildPattern(scene->target, scene->segmentation, o);
  EXPECT_DOUBLE_EQ(fine.figures.edgeLength, 0.01);
  EXPECT_GT(coarse.figures.triangles, 700);
  EXPECT_LT(coarse.figures.triangles, 900);
  EXPECT_GT(fine.figures.triangles, 4 * coarse.figures.triangles);
  expectSound(*scene, coarse);
}

TEST(PatternBuild, NonDiskSegmentIsAProblemNotAThrow) {
  auto design = readDesignJson(readFileBytes(dataPath("sphere-equator.billow.json")));
  design.seams.clear();  // no seam: one closed segment
  auto closed = makeDesignScene(design, dataPath("sphere-equator.billow.json"), {examplesDir()});
  const BuiltPattern bp = buildPattern(closed->target, closed->segmentation);
  EXPECT_FALSE(bp.ok());
  EXPECT_TRUE(bp.pattern.panels.empty());
  ASSERT_FALSE(bp.problems.empty());
  EXPECT_EQ(bp.problems[0].code, "pattern.not-disk");
  EXPECT_NE(bp.problems[0].message.find("cannot be laid flat"), std::string::npos);
}

TEST(PatternBuild, PanelsThatOverlapOrAreSewnToThemselvesAreProblemsWithAPlace) {
  const auto scene = fixture("sphere-equator.billow.json");
  const Segmentation& seg = scene->segmentation;
  // A flattened outline that runs into itself (two of its points swapped across the disc): the mesher's
  // refusal becomes an instruction placed where the outline first meets itself.
  FlatSegment fs = flattenForPattern(seg, analyzeSeams(seg), 0);
  const std::vector<int>& loop = fs.flat.boundary;
  const int n = static_cast<int>(loop.size());
  ASSERT_GT(n, 20);
  fs.flat.uv.row(loop[n / 4]).swap(fs.flat.uv.row(loop[3 * n / 4]));
  Points2 polygon(n, 2);
  for (int i = 0; i < n; ++i) polygon.row(i) = fs.flat.uv.row(loop[i]);
  const int crossing = outlineCrossing(polygon);
  ASSERT_GE(crossing, 0);
  const SegmentationProblem overlap =
      meshProblem(seg, fs, Error("panel.self-intersecting", "The panel outline crosses itself."));
  EXPECT_EQ(overlap.code, "pattern.overlaps");
  EXPECT_EQ(overlap.severity, "error");
  EXPECT_EQ(overlap.segment, 0);
  EXPECT_EQ(overlap.location, fs.sub.mesh.V.row(loop[crossing]).transpose());
  EXPECT_EQ(overlap.message.rfind("Segment 1 would overlap itself when laid flat, near the ", 0), 0u)
      << overlap.message;
  EXPECT_NE(overlap.message.find("a seam across it there"), std::string::npos) << overlap.message;
  // Any other refusal keeps the mesher's words, placed on the segment.
  const SegmentationProblem other = meshProblem(seg, fs, Error("panel.bad-input", "Too few points."));
  EXPECT_EQ(other.code, "pattern.mesh-failed");
  EXPECT_EQ(other.location, seg.segments[0].labelPoint);

  // A sewing error names a panel vertex: the problem is placed there, on the panel's segment.
  const BuiltPattern bp = buildPattern(scene->target, seg);
  ASSERT_TRUE(bp.ok());
  const SegmentationProblem sewn =
      sewingProblem(bp, seg, Error("pattern.degenerate", "two corners sewn together", 1, 0));
  EXPECT_EQ(sewn.code, "pattern.not-sewn");
  EXPECT_EQ(sewn.segment, bp.panels[1].segment);
  EXPECT_EQ(sewn.location, bp.panels[1].targetPosition.row(0).transpose());
  EXPECT_EQ(sewn.message.rfind(bp.pattern.panels[1].name + " would be sewn to itself near the ", 0), 0u)
      << sewn.message;
  // Without a place it still says what is wrong.
  const SegmentationProblem unplaced = sewingProblem(bp, seg, Error("pattern.open", "An edge is not sewn."));
  EXPECT_EQ(unplaced.message, "A panel cannot be sewn: An edge is not sewn.");
}

TEST(PatternBuild, ASegmentThatFoldsWhenLaidFlatIsAWarningPlacedWhereItFolds) {
  // A sausage eight times as long as it is round, with one seam around it near its left end: the long part is a
  // closed-ended tube, whose harmonic map into the flat disc squeezes it past what doubles hold, so it folds after
  // every fallback (flatten.hpp). The panels are still made; the designer hears where and what helps.
  const double r = 0.05, length = 8 * 2 * M_PI * r;
  const auto scene = test::sceneOf(capsule(12, r, length));
  DesignSeam loop;
  loop.closed = true;
  for (const double a : {0.3, 2.4, 4.5})
    loop.points.push_back(
        DesignPoint{false, {}, Eigen::Vector3d(-length / 2 + 0.02, r * std::cos(a), r * std::sin(a))});
  scene->design.seams = {loop};
  traceDesignSeams(*scene);
  segmentDesignScene(*scene);
  const Segmentation& seg = scene->segmentation;
  ASSERT_EQ(seg.segments.size(), 2u);
  const int tube = seg.segments[0].area > seg.segments[1].area ? 0 : 1;
  const BuiltPattern bp = buildPattern(scene->target, seg);
  EXPECT_TRUE(bp.ok()) << "a warning, not a refusal";
  EXPECT_EQ(bp.pattern.panels.size(), 2u);
  std::vector<const SegmentationProblem*> folded;
  for (const SegmentationProblem& p : bp.problems)
    if (p.code == "pattern.flipped") folded.push_back(&p);
  ASSERT_EQ(folded.size(), 1u);
  const SegmentationProblem& p = *folded[0];
  EXPECT_EQ(p.severity, "warning");
  EXPECT_EQ(p.segment, tube);
  EXPECT_EQ(
      p.message.rfind(
          "Segment " + std::to_string(tube + 1) + " cannot be laid flat without folding over itself near the ", 0),
      0u)
      << p.message;
  EXPECT_NE(p.message.find("A seam across it there"), std::string::npos) << p.message;
  // Placed on the tube where it folds, away from the seam (on the target, in the scene's meters).
  const double x0 = scene->target.V.col(0).minCoeff(), x1 = scene->target.V.col(0).maxCoeff();
  EXPECT_GT(p.location.x(), x0 + 0.25 * (x1 - x0)) << "on the tube, past the seam";
  const Eigen::Vector3d axis(p.location.x(), 0, 0);
  const double radius = scene->target.V.col(1).maxCoeff();
  EXPECT_NEAR((p.location - axis).norm(), radius, 0.05 * radius) << "on the surface";
}

TEST(PatternBuild, SlitFromTheEquatorIsSewnBackOnItself) {
  auto design = readDesignJson(readFileBytes(dataPath("sphere-equator.billow.json")));
  DesignSeam slit;  // from the equator's first control point up into the northern hemisphere
  slit.points.resize(2);
  slit.points[0].position = Eigen::Vector3d(1, 0, 0);
  slit.points[1].position = Eigen::Vector3d(0.6, 0.8, 0);
  design.seams.push_back(slit);
  auto scene = makeDesignScene(design, dataPath("sphere-equator.billow.json"), {examplesDir()});
  ASSERT_EQ(scene->segmentation.segments.size(), 2u);
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation);
  ASSERT_TRUE(bp.ok()) << (bp.problems.empty() ? "" : bp.problems[0].message);
  ASSERT_EQ(bp.pattern.panels.size(), 2u);
  expectSound(*scene, bp);
  int slitPieces = 0;
  for (size_t p = 0; p < 2; ++p)
    for (const PanelPiece& piece : bp.panels[p].pieces) slitPieces += piece.neighborPanel == static_cast<int>(p);
  EXPECT_EQ(slitPieces, 2);  // the two sides of the slit, stitched to each other on the same panel
}

TEST(PatternBuild, KeepSewnSeamsSimpleGivesAClosedCurveThreeEdgesAndTwinSingleEdgesTwo) {
  std::vector<int> counts{1, 2, 1, 1, 1, 1, 7};
  // 0: closed; 1: closed with 2 edges; 2 and 3: single edges between points 5 and 6 (either way round); 4: a single
  // edge between 5 and 7 alone; 5: a single edge between 8 and 9, beside a curve of 7 edges between them.
  const std::vector<std::array<int, 2>> ends{{4, 4}, {3, 3}, {5, 6}, {6, 5}, {5, 7}, {8, 9}, {9, 8}};
  keepSewnSeamsSimple(counts, ends);
  EXPECT_EQ(counts, (std::vector<int>{3, 3, 2, 2, 1, 1, 7}));
}

// A small closed seam round the pole, shorter than two edges, with two corners on it: a slit into the cap from one,
// and a seam from each down to the other pole. Every panel has three or four pieces, so none is held to a polygon
// by its own pieces, and the loop's two halves were an edge each: a loop of two edges, sewn as one edge with four
// triangles ("Panel N would be sewn to itself ... its seams touch there", on the skull's suggested bands).
TEST(PatternBuild, ASmallClosedSeamSplitInTwoGetsAThirdEdge) {
  auto design = readDesignJson(readFileBytes(dataPath("sphere-equator.billow.json")));
  const double r = 0.12, y = std::sqrt(1 - r * r);
  const auto seam = [](const std::vector<Eigen::Vector3d>& points, bool closed) {
    DesignSeam s;
    s.closed = closed;
    s.points.resize(points.size());
    for (size_t k = 0; k < points.size(); ++k) s.points[k].position = points[k].normalized();
    return s;
  };
  design.seams = {seam({{r, y, 0}, {0, y, r}, {-r, y, 0}, {0, y, -r}}, true), seam({{r, y, 0}, {0.03, 1, 0}}, false),
                  seam({{r, y, 0}, {1, 0, 0}, {0, -1, 0}}, false), seam({{-r, y, 0}, {-1, 0, 0}, {0, -1, 0}}, false)};
  auto scene = makeDesignScene(design, dataPath("sphere-equator.billow.json"), {examplesDir()});
  ASSERT_EQ(scene->segmentation.segments.size(), 3u);
  PatternBuildOptions options;
  options.edgeLength = 0.3 * 0.25;  // the loop (0.19 m round, the sphere 0.25 m in radius) is 2.5 edges long
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation, options);
  ASSERT_TRUE(bp.ok()) << (bp.problems.empty() ? "" : bp.problems[0].message);
  expectSound(*scene, bp);
  int loopEdges = 0;
  for (const BuiltPanel& panel : bp.panels)
    for (const PanelPiece& piece : panel.pieces) {
      if (piece.seam == 0) loopEdges += static_cast<int>(piece.rows.size()) - 1;
      if (panel.pieces.size() < 3) ADD_FAILURE() << "a panel of " << panel.pieces.size() << " pieces";
    }
  EXPECT_GE(loopEdges, 2 * 3);  // counted from both sides
}

// A dart sewn shut (pieces 0 and 1 of one panel stitched to each other) whose mesh joins an inside vertex to both
// its sides next to the tip: sewn, those two edges would be one, a pinch sewPattern refuses ("more than two outer
// panels meet along one edge"). Stitching flips one of them to the other diagonal of its quad.
TEST(PatternBuild, AnInsideVertexMeshedToBothSidesOfADartIsFlippedOffOne) {
  BuiltPattern built;
  Panel panel;
  panel.name = "Panel 1";
  panel.vertices.resize(10, 2);  // the outline (the dart P0 A1 T B1 P1 cut up into a square), then X inside
  panel.vertices << 0, 0, 0.8, 0, 0.9, 0.5, 1, 1, 1.1, 0.5, 1.2, 0, 2, 0, 2, 2, 0, 2, 1, 1.3;
  enum { L, P0, A1, T, B1, P1, R, RT, LT, X };
  panel.triangles.resize(9, 3);
  panel.triangles << L, P0, A1, L, A1, X, L, X, LT, A1, T, X, T, B1, X, B1, P1, R, B1, R, X, X, R, RT, X, RT, LT;
  const double area = panelArea(panel);
  BuiltPanel bp;
  bp.boundaryVertices = 9;
  bp.targetPosition = Vertices::Zero(10, 3);
  bp.pieces = {{{P0, A1, T}, 0, 0, 1}, {{T, B1, P1}, 0, 0, 0}, {{P1, R, RT, LT, L, P0}, 1}};
  built.pattern.panels = {panel};
  built.panels = {bp};
  // Sewn points as the stitches make them; every edge of the panel, sewn, must join two points and be used once
  // each way at most.
  const auto pinches = [](const BuiltPattern& b) {
    UnionFind point(static_cast<int>(b.pattern.panels[0].vertices.rows()));
    for (const Stitch& s : b.pattern.stitches) point.unite(s.vertexA, s.vertexB);
    std::map<std::pair<int, int>, int> uses;
    int bad = 0;
    const Triangles& F = b.pattern.panels[0].triangles;
    for (int t = 0; t < F.rows(); ++t)
      for (int c = 0; c < 3; ++c) {
        const int u = point.find(F(t, c)), v = point.find(F(t, (c + 1) % 3));
        bad += u == v || ++uses[{u, v}] > 1;
      }
    return bad;
  };
  built.pattern.stitches = {{0, A1, 0, B1}};  // as stitchBuiltPattern would, before mending
  ASSERT_GT(pinches(built), 0) << "the fixture must pinch when sewn";
  stitchBuiltPattern(built);
  EXPECT_EQ(pinches(built), 0);
  const Panel& mended = built.pattern.panels[0];
  EXPECT_EQ(mended.triangles.rows(), 9);
  EXPECT_NEAR(panelArea(mended), area, 1e-12);
  for (int t = 0; t < mended.triangles.rows(); ++t)
    EXPECT_GT(signedArea(mended, t), 0) << "triangle " << t << " is flipped";
  const Triangles& F = mended.triangles;
  int edgesAtX = 0;  // X keeps one of its two edges to the sewn point A1 = B1
  for (int t = 0; t < F.rows(); ++t)
    for (int c = 0; c < 3; ++c) {
      const int u = F(t, c), v = F(t, (c + 1) % 3);
      edgesAtX += u == X && (v == A1 || v == B1);
    }
  EXPECT_EQ(edgesAtX, 1);
}

TEST(PatternBuild, SpotWithTenSeams) {
  const auto scene = fixture("spot-ten-seams.billow.json");
  int disks = 0;
  for (const Segment& s : scene->segmentation.segments) disks += s.isDisk;
  ASSERT_EQ(disks, static_cast<int>(scene->segmentation.segments.size()));
  PatternBuildOptions o;
  o.triangles = 6000;
  const auto t0 = std::chrono::steady_clock::now();
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation, o);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(bp.ok()) << (bp.problems.empty() ? "" : bp.problems[0].message);
  EXPECT_EQ(bp.pattern.panels.size(), scene->segmentation.segments.size());
  expectSound(*scene, bp);
  EXPECT_GT(bp.figures.triangles, 4500);
  EXPECT_LT(bp.figures.triangles, 8000);
  std::printf(
      "[timing] spot, %zu seams, %zu segments: pattern of %d triangles built in %.1f ms (flatten %.1f, mesh "
      "%.1f); seam mismatch %.3f, edge mismatch %.3f\n",
      scene->curves.size(), scene->segmentation.segments.size(), bp.figures.triangles, ms, bp.figures.flattenMs,
      bp.figures.meshMs, bp.figures.maxSeamLengthMismatch, bp.figures.maxEdgeLengthMismatch);
}
