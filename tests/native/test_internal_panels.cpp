// Internal panels (pattern/internal_panels.hpp, paper Sec. 3.2 and Fig. 2): an internal connection between two
// seams becomes one more panel, marked internal, a disk sewn onto the outer panels' samples along both seams
// (the same points on the target, the same flattened edge lengths); inflated, it is taut and holds the seams
// closer than without it; the optimizer runs on it; bad connections are problems, never throws.
#include <gtest/gtest.h>
#include <limits.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "io/mesh_file.hpp"
#include "io/pattern_json.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "panel_checks.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/internal_panels.hpp"
#include "simulate/inflate.hpp"
#include "test_support.hpp"

using namespace billow;
using billow::test::dataPath;
using billow::test::examplesDir;
using billow::test::expectDisk;
using billow::test::signedArea;

namespace {

// The 0.5 m sphere cut into three gores by meridians 1, 2, 3 (pole to pole), plus extra seams.
std::unique_ptr<DesignScene> gores(const std::vector<DesignSeam>& extra = {}) {
  Design design = readDesignJson(readFileBytes(dataPath("sphere-gores.billow.json")));
  for (const DesignSeam& s : extra) design.seams.push_back(s);
  return makeDesignScene(design, dataPath("sphere-gores.billow.json"), {examplesDir()});
}

// A cushion: the sphere squashed to 40 % of its height (0.5 m wide, 0.2 m high), cut at its equator, each half
// cut again by an arc over its pole ("top", "bottom": both from (1, 0, 0) to (-1, 0, 0)). Inflated it wants
// to become round, pushing the poles apart; a connection between the arcs is a vertical diaphragm holding them.
std::unique_ptr<DesignScene> cushion() {
  Design design = readDesignJson(readFileBytes(dataPath("sphere-equator.billow.json")));
  design.target.kind = DesignTarget::Inline;
  design.target.mesh = readMeshBytes(readFileBytes(examplesDir() + "/sphere.obj"), "sphere.obj");
  design.target.mesh.V.col(1) *= 0.4;
  design.height = 0.2;
  const auto seam = [](const std::string& name, bool closed, std::vector<Eigen::Vector3d> points) {
    DesignSeam s;
    s.name = name, s.closed = closed;
    for (const Eigen::Vector3d& x : points) {
      DesignPoint p;
      p.position = x;
      s.points.push_back(p);
    }
    return s;
  };
  std::vector<Eigen::Vector3d> equator;  // close control points: on a flat spheroid long geodesics leave it
  for (int k = 0; k < 6; ++k) equator.emplace_back(std::cos(k * M_PI / 3), 0, std::sin(k * M_PI / 3));
  design.seams = {seam("equator", true, equator), seam("top", false, {{1, 0, 0}, {0, 0.4, 0}, {-1, 0, 0}}),
                  seam("bottom", false, {{1, 0, 0}, {0, -0.4, 0}, {-1, 0, 0}})};
  return makeDesignScene(design, dataPath("sphere-equator.billow.json"), {examplesDir()});
}

PatternBuildOptions optionsFor(const DesignScene& scene, std::vector<InternalConnection> connections,
                               int triangles = 3000) {
  PatternBuildOptions o;
  o.triangles = triangles;
  o.connections = std::move(connections);
  for (const DesignSeam& s : scene.design.seams) o.seamNames.push_back(s.name);
  return o;
}

bool hasProblem(const BuiltPattern& bp, const std::string& text) {
  for (const SegmentationProblem& p : bp.problems)
    if (p.code == "pattern.connection" && p.severity == "error" && p.message.find(text) != std::string::npos)
      return true;
  return false;
}

}  // namespace

