// optimize/harmonic_interior.hpp: the interior follows the outlines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "optimize/harmonic_interior.hpp"
#include "optimize/rest_derivatives.hpp"
#include "optimize_fixture.hpp"

using namespace billow;
using namespace billow::test;

// harmonic_interior.hpp: an affine motion of a panel's boundary moves its interior by the same affine map
// (cotangent weights are exact for linear functions), and the reduced gradient is the chain rule.
TEST(HarmonicInterior, HarmonicInteriorFollowsAffineMotionsAndChainsGradients) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 400);
  const SewnMesh mesh = sewPattern(f.built.pattern);
  std::vector<int> boundary;
  for (const BuiltPanel& bp : f.built.panels) boundary.push_back(bp.boundaryVertices);
  const Eigen::VectorXd X0 = packPattern(f.built.pattern);
  const HarmonicInterior interior(f.built.pattern, mesh.panelVertexStart, boundary, X0);
  ASSERT_TRUE(interior.ok());
  Eigen::Matrix2d A;
  A << 1.03, 0.2, -0.1, 0.95;
  const Eigen::Vector2d t(0.3, -0.1);
  Eigen::VectorXd X = X0;
  int interiorRows = 0;
  for (int r = 0; r < X.size() / 2; ++r) {
    if (interior.interior(r)) {
      X.segment<2>(2 * r) = Eigen::Vector2d(5, 5);  // overwritten by extend
      ++interiorRows;
    } else {
      X.segment<2>(2 * r) = A * X0.segment<2>(2 * r) + t;
    }
  }
  ASSERT_GT(interiorRows, 0);
  interior.extend(X);
  double error = 0;
  for (int r = 0; r < X.size() / 2; ++r)
    error = std::max(error, (X.segment<2>(2 * r) - (A * X0.segment<2>(2 * r) + t)).norm());
  EXPECT_LT(error, 1e-12);
  // F(X) = sum_r c_r . X_r on the extended pattern: its gradient in the boundary rows by reduce() against
  // finite differences along a boundary direction.
  const Eigen::VectorXd c = randomDirection(X0, 7);
  const Eigen::VectorXd v = [&] {
    Eigen::VectorXd w = randomDirection(X0, 8);
    for (int r = 0; r < w.size() / 2; ++r)
      if (interior.interior(r)) w.segment<2>(2 * r).setZero();
    return w;
  }();
  Eigen::VectorXd g = c;
  interior.reduce(g);
  for (int r = 0; r < g.size() / 2; ++r)
    if (interior.interior(r)) {
      EXPECT_EQ(g.segment<2>(2 * r).norm(), 0);
    }
  Eigen::VectorXd Xp = X0 + 1e-3 * v, Xm = X0 - 1e-3 * v;
  interior.extend(Xp), interior.extend(Xm);
  const double fd = (c.dot(Xp) - c.dot(Xm)) / 2e-3;
  EXPECT_NEAR(fd, g.dot(v), 1e-9 * std::abs(fd) + 1e-12);
}
