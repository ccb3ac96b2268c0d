// optimize/stopping_rule.hpp: the app's stopping rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "optimize/stopping_rule.hpp"
#include "optimize_fixture.hpp"

using namespace billow;
using namespace billow::test;

// The app's stopping rule (optimize/stopping_rule.hpp) sets when to stop and nothing else.
TEST(StoppingRule, AppStoppingRuleSetsOnlyWhenToStop) {
  OptimizeOptions base;
  base.weights.cover = 7, base.remeshing.every = 9;
  const OptimizeOptions app = appStoppingRule(base);
  EXPECT_EQ(app.stopping.maxIterations, 150);
  EXPECT_EQ(app.stopping.windowIterations, 20);
  EXPECT_DOUBLE_EQ(app.stopping.windowMove, 2e-3);
  EXPECT_DOUBLE_EQ(app.stopping.windowDecrease, 1e-2);
  EXPECT_DOUBLE_EQ(app.sliding.iterationFactor, base.sliding.iterationFactor);
  EXPECT_DOUBLE_EQ(app.weights.cover, 7);
  EXPECT_EQ(app.remeshing.every, 9);
  EXPECT_EQ(OptimizeOptions{}.stopping.windowIterations, 0)
      << "the CLI's and the bench's runs go on to full convergence";
}

namespace {
// A history of objectives, one record per iteration from 0.
std::vector<OptimizeRecord> objectiveHistory(const std::vector<double>& objectives) {
  std::vector<OptimizeRecord> h;
  for (size_t i = 0; i < objectives.size(); ++i) {
    OptimizeRecord r;
    r.iteration = int(i), r.objective = objectives[i];
    h.push_back(r);
  }
  return h;
}
}  // namespace

// The objective window: only a decrease of the best objective over the last `window` iterations keeps the run
// going, never measured across a remeshing, and the final seam-length projection counts as no iterate.
TEST(StoppingRule, ObjectiveWindowCountsNewBestsOfThisMesh) {
  std::vector<double> E(31);
  for (int i = 0; i <= 30; ++i) E[i] = 1.0 - 0.002 * i;  // 2 % over 10 iterations
  const auto last = [](const std::vector<OptimizeRecord>& h) { return h.back().objective; };
  std::vector<OptimizeRecord> h = objectiveHistory(E);
  EXPECT_EQ(readObjectiveWindow(h, 30, 10, 1e-2, last(h)), ObjectiveWindow::GoesOn);
  EXPECT_EQ(readObjectiveWindow(h, 30, 10, 3e-2, last(h)), ObjectiveWindow::NoDecrease);
  EXPECT_EQ(readObjectiveWindow(h, 9, 10, 3e-2, last(h)), ObjectiveWindow::GoesOn) << "the window is not full";

  // Snapping back and forth: the objective alternates, the best does not move.
  for (int i = 15; i <= 30; ++i) h[i].objective = (i % 2 ? 0.90 : 0.80);
  EXPECT_EQ(readObjectiveWindow(h, 30, 10, 1e-2, 0.90), ObjectiveWindow::NoDecrease);

  // A remeshing five iterations ago: the window has not yet a start on this mesh.
  h = objectiveHistory(std::vector<double>(31, 0.5));
  h[26].remeshed = true;
  EXPECT_EQ(readObjectiveWindow(h, 30, 10, 1e-2, 0.5), ObjectiveWindow::GoesOn);
  h[26].remeshed = false, h[15].remeshed = true;
  EXPECT_EQ(readObjectiveWindow(h, 30, 10, 1e-2, 0.5), ObjectiveWindow::NoDecrease);

  // The final projection's record (lower than any iterate) is not a new best.
  h = objectiveHistory(std::vector<double>(31, 0.5));
  OptimizeRecord projected = h.back();
  projected.objective = 0.1, projected.projected = true;
  h.push_back(projected);
  EXPECT_EQ(readObjectiveWindow(h, 30, 10, 1e-2, 0.5), ObjectiveWindow::NoDecrease);
}

