// The pattern optimizer (optimize/pattern_optimizer.hpp) on whole runs: on the three-gore sphere the optimized
// inflated shape is much closer to the target than the flattened one, seam lengths match exactly and the
// objective decreases over every accepted step; the mechanisms that keep it going (predicted starts, Gauss-Seidel
// sweeps, resettling, remeshing, the stopping rules, sliding seams), and a heavy seam stays where it was drawn
// while a light one slides further.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "export/outline.hpp"
#include "mesh/simplify.hpp"
#include "optimize/stopping_rule.hpp"
#include "optimize_fixture.hpp"
#include "seams/surface_distance.hpp"

using namespace billow;
using namespace billow::test;

// The optimizer's variables are the panels' outlines and the interior follows them, so what the optimizer shows
// is what the cut panels give: their outlines meshed anew and inflated land within a few percent of the
// optimizer's own figure.
TEST(PatternOptimizer, ThreeGoreSphereGetsMuchCloser) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 90;
  o.keepShapes = true;
  const OptimizeRun r = optimize(f, o, 90, true);
  std::printf(
      "[figures] three-gore sphere: preview quality (within 5 %% of the diagonal of the final shape) at "
      "iteration %d, %.0f ms\n",
      r.previewIteration, r.previewMs);
  ASSERT_GE(r.history.size(), 3u);
  const OptimizeRecord &first = r.history.front(), &last = r.history.back();
  for (const auto& h : r.history)
    std::printf(
        "[figures] gores it %3d%s E %.4e (t %.2e s %.2e l %.2e b %.2e L %.2e) rms %.3f%% max %.3f%% "
        "mismatch %.1e grad %.1e alpha %.2g newton %d %.0f ms\n",
        h.iteration, h.projected ? "P" : " ", h.objective, h.terms.target, h.terms.seam, h.terms.length, h.terms.smooth,
        h.terms.laplace, 100 * h.distanceRms, 100 * h.distanceMax, h.seamMismatch, h.gradient, h.stepLength,
        h.equilibriumIterations, h.ms);
  std::printf(
      "[figures] three-gore sphere (%d triangles): distance rms %.3f%% -> %.3f%% of the diagonal (factor %.1f), "
      "max %.3f%% -> %.3f%%, %zu records, %s, %.0f ms; cut panels %.3f%% (%d elements)\n",
      f.built.figures.triangles, 100 * first.distanceRms, 100 * last.distanceRms, first.distanceRms / last.distanceRms,
      100 * first.distanceMax, 100 * last.distanceMax, r.history.size(), toString(r.state), r.ms,
      100 * r.cut.distanceRms, r.cut.elements);
  EXPECT_GT(first.distanceRms / last.distanceRms, 2.5);  // 5.8 % -> 1.96 %: three gores on fixed meridians
  EXPECT_LT(last.seamMismatch, 1e-4);
  expectObjectiveNeverRises(r.history);
  ASSERT_TRUE(r.cut.ok) << r.cut.message;
  EXPECT_NEAR(r.cut.distanceRms, last.distanceRms, 0.1 * last.distanceRms);
  EXPECT_LT(r.cut.distanceRms, 0.5 * first.distanceRms);
}

// The target's distances to the inflated shape are measured once per iterate (for the record's figure; every
// vertex of a target no finer than the balloon, as here), and the app streams them from there: they are the shape's
// own until the shape changes.
TEST(PatternOptimizer, TargetDistancesAreThoseOfTheCurrentShape) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 3;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  EXPECT_EQ(opt.targetDistances(), nullptr) << "nothing measured before the first equilibrium";
  for (int k = 0; k < 3 && opt.step(1) == OptimizeState::Running; ++k) {
    const Eigen::VectorXd* measured = opt.targetDistances();
    ASSERT_NE(measured, nullptr);
    const TargetCoverage fresh = targetCoverage(opt.objective().imls().target(), opt.inflated(),
                                                outerTriangles(opt.mesh()), opt.objective().modelSize());
    EXPECT_EQ(*measured, fresh.distances);
    EXPECT_NEAR(opt.history().back().targetDistanceRms, fresh.summary.rms, 1e-15);
  }
}

// On a target with more than twice as many vertices as the balloon's outer surface, a record during the run
// measures the target at E_cover's sample of its vertices (the whole target took a quarter of a coarse run on a
// 94k-vertex scan): close to the whole measure, and the app then measures the whole itself. The figures a run keeps,
// its last record and its own mesh's last before the cut panels (the app compares the two), measure every vertex.
TEST(PatternOptimizer, AFineTargetIsSampledDuringARunAndMeasuredWholeWhereItsFiguresAreKept) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 200);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 6;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  const TriMesh& target = opt.objective().imls().target();
  const double D = opt.objective().modelSize();
  ASSERT_LT(opt.objective().coverVertices().size(), size_t(target.numVertices())) << "a target finer than the balloon";
  int sampled = 0;
  while (opt.step(1) == OptimizeState::Running) {
    const OptimizeRecord& r = opt.history().back();
    if (!r.targetSampled) continue;
    ++sampled;
    EXPECT_EQ(opt.targetDistances(), nullptr) << "no whole field to stream";
    const TargetCoverage whole = targetCoverage(target, opt.inflated(), outerTriangles(opt.mesh()), D);
    EXPECT_NEAR(r.targetDistanceRms, whole.summary.rms, 0.15 * whole.summary.rms) << "iteration " << r.iteration;
    EXPECT_LE(r.targetDistanceMax, whole.summary.max + 1e-15);
  }
  EXPECT_GE(sampled, 3);
  ASSERT_NE(opt.state(), OptimizeState::Failed) << opt.message();
  const auto& h = opt.history();
  const OptimizeRecord& last = h.back();
  EXPECT_FALSE(last.targetSampled);
  const TargetCoverage whole = targetCoverage(target, opt.inflated(), outerTriangles(opt.mesh()), D);
  EXPECT_EQ(last.targetDistanceRms, whole.summary.rms);
  ASSERT_NE(opt.targetDistances(), nullptr);
  EXPECT_EQ(*opt.targetDistances(), whole.distances);
  const auto cut = std::find_if(h.rbegin(), h.rend(), [](const OptimizeRecord& q) { return q.cutPanels; });
  ASSERT_NE(cut, h.rend()) << "the run ends on its cut panels";
  ASSERT_NE(std::next(cut), h.rend());
  EXPECT_FALSE(std::next(cut)->targetSampled) << "the own mesh's last figures, which the cut panels' are compared with";
  for (const OptimizeRecord& q : h)  // the last iterate's, recorded before the run ended, too
    if (q.iteration == last.iteration) EXPECT_FALSE(q.targetSampled);
}

// A fine target (a scan, tens of thousands of triangles and more) is optimized on its working copy, and what the run
// reports, the distance both ways, is measured on the target itself.
TEST(PatternOptimizer, AFineTargetIsOptimizedOnItsWorkingCopyAndMeasuredOnItself) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 200);
  ASSERT_TRUE(f.built.ok());
  TriMesh fine = f.scene->target;
  while (fine.numTriangles() <= 2 * kWorkingTargetTriangles) fine = splitInFour(fine);
  OptimizeOptions o;
  o.stopping.maxIterations = 4;
  PatternOptimizer opt(fine, f.built, f.weights, o);
  EXPECT_NEAR(opt.objective().imls().target().numTriangles(), kWorkingTargetTriangles, 2);
  while (opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_NE(opt.state(), OptimizeState::Failed) << opt.message();
  const OptimizeRecord& last = opt.history().back();
  const double D = opt.objective().modelSize();
  const TargetCoverage whole = targetCoverage(fine, opt.inflated(), outerTriangles(opt.mesh()), D);
  EXPECT_EQ(last.targetDistanceRms, whole.summary.rms);
  ASSERT_NE(opt.targetDistances(), nullptr);
  EXPECT_EQ(opt.targetDistances()->size(), fine.numVertices()) << "one per vertex of the target itself";
  const SurfaceProjector projector(fine);
  const Eigen::VectorXd& w = opt.objective().targetWeights();
  double sum = 0;
  int count = 0;
  for (int i = 0; i < opt.inflated().rows(); ++i) {
    if (w[i] == 0) continue;
    double d = 0;
    projector.project(opt.inflated().row(i).transpose(), &d);
    sum += (d / D) * (d / D), ++count;
  }
  EXPECT_DOUBLE_EQ(last.distanceRms, std::sqrt(sum / count));
  EXPECT_LT(last.distanceRms, opt.history().front().distanceRms) << "closer than the flattened panels";
}