TEST(InternalPanels, ConnectionBetweenTwoMeridiansAddsAnInternalPanelSewnOnBothSeams) {
  const auto scene = gores();
  ASSERT_TRUE(scene->segmentation.ok());
  const auto t0 = std::chrono::steady_clock::now();
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {{0, 1}}));
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(bp.ok()) << (bp.problems.empty() ? "" : bp.problems[0].message);
  const BuiltPattern plain = buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {}));
  ASSERT_EQ(plain.pattern.panels.size(), 3u);
  ASSERT_EQ(bp.pattern.panels.size(), 4u);  // one more panel, the internal one, last
  ASSERT_EQ(bp.connectionPanel, std::vector<int>{3});
  EXPECT_EQ(bp.figures.internalPanels, 1);
  const Panel& internal = bp.pattern.panels[3];
  const BuiltPanel& built = bp.panels[3];
  EXPECT_TRUE(internal.internal);
  for (int p = 0; p < 3; ++p) EXPECT_FALSE(bp.pattern.panels[p].internal);
  EXPECT_EQ(internal.name, "internal 1 (seams meridian 1|meridian 2)");
  EXPECT_EQ(built.segment, -1);
  EXPECT_EQ(built.connection, 0);
  EXPECT_EQ(built.interior, "ruled");
  // The outer panels are the same as without the connection.
  for (int p = 0; p < 3; ++p) EXPECT_EQ(bp.pattern.panels[p].vertices, plain.pattern.panels[p].vertices);
  expectDisk(internal, built.boundaryVertices);
  for (int t = 0; t < internal.triangles.rows(); ++t) EXPECT_GT(signedArea(internal, t), 0) << "triangle " << t;
  EXPECT_GT(internal.triangles.rows(), 100);
  // The two meridians meet at the poles: a lens with two pieces (one per seam) and no free ruling.
  ASSERT_EQ(built.pieces.size(), 2u);
  EXPECT_EQ(built.pieces[0].seam, 0);
  EXPECT_EQ(built.pieces[1].seam, 1);
  // A ruled surface flattens with nearly its own area (between two meridians it is a developable cylinder).
  EXPECT_NEAR(built.flattenAreaRatio, 1.0, 0.02);

  // Every piece on a seam is sewn to an outer piece there, sample k to sample N - k: the same simulation
  // vertex, the same point on the target, the same flattened edge lengths.
  const SewnMesh sewn = sewPattern(bp.pattern);
  double worstEdge = 0;
  for (const PanelPiece& piece : built.pieces) {
    ASSERT_GE(piece.neighborPanel, 0);
    ASSERT_LT(piece.neighborPanel, 3);
    const PanelPiece& outer = bp.panels[piece.neighborPanel].pieces[piece.neighborPiece];
    EXPECT_EQ(outer.seam, piece.seam);
    ASSERT_EQ(outer.rows.size(), piece.rows.size());
    const PanelPiece& other = bp.panels[outer.neighborPanel].pieces[outer.neighborPiece];
    const int n = static_cast<int>(piece.rows.size()) - 1;
    for (int k = 0; k <= n; ++k) {
      const int vi = piece.rows[k], vo = outer.rows[n - k], vp = other.rows[k];
      EXPECT_EQ(sewn.simVertex(3, vi), sewn.simVertex(piece.neighborPanel, vo));
      EXPECT_EQ(sewn.simVertex(3, vi), sewn.simVertex(outer.neighborPanel, vp));
      if (k > 0 && k < n) {
        EXPECT_EQ(built.seam[vi], piece.seam);  // corners: the seam of the piece leaving them
      }
      // The stitched point: the mean of the outer panels' points there (which differ by the flattening only).
      const Eigen::Vector3d mean = 0.5 * (bp.panels[piece.neighborPanel].targetPosition.row(vo) +
                                          bp.panels[outer.neighborPanel].targetPosition.row(vp))
                                             .transpose();
      const bool pole = std::abs(std::abs(mean.y()) - 0.25) < 1e-9;  // a third outer panel meets there
      if (!pole) {
        EXPECT_LT((built.targetPosition.row(vi).transpose() - mean).norm(), 1e-9);
      }
      EXPECT_LE((built.targetPosition.row(vi) - bp.panels[piece.neighborPanel].targetPosition.row(vo)).norm(),
                bp.figures.maxStitchTargetDistance + 1e-12);
      EXPECT_LT(std::abs(built.targetPosition.row(vi).norm() - 0.25), 5e-3 * 0.25);  // on the sphere
      if (k == n) continue;
      const auto len = [&](int panel, int a, int b) {
        return (bp.pattern.panels[panel].vertices.row(a) - bp.pattern.panels[panel].vertices.row(b)).norm();
      };
      const double li = len(3, piece.rows[k], piece.rows[k + 1]);
      const double lo = len(piece.neighborPanel, outer.rows[n - k], outer.rows[n - k - 1]);
      const double lp = len(outer.neighborPanel, other.rows[k], other.rows[k + 1]);
      EXPECT_NEAR(li, 0.5 * (lo + lp), 1e-9 * li);  // the mean of the two outer panels' edges
      worstEdge = std::max(worstEdge, std::abs(li - lo) / lo);
    }
  }
  EXPECT_LT(worstEdge, 0.02);
  EXPECT_LT(bp.figures.maxEdgeLengthMismatch, 0.02);
  // The interior lies between the seams, inside the sphere, and the poles are one point for four panels.
  for (int v = built.boundaryVertices; v < internal.vertices.rows(); ++v) {
    EXPECT_LT(built.targetPosition.row(v).norm(), 0.25 * (1 + 1e-6));
    EXPECT_EQ(built.targetPoint[v].face, -1);
    EXPECT_EQ(built.seam[v], -1);
  }
  std::map<int, int> sizes;
  for (int c : sewn.stitchedCount) ++sizes[c];
  EXPECT_EQ(sizes[4], 2);  // the poles
  EXPECT_GT(windingNumber(scene->target, Eigen::Vector3d::Zero()), 0.99);
  EXPECT_LT(std::abs(windingNumber(scene->target, Eigen::Vector3d(0.3, 0, 0))), 0.01);
  std::printf(
      "[figures] sphere gores + connection: %d panels (%d internal), %d triangles (internal %d), build %.1f ms\n",
      bp.figures.panels, bp.figures.internalPanels, bp.figures.triangles, static_cast<int>(internal.triangles.rows()),
      ms);
}

