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