// A resettled branch (the balloon snapped into another equilibrium, its objective higher) is given half a window
// to come below the best iterate before it; the fish's branches that paid came back in 5 and 7 iterations.
TEST(StoppingRule, AResettledBranchHasHalfAWindowToComeBack) {
  // Falling fast to 0.70 at iteration 20, then snapped up to 0.80 and falling 1 % of E per iteration.
  std::vector<double> E(21);
  for (int i = 0; i <= 20; ++i) E[i] = 1.0 - 0.015 * i;
  std::vector<OptimizeRecord> h = objectiveHistory(E);
  OptimizeRecord snapped = h.back();
  snapped.objective = 0.80, snapped.resettled = true;
  h.push_back(snapped);
  for (int i = 21; i <= 26; ++i) {
    OptimizeRecord r;
    r.iteration = i, r.objective = 0.80 - 0.008 * (i - 20);
    h.push_back(r);
  }
  // Iteration 24, 4 since the resettling: still its time (the best before it, 0.70, not yet reached: 0.768).
  std::vector<OptimizeRecord> upTo24(h.begin(), h.begin() + 26);
  ASSERT_EQ(upTo24.back().iteration, 24);
  EXPECT_EQ(readObjectiveWindow(upTo24, 24, 20, 1e-3, upTo24.back().objective), ObjectiveWindow::GoesOn);
  // Iteration 26, half a window (10) gone? Not yet: 6. At a window of 12 it is.
  EXPECT_EQ(readObjectiveWindow(h, 26, 20, 1e-3, h.back().objective), ObjectiveWindow::GoesOn);
  EXPECT_EQ(readObjectiveWindow(h, 26, 12, 1e-3, h.back().objective), ObjectiveWindow::SnapsAway);
  // A branch that comes below the best before it goes on.
  h.back().objective = 0.69;
  EXPECT_EQ(readObjectiveWindow(h, 26, 12, 1e-3, h.back().objective), ObjectiveWindow::GoesOn);
}

// Steps that come after a snapped trial are held at a fold of the balloon's equilibria: longer ones cross it, and
// among them a step cut to a tenth of its direction's is held as well (the fish's last steps alternate between the
// two; short steps alone are also a curved valley's). A
// quarter window of such steps ends the run once they gain less than the window's rate (1 % over 20: 0.25 % over
// 5); so does nothing else: a step that found no snap, a resettling or a faster gain keeps it going.
TEST(StoppingRule, StepsHeldAtAFoldEndTheRunAtTheWindowsRate) {
  // 5 % over the first 20 iterations (the full window goes on), then 0.2 % over the last five.
  std::vector<double> E(26);
  for (int i = 0; i <= 20; ++i) E[i] = 1.0 - 0.0025 * i;
  for (int i = 21; i <= 25; ++i) E[i] = E[20] - 0.0004 * (i - 20);
  std::vector<OptimizeRecord> h = objectiveHistory(E);
  const auto verdict = [&](const std::vector<OptimizeRecord>& r) {
    return readObjectiveWindow(r, 25, 20, 1e-2, r.back().objective);
  };
  EXPECT_EQ(verdict(h), ObjectiveWindow::GoesOn) << "no step was held";
  for (int i = 21; i <= 25; ++i) h[i].snapLimited = true;
  EXPECT_EQ(verdict(h), ObjectiveWindow::HeldAtFold);

  std::vector<OptimizeRecord> free = h;
  free[23].snapLimited = false;
  EXPECT_EQ(verdict(free), ObjectiveWindow::GoesOn) << "one of the five steps met no snap";
  std::vector<OptimizeRecord> cut = free;
  cut[23].cutShort = true;
  EXPECT_EQ(verdict(cut), ObjectiveWindow::HeldAtFold) << "a step cut to a tenth of its direction's cannot grow either";
  cut[21].snapLimited = cut[25].snapLimited = false, cut[21].cutShort = cut[25].cutShort = true;
  EXPECT_EQ(verdict(cut), ObjectiveWindow::GoesOn) << "most of the five steps cut short, not after a snap: no fold";
  std::vector<OptimizeRecord> resettled = h;
  resettled[23].resettled = true;
  EXPECT_EQ(verdict(resettled), ObjectiveWindow::GoesOn) << "a resettling within the five";
  std::vector<OptimizeRecord> faster = h;
  for (int i = 21; i <= 25; ++i) faster[i].objective = E[20] - 0.001 * (i - 20);
  EXPECT_EQ(verdict(faster), ObjectiveWindow::GoesOn) << "0.5 % over five steps: the window's rate is 0.25 %";
}
