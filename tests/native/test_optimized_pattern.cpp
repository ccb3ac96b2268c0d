// optimize/optimized_pattern.hpp: the optimizer's state as a pattern with its inflated shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "optimize/optimized_pattern.hpp"
#include "optimize_fixture.hpp"
#include "simulate/initial_shape.hpp"

using namespace billow;
using namespace billow::test;

// The optimizer's state as a pattern (optimize/optimized_pattern.hpp), what the app shows and the CLI inflates
// last: its current panels and stitches, and as "inflated" its shape, so an inflation from it starts exactly where
// the optimizer stands; also after the panels were meshed anew (other vertices than the flattened pattern's).
TEST(OptimizedPattern, OptimizedPatternStartsWhereTheOptimizerStands) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 4, o.remeshing.every = 3;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_NE(opt.state(), OptimizeState::Failed) << opt.message();
  ASSERT_EQ(opt.timings().remeshings, 2);  // on its schedule, and the cut panels at the end
  const Pattern p = optimizedPattern(opt);
  ASSERT_EQ(p.panels.size(), f.built.pattern.panels.size());
  ASSERT_EQ(p.inflated.size(), p.panels.size());
  EXPECT_EQ(p.stitches.size(), opt.pattern().stitches.size());
  const PanelVertices& flat = f.built.pattern.panels[0].vertices;
  EXPECT_TRUE(p.panels[0].vertices.rows() != flat.rows() || !p.panels[0].vertices.isApprox(flat, 1e-3))
      << "the panels were meshed anew";
  for (size_t k = 0; k < p.panels.size(); ++k) {
    EXPECT_EQ(p.panels[k].vertices, opt.pattern().panels[k].vertices);
    EXPECT_EQ(p.inflated[k].rows(), p.panels[k].vertices.rows());
  }
  EXPECT_EQ(p.material.name, f.built.pattern.material.name);
  EXPECT_DOUBLE_EQ(p.pressure, f.built.pattern.pressure);
  const SewnMesh mesh = sewPattern(p);
  const Vertices start = startFromInflated(p, mesh);
  ASSERT_EQ(start.rows(), opt.inflated().rows());
  EXPECT_LT((start - opt.inflated()).cwiseAbs().maxCoeff(), 1e-12);
}