// A step whose equilibrium is predicted to move the balloon far beyond the last steps' is shortened before it is
// tried (OptimizeSearch::shapeStepGrowth, 5 by default): such trials settle higher about half the time, after
// many Newton iterations. Held to twice here; without the limit some accepted step grows more than that.
TEST(PatternOptimizer, StepsGrowNoMoreThanTheLimitInPredictedShapeMove) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const Fixture f = makeFixture("../../bench/designs/penguin-front-back.billow.json", 1000);
  ASSERT_TRUE(f.built.ok());
  for (double growth : {0.0, 2.0}) {
    OptimizeOptions o;
    o.search.shapeStepGrowth = growth;
    o.remeshing.coarseFactor = 1;
    o.stopping.maxIterations = 40;
    PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
    while (opt.step(5) == OptimizeState::Running) {
    }
    double largestGrowth = 0;
    std::vector<double> last;  // of the last three accepted steps
    for (const OptimizeRecord& r : opt.history()) {
      if (r.iteration == 0 || r.remeshed || r.resettled || r.restored || r.projected) continue;  // no step
      const double before = last.empty() ? 0 : *std::max_element(last.begin(), last.end());
      if (before > 0) largestGrowth = std::max(largestGrowth, r.predictedMove / before);
      last.push_back(r.predictedMove);
      if (last.size() > 3) last.erase(last.begin());
    }
    std::printf("[figures] penguin 1k, step growth limit %.0f: largest growth %.2f over %d iterations, rms %.3f%%\n",
                growth, largestGrowth, opt.iterations(), 100 * opt.history().back().distanceRms);
    if (growth > 0)
      // The step is shortened once, linearly in alpha, and the seam-length projection bends it a little: 1.5 %
      // over natively, 5.9 % in wasm since the factorization's ordering changed (session 43).
      EXPECT_LE(largestGrowth, 1.1 * growth);
    else
      EXPECT_GT(largestGrowth, 2) << "no step grew that much: the test shows nothing";
  }
}

TEST(PatternOptimizer, ProjectedTrialsEndWhereTheTangentialGradientIsSmall) {
  // With every trial projected onto equal seam lengths, the part of a step across that set is undone by the
  // projection. L-BFGS works with the gradient's tangential part and the line search measures its slope along the
  // projected path (g T d), so the run ends at a stationary point of the constrained problem, where the recorded
  // (tangential) gradient is small. With the slope g d it stopped at 5.0e-3, searching down to steps of 1e-4
  // along directions that were no descent once projected.
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.remeshing.cutPanels = false;  // stationary on its own mesh; the cut panels' fresh mesh is not
  const OptimizeRun r = optimize(f, o, 80);
  ASSERT_GE(r.history.size(), 3u);
  EXPECT_LT(r.history.back().seamMismatch, 1e-4);
  expectObjectiveNeverRises(r.history);
  std::printf("[figures] sphere gores 800: %d iterations, rms %.3f%%, gradient %.2e, %s\n", r.iterations,
              100 * r.history.back().distanceRms, r.history.back().gradient, r.message.c_str());
  EXPECT_LT(r.history.back().gradient, 1e-3);  // the Lagrangian's gradient (measured 2.3e-4)
  EXPECT_GT(r.history.front().gradient, 10 * r.history.back().gradient)
      << "the run started stationary: it shows nothing";
}

TEST(PatternOptimizer, GaussSeidelBeforeEachSolveSavesNewtonIterations) {
  // A step of the panels leaves parts of the foil slack at the last shape (its rest lengths change by more than
  // the sheet's strain); Gauss-Seidel sweeps push them out before Newton (OptimizeSearch::gaussSeidelSweeps).
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  double perSolve[2] = {0, 0};
  for (int sweeps : {0, 10}) {
    OptimizeOptions o;
    o.search.gaussSeidelSweeps = sweeps;
    o.search.predictEquilibrium = false;  // from the last shape, as before the prediction (next test)
    PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
    while (opt.step(1) == OptimizeState::Running && opt.iterations() < 15) {
    }
    ASSERT_GE(opt.iterations(), 15) << opt.message();
    int newton = 0;
    for (size_t k = 1; k < opt.history().size(); ++k) newton += opt.history()[k].equilibriumIterations;
    perSolve[sweeps > 0] = double(newton) / (opt.history().size() - 1);
    expectObjectiveNeverRises(opt.history());
    std::printf("[figures] sphere gores 800, %d sweeps: %.1f Newton iterations per accepted solve, rms %.3f%%\n",
                sweeps, perSolve[sweeps > 0], 100 * opt.history().back().distanceRms);
  }
  EXPECT_LT(perSolve[1], 0.8 * perSolve[0]);
}

TEST(PatternOptimizer, PredictedStartSavesNewtonIterations) {
  // Each trial's solve starts from x + dx, dx = -K^-1 dg/dX dX with the adjoint's factorization
  // (OptimizeSearch::predictEquilibrium), instead of from the last shape.
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  double perSolve[2] = {0, 0};
  for (bool predict : {false, true}) {
    OptimizeOptions o;
    o.search.predictEquilibrium = predict;
    PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
    while (opt.step(1) == OptimizeState::Running && opt.iterations() < 15) {
    }
    ASSERT_GE(opt.iterations(), 15) << opt.message();
    int newton = 0;
    for (size_t k = 1; k < opt.history().size(); ++k) newton += opt.history()[k].equilibriumIterations;
    perSolve[predict] = double(newton) / (opt.history().size() - 1);
    expectObjectiveNeverRises(opt.history());
    std::printf("[figures] sphere gores 800, prediction %s: %.1f Newton iterations per accepted solve, rms %.3f%%\n",
                predict ? "on" : "off", perSolve[predict], 100 * opt.history().back().distanceRms);
  }
  EXPECT_LT(perSolve[1], 0.75 * perSolve[0]);
}

// The gallery's first fish: an internal panel in the middle plane between the back and belly seams. The
// inflating sides pull that outline inward, so the panel goes slack: a floppy flap whose inside vertices have
// no stiffness. The optimizer used to stop after one step there (its adjoint failed; 2.8 % RMS at 1k); now
// it goes on like on any other design.
TEST(PatternOptimizer, SlackInternalPanelDoesNotStopTheOptimizer) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const Fixture f = makeFixture("fish-midplane.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  ASSERT_EQ(f.built.pattern.panels.size(), 3u);
  ASSERT_TRUE(f.built.pattern.panels[2].internal);
  OptimizeOptions oo;
  oo.stopping.maxIterations = 30;
  const OptimizeRun r = optimize(f, oo);
  const auto& h = r.history;
  std::printf(
      "[figures] fish with a slack internal panel, 600 elements: %d iterations, rms %.3f %% -> %.3f %%, target to "
      "inflated %.3f %% -> %.3f %% (%s)\n",
      r.iterations, 100 * h.front().distanceRms, 100 * h.back().distanceRms, 100 * h.front().targetDistanceRms,
      100 * h.back().targetDistanceRms, r.message.c_str());
  EXPECT_EQ(r.iterations, 30) << r.message;
  // before: 0.73; E_target alone 0.65; with E_cover 0.68 (it trades some of this figure for the target's side)
  EXPECT_LT(h.back().distanceRms, 0.72 * h.front().distanceRms);
  expectObjectiveNeverRises(h, 1e-12);
}