TEST(InternalPanels, SeamsThatDoNotMeetGiveAPanelWithFreeRulings) {
  // Two slits up from the equator of the sphere, 120 degrees apart: the panel between them is a strip through
  // the inside, sewn along both slits and free along the two rulings at their ends.
  Design design = readDesignJson(readFileBytes(dataPath("sphere-equator.billow.json")));
  const auto slit = [](const std::string& name, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    DesignSeam s;
    s.name = name;
    s.points.resize(2);
    s.points[0].position = from, s.points[1].position = to;
    return s;
  };
  design.seams.push_back(slit("east", {1, 0, 0}, {0.6, 0.8, 0}));
  design.seams.push_back(slit("west", {-0.5, 0, 0.8660254037844386}, {-0.3, 0.8, 0.5196152422706632}));
  const auto scene = makeDesignScene(design, dataPath("sphere-equator.billow.json"), {examplesDir()});
  ASSERT_TRUE(scene->segmentation.ok());
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {{2, 1}}, 2000));
  ASSERT_TRUE(bp.ok()) << (bp.problems.empty() ? "" : bp.problems[0].message);
  ASSERT_EQ(bp.pattern.panels.size(), 3u);
  const BuiltPanel& built = bp.panels[2];
  const Panel& internal = bp.pattern.panels[2];
  EXPECT_EQ(internal.name, "internal 1 (seams west|east)");
  expectDisk(internal, built.boundaryVertices);
  for (int t = 0; t < internal.triangles.rows(); ++t) EXPECT_GT(signedArea(internal, t), 0) << "triangle " << t;
  ASSERT_EQ(built.pieces.size(), 4u);  // west, the ruling at the tips, east backwards, the ruling on the equator
  int free = 0;
  for (const PanelPiece& piece : built.pieces) {
    if (piece.seam >= 0) {
      EXPECT_GE(piece.neighborPanel, 0);
      continue;
    }
    ++free;
    EXPECT_EQ(piece.neighborPanel, -1);
    for (size_t k = 1; k + 1 < piece.rows.size(); ++k) EXPECT_EQ(built.seam[piece.rows[k]], -1);
    // A straight ruling, kept at its length when laid flat.
    const Eigen::Vector3d a = built.targetPosition.row(piece.rows.front()),
                          b = built.targetPosition.row(piece.rows.back());
    const double flat = (internal.vertices.row(piece.rows.front()) - internal.vertices.row(piece.rows.back())).norm();
    EXPECT_NEAR(flat, (b - a).norm(), 1e-9);
    EXPECT_NEAR(piece.targetLength, (b - a).norm(), 1e-12);
    for (size_t k = 1; k + 1 < piece.rows.size(); ++k) {
      const Eigen::Vector3d x = built.targetPosition.row(piece.rows[k]);
      EXPECT_LT((x - a).cross(b - a).norm() / (b - a).norm(), 1e-12);
    }
  }
  EXPECT_EQ(free, 2);
  // The equator ruling is a chord of 120 degrees: sqrt(3) r.
  EXPECT_NEAR(built.pieces[3].targetLength, std::sqrt(3.0) * 0.25, 0.01);
  // The stitches of the internal panel keep the seam samples: no stitch joins a ruling vertex.
  const SewnMesh sewn = sewPattern(bp.pattern);
  for (const PanelPiece& piece : built.pieces)
    for (size_t k = 1; piece.seam < 0 && k + 1 < piece.rows.size(); ++k)
      EXPECT_EQ(sewn.stitchedCount[sewn.simVertex(2, piece.rows[k])], 1);
  const InflateResult r = inflate(bp.pattern);
  EXPECT_TRUE(r.converged) << r.message;
}

