// Gauss-Seidel sweeps before Newton (simulate/gauss_seidel.hpp): nonlinear Gauss-Seidel never raises the energy,
// removes most of the mesh-scale force a prolongated start carries, leaves an equilibrium where it is, and saves Newton
// iterations.
#include <gtest/gtest.h>

#include "simulate/coarse_start.hpp"
#include "simulate/example_patterns.hpp"
#include "simulate/gauss_seidel.hpp"
#include "test_support.hpp"

using namespace billow;
using billow::test::example;

namespace {

// Pi and the largest relative vertex force at x (the solver's own measures).
struct State {
  double energy = 0, residual = 0;
};
State stateAt(const SewnMesh& mesh, const Pattern& p, const Vertices& x, InflateOptions o = {}) {
  o.maxIterations = 0;  // assembles once and stops
  InflationSolver s(mesh, p.material, p.pressure, o, x);
  s.step(1);
  const double scale = p.pressure * mesh.meanEdgeLength * mesh.meanEdgeLength;
  return {s.energy(), s.gradient().lpNorm<Eigen::Infinity>() / scale};
}

int newtonIterations(const Pattern& p, const Vertices& x0) {
  const InflateResult r = billow::test::solve(p, x0);
  EXPECT_TRUE(r.converged);
  return r.iterations;
}

}  // namespace

class GaussSeidelExample : public ::testing::TestWithParam<const char*> {};

TEST_P(GaussSeidelExample, RemovesMostOfTheProlongatedForcesAndSavesNewtonIterations) {
  const Pattern p = example(GetParam(), 8000);
  const SewnMesh mesh = sewPattern(p);
  InflateOptions none;
  none.gaussSeidelSweeps = 0;  // no sweeps: the raw prolongated shape
  StartReport report;
  const Vertices raw = startPositions(p, mesh, none, &report);
  ASSERT_GE(report.levels, 1);
  const State before = stateAt(mesh, p, raw);
  Vertices x = raw;
  const GaussSeidelReport s = gaussSeidelSweeps(mesh, p.material, p.pressure, {}, x, 10);
  EXPECT_EQ(s.sweeps, 10);
  EXPECT_GT(s.moves, mesh.numVertices);
  ASSERT_TRUE(x.allFinite());
  const State after = stateAt(mesh, p, x);
  // The solver's residual leaves out the six pinned coordinates: at most the sweeps'.
  EXPECT_LE(before.residual, s.residualBefore * (1 + 1e-9));
  EXPECT_LE(after.residual, s.residualAfter * (1 + 1e-9));
  EXPECT_GT(before.residual, 0.5 * s.residualBefore);
  EXPECT_LT(after.energy, before.energy);
  EXPECT_LT(s.residualAfter, s.residualBefore / 5) << s.residualBefore << " -> " << s.residualAfter;
  EXPECT_LT(after.residual, before.residual / 5) << before.residual << " -> " << after.residual;
  // Fewer Newton iterations after the sweeps, and the same equilibrium.
  const int fromRaw = newtonIterations(p, raw), fromSmoothed = newtonIterations(p, x);
  EXPECT_LT(fromSmoothed, fromRaw) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Examples, GaussSeidelExample, ::testing::Values("mylar", "sphere3", "pillow"));

TEST(GaussSeidel, EverySweepLowersTheEnergyAndAnEquilibriumStaysPut) {
  const Pattern p = example("sphere3", 3000);
  const SewnMesh mesh = sewPattern(p);
  InflateOptions none;
  none.gaussSeidelSweeps = 0;
  Vertices x = startPositions(p, mesh, none);
  double energy = stateAt(mesh, p, x).energy;
  for (int sweep = 0; sweep < 5; ++sweep) {
    gaussSeidelSweeps(mesh, p.material, p.pressure, {}, x, 1);
    const double e = stateAt(mesh, p, x).energy;
    EXPECT_LE(e, energy) << "sweep " << sweep;
    energy = e;
  }
  // At equilibrium every force is below the threshold: nothing moves.
  InflationSolver solver(mesh, p.material, p.pressure, {}, x);
  while (solver.step(50) == InflateState::Running) {
  }
  ASSERT_EQ(solver.state(), InflateState::Converged);
  Vertices y = solver.positions();
  const GaussSeidelReport r = gaussSeidelSweeps(mesh, p.material, p.pressure, {}, y, 3);
  EXPECT_EQ(r.moves, 0);
  EXPECT_LT(r.residualBefore, 1e-4);
  EXPECT_EQ((y - solver.positions()).norm(), 0.0);
}

TEST(GaussSeidel, StartPositionsReportsTheSweeps) {
  const Pattern p = example("mylar", 6000);
  const SewnMesh mesh = sewPattern(p);
  StartReport report;
  startPositions(p, mesh, {}, &report);
  ASSERT_GE(report.levels, 1);
  EXPECT_GT(report.gaussSeidelMs, 0);
  EXPECT_LT(report.residualAfterGaussSeidel, report.residualProlongated / 5);
  InflateOptions none;
  none.gaussSeidelSweeps = 0;
  startPositions(p, mesh, none, &report);
  EXPECT_EQ(report.residualProlongated, 0);
}