// The gallery fish's four outer panels without its internal panel, at 600 elements: after a few steps the
// inflated shape sits in an unstable equilibrium (a tiny change of the panels makes it snap into another one,
// so E(X) jumps and no step passes the line search). The optimizer used to stop there ("no further decrease
// along the gradient", 1.56 % RMS at 1k after 6 iterations); it now takes the shape the balloon snaps into
// (a "resettled" record, the objective may rise) and goes on. The seams' stiffness (InflateOptions::
// seamStiffness) takes that instability away on this design (1.56 % -> 1.03 % in 25 plain iterations), so the
// test runs without it, where the instability is known to occur.
TEST(PatternOptimizer, UnstableEquilibriumIsResettledNotTheEnd) {
  const Fixture f = makeFixture("fish-four-panels.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions oo;
  oo.stopping.maxIterations = 25;
  oo.inflate.seamStiffness = 0;
  oo.remeshing.cutPanels = false;  // the resettling on this mesh, not the cut panels
  const OptimizeRun r = optimize(f, oo);
  const auto& h = r.history;
  const int resettled = int(std::count_if(h.begin(), h.end(), [](const OptimizeRecord& k) { return k.resettled; }));
  std::printf(
      "[figures] fish without its internal panel, 600 elements: %d iterations, %d resettled, rms %.3f %% -> "
      "%.3f %% (%s)\n",
      r.iterations, resettled, 100 * h.front().distanceRms, 100 * h.back().distanceRms, r.message.c_str());
  EXPECT_EQ(r.iterations, 25) << r.message;
  EXPECT_GE(resettled, 1);
  EXPECT_EQ(resettled, r.resettlings);
  EXPECT_LT(h.back().distanceRms, h.front().distanceRms);
  expectObjectiveNeverRises(h, 1e-12);
  expectEndsAtItsBest(h);
}

// Issue 24: a foil balloon of front and back panels creeps towards the end of its equilibrium: L-BFGS steps snap
// the balloon into another equilibrium, whose solve took 25-110 Newton iterations before the line search refused
// it. The stuffed toy seen from the front does so within 20 iterations (the bench's penguin and fish did too,
// until their seams stopped leaving sliver triangles along the outline and kept its sharp turns). A trial that
// leaves its predicted shape by far is now abandoned as it goes (two such snaps in a row take the shape it snaps
// into, a resettling). And no step makes a panel's outline cross itself: such a panel overlaps itself and cannot
// be cut, although none of its triangles folds (the optimizer's cow and penguin did).
TEST(PatternOptimizer, FrontBackStuffedToyAbandonsTrialsThatSnapAndKeepsItsOutlines) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const Fixture f = makeFixture("stuffedtoy-front-back.billow.json", 1500);
  ASSERT_TRUE(f.built.ok());
  // Its steps free to grow: held to five times the last ones' (the default), none of its first 20 iterations'
  // trials snaps (13 refused, 3.1 s).
  OptimizeOptions o;
  o.search.shapeStepGrowth = 0;
  o.remeshing.cutPanels = false;  // the outlines on the run's own mesh
  const std::unique_ptr<PatternOptimizer> optimized = optimizedFor(f, 20, o);
  const PatternOptimizer& opt = *optimized;
  const OptimizeTimings& t = opt.timings();
  const auto& h = opt.history();
  int newton = 0;
  for (const auto& r : h) newton += r.equilibriumIterations;
  std::printf(
      "[figures] stuffed toy front/back 1.5k: %d iterations, %d solves (%d trials refused, %d snapped), %d resettled, "
      "Newton %d accepted, rms %.3f %% -> %.3f %%, %.1f s\n",
      opt.iterations(), t.equilibriumSolves, t.rejectedTrials, t.snappedTrials, t.resettlings, newton,
      100 * h.front().distanceRms, 100 * h.back().distanceRms, t.totalMs / 1000);
  EXPECT_EQ(opt.iterations(), 20) << opt.message();
  EXPECT_GE(t.snappedTrials, 1);
  EXPECT_LT(h.back().distanceRms, 0.5 * h.front().distanceRms);
  expectObjectiveNeverRises(h, 1e-12);
  expectEndsAtItsBest(h);
  expectCuttableOutlines(opt.pattern());
  expectSameSeamRods(f.built.pattern, opt.pattern());
}

// Issue 24: near some patterns the balloon's equilibrium chatters (wrinkled fabric changing regime: a trial's residual
// alternates between 0.02 and 0.2 for its whole Newton budget), and so does every shorter trial. The stuffed toy's
// outline seen from above (the Outline tool's seam, tests/data) at 1,500 elements spent the whole budget on 43 trials
// (3,020 Newton iterations in all, 8.7 s), line searches halving down to steps of 1e-6. Five such trials in a row are
// now taken as a snap: the shape the balloon moves to (a resettling), else the line search ends.
TEST(PatternOptimizer, TrialsThatDoNotSettleAreTakenAsASnap) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const Fixture f = makeFixture("stuffedtoy-from-above.billow.json", 1500);
  ASSERT_TRUE(f.built.ok());
  // On the path where the trials chattered: E_fair holds off the needles this outline grew there (2 teeth), and the
  // coarse phase's reach at the seams takes it elsewhere; those runs meet no unsettled trial.
  OptimizeOptions o = appStoppingRule();
  o.weights.fair = 0;
  o.remeshing.coarseCoverReachAtSeams = 0;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(5) == OptimizeState::Running) {
  }
  const OptimizeTimings& t = opt.timings();
  const auto& h = opt.history();
  std::printf(
      "[figures] stuffed toy from above 1.5k, app rule: %d iterations, %d solves, %d trials unsettled, %d resettled, "
      "Newton %d, rms %.3f %% -> %.3f %%, %.1f s (%s)\n",
      opt.iterations(), t.equilibriumSolves, t.unsettledTrials, t.resettlings, t.newtonIterations,
      100 * h.front().distanceRms, 100 * h.back().distanceRms, t.totalMs / 1000, opt.message().c_str());
  ASSERT_EQ(opt.state(), OptimizeState::Converged) << opt.message();
  EXPECT_LT(t.unsettledTrials, 25);
  EXPECT_LT(h.back().distanceRms, 0.7 * h.front().distanceRms);
  expectEndsAtItsBest(h);
  expectCuttableOutlines(opt.pattern());
}

// The stuffed toy's outline from the front (the Outline tool's seam, tests/data) runs into thin notches (around the
// thin disc ears): the flattened panels have slits, and steps that made their sides cross were refused until the
// optimizer stopped (after 9 iterations at 2.9 % here). E_gap holds the sides apart, so the steps go along them.
TEST(PatternOptimizer, FrontBackStuffedToyGoesOnAlongItsOutlinesThinNotches) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const Fixture f = makeFixture("stuffedtoy-front-back.billow.json", 1500);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.remeshing.cutPanels = false;  // the outlines on the run's own mesh
  const std::unique_ptr<PatternOptimizer> optimized = optimizedFor(f, 20, o);
  const PatternOptimizer& opt = *optimized;
  const auto& h = opt.history();
  std::printf("[figures] stuffed toy front/back 1.5k: %d iterations, rms %.3f %% -> %.3f %%, E_gap %.2e, %.1f s\n",
              opt.iterations(), 100 * h.front().distanceRms, 100 * h.back().distanceRms, h.back().terms.gap,
              opt.timings().totalMs / 1000);
  EXPECT_EQ(opt.iterations(), 20) << opt.message();
  EXPECT_GT(h.back().terms.gap, 0) << "the barrier held an outline apart";
  EXPECT_LT(h.back().distanceRms, 0.45 * h.front().distanceRms);
  expectObjectiveNeverRises(h, 1e-5);
  expectCuttableOutlines(opt.pattern());
  expectSameSeamRods(f.built.pattern, opt.pattern());
}