TEST(InternalPanels, InflatedInternalPanelIsTautAndHoldsTheSeamsCloser) {
  const auto scene = cushion();
  ASSERT_TRUE(scene->segmentation.ok());
  ASSERT_EQ(scene->segmentation.segments.size(), 4u);
  PatternBuildOptions o = optionsFor(*scene, {{1, 2}}, 1500);
  const BuiltPattern with = buildPattern(scene->target, scene->segmentation, o);
  o.connections.clear();
  const BuiltPattern without = buildPattern(scene->target, scene->segmentation, o);
  ASSERT_TRUE(with.ok()) << (with.problems.empty() ? "" : with.problems[0].message);
  ASSERT_EQ(with.pattern.panels.size(), 5u);
  EXPECT_EQ(with.pattern.panels[4].name, "internal 1 (seams top|bottom)");
  EXPECT_EQ(with.panels[4].pieces.size(), 2u);  // the arcs meet at both ends: no free ruling
  // A plane (the diaphragm z = 0), but its seam edges take the lengths of the flattened outer panels, which
  // differ from the target's by up to ~10 % on this strongly curved cushion.
  EXPECT_NEAR(with.panels[4].flattenAreaRatio, 1.0, 0.1);
  const auto t0 = std::chrono::steady_clock::now();
  const InflateResult r = inflate(with.pattern);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const InflateResult r0 = inflate(without.pattern);
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_TRUE(r0.converged) << r0.message;
  const SewnMesh mesh = sewPattern(with.pattern), mesh0 = sewPattern(without.pattern);
  // Distance between the mid-points of the two connected arcs (the poles).
  const auto gap = [](const BuiltPattern& bp, const SewnMesh& m, const Vertices& x) {
    const auto mid = [&](int seam) {
      std::pair<int, int> best{-1, -1};
      double d = 1e300;
      for (size_t p = 0; p < bp.panels.size(); ++p)
        for (int v = 0; v < bp.panels[p].boundaryVertices; ++v)
          if (bp.panels[p].seam[v] == seam &&
              std::hypot(bp.panels[p].targetPosition(v, 0), bp.panels[p].targetPosition(v, 2)) < d)
            d = std::hypot(bp.panels[p].targetPosition(v, 0), bp.panels[p].targetPosition(v, 2)),
            best = {static_cast<int>(p), v};
      return m.simVertex(best.first, best.second);
    };
    return (x.row(mid(1)) - x.row(mid(2))).norm();
  };
  const double dWith = gap(with, mesh, r.positions), dWithout = gap(without, mesh0, r0.positions);
  EXPECT_LT(dWith, 0.9 * dWithout);
  EXPECT_LT(dWith, 0.2 * 1.05);  // about the target's height
  EXPECT_LT(r.volume, r0.volume);
  // The internal panel is in tension (taut, or wrinkled: tense across the wrinkles) and carries about as much
  // as the outer panels do.
  int tense = 0, internalTriangles = 0, outerTriangles = 0;
  double internalTension = 0, outerTension = 0;
  for (int f = 0; f < mesh.numTriangles(); ++f) {
    if (mesh.outer[f]) {
      ++outerTriangles, outerTension += r.fields.tension[f];
      continue;
    }
    ++internalTriangles, tense += r.fields.regime[f] != 0, internalTension += r.fields.tension[f];
  }
  internalTension /= internalTriangles, outerTension /= outerTriangles;
  EXPECT_GT(tense, internalTriangles / 2);
  EXPECT_GT(internalTension, 0.25 * outerTension);
  std::printf(
      "[figures] cushion + diaphragm: %d triangles, inflated in %d iterations (%.0f ms); arc mid-points %.4f m apart "
      "(%.4f m without), volume %.5f m^3 (%.5f), diaphragm tension %.1f N/m (outer %.1f), tense %d/%d\n",
      mesh.numTriangles(), r.iterations, ms, dWith, dWithout, r.volume, r0.volume, internalTension, outerTension, tense,
      internalTriangles);
}

