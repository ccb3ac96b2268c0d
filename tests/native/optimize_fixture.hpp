// What the optimizer's tests share (test_pattern_optimizer.cpp and the tests of its parts): a design loaded and
// built as the CLI and the design bench do, random pattern directions, a run to the end, and the properties
// every run keeps.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "export/polygon.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "pattern/design_scene.hpp"
#include "simulate/seam_rods.hpp"
#include "test_support.hpp"

namespace billow::test {

struct Fixture {
  std::unique_ptr<DesignScene> scene;
  BuiltPattern built;
  std::vector<double> weights;
};

// As the CLI and the design bench start (pattern/design_scene.hpp): an internal panel for each of the design's
// connections.
inline Fixture makeFixture(const std::string& name, int triangles) {
  Fixture f;
  f.scene = loadDesignScene(dataPath(name), {examplesDir()});
  f.built = buildDesignPattern(*f.scene, triangles);
  f.weights = designSeamWeights(f.scene->design);
  return f;
}

// Smooth random direction in pattern space (per-panel affine + sine bumps), unit max norm.
inline Eigen::VectorXd randomDirection(const Eigen::VectorXd& X, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double a = u(rng), b = u(rng), c = u(rng), d = u(rng), k = 20 + 10 * u(rng);
  Eigen::VectorXd v(X.size());
  for (int i = 0; i < X.size() / 2; ++i) {
    const double x = X[2 * i], y = X[2 * i + 1];
    v[2 * i] = a * x + c * std::sin(k * y), v[2 * i + 1] = b * y + d * std::cos(k * x);
  }
  return v / v.cwiseAbs().maxCoeff();
}

// The largest absolute length difference of two stitched edges [m].
inline double largestLengthDifference(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& Y) {
  double m = 0;
  for (const auto& e : pairs)
    m = std::max(m, std::abs((Y.segment<2>(2 * e.a1) - Y.segment<2>(2 * e.a0)).norm() -
                             (Y.segment<2>(2 * e.b1) - Y.segment<2>(2 * e.b0)).norm()));
  return m;
}

struct OptimizeRun {
  std::vector<OptimizeRecord> history;
  OptimizeState state = OptimizeState::Running;
  double ms = 0;
  Vertices x;
  Pattern pattern;
  double seamShift = 0;       // max distance of the sewn seam vertices from where they were drawn [m]
  int previewIteration = -1;  // first record whose shape is within 5 % of the diagonal of the final one
  double previewMs = 0;
  int iterations = 0, resettlings = 0;
  std::string message;
  CutPanelsCheck cut;  // when asked for: the final outlines meshed anew and inflated
};

// Runs until the optimizer ends (or maxIterations, checked every 5).
inline OptimizeRun optimize(const Fixture& f, const OptimizeOptions& o,
                            int maxIterations = std::numeric_limits<int>::max(), bool checkCut = false) {
  const auto t0 = std::chrono::steady_clock::now();
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(5, 500) == OptimizeState::Running && opt.iterations() < maxIterations) {
  }
  OptimizeRun r;
  r.history = opt.history(), r.state = opt.state(), r.x = opt.inflated(), r.pattern = opt.pattern();
  r.iterations = opt.iterations(), r.resettlings = opt.timings().resettlings, r.message = opt.message();
  if (checkCut) r.cut = opt.checkCutPanels();
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const double D = opt.objective().modelSize();
  for (size_t k = 0; k < opt.shapes().size() && r.previewIteration < 0; ++k)
    if ((opt.shapes()[k] - r.x).rowwise().norm().maxCoeff() < 0.05 * D)
      r.previewIteration = r.history[k].iteration, r.previewMs = r.history[k].ms;
  for (const auto& s : opt.objective().seamVertices())
    r.seamShift = std::max(r.seamShift, (r.x.row(s.vertex).transpose() - s.target).norm());
  return r;
}