// The coarse first phase (OptimizeRemeshing::coarseFactor, on by default at 3k): the flattened panels meshed at
// twice the edge length until that mesh's stopping rule or its iterations end it, then the outlines meshed at
// the design's edge length. What the coarse phase found carries over (the penguin's fine phase starts at a
// quarter of the flattened panels' distance), and however the run ends, it ends on the design's mesh.
TEST(PatternOptimizer, CoarseFirstPhaseCarriesOverToTheDesignsMesh) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const Fixture f = makeFixture("../../bench/designs/penguin-front-back.billow.json", 3000);
  ASSERT_TRUE(f.built.ok());
  const int designTriangles = f.built.figures.triangles;
  for (const int iterations : {40, 6}) {
    OptimizeOptions o;
    o.stopping.maxIterations = iterations;
    o.keepShapes = true;
    PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
    while (opt.step(1) == OptimizeState::Running) {
    }
    const auto& h = opt.history();
    const auto switched = std::find_if(h.begin(), h.end(), [](const OptimizeRecord& r) { return r.remeshed; });
    ASSERT_NE(switched, h.end()) << "no switch to the design's mesh";
    const size_t k = size_t(switched - h.begin());
    std::printf(
        "[figures] fb-penguin 3k, %d iterations: coarse phase %d iterations (%.2f s), rms %.3f %% -> %.3f %%; "
        "fine phase from %.3f %% to %.3f %%, %.1f s\n",
        iterations, switched->iteration, h[k - 1].ms / 1000, 100 * h.front().distanceRms, 100 * h[k - 1].distanceRms,
        100 * switched->distanceRms, 100 * h.back().distanceRms, opt.timings().totalMs / 1000);
    // The switch, and the cut panels at the end (OptimizeRemeshing::cutPanels; cut again from an earlier iterate
    // where the last one's cut snapped).
    EXPECT_EQ(std::count_if(h.begin(), h.end(), [](const OptimizeRecord& r) { return r.remeshed && !r.cutPanels; }), 1);
    EXPECT_GE(std::count_if(h.begin(), h.end(), [](const OptimizeRecord& r) { return r.cutPanels; }), 1);
    EXPECT_LE(switched->iteration, iterations / 2);
    EXPECT_LT(opt.shapes().front().rows(), 0.4 * opt.inflated().rows()) << "the first phase is not coarse";
    EXPECT_NEAR(opt.mesh().numTriangles(), designTriangles, 0.15 * designTriangles);
    EXPECT_EQ(opt.iterations(), iterations) << opt.message();
    EXPECT_LT(h.back().seamMismatch, 1e-9);
    expectCuttableOutlines(opt.pattern());
    if (iterations == 40) {
      EXPECT_LT(switched->distanceRms, 0.5 * h.front().distanceRms);
      // The fine phase gets closer on its mesh; the cut panels at the end may not (the penguin's flippers can
      // snap out once cut: bench/README.md "The cut panels").
      double fineBest = INFINITY;
      for (auto r = switched + 1; r != h.end() && !r->cutPanels; ++r) fineBest = std::min(fineBest, r->distanceRms);
      EXPECT_LT(fineBest, switched->distanceRms);
    }
  }
}

// The coarse phase reaches farther from the seams (OptimizeRemeshing::coarseCoverReachAtSeams): the cow from its
// side with a gusset strip left its hooves, past the strip's reach, for the fine phase to grow the legs towards over
// some 20 iterations, so the preview (within 5 % of the final shape) came only then, 1.5-4.7 s natively. Reaching
// from the seams, the coarse phase ends nearer the target the other way (1.55 % against 1.82 %).
TEST(PatternOptimizer, CoarsePhaseReachesALimbPastTheOutline) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  const Fixture f = makeFixture("../../bench/designs/spot-gusset.billow.json", 3000);
  ASSERT_TRUE(f.built.ok());
  double rms[2];
  for (const int withReach : {0, 1}) {
    OptimizeOptions o;
    o.stopping.maxIterations = 150;  // the app's: a coarse phase of up to 30
    if (!withReach) o.remeshing.coarseCoverReachAtSeams = 0;
    PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
    while (opt.step(1) == OptimizeState::Running && !opt.history().back().remeshed) {
    }
    const auto& h = opt.history();
    ASSERT_GE(h.size(), 3u);
    ASSERT_TRUE(h.back().remeshed) << "no switch to the design's mesh";
    const OptimizeRecord& last = h[h.size() - 2];  // the coarse phase's last iterate
    rms[withReach] = last.targetDistanceRms;
    std::printf(
        "[figures] gusset-spot 3k, coarse reach at the seams %s: after %d coarse iterations target to inflated "
        "%.3f %% (farthest %.2f %%), inflated to target %.3f %%\n",
        withReach ? "0.15" : "none", last.iteration, 100 * last.targetDistanceRms, 100 * last.targetDistanceMax,
        100 * last.distanceRms);
  }
  EXPECT_LT(rms[1], 0.9 * rms[0]);
}

// A maker cuts the outlines: the cut panels are the current outlines meshed anew at the design's edge length. The
// check once settled them through a coarse first phase of its own, which meshed the outlines at twice the edge
// length and back: here their vertices then lay up to 13 mm (2 % of the model) off the outlines and inflated 18 %
// farther from the target than the run's own figure (the cat from its side: 1.476 % against 0.824 % cut at once,
// bench/README.md "The cut panels"). Meshed at once, they move only where the exact seam lengths pull chords
// that differ across a seam (4 mm here, 7 %).
// And a held-seam run ends on such cut panels, settled: the optimizer's own mesh can hold an equilibrium they do
// not have (a gusseted penguin's flippers, down at 0.73 % on the run's mesh, stood out once cut: 2.88 %), so the
// figure the designer reads is the cut panels'.
TEST(PatternOptimizer, RunEndsOnItsCutPanelsMeshedAtTheDesignsEdgeLength) {
  const Fixture f = makeFixture("../../bench/designs/penguin-front-back.billow.json", 2000);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 4;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_EQ(opt.state(), OptimizeState::Stopped);
  const auto& history = opt.history();
  const auto lastRemeshing =
      std::find_if(history.rbegin(), history.rend(), [](const OptimizeRecord& r) { return r.remeshed; });
  ASSERT_NE(lastRemeshing, history.rend());
  EXPECT_EQ(lastRemeshing->iteration, 4);  // after the last iteration, not the coarse phase's switch
  EXPECT_EQ(opt.timings().remeshings, 2);
  EXPECT_NEAR(opt.mesh().numTriangles(), f.built.figures.triangles, 0.15 * f.built.figures.triangles);

  const CutPanelsCheck cut = opt.checkCutPanels();
  ASSERT_TRUE(cut.ok) << cut.message;
  const double D = opt.objective().modelSize(), rms = history.back().distanceRms;
  const Outlines cutOutlines = buildOutlines(cut.pattern), runOutlines = buildOutlines(opt.pattern());
  ASSERT_EQ(cut.pattern.panels.size(), opt.pattern().panels.size());
  double farthest = 0;
  for (size_t p = 0; p < cut.pattern.panels.size(); ++p) {
    const Polygon2 outline = runOutlines.panels[p].points(opt.pattern().panels[p]);
    for (const Vec2& q : cutOutlines.panels[p].points(cut.pattern.panels[p]))
      farthest = std::max(farthest, distanceToBoundary(q, outline));
  }
  std::printf(
      "[figures] fb-penguin 2k after 4 iterations: rms %.3f %% (its cut panels), cut again %.3f %% (%d elements, %.0f "
      "ms), their outline vertices up to %.1f mm off the outlines\n",
      100 * rms, 100 * cut.distanceRms, cut.elements, cut.ms, 1000 * farthest);
  EXPECT_NEAR(cut.elements, f.built.figures.triangles, 0.15 * f.built.figures.triangles);
  EXPECT_LT(farthest, 0.01 * D);
  // A second cut resamples the resampled outlines and settles afresh: close, not equal. The penguin's flippers have two
  // equilibria ("The cut panels" in bench/README.md), and a fresh solve may take the other: 1.60 -> 1.85 % on this
  // path.
  EXPECT_NEAR(cut.distanceRms, rms, 0.2 * rms);
}