TEST(InternalPanels, OptimizerRunsOnAPatternWithAnInternalPanel) {
  const auto scene = gores();
  const BuiltPattern bp = buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {{0, 1}}, 600));
  ASSERT_TRUE(bp.ok());
  OptimizeOptions oo;
  oo.stopping.maxIterations = 3;
  PatternOptimizer optimizer(scene->target, bp, {1, 1, 1}, oo);
  // Internal panel vertices off the seams carry no target distance (they are not meant to lie on the target).
  const SewnMesh& m = optimizer.mesh();
  const BuiltPanel& internal = bp.panels[3];
  for (int v = internal.boundaryVertices; v < internal.targetPosition.rows(); ++v)
    EXPECT_EQ(optimizer.objective().targetWeights()[m.simVertex(3, v)], 0);
  // Its seam edges are paired with the outer ones (E_length): the outer pairs plus one per internal seam edge.
  size_t internalSeamEdges = 0;
  for (const PanelPiece& p : internal.pieces)
    if (p.neighborPanel >= 0) internalSeamEdges += p.rows.size() - 1;
  const PatternObjective plainObjective(
      optimizer.objective().imls(), buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {}, 600)),
      sewPattern(buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {}, 600)).pattern), {1, 1, 1}, {});
  EXPECT_EQ(optimizer.objective().edgePairs().size(), plainObjective.edgePairs().size() + internalSeamEdges);
  OptimizeState state = OptimizeState::Running;
  while (state == OptimizeState::Running) state = optimizer.step(1);
  EXPECT_NE(state, OptimizeState::Failed) << optimizer.message();
  ASSERT_FALSE(optimizer.history().empty());
  const OptimizeRecord& last = optimizer.history().back();
  EXPECT_TRUE(std::isfinite(last.objective));
  EXPECT_LE(last.objective, optimizer.history().front().objective * (1 + 1e-9) + 1e-15);
  EXPECT_LT(last.seamMismatch, 1e-6);  // the exact seam-length projection includes the internal panel
  EXPECT_TRUE(optimizer.pattern().panels[3].internal);
  std::printf("[figures] optimize with an internal panel: %d iterations, distance rms %.4f -> %.4f, mismatch %.1e\n",
              optimizer.iterations(), optimizer.history().front().distanceRms, last.distanceRms, last.seamMismatch);
}

TEST(InternalPanels, BadConnectionsAreProblemsNotThrows) {
  const auto scene = gores();
  const BuiltPattern same = buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {{1, 1}}));
  EXPECT_FALSE(same.ok());
  EXPECT_EQ(same.pattern.panels.size(), 3u);  // the outer panels are still built
  EXPECT_EQ(same.connectionPanel, std::vector<int>{-1});
  EXPECT_TRUE(hasProblem(same,
                         "The internal connection between seams \"meridian 2\" and \"meridian 2\" cannot be "
                         "built: it joins a seam to itself"));
  const BuiltPattern missing =
      buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {{0, 7}, {-1, 2}, {0, 2}}));
  EXPECT_FALSE(missing.ok());
  EXPECT_TRUE(hasProblem(missing,
                         "between seams \"meridian 1\" and 8 cannot be built: there is no seam 8 (the "
                         "design has 3 seams)."));
  EXPECT_TRUE(hasProblem(missing, "there is no seam 0"));
  ASSERT_EQ(missing.pattern.panels.size(), 4u);  // the good connection is built
  EXPECT_EQ(missing.connectionPanel, (std::vector<int>{-1, -1, 3}));
  EXPECT_EQ(missing.pattern.panels[3].name, "internal 3 (seams meridian 1|meridian 3)");
}