// The objective never rises over an L-BFGS step (by more than `relative`): the final seam-length projection,
// a new mesh (a new discretization of E) and a resettled shape (another equilibrium of the same panels) are
// not steps.
inline void expectObjectiveNeverRises(const std::vector<OptimizeRecord>& h, double relative = 0) {
  for (size_t k = 1; k < h.size(); ++k) {
    if (!h[k].projected && !h[k].remeshed && !h[k].resettled) {
      EXPECT_LE(h[k].objective, h[k - 1].objective * (1 + relative)) << "iteration " << k;
    }
  }
}

// Nothing the optimizer found is lost: a resettling may leave it at a worse equilibrium, and then it goes back to
// its best iterate (of the last mesh) before the final seam-length projection.
inline void expectEndsAtItsBest(const std::vector<OptimizeRecord>& h) {
  double best = INFINITY;
  const OptimizeRecord* last = nullptr;
  for (const OptimizeRecord& r : h) {
    if (r.remeshed) best = INFINITY;
    if (!r.projected) best = std::min(best, r.objective), last = &r;
  }
  ASSERT_NE(last, nullptr);
  EXPECT_LE(last->objective, best * (1 + 1e-12));
}

// The optimizer after `iterations` iterations (or where it stopped), stepped as the app's worker steps it.
inline std::unique_ptr<PatternOptimizer> optimizedFor(const Fixture& f, int iterations, OptimizeOptions oo = {}) {
  oo.stopping.maxIterations = iterations;
  oo.remeshing.coarseFactor = 1;  // the design's mesh throughout: the tests follow its outlines and seam rods
  auto opt = std::make_unique<PatternOptimizer>(f.scene->target, f.built, f.weights, oo);
  while (opt->step(5) == OptimizeState::Running) {
  }
  return opt;
}

// No panel's outline crosses itself: a maker can cut every panel (the optimizer lists each outline first, in order).
inline void expectCuttableOutlines(const Pattern& pattern) {
  for (const Panel& panel : pattern.panels) {
    Polygon2 polygon;
    for (int v : outlineVertices(panel)) polygon.push_back(panel.vertices.row(v).transpose());
    EXPECT_FALSE(selfIntersects(polygon)) << panel.name;
  }
}

// Teeth and slits of a panel's outline: consecutive outline vertices that both turn by more than `degrees`, the
// other way from each other. A maker cuts round a lobe, not through a saw tooth or a slit notch.
inline int outlineTeeth(const Panel& panel, double degrees = 45) {
  const std::vector<int> loop = outlineVertices(panel);
  const int n = int(loop.size());
  std::vector<double> turn(n);
  for (int j = 0; j < n; ++j) {
    const Eigen::Vector2d a = panel.vertices.row(loop[(j + n - 1) % n]), b = panel.vertices.row(loop[j]),
                          c = panel.vertices.row(loop[(j + 1) % n]);
    const Eigen::Vector2d u = b - a, v = c - b;
    turn[j] = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v)) * 180 / M_PI;
  }
  int teeth = 0;
  for (int j = 0; j < n; ++j) {
    const double before = turn[(j + n - 1) % n];
    teeth += std::abs(turn[j]) > degrees && std::abs(before) > degrees && turn[j] * before < 0;
  }
  return teeth;
}

// The cut panels inflate with the seam rods the optimizer's balloon had: the simulator's corner rule (seam_rods.hpp)
// picks the same seam vertices on the optimized pattern as on the flattened one (E_corner).
inline void expectSameSeamRods(const Pattern& flattened, const Pattern& optimized) {
  const auto rods = [](const Pattern& p) {
    std::vector<std::array<int, 3>> t = makeSeamRods(sewPattern(p), 1).triples;
    std::sort(t.begin(), t.end());
    return t;
  };
  const std::vector<std::array<int, 3>> before = rods(flattened), after = rods(optimized);
  EXPECT_FALSE(before.empty());
  EXPECT_EQ(before, after) << before.size() << " rods in the flattened pattern, " << after.size() << " cut";
}

}  // namespace billow::test