// The run's end meshes the outlines anew as they are cut (OptimizeRemeshing::cutPanels). Where the last iterates sit
// near the fold of their equilibrium, the cut panels can snap into another one (fb-spot: the head across the
// thickness, 1.3 -> 1.9 %); then an earlier iterate is cut instead, and the designer gets cut panels about as close
// as the optimizer's own mesh was. The snapped cut's settle is abandoned once it has moved beyond any cut that keeps
// its shape, so it leaves no record. The cow at 1,700 elements, its flattened panels moved at the rounding level (seed
// 7, as `billow_design_bench --perturb` moves them): a path whose cut snaps (seeds 7, 8, 9, 11, 12 and 14 of 1-14 do).
TEST(PatternOptimizer, CutPanelsThatSnapAreCutFromAnEarlierIterate) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  Fixture f = makeFixture("../../bench/designs/spot-front-back.billow.json", 1700);
  ASSERT_TRUE(f.built.ok());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (Panel& panel : f.built.pattern.panels)
    for (int v = 0; v < panel.vertices.rows(); ++v)
      for (int k = 0; k < 2; ++k) panel.vertices(v, k) += 1e-12 * f.built.figures.edgeLength * u(rng);
  // On the path where the cut snapped (with E_fair its cut did not snap).
  OptimizeOptions o = appStoppingRule();
  o.weights.fair = 0;
  const OptimizeRun r = optimize(f, o);
  ASSERT_EQ(r.state, OptimizeState::Converged) << r.message;
  const auto& h = r.history;
  std::vector<size_t> cuts;
  for (size_t k = 0; k < h.size(); ++k)
    if (h[k].cutPanels) cuts.push_back(k);
  ASSERT_EQ(cuts.size(), 1u);
  ASSERT_GE(cuts[0], 2u);
  // The earlier iterate's cut shape on the optimizer's mesh, what the panes compare the cut panels with, comes
  // right after the last iterate's.
  const OptimizeRecord &earlier = h[cuts[0] - 1], &ownLast = h[cuts[0] - 2];
  ASSERT_TRUE(earlier.restored) << "the last iterate's cut did not snap here: this test needs a path whose cut does";
  EXPECT_TRUE(ownLast.projected);
  double ownBest = INFINITY;  // the closest iterate on the optimizer's own mesh, from its last remeshing on
  for (size_t k = cuts[0] - 2; k > 0 && !h[k].remeshed; --k) ownBest = std::min(ownBest, h[k].distanceRms);
  const double designers = h.back().distanceRms;
  std::printf(
      "[figures] fb-spot 1.7k, perturbed (7): own mesh %.3f %% (its best %.3f %%), its cut snapped; an earlier "
      "iterate %.3f %%, cut %.3f %%\n",
      100 * ownLast.distanceRms, 100 * ownBest, 100 * earlier.distanceRms, 100 * designers);
  EXPECT_GT(earlier.objective, ownLast.objective);
  EXPECT_LT(h[cuts[0]].objective, 1.25 * earlier.objective);  // kept its shape (kCutSnapRatio)
  EXPECT_LT(designers, 1.1 * ownBest);
  expectCuttableOutlines(r.pattern);
}

// Flat-cut outlines come out as a maker cuts them. Trials are projected onto equal seam lengths; with full steps the
// projection undid a step's part across that set by the shortest move, at the outlines' kinks, which grew into saw
// teeth and slits (fb-bunny at 3,000 elements: 1-5 a panel on every path of four, 5 on this one; fb-spot 1-7; the
// mushroom's gusset strip 4-9), so the steps are taken along the set's tangent (OptimizeSearch::projectEveryStep).
// The round balloon's two discs, tangent steps and all, gathered their rim into spikes and slits a vertex wide on the
// plateau where nothing fair was left to gain (5 and 13 teeth on this design), which E_fair holds off.
TEST(PatternOptimizer, FlatCutOutlinesComeOutWithoutTeeth) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  for (const char* design : {"../../bench/designs/bunny-front-back.billow.json", "sphere-equator.billow.json"}) {
    const Fixture f = makeFixture(design, 3000);
    ASSERT_TRUE(f.built.ok()) << design;
    for (const Panel& panel : f.built.pattern.panels) ASSERT_EQ(outlineTeeth(panel), 0) << "flattened " << panel.name;
    const OptimizeRun r = optimize(f, appStoppingRule());
    ASSERT_NE(r.state, OptimizeState::Failed) << design << ": " << r.message;
    EXPECT_LT(r.history.back().distanceRms, 0.8 * r.history.front().distanceRms)
        << design << ": the run gained little, it shows nothing";
    int teeth = 0;
    for (const Panel& panel : r.pattern.panels) {
      teeth += outlineTeeth(panel);
      EXPECT_EQ(outlineTeeth(panel), 0) << design << ", " << panel.name;
    }
    std::printf("[figures] %s 3k, app rule: %d iterations, rms %.3f %% -> %.3f %%, %d teeth\n", design, r.iterations,
                100 * r.history.front().distanceRms, 100 * r.history.back().distanceRms, teeth);
  }
}

// Under the app's rule the coarse phase ends on its own window, shorter than the fine mesh's: at the first iteration
// where its best objective fell by less than 1 % over the last coarseWindow iterations (fb-spot's coarse optimum
// once came within a dozen, and its 20-iteration window ran on to the 26th: 1.4 s of wasm without change). The six
// gores of a sphere: their coarse phase ends at the 21st.
TEST(PatternOptimizer, CoarsePhaseEndsOnItsOwnWindow) {
  const Fixture f = makeFixture("../../bench/designs/sphere6.billow.json", 3000);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o = appStoppingRule();
  o.stopping.maxIterations = 60;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  const auto switched = [&] {
    return std::any_of(opt.history().begin(), opt.history().end(), [](const OptimizeRecord& r) { return r.remeshed; });
  };
  while (!switched() && opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_TRUE(switched());
  const auto& h = opt.history();
  const size_t k =
      size_t(std::find_if(h.begin(), h.end(), [](const OptimizeRecord& r) { return r.remeshed; }) - h.begin());
  const int window = o.remeshing.coarseWindow, last = h[k - 1].iteration;
  ASSERT_LT(window, o.stopping.windowIterations);
  // The window rule as the coarse phase read it after iteration `at`.
  const auto windowEnds = [&](int at) {
    std::vector<OptimizeRecord> seen;
    for (size_t j = 0; j < k && h[j].iteration <= at; ++j) seen.push_back(h[j]);
    return readObjectiveWindow(seen, at, window, o.stopping.windowDecrease, seen.back().objective) !=
           ObjectiveWindow::GoesOn;
  };
  std::printf("[figures] sphere6 3k, app rule: coarse phase %d iterations, %.2f s, rms %.3f %% -> %.3f %%\n", last,
              h[k - 1].ms / 1000, 100 * h.front().distanceRms, 100 * h[k - 1].distanceRms);
  EXPECT_LT(last, o.remeshing.coarseIterations) << "the phase ran to its cap";
  EXPECT_TRUE(windowEnds(last));
  for (int at = window; at < last; ++at) EXPECT_FALSE(windowEnds(at)) << "the window would have ended it at " << at;
  EXPECT_LT(h[k - 1].distanceRms, 0.9 * h.front().distanceRms) << "the coarse phase gained nothing";
}

// Sec. 5.3: the panels meshed again from their outlines (every 4 iterations here) and the optimization goes
// on from there: no panel is lost, seams keep matching, the shape barely moves across the remesh and keeps
// getting closer to the target afterwards.
TEST(PatternOptimizer, RemeshingKeepsPanelsAndSeamsAndGoesOn) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.remeshing.every = 4;
  o.stopping.maxIterations = 30;
  o.remeshing.cutPanels = false;  // the schedule's remeshings only
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_GE(opt.timings().remeshings, 1);
  const auto& h = opt.history();
  const auto at = std::find_if(h.begin(), h.end(), [](const OptimizeRecord& r) { return r.remeshed; });
  ASSERT_NE(at, h.end());
  ASSERT_NE(at, h.begin());
  const OptimizeRecord &before = *(at - 1), &after = *at, &last = h.back();
  std::printf(
      "[figures] remesh at iteration %d: rms %.3f%% -> %.3f%%, then %.3f%% after %d iterations; %d "
      "remeshings (%.0f ms), %d elements (the design %d)\n",
      after.iteration, 100 * before.distanceRms, 100 * after.distanceRms, 100 * last.distanceRms, last.iteration,
      opt.timings().remeshings, opt.timings().remeshMs, opt.mesh().numTriangles(), int(f.built.figures.triangles));
  EXPECT_EQ(opt.pattern().panels.size(), f.built.pattern.panels.size());
  // At the design's size: meshed by its edge length alone, sliding runs went on at 1.45 x its triangles.
  EXPECT_NEAR(opt.mesh().numTriangles(), f.built.figures.triangles, 0.1 * f.built.figures.triangles);
  EXPECT_NEAR(after.distanceRms, before.distanceRms, 0.2 * before.distanceRms);
  EXPECT_LT(last.distanceRms, after.distanceRms);
  EXPECT_LT(last.seamMismatch, 1e-4);
  EXPECT_NO_THROW(sewPattern(opt.pattern()));
  EXPECT_NE(opt.state(), OptimizeState::Failed) << opt.message();
}