TEST(InternalPanels, CrossingAndClosedSeamsAreProblems) {
  // Seam 4 crosses meridian 1 (its ends are slits inside gores 1 and 3).
  DesignSeam across;
  across.name = "across";
  across.points.resize(2);
  across.points[0].position = Eigen::Vector3d(0.7, 0.5, -0.5);
  across.points[1].position = Eigen::Vector3d(0.7, 0.5, 0.5);
  const auto scene = gores({across});
  ASSERT_TRUE(scene->segmentation.ok());
  const BuiltPattern crossing = buildPattern(scene->target, scene->segmentation, optionsFor(*scene, {{0, 3}}, 1500));
  EXPECT_FALSE(crossing.ok());
  EXPECT_TRUE(hasProblem(crossing, "cross or touch each other")) << crossing.problems.back().message;
  // A closed seam (the equator) cannot take an internal panel yet.
  Design design = readDesignJson(readFileBytes(dataPath("sphere-equator.billow.json")));
  DesignSeam slit;  // from the equator up into the northern hemisphere
  slit.name = "slit";
  slit.points.resize(2);
  slit.points[0].position = Eigen::Vector3d(1, 0, 0);
  slit.points[1].position = Eigen::Vector3d(0.6, 0.8, 0);
  design.seams.push_back(slit);
  const auto equator = makeDesignScene(design, dataPath("sphere-equator.billow.json"), {examplesDir()});
  const BuiltPattern closed =
      buildPattern(equator->target, equator->segmentation, optionsFor(*equator, {{0, 1}}, 1500));
  EXPECT_EQ(closed.pattern.panels.size(), 2u);
  EXPECT_TRUE(hasProblem(closed,
                         "The internal connection between seams \"equator\" and \"slit\" cannot be built: "
                         "internal panels between closed seams are not supported yet"));
}

// ---- The CLI (native only: it runs the billow executable next to this test binary) ----

TEST(InternalPanels, CliDesignBuildsTheConnectionAndInflateReadsIt) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  using nlohmann::json;
  json doc = json::parse(readFileBytes(dataPath("sphere-gores.billow.json")));
  doc["target"]["obj"] = dataPath("../../web/public/examples/sphere.obj");
  doc["connections"] = json::array({{{"seams", {0, 1}}}});
  const std::string design = testing::TempDir() + "billow-gores-connection.billow.json";
  std::ofstream(design) << doc.dump();
  const std::string dir = testing::TempDir() + "billow-design-connection";
  ASSERT_EQ(
      test::runQuiet(test::cliPath() + " design " + design + " --out-dir " + dir + " --no-optimize --resolution 1000"),
      0);
  const json pattern = json::parse(readFileBytes(dir + "/pattern.json"));
  ASSERT_EQ(pattern["panels"].size(), 4u);
  EXPECT_TRUE(pattern["panels"][3]["internal"].get<bool>());
  EXPECT_EQ(pattern["panels"][3]["name"], "internal 1 (seams meridian 1|meridian 2)");
  EXPECT_FALSE(pattern["panels"][0]["internal"].get<bool>());
  const json report = json::parse(readFileBytes(dir + "/report.json"));
  EXPECT_TRUE(report["inflate"]["converged"].get<bool>());
  EXPECT_EQ(report["internal_panels"], 1);
  // billow inflate re-inflates the written pattern, internal panel included.
  ASSERT_EQ(test::runQuiet(test::cliPath() + " inflate " + dir + "/pattern.json --obj " + dir + "/again.obj"), 0);
  const TriMesh again = readMeshBytes(readFileBytes(dir + "/again.obj"), "again.obj");
  const Pattern p = readPatternJson(readFileBytes(dir + "/pattern.json"));
  EXPECT_EQ(again.numTriangles(), static_cast<int>(outerTriangles(sewPattern(p)).rows()));
  // billow segment lists the connection; a bad one makes billow design fail with the problem.
  const std::string segments = testing::TempDir() + "billow-gores-connection.segments.json";
  ASSERT_EQ(test::runQuiet(test::cliPath() + " segment " + design + " --out " + segments), 0);
  const json s = json::parse(readFileBytes(segments));
  ASSERT_EQ(s["connections"].size(), 1u);
  EXPECT_EQ(s["connections"][0]["seams"], json({0, 1}));
  doc["connections"] = json::array({{{"seams", {1, 1}}}});
  std::ofstream(design) << doc.dump();
  EXPECT_EQ(
      test::runQuiet(test::cliPath() + " design " + design + " --out-dir " + dir + " --no-optimize --resolution 1000"),
      1);
#endif
}
