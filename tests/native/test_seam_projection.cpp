// optimize/seam_projection.hpp: equal seam lengths, the tangent of that set.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "optimize/rest_derivatives.hpp"
#include "optimize/seam_projection.hpp"
#include "optimize_fixture.hpp"

using namespace billow;
using namespace billow::test;

TEST(SeamProjection, TangentToSeamLengthsIsAProjectionThatKeepsLengthsToFirstOrder) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  PatternOptimizer opt(f.scene->target, f.built, f.weights, {});
  const auto& pairs = opt.objective().edgePairs();
  ASSERT_GT(pairs.size(), 10u);
  Eigen::VectorXd X = packPattern(f.built.pattern);
  projectSeamLengths(pairs, X);
  const Eigen::VectorXd v = randomDirection(X, 3);
  const Eigen::VectorXd t = tangentToSeamLengths(pairs, X, v);
  // Idempotent, and the removed part is normal to the tangent (orthogonal projection).
  EXPECT_LT((tangentToSeamLengths(pairs, X, t) - t).norm(), 1e-9 * v.norm());
  EXPECT_LT(std::abs((v - t).dot(t)), 1e-9 * v.squaredNorm());
  EXPECT_GT(t.norm(), 0.1 * v.norm());
  // A small move along it keeps every pair's lengths equal to second order; along v they part at first order.
  const auto mismatch = [&](const Eigen::VectorXd& Y) { return largestLengthDifference(pairs, Y); };
  const double h = 1e-4 * opt.objective().meanEdgeLength() / v.lpNorm<Eigen::Infinity>();
  const double alongV = mismatch(X + h * v), alongT = mismatch(X + h * (v.norm() / t.norm()) * t);
  EXPECT_GT(alongV, 1e-9 * opt.objective().meanEdgeLength());
  EXPECT_LT(alongT, 1e-3 * alongV) << alongT << " vs " << alongV;
}