// OptimizeRemeshing::every remeshes on a schedule, at most once per iteration and none after the last one.
TEST(PatternOptimizer, RemeshingOnItsSchedule) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 6, o.remeshing.maxRemeshings = 100, o.remeshing.every = 3;
  o.remeshing.cutPanels = false;  // the schedule's remeshings only
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_NE(opt.state(), OptimizeState::Failed) << opt.message();
  std::vector<int> at;
  for (const OptimizeRecord& r : opt.history())
    if (r.remeshed) at.push_back(r.iteration);
  std::printf("[figures] every 3: %d iterations, %d remeshings\n", opt.iterations(), opt.timings().remeshings);
  ASSERT_FALSE(at.empty());
  for (size_t k = 1; k < at.size(); ++k) EXPECT_GT(at[k], at[k - 1]) << "two remeshings at iteration " << at[k];
  for (int i : at) EXPECT_EQ(i % 3, 0) << i;
  EXPECT_EQ(opt.timings().remeshings, (opt.iterations() - 1) / 3);
  EXPECT_EQ(opt.pattern().panels.size(), f.built.pattern.panels.size());
}

// Outlines that zig-zag below the edge length (free seams, a weak E_smooth) resample into chords
// that differ across a seam. Such a remeshing is refused and the old mesh kept, so every iterate still sews
// (one used to go on with stitched edges 1.5 times apart). So is one whose seam-length projection pulls an
// outline across itself: no iterate is a panel that cannot be cut.
TEST(PatternOptimizer, RemeshingThatWouldNotSewKeepsTheOldMesh) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.weights.seam = 0, o.weights.smooth = 0.05;
  o.remeshing.every = 5, o.remeshing.maxRemeshings = 100, o.stopping.maxIterations = 60;
  o.sliding.seamWeight = 0;  // these settings as they are, not those of sliding seams (slidingOptions)
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
    SCOPED_TRACE("iteration " + std::to_string(opt.iterations()));
    expectCuttableOutlines(opt.pattern());
  }
  ASSERT_NE(opt.state(), OptimizeState::Failed) << opt.message();
  EXPECT_GE(opt.timings().remeshings, 3);
  double worst = 0;
  for (const OptimizeRecord& r : opt.history()) worst = std::max(worst, r.seamMismatch);
  std::printf("[figures] %d iterations, %d remeshings, largest seam mismatch of any iterate %.1e\n", opt.iterations(),
              opt.timings().remeshings, worst);
  EXPECT_LT(worst, 1e-4);
}

// OptimizeStopping::windowDecrease: converged at the first iteration where the objective fell by less than
// that fraction over the last windowIterations iterations, and not before.
TEST(PatternOptimizer, StopsWhenTheObjectiveNoLongerDecreasesNoticeably) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.windowIterations = 5, o.stopping.windowMove = 0, o.stopping.windowDecrease = 0.05;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_EQ(opt.state(), OptimizeState::Converged);
  EXPECT_EQ(opt.message(), "the objective no longer decreases noticeably");
  std::vector<double> E(opt.iterations() + 1, NAN);
  for (const OptimizeRecord& r : opt.history())
    // Not the final seam-length projection, nor the cut panels' record (another mesh) at the same iteration.
    if (!r.projected && !r.cutPanels) E[r.iteration] = r.objective;
  const int n = opt.iterations();
  ASSERT_GE(n, 5);
  EXPECT_LT(E[n - 5] - E[n], 0.05 * E[n]);
  for (int k = 5; k < n; ++k) EXPECT_GE(E[k - 5] - E[k], 0.05 * E[k]) << "iteration " << k;
  std::printf("[figures] sphere gores 800: stopped at iteration %d, objective %.4e (5 before: %.4e)\n", n, E[n],
              E[n - 5]);
}

// The app's work budget (OptimizeStopping::maxWork): the run ends at the first iteration whose work (Newton
// iterations of every solve plus kIterationWork per iteration) reaches it, as converged, and on its cut panels.
TEST(PatternOptimizer, StopsOnceItsWorkIsDone) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  const auto workOf = [](const PatternOptimizer& opt) {
    return opt.timings().newtonIterations + OptimizeStopping::kIterationWork * opt.iterations();
  };
  PatternOptimizer free(f.scene->target, f.built, f.weights, OptimizeOptions{});
  while (free.step(1) == OptimizeState::Running) {
  }
  const int budget = workOf(free) / 2;
  OptimizeOptions o;
  o.stopping.maxWork = budget;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  std::vector<int> work;
  while (opt.step(1) == OptimizeState::Running) work.push_back(workOf(opt));
  std::printf("[figures] sphere gores 800: %d iterations, work %d; budget %d: %d iterations\n", free.iterations(),
              workOf(free), budget, opt.iterations());
  ASSERT_EQ(opt.state(), OptimizeState::Converged);
  EXPECT_EQ(opt.message(), "its work budget was spent (more steps seldom bring the cut panels closer)");
  ASSERT_GE(work.size(), 2u);
  EXPECT_GE(work.back(), budget);
  EXPECT_LT(work[work.size() - 2], budget) << "it went on past its budget";
  EXPECT_LT(opt.iterations(), free.iterations());
  const auto last = std::find_if(opt.history().rbegin(), opt.history().rend(),
                                 [](const OptimizeRecord& r) { return !r.projected; });  // not the final projection
  ASSERT_NE(last, opt.history().rend());
  EXPECT_TRUE(last->cutPanels) << "the run did not end on its cut panels";
}

// A window with a remeshing in it is no stall either: the objective there is that of another mesh. With the
// panels meshed anew every 4 iterations every 5-iteration window holds one, and the rule never ends the run
// (without that, this run stopped at iteration 9). Every 5 iterations, a window may start on a fresh mesh and
// is judged as any other.
TEST(PatternOptimizer, ObjectiveWindowDoesNotSpanARemeshing) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  for (const int every : {4, 5}) {
    OptimizeOptions o;
    o.stopping.windowIterations = 5, o.stopping.windowMove = 0, o.stopping.windowDecrease = 0.05;
    o.remeshing.every = every, o.remeshing.maxRemeshings = 100, o.stopping.maxIterations = 40;
    PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
    while (opt.step(1) == OptimizeState::Running) {
    }
    std::printf("[figures] remeshing every %d: %s (%s) at iteration %d, %d remeshings\n", every, toString(opt.state()),
                opt.message().c_str(), opt.iterations(), opt.timings().remeshings);
    EXPECT_NE(opt.state(), OptimizeState::Failed) << opt.message();
    EXPECT_GE(opt.timings().remeshings, every == 4 ? 5 : 1);
    if (every == 4) {
      EXPECT_NE(opt.message(), "the objective no longer decreases noticeably");
    } else {
      EXPECT_EQ(opt.message(), "the objective no longer decreases noticeably");
      EXPECT_EQ(opt.iterations() % 5, 0) << "a window over a remeshing was judged";
    }
  }
}

// OptimizeSliding::seamWeight: a seam whose weight (times weights.seam) is below it slides, and the
// optimizer then steps tangent to equal seam lengths, meshes the panels anew on a schedule and holds its outline
// regularizers at a physical length.
TEST(PatternOptimizer, SlidingSeamsChangeHowTheOptimizerWorks) {
  OptimizeOptions o;
  o.stopping.maxIterations = 300;
  o.stopping.windowDecrease = 0.01;
  EXPECT_FALSE(hasSlidingSeams(o, {1, 1, 1}));
  EXPECT_FALSE(hasSlidingSeams(o, {}));
  EXPECT_TRUE(hasSlidingSeams(o, {1, 0.05, 1}));
  EXPECT_TRUE(hasSlidingSeams(o, {1, 0, 1}));
  OptimizeOptions unweighted = o;
  unweighted.weights.seam = 0;
  EXPECT_TRUE(hasSlidingSeams(unweighted, {1, 1}));
  OptimizeOptions never = o;
  never.sliding.seamWeight = 0;
  EXPECT_FALSE(hasSlidingSeams(never, {0, 0}));

  const double D = 2, atReference = o.sliding.regularizerEdgeLength * D;
  const OptimizeOptions held = slidingOptions(o, {1, 1}, atReference / 2, D);
  EXPECT_FALSE(held.search.gaussNewton);
  EXPECT_EQ(held.stopping.maxIterations, o.stopping.maxIterations);
  EXPECT_EQ(held.stopping.windowDecrease, o.stopping.windowDecrease);
  EXPECT_EQ(held.stopping.distanceWindow, 0);
  EXPECT_EQ(held.remeshing.every, o.remeshing.every);
  EXPECT_EQ(held.remeshing.stallIterations, 0);
  EXPECT_EQ(held.search.sobolevLength, o.search.sobolevLength);
  EXPECT_EQ(held.weights.smooth, o.weights.smooth);
  EXPECT_EQ(held.weights.slidingBelow, o.weights.slidingBelow);

  const OptimizeOptions coarse = slidingOptions(o, {1, 0}, 2 * atReference, D);  // coarser than the reference
  EXPECT_TRUE(coarse.search.gaussNewton);
  EXPECT_EQ(coarse.remeshing.every, o.sliding.remeshEvery);
  EXPECT_EQ(coarse.remeshing.stallIterations, o.sliding.stallIterations);
  EXPECT_EQ(coarse.stopping.maxIterations, 2 * o.stopping.maxIterations);  // OptimizeSliding::iterationFactor
  EXPECT_EQ(coarse.stopping.windowDecrease, 0);
  EXPECT_EQ(coarse.stopping.distanceWindow, o.sliding.distanceWindow);
  EXPECT_GE(coarse.remeshing.maxRemeshings * coarse.remeshing.every, coarse.stopping.maxIterations);
  EXPECT_EQ(coarse.search.sobolevLength, o.search.sobolevLength);
  EXPECT_EQ(coarse.weights.smooth, o.weights.smooth);
  EXPECT_EQ(coarse.weights.slidingSmooth, o.weights.slidingSmooth);
  EXPECT_EQ(coarse.search.maxMoveEdges, o.search.maxMoveEdges);

  const OptimizeOptions fine = slidingOptions(o, {1, 0}, atReference / 2, D);  // twice as fine
  EXPECT_NEAR(fine.search.sobolevLength, 2 * o.search.sobolevLength, 1e-12);   // the same length in meters
  EXPECT_NEAR(fine.search.maxMoveEdges, 2 * o.search.maxMoveEdges, 1e-12);
  EXPECT_EQ(fine.weights.smooth, o.weights.smooth);  // held seams' outlines as they were
  EXPECT_NEAR(fine.weights.slidingSmooth, 4 * o.weights.slidingSmooth, 1e-12);
  EXPECT_EQ(fine.weights.slidingBelow, o.sliding.seamWeight);
  EXPECT_EQ(fine.weights.target, o.weights.target);
}

// Paper Sec. 6: the sphere's seams were left free to slide. Three gores held on their meridians end near 2 %
// RMS (ThreeGoreSphereGetsMuchCloser); let slide, the panels turn into S-shaped strips and the sphere gets far
// closer, as cut (the final outlines meshed anew), with seams that still sew.
TEST(PatternOptimizer, SlidingSeamsLetTheSphereFitFarBetter) {
  BILLOW_NATIVE_ONLY_LONG_RUN();
  Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 110;
  const OptimizeRun held = optimize(f, o, 110, true);
  std::fill(f.weights.begin(), f.weights.end(), 0.0);
  // Sliding, to its own stop: the distance window (OptimizeSliding::distanceWindow) ends it well before the
  // iteration limit, and not on the first plateau (held-seam figures) but once the seams have slid.
  o.stopping.maxIterations = 300;
  const OptimizeRun sliding = optimize(f, o, std::numeric_limits<int>::max(), true);
  EXPECT_EQ(sliding.state, OptimizeState::Converged) << sliding.message;
  EXPECT_NE(sliding.message.find("distance"), std::string::npos) << sliding.message;
  EXPECT_LT(sliding.iterations, 300);
  ASSERT_TRUE(held.cut.ok) << held.cut.message;
  ASSERT_TRUE(sliding.cut.ok) << sliding.cut.message;
  int remeshings = 0;
  for (const OptimizeRecord& r : sliding.history) remeshings += r.remeshed;
  std::printf(
      "[figures] sphere gores 800: held seams %.3f%% (cut %.3f%%, %d iterations), sliding %.3f%% (cut %.3f%%, %d "
      "iterations, %d remeshings)\n",
      100 * held.history.back().distanceRms, 100 * held.cut.distanceRms, held.iterations,
      100 * sliding.history.back().distanceRms, 100 * sliding.cut.distanceRms, sliding.iterations, remeshings);
  EXPECT_GE(remeshings, 4);
  EXPECT_LT(sliding.cut.distanceRms, 0.6 * held.cut.distanceRms);
  EXPECT_LT(sliding.history.back().seamMismatch, 1e-4);
  EXPECT_NO_THROW(sewPattern(sliding.pattern));
  EXPECT_NE(sliding.state, OptimizeState::Failed) << sliding.message;
}

// The paper's sphere row (three sliding gores at 700 elements, bench/designs): the gores sit on their symmetric
// meridian layout at 2.02 % from the fourth iteration, a minimum of that mesh, and leave it only on a fresh mesh.
// Meshed anew once the objective stalls there (OptimizeSliding::stallIterations), not at the schedule's 20th
// iteration, and with the Gauss-Newton damping carried over to the new mesh, they leave it 8-15 iterations sooner.
TEST(PatternOptimizer, SlidingGoresLeaveTheirFirstPlateauOnAFreshMesh) {
  Fixture f = makeFixture("../../bench/designs/sphere3-sliding.billow.json", 700);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 300;
  const OptimizeRun stall = optimize(f, o, 40);
  o.sliding.stallIterations = 0;
  const OptimizeRun wait = optimize(f, o, 40);
  const auto firstRemeshing = [](const OptimizeRun& r) {
    for (size_t k = 0; k < r.history.size(); ++k)
      if (r.history[k].remeshed) return k;
    return r.history.size();
  };
  const auto offThePlateau = [](const OptimizeRun& r) {  // the first iteration below 1.5 %
    for (const OptimizeRecord& h : r.history)
      if (h.iteration > 4 && h.distanceRms < 0.015) return h.iteration;
    return 1000;
  };
  const size_t k = firstRemeshing(stall), scheduled = firstRemeshing(wait);
  ASSERT_GT(k, 0u);
  ASSERT_LT(k, stall.history.size());
  ASSERT_LT(scheduled, wait.history.size());
  const OptimizeRecord& before = stall.history[k - 1];
  std::printf("[figures] sliding gores 700: remeshed at %d (schedule: %d), below 1.5 %% at iteration %d (%d)\n",
              stall.history[k].iteration, wait.history[scheduled].iteration, offThePlateau(stall), offThePlateau(wait));
  EXPECT_LT(stall.history[k].iteration, o.sliding.remeshEvery);
  EXPECT_EQ(wait.history[scheduled].iteration, o.sliding.remeshEvery);
  // The rule: the last iterations on that mesh lowered the objective by less than a thousandth.
  const int n = OptimizeSliding{}.stallIterations;
  const auto start = std::find_if(stall.history.begin(), stall.history.end(),
                                  [&](const OptimizeRecord& h) { return h.iteration == before.iteration - n; });
  ASSERT_NE(start, stall.history.end());
  EXPECT_LT(start->objective - before.objective, 1e-3 * before.objective);
  EXPECT_LT(before.distanceRms, 0.021);  // on the plateau
  EXPECT_LE(offThePlateau(stall), 35);
  EXPECT_LE(offThePlateau(stall), offThePlateau(wait));
}

TEST(PatternOptimizer, HeavySeamStaysLightSeamSlides) {
  Fixture f = makeFixture("sphere-gores.billow.json", 400);
  OptimizeOptions o;
  o.stopping.maxIterations = 25;
  std::fill(f.weights.begin(), f.weights.end(), 100.0);
  const OptimizeRun heavy = optimize(f, o, 25);
  std::fill(f.weights.begin(), f.weights.end(), 0.01);
  const OptimizeRun light = optimize(f, o, 25);
  const double D = (f.scene->target.V.colwise().maxCoeff() - f.scene->target.V.colwise().minCoeff()).norm();
  std::printf("[figures] seam shift: weight 100 -> %.3f %% of the diagonal, weight 0.01 -> %.3f %%\n",
              100 * heavy.seamShift / D, 100 * light.seamShift / D);
  EXPECT_LT(heavy.seamShift, 0.02 * D);
  EXPECT_GT(light.seamShift, 2 * heavy.seamShift);
}

// DESIGN.md: "the optimizer must also recover from a poor [flattening]". The koala cut into 18 panels along
// plane sections (bench/designs/teddy.billow.json) has segments far from developable: their flattened seam
// sides differ by up to ~50 %, and projecting them onto equal lengths at once folds panels. The optimizer
// then goes on with the seam-length penalty alone instead of stopping before its first step.
TEST(PatternOptimizer, RecoversFromAPoorFlattening) {
  Fixture f = makeFixture("../../bench/designs/teddy.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  if (f.built.figures.maxSeamLengthMismatch < 0.2) {
    // The flattening got better: make it poor again, every other panel 1.5 times too large (its seam sides
    // then differ from its neighbours' by up to 50 %).
    for (size_t p = 0; p < f.built.pattern.panels.size(); p += 2) {
      PanelVertices& V = f.built.pattern.panels[p].vertices;
      const Eigen::RowVector2d c = V.colwise().mean();
      V = ((V.rowwise() - c) * 1.5).rowwise() + c;
    }
  }
  OptimizeOptions o;
  o.stopping.maxIterations = 6;
  const OptimizeRun r = optimize(f, o, 6);
  std::printf(
      "[figures] koala, 18 panels: %zu records, %s, distance rms %.3f%% -> %.3f%%, seam mismatch %.2f -> %.2f\n",
      r.history.size(), toString(r.state), 100 * r.history.front().distanceRms, 100 * r.history.back().distanceRms,
      r.history.front().seamMismatch, r.history.back().seamMismatch);
  ASSERT_NE(r.state, OptimizeState::Failed);
  ASSERT_GE(r.history.size(), 4u) << "no step was taken";
  EXPECT_LT(r.history.back().objective, 0.9 * r.history.front().objective);
  EXPECT_LT(r.history.back().distanceRms, r.history.front().distanceRms);
}

// A flattened panel with a triangle no simulation can take (two outline points a hair apart, where seams ended a hair
// from each other) is named as such, not as a pattern that does not settle: it cannot even be simulated.
TEST(PatternOptimizer, ASliverInAFlattenedPanelIsNamed) {
  Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  Panel& panel = f.built.pattern.panels[1];
  const int a = panel.triangles(0, 0), b = panel.triangles(0, 1), c = panel.triangles(0, 2);
  const Eigen::RowVector2d mid = 0.5 * (panel.vertices.row(a) + panel.vertices.row(b));
  panel.vertices.row(c) = mid + 1e-8 * (panel.vertices.row(c) - mid);  // counterclockwise still, but a hair high
  OptimizeOptions o;
  o.remeshing.coarseFactor = 1;  // the flattened mesh itself, not a coarse one meshed anew
  const OptimizeRun r = optimize(f, o, 5);
  EXPECT_EQ(r.state, OptimizeState::Failed);
  EXPECT_NE(r.message.find("sliver"), std::string::npos) << r.message;
}

TEST(PatternOptimizer, APanelBoundedByOneLoopStaysSmoothWhereTheLoopStarts) {
  // The two-disc sphere: each panel's outline is one seam loop, whose start is its only corner. The optimized
  // outline turns there about as much as anywhere else (it bent into a 58 degree hook when left free).
  const Fixture f = makeFixture("sphere-equator.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 60;
  o.remeshing.cutPanels = false;  // its corner by the flattened panel's vertex numbers
  const OptimizeRun r = optimize(f, o, 60);
  for (size_t p = 0; p < r.pattern.panels.size(); ++p) {
    ASSERT_EQ(f.built.panels[p].pieces.size(), 1u);
    const int nb = f.built.panels[p].boundaryVertices;
    const PanelVertices& V = r.pattern.panels[p].vertices;
    std::vector<double> turn(nb);
    for (int j = 0; j < nb; ++j) {
      const Eigen::Vector2d u = V.row(j) - V.row((j + nb - 1) % nb), w = V.row((j + 1) % nb) - V.row(j);
      turn[j] = std::abs(std::atan2(u.x() * w.y() - u.y() * w.x(), u.dot(w)));
    }
    const int corner = f.built.panels[p].pieces[0].rows.front();
    std::vector<double> sorted = turn;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[nb / 2];
    std::printf("[figures] one-loop panel %zu: turns %.1f degrees at its corner, median %.1f, largest %.1f\n", p,
                turn[corner] * 180 / M_PI, median * 180 / M_PI, sorted.back() * 180 / M_PI);
    EXPECT_LT(turn[corner], 3 * median + 0.05) << "panel " << p;
  }
}

// A run of no iterations (a suggested layout's first look) measures the flattened panels' settled shape and stops
// there: no gradient (an adjoint solve nothing would use), and projected onto equal seam lengths as it started, no
// second settle as its cut. Its figures are those of a run's first iterate, to the alignment's tolerance.
TEST(PatternOptimizer, AFirstLookOnlyMeasures) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o = appStoppingRule();
  o.stopping.maxIterations = 0, o.remeshing.cutPanels = false;
  PatternOptimizer look(f.scene->target, f.built, f.weights, o);
  while (look.step(5) == OptimizeState::Running) {
  }
  EXPECT_EQ(look.state(), OptimizeState::Stopped) << look.message();
  ASSERT_EQ(look.history().size(), 1u);
  EXPECT_FALSE(look.history()[0].projected);
  EXPECT_EQ(look.timings().adjointMs, 0);
  EXPECT_EQ(look.timings().equilibriumSolves, 1);
  EXPECT_LT(look.history()[0].seamMismatch, 1e-9);
  o.stopping.maxIterations = 1;
  PatternOptimizer run(f.scene->target, f.built, f.weights, o);
  run.step(0);  // the first equilibrium only
  ASSERT_EQ(run.history().size(), 1u);
  EXPECT_GT(run.timings().adjointMs, 0);
  const OptimizeRecord &a = look.history()[0], &b = run.history()[0];
  EXPECT_NEAR(a.distanceRms, b.distanceRms, 1e-3 * b.distanceRms);
  EXPECT_NEAR(a.targetDistanceRms, b.targetDistanceRms, 1e-3 * b.targetDistanceRms);
  EXPECT_NEAR(a.objective, b.objective, 1e-4 * b.objective);
}

// A budget of Newton iterations (a suggested layout's: suggest/seam_layouts.hpp) stops the run between two
// iterations once its solves have spent it, on the same path as the run without one.
TEST(PatternOptimizer, ANewtonBudgetStopsTheRunOnceSpent) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o = appStoppingRule();
  o.remeshing.cutPanels = false;
  const std::unique_ptr<PatternOptimizer> free = optimizedFor(f, 20, o);
  const int spent = free->timings().newtonIterations;
  ASSERT_GT(free->iterations(), 6);

  o.stopping.maxNewtonIterations = spent / 3;
  const std::unique_ptr<PatternOptimizer> held = optimizedFor(f, 20, o);
  EXPECT_EQ(held->state(), OptimizeState::Stopped);
  EXPECT_EQ(held->message(), "the work allowed for it was done");
  EXPECT_GE(held->timings().newtonIterations, spent / 3);
  EXPECT_LT(held->iterations(), free->iterations());
  ASSERT_GE(held->history().size(), 2u);
  // The same path: each iterate as the free run's.
  for (size_t k = 0; k + 1 < held->history().size(); ++k)
    EXPECT_DOUBLE_EQ(held->history()[k].objective, free->history()[k].objective) << "iterate " << k;
}
