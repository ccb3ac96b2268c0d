// Pattern optimization (optimize/pattern_optimizer.hpp): objective gradients and the reduced (adjoint)
// gradient against finite differences; on the three-gore sphere the optimized inflated shape is much closer
// to the target than the flattened one, seam lengths match exactly, and the objective decreases over every
// accepted step; a heavy seam stays where it was drawn while a light one slides further.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "export/polygon.hpp"
#include "io/mesh_file.hpp"
#include "optimize/adjoint.hpp"
#include "optimize/harmonic_interior.hpp"
#include "optimize/optimized_pattern.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "optimize/rest_derivatives.hpp"
#include "optimize/seam_projection.hpp"
#include "optimize/stopping_rule.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/remesh_pattern.hpp"
#include "simulate/initial_shape.hpp"

using namespace billow;

namespace {

std::string dataPath(const std::string& name) { return std::string(BILLOW_TEST_DATA_DIR) + "/" + name; }
std::string examplesDir() { return std::string(BILLOW_TEST_DATA_DIR) + "/../../web/public/examples"; }

struct Fixture {
  std::unique_ptr<DesignScene> scene;
  BuiltPattern built;
  std::vector<double> weights;
};

// As the CLI and the design bench start (pattern/design_scene.hpp): an internal panel for each of the design's
// connections.
Fixture makeFixture(const std::string& name, int triangles) {
  Fixture f;
  f.scene = loadDesignScene(dataPath(name), {examplesDir()});
  f.built = buildDesignPattern(*f.scene, triangles);
  f.weights = designSeamWeights(f.scene->design);
  return f;
}

// Smooth random direction in pattern space (per-panel affine + sine bumps), unit max norm.
Eigen::VectorXd randomDirection(const Eigen::VectorXd& X, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double a = u(rng), b = u(rng), c = u(rng), d = u(rng), k = 20 + 10 * u(rng);
  Eigen::VectorXd v(X.size());
  for (int i = 0; i < X.size() / 2; ++i) {
    const double x = X[2 * i], y = X[2 * i + 1];
    v[2 * i] = a * x + c * std::sin(k * y), v[2 * i + 1] = b * y + d * std::cos(k * x);
  }
  return v / v.lpNorm<Eigen::Infinity>();
}

// The largest absolute length difference of two stitched edges [m].
double largestLengthDifference(const std::vector<PatternObjective::EdgePair>& pairs, const Eigen::VectorXd& Y) {
  double m = 0;
  for (const auto& e : pairs)
    m = std::max(m, std::abs((Y.segment<2>(2 * e.a1) - Y.segment<2>(2 * e.a0)).norm() -
                             (Y.segment<2>(2 * e.b1) - Y.segment<2>(2 * e.b0)).norm()));
  return m;
}

}  // namespace

TEST(Optimize, PatternObjectiveGradientMatchesFiniteDifferences) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 400);
  ASSERT_TRUE(f.built.ok());
  const ImlsDistance imls(f.scene->target);
  const SewnMesh mesh = sewPattern(f.built.pattern);
  OptimizeWeights w;
  w.smooth = 1, w.laplace = 1, w.length = 1, w.quality = 1;  // every term visible
  const PatternObjective obj(imls, f.built, mesh, f.weights, w);
  ASSERT_FALSE(obj.edgePairs().empty());
  Eigen::VectorXd X = packPattern(f.built.pattern), g;
  X += 1e-3 * randomDirection(X, 3);  // unequal lengths, so E_length is not at its minimum
  ObjectiveTerms t;
  obj.patternEnergy(X, &g, &t);
  EXPECT_GT(t.length, 0);
  EXPECT_GT(t.smooth, 0);
  EXPECT_GT(t.laplace, 0);
  EXPECT_GT(t.quality, 0);
  for (unsigned s = 1; s <= 3; ++s) {
    const Eigen::VectorXd v = randomDirection(X, 10 + s);
    const double eps = 1e-6;
    const double fd = (obj.patternEnergy(X + eps * v, nullptr) - obj.patternEnergy(X - eps * v, nullptr)) / (2 * eps);
    EXPECT_NEAR(fd, g.dot(v), 1e-5 * std::abs(g.dot(v)) + 1e-14) << "direction " << s;
  }
  // E_smooth weighs a sliding seam's outline slidingSmooth times as much, and only that seam's: with the first
  // of the three seams sliding, E_smooth lies strictly between the held and the all-sliding values; its gradient
  // still matches.
  OptimizeWeights sliding = w;
  sliding.slidingSmooth = 5, sliding.slidingBelow = 0.1;
  ObjectiveTerms held, one, all;
  PatternObjective(imls, f.built, mesh, {1, 1, 1}, sliding).patternEnergy(X, nullptr, &held);
  const PatternObjective oneSliding(imls, f.built, mesh, {0, 1, 1}, sliding);
  oneSliding.patternEnergy(X, &g, &one);
  PatternObjective(imls, f.built, mesh, {0, 0, 0}, sliding).patternEnergy(X, nullptr, &all);
  EXPECT_NEAR(held.smooth, t.smooth, 1e-12 * t.smooth);
  EXPECT_NEAR(all.smooth, 5 * held.smooth, 1e-9 * all.smooth);
  EXPECT_GT(one.smooth, 1.2 * held.smooth);
  EXPECT_LT(one.smooth, 0.8 * all.smooth);
  const Eigen::VectorXd v = randomDirection(X, 21);
  const double eps = 1e-6;
  const double fd =
      (oneSliding.patternEnergy(X + eps * v, nullptr) - oneSliding.patternEnergy(X - eps * v, nullptr)) / (2 * eps);
  EXPECT_NEAR(fd, g.dot(v), 1e-5 * std::abs(g.dot(v)) + 1e-14);
}

// E_gap: a gore squeezed across its width brings its two sides within an edge length of each other (no triangle
// folds); the barrier is zero on the flattened gores, grows as the sides close in, and its gradient matches finite
// differences.
TEST(Optimize, OutlineGapBarrierGrowsAsAnOutlineClosesOnItself) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 400);
  const ImlsDistance imls(f.scene->target);
  const SewnMesh mesh = sewPattern(f.built.pattern);
  OptimizeWeights w;
  w.length = w.smooth = w.laplace = w.quality = 0;  // E_gap alone
  const PatternObjective obj(imls, f.built, mesh, f.weights, w);
  const Eigen::VectorXd X0 = packPattern(f.built.pattern);
  ObjectiveTerms t0;
  EXPECT_EQ(obj.patternEnergy(X0, nullptr, &t0), 0) << "the flattened gores keep apart";
  // Squeeze panel 0 across its width (about its centroid, along the axis its outline is narrowest on).
  const int first = mesh.panelVertexStart[0], count = mesh.panelVertexStart[1] - first;
  const auto squeeze = [&](double factor) {
    Eigen::VectorXd X = X0;
    Eigen::Matrix<double, Eigen::Dynamic, 2> P(count, 2);
    for (int v = 0; v < count; ++v) P.row(v) = X0.segment<2>(2 * (first + v)).transpose();
    const Eigen::RowVector2d c = P.colwise().mean();
    const Eigen::Matrix2d C = (P.rowwise() - c).transpose() * (P.rowwise() - c);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(C);
    const Eigen::Vector2d narrow = es.eigenvectors().col(0);  // the smaller eigenvalue's axis
    for (int v = 0; v < count; ++v) {
      const Eigen::Vector2d q = P.row(v).transpose() - c.transpose();
      X.segment<2>(2 * (first + v)) = c.transpose() + q - (1 - factor) * q.dot(narrow) * narrow;
    }
    return X;
  };
  // The barrier rises without bound as the sides close in (logarithmically, as IPC's).
  double previous = 0, atTenth = 0;
  for (double factor : {0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.001}) {
    ObjectiveTerms t;
    obj.patternEnergy(squeeze(factor), nullptr, &t);
    EXPECT_GT(t.gap, previous) << "squeezed to " << factor;
    previous = t.gap;
    if (factor == 0.1) atTenth = t.gap;
  }
  EXPECT_GT(previous, 5 * atTenth);
  Eigen::VectorXd g;
  const Eigen::VectorXd X = squeeze(0.02);
  obj.patternEnergy(X, &g);
  for (unsigned s = 1; s <= 3; ++s) {
    const Eigen::VectorXd v = randomDirection(X, 30 + s);
    const double eps = 1e-8;
    const double fd = (obj.patternEnergy(X + eps * v, nullptr) - obj.patternEnergy(X - eps * v, nullptr)) / (2 * eps);
    EXPECT_NEAR(fd, g.dot(v), 1e-5 * std::abs(g.dot(v)) + 1e-14) << "direction " << s;
  }
}

TEST(Optimize, ShapeObjectiveGradientMatchesFiniteDifferences) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 400);
  const ImlsDistance imls(f.scene->target);
  const SewnMesh mesh = sewPattern(f.built.pattern);
  const PatternObjective obj(imls, f.built, mesh, f.weights, {});
  ASSERT_FALSE(obj.seamVertices().empty());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  Vertices x(mesh.numVertices, 3);
  const double h = imls.supportRadius();
  for (size_t p = 0; p < f.built.panels.size(); ++p)
    for (int v = 0; v < f.built.panels[p].targetPosition.rows(); ++v)
      x.row(mesh.simVertex(int(p), v)) = f.built.panels[p].targetPosition.row(v);
  for (int v = 0; v < x.rows(); ++v) x.row(v) += 0.2 * h * Eigen::RowVector3d(u(rng), u(rng), u(rng));
  Eigen::VectorXd X = packPattern(f.built.pattern);
  X += 0.1 * obj.meanEdgeLength() * randomDirection(X, 4);  // uneven rest areas
  Eigen::VectorXd g, gX;
  ObjectiveTerms t;
  obj.shapeEnergy(x, X, &g, &gX, &t);
  EXPECT_GT(t.target, 0);
  EXPECT_GT(t.cover, 0);
  EXPECT_GT(t.seam, 0);
  // E_cover alone (the target's points to their closest points on the shape), by finite differences too: with
  // the default kernel (its scale far above these distances: nearly d^2) and a kernel scale among the distances
  // (most points on the kernel's bend or beyond it).
  for (const double reach : {OptimizeWeights{}.coverReach, 0.003}) {
    OptimizeWeights coverOnly;
    coverOnly.target = 0, coverOnly.seam = 0, coverOnly.coverReach = reach;
    const PatternObjective cover(imls, f.built, mesh, f.weights, coverOnly);
    Eigen::VectorXd gc;
    ObjectiveTerms tc;
    cover.shapeEnergy(x, X, &gc, nullptr, &tc);
    EXPECT_EQ(tc.target, 0);
    if (reach == OptimizeWeights{}.coverReach)
      EXPECT_NEAR(tc.cover, t.cover, 1e-12 * t.cover);
    else
      EXPECT_LT(tc.cover, 0.7 * t.cover) << "the kernel's bend is not exercised";
    for (int s = 0; s < 3; ++s) {
      Vertices dx(x.rows(), 3);
      for (int v = 0; v < x.rows(); ++v) dx.row(v) = Eigen::RowVector3d(u(rng), u(rng), u(rng));
      const double eps = 1e-7 * h;
      const double fd =
          (cover.shapeEnergy(x + eps * dx, X, nullptr) - cover.shapeEnergy(x - eps * dx, X, nullptr)) / (2 * eps);
      const double an = gc.dot(Eigen::Map<const Eigen::VectorXd>(dx.data(), dx.size()));
      EXPECT_NEAR(fd, an, 1e-5 * std::abs(an)) << "E_cover, reach " << reach << ", direction " << s;
    }
  }
  for (int s = 0; s < 3; ++s) {
    Vertices dx(x.rows(), 3);
    for (int v = 0; v < x.rows(); ++v) dx.row(v) = Eigen::RowVector3d(u(rng), u(rng), u(rng));
    const double eps = 1e-7 * h;
    Vertices xp = x + eps * dx, xm = x - eps * dx;
    const double fd = (obj.shapeEnergy(xp, X, nullptr) - obj.shapeEnergy(xm, X, nullptr)) / (2 * eps);
    const double an = g.dot(Eigen::Map<const Eigen::VectorXd>(dx.data(), dx.size()));
    EXPECT_NEAR(fd, an, 1e-5 * std::abs(an)) << "direction " << s;
  }
  // E_target weighs by the current rest areas: its derivative in X at fixed x.
  ASSERT_GT(gX.norm(), 0);
  for (unsigned s = 1; s <= 3; ++s) {
    const Eigen::VectorXd v = randomDirection(X, 20 + s);
    const double eps = 1e-6 * obj.meanEdgeLength();
    const double fd = (obj.shapeEnergy(x, X + eps * v, nullptr) - obj.shapeEnergy(x, X - eps * v, nullptr)) / (2 * eps);
    EXPECT_NEAR(fd, gX.dot(v), 1e-5 * std::abs(gX.dot(v)) + 1e-14) << "direction " << s;
  }
}

// Sliding pattern vertices within a panel (with their inflated positions) re-samples the surface but does not
// change it: E_target, a quadrature of the surface integral of d^2, must hardly change. With weights fixed at
// the flattened pattern it did (the optimizer collapsed rest triangles to crowd vertices where d is small).
TEST(Optimize, TargetDistanceDoesNotRewardSlidingVertices) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 1000);
  const ImlsDistance imls(f.scene->target);
  const SewnMesh mesh = sewPattern(f.built.pattern);
  const PatternObjective obj(imls, f.built, mesh, f.weights, {});
  // The surface: each panel laid flat through the target's centre, x = phi(X), so sliding X within the panel
  // moves x within the same plane (the same surface, resampled); d varies smoothly over it.
  const Eigen::RowVector3d centre = f.scene->target.V.colwise().mean();
  const Eigen::VectorXd X0 = packPattern(f.built.pattern);
  std::vector<Eigen::Vector2d> panelCentre;
  for (const Panel& panel : f.built.pattern.panels) panelCentre.push_back(panel.vertices.colwise().mean().transpose());
  const auto place = [&](const Eigen::VectorXd& X) {
    Vertices x = Vertices::Zero(mesh.numVertices, 3);
    for (size_t p = 0; p < f.built.pattern.panels.size(); ++p)
      for (int v = 0; v < f.built.pattern.panels[p].vertices.rows(); ++v) {
        const Eigen::Vector2d q = X.segment<2>(2 * (mesh.panelVertexStart[p] + v)) - panelCentre[p];
        x.row(mesh.simVertex(int(p), v)) = centre + Eigen::RowVector3d(q.x(), q.y(), 0);
      }
    return x;
  };
  const Vertices x = place(X0);
  // Slide every third interior vertex a third of the way toward its neighbour closest to the target.
  Eigen::VectorXd X = X0;
  for (size_t p = 0; p < f.built.panels.size(); ++p) {
    const Panel& panel = f.built.pattern.panels[p];
    const auto dist = [&](int k) { return std::abs(imls.distance(x.row(mesh.simVertex(int(p), k)).transpose())); };
    std::vector<int> best(panel.vertices.rows(), -1);
    for (int t = 0; t < panel.triangles.rows(); ++t)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          const int i = panel.triangles(t, a), j = panel.triangles(t, b);
          if (i != j && (best[i] < 0 || dist(j) < dist(best[i]))) best[i] = j;
        }
    for (int v = f.built.panels[p].boundaryVertices; v < panel.vertices.rows(); v += 3) {
      const int g = mesh.panelVertexStart[p] + v, b = mesh.panelVertexStart[p] + best[v];
      X.segment<2>(2 * g) += (X0.segment<2>(2 * b) - X0.segment<2>(2 * g)) / 3;
    }
  }
  ObjectiveTerms before, after, fixedWeights;
  obj.shapeEnergy(x, X0, nullptr, nullptr, &before);
  obj.shapeEnergy(place(X), X, nullptr, nullptr, &after);
  obj.shapeEnergy(place(X), X0, nullptr, nullptr, &fixedWeights);  // the weights of the unslid pattern
  std::printf(
      "[figures] sliding vertices toward the target: E_target %.4e -> %.4e (%.2f %%), with fixed weights %.4e "
      "(%.2f %%)\n",
      before.target, after.target, 100 * (after.target / before.target - 1), fixedWeights.target,
      100 * (fixedWeights.target / before.target - 1));
  EXPECT_LT(std::abs(after.target / before.target - 1), 0.2 * std::abs(fixedWeights.target / before.target - 1));
}

// dE/dX by the adjoint against central differences of E(x(X), X), x re-solved (and re-aligned).
TEST(Optimize, ReducedGradientMatchesFiniteDifferences) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 300);
  OptimizeOptions o;
  o.inflate.tolerance = 1e-11;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  const Eigen::VectorXd X = packPattern(f.built.pattern);
  double E = 0;
  Eigen::VectorXd g;
  ASSERT_TRUE(opt.evaluate(X, &E, &g));
  for (unsigned s = 1; s <= 3; ++s) {
    const Eigen::VectorXd v = randomDirection(X, s);
    const double eps = 1e-6 * opt.objective().meanEdgeLength();
    double Ep = 0, Em = 0;
    ASSERT_TRUE(opt.evaluate(X + eps * v, &Ep, nullptr));
    ASSERT_TRUE(opt.evaluate(X - eps * v, &Em, nullptr));
    const double fd = (Ep - Em) / (2 * eps), an = g.dot(v);
    std::printf("[figures] reduced gradient direction %u: adjoint %.9e, finite differences %.9e\n", s, an, fd);
    // To 1e-6: the seam rods' coefficient follows the panels, and without its derivative (addRodGradientProduct)
    // the two differ by about 1e-5.
    EXPECT_NEAR(fd, an, 1e-6 * std::abs(an)) << "direction " << s;
  }
}

// A vertex with no stiffness at all (inside a slack internal panel: no pressure there and every triangle
// slack) is a zero row of K. The adjoint treats it as free (lambda = 0 there) and solves the rest exactly;
// before, no factorization succeeded and the reduced gradient lost its equilibrium part.
TEST(Optimize, AdjointSolvesAroundAVertexWithoutStiffness) {
  const int n = 12;  // four "vertices"; DOFs 6..8 have no stiffness
  std::vector<Eigen::Triplet<double>> trip;
  for (int i = 0; i < n; ++i) {
    if (i >= 6 && i < 9) continue;
    trip.emplace_back(i, i, 4.0 + i);
    if (i + 1 < n && !(i + 1 >= 6 && i + 1 < 9)) trip.emplace_back(i, i + 1, -1.0), trip.emplace_back(i + 1, i, -1.0);
  }
  trip.emplace_back(2, 10, -0.5), trip.emplace_back(10, 2, -0.5);
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  b.segment<3>(6).setZero();
  Eigen::VectorXd lambda;
  const double residual = solveAdjoint(K, b, {0}, lambda);
  EXPECT_LT(residual, 1e-10);
  ASSERT_EQ(lambda.size(), n);
  EXPECT_EQ(lambda[0], 0);
  EXPECT_EQ(lambda.segment<3>(6).norm(), 0);
  Eigen::VectorXd r = K * lambda - b;
  r[0] = 0;  // the pin's reaction
  EXPECT_LT(r.norm(), 1e-10 * b.norm());
}

// PinnedStiffness keeps solveAdjoint's factorization: another right-hand side solves with the same K (the
// optimizer's prediction of the next equilibrium), held at the pins and the DOFs without stiffness.
TEST(Optimize, PinnedStiffnessSolvesAgainWithTheSameFactorization) {
  const int n = 12;
  std::vector<Eigen::Triplet<double>> trip;
  for (int i = 0; i < n; ++i) {
    if (i >= 6 && i < 9) continue;
    trip.emplace_back(i, i, 4.0 + i);
    if (i + 1 < n && !(i + 1 >= 6 && i + 1 < 9)) trip.emplace_back(i, i + 1, -1.0), trip.emplace_back(i + 1, i, -1.0);
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
  PinnedStiffness s;
  Eigen::VectorXd y;
  EXPECT_FALSE(s.solveAgain(Eigen::VectorXd::Ones(n), y));  // nothing factorized yet
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0), lambda;
  EXPECT_LT(s.solve(K, b, {0}, lambda), 1e-10);
  const Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(n, -3.0, 5.0);
  ASSERT_TRUE(s.solveAgain(c, y));
  EXPECT_EQ(y[0], 0);
  EXPECT_EQ(y.segment<3>(6).norm(), 0);
  Eigen::VectorXd r = K * y - c;
  r[0] = 0, r.segment<3>(6).setZero();  // the pin's reaction; the free DOFs
  EXPECT_LT(r.norm(), 1e-10 * c.norm());
  Eigen::VectorXd direct;
  solveAdjoint(K, c, {0}, direct);
  EXPECT_LT((direct - y).norm(), 1e-12 * y.norm());
}

// The same at an iterate of the gallery's three-gore sphere at 3k elements, where the optimizer used to stop
// (bench/README.md), along the steepest-descent direction it would search. The rigid alignment must be
// converged for this: with 30 Gauss-Newton steps (the old limit) the nearly rotation-invariant sphere left
// it off by 1-2 %.
TEST(Optimize, ReducedGradientMatchesFiniteDifferencesAt3k) {
  const Fixture f = makeFixture("../../web/public/gallery/sphere3.billow.json", 3000);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.inflate.tolerance = 1e-10;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  opt.step(4);
  ASSERT_EQ(opt.state(), OptimizeState::Running);
  const Eigen::VectorXd X = packPattern(opt.pattern());
  double E = 0;
  Eigen::VectorXd g;
  ASSERT_TRUE(opt.evaluate(X, &E, &g));
  Eigen::VectorXd v = -g;
  double longest = 0;
  for (int k = 0; k < v.size() / 2; ++k) longest = std::max(longest, v.segment<2>(2 * k).norm());
  v /= longest;  // the largest vertex move is 1
  const double eps = 1e-5 * opt.objective().meanEdgeLength();
  double Ep = 0, Em = 0;
  ASSERT_TRUE(opt.evaluate(X + eps * v, &Ep, nullptr));
  ASSERT_TRUE(opt.evaluate(X - eps * v, &Em, nullptr));
  const double fd = (Ep - Em) / (2 * eps), an = g.dot(v);
  std::printf("[figures] sphere3 at %d elements, iteration %d: adjoint %.9e, finite differences %.9e\n",
              f.built.figures.triangles, opt.iterations(), an, fd);
  EXPECT_NEAR(fd, an, 1e-3 * std::abs(an));
}

// harmonic_interior.hpp: an affine motion of a panel's boundary moves its interior by the same affine map
// (cotangent weights are exact for linear functions), and the reduced gradient is the chain rule.
TEST(Optimize, HarmonicInteriorFollowsAffineMotionsAndChainsGradients) {
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
    if (interior.interior(r)) EXPECT_EQ(g.segment<2>(2 * r).norm(), 0);
  Eigen::VectorXd Xp = X0 + 1e-3 * v, Xm = X0 - 1e-3 * v;
  interior.extend(Xp), interior.extend(Xm);
  const double fd = (c.dot(Xp) - c.dot(Xm)) / 2e-3;
  EXPECT_NEAR(fd, g.dot(v), 1e-9 * std::abs(fd) + 1e-12);
}

namespace {

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
OptimizeRun optimize(const Fixture& f, const OptimizeOptions& o, int maxIterations = std::numeric_limits<int>::max(),
                     bool checkCut = false) {
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
void expectObjectiveNeverRises(const std::vector<OptimizeRecord>& h, double relative = 0) {
  for (size_t k = 1; k < h.size(); ++k)
    if (!h[k].projected && !h[k].remeshed && !h[k].resettled)
      EXPECT_LE(h[k].objective, h[k - 1].objective * (1 + relative)) << "iteration " << k;
}

// Nothing the optimizer found is lost: a resettling may leave it at a worse equilibrium, and then it goes back to
// its best iterate (of the last mesh) before the final seam-length projection.
void expectEndsAtItsBest(const std::vector<OptimizeRecord>& h) {
  double best = INFINITY;
  const OptimizeRecord* last = nullptr;
  for (const OptimizeRecord& r : h) {
    if (r.remeshed) best = INFINITY;
    if (!r.projected) best = std::min(best, r.objective), last = &r;
  }
  ASSERT_NE(last, nullptr);
  EXPECT_LE(last->objective, best * (1 + 1e-12));
}

}  // namespace

// The optimizer's variables are the panels' outlines and the interior follows them, so what the optimizer shows
// is what the cut panels give: their outlines meshed anew and inflated land within a few percent of the
// optimizer's own figure.
TEST(Optimize, ThreeGoreSphereGetsMuchCloser) {
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

TEST(Optimize, TangentToSeamLengthsIsAProjectionThatKeepsLengthsToFirstOrder) {
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

TEST(Optimize, ProjectedTrialsEndWhereTheTangentialGradientIsSmall) {
  // With every trial projected onto equal seam lengths, the part of a step across that set is undone by the
  // projection. The line search measures its slope along the projected path (g T d), so both the default
  // steps and L-BFGS on the tangential part (OptimizeSearch::tangentSteps) end at a stationary point of the
  // constrained problem, where the recorded (tangential) gradient is small. With the slope g d the default
  // stopped at 5.0e-3, searching down to steps of 1e-4 along directions that were no descent once projected.
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  double rms[2] = {0, 0}, gradient[2] = {0, 0};
  for (const bool tangent : {false, true}) {
    OptimizeOptions o;
    o.search.tangentSteps = tangent;
    const OptimizeRun r = optimize(f, o, 80);
    ASSERT_GE(r.history.size(), 3u);
    EXPECT_LT(r.history.back().seamMismatch, 1e-4);
    expectObjectiveNeverRises(r.history);
    rms[tangent] = r.history.back().distanceRms;
    gradient[tangent] = r.history.back().gradient;
    std::printf("[figures] sphere gores 800, tangent steps %d: %d iterations, rms %.3f%%, gradient %.2e, %s\n",
                int(tangent), r.iterations, 100 * rms[tangent], gradient[tangent], r.message.c_str());
  }
  EXPECT_LT(gradient[0], 1e-3);  // the Lagrangian's gradient (measured 1.2e-4; tangent steps 2.3e-4)
  EXPECT_LT(gradient[1], 1e-3);
  EXPECT_LT(rms[1], 1.01 * rms[0]);
  EXPECT_LT(rms[0], 1.01 * rms[1]);
}

TEST(Optimize, GaussSeidelBeforeEachSolveSavesNewtonIterations) {
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

TEST(Optimize, PredictedStartSavesNewtonIterations) {
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
TEST(Optimize, SlackInternalPanelDoesNotStopTheOptimizer) {
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
TEST(Optimize, UnstableEquilibriumIsResettledNotTheEnd) {
  const Fixture f = makeFixture("fish-four-panels.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions oo;
  oo.stopping.maxIterations = 25;
  oo.inflate.seamStiffness = 0;
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

// Issue 24: a foil-balloon penguin (front and back panels, seen from the front) creeps towards the end of its
// equilibrium: L-BFGS steps snap the balloon into another equilibrium, whose solve took 25-110 Newton iterations
// before the line search refused it. A trial that leaves its predicted shape by far is now abandoned as it goes
// (two such snaps in a row take the shape it snaps into, a resettling). And no step makes a panel's outline
// cross itself: such a panel overlaps itself and cannot be cut, although none of its triangles folds (the
// optimizer's cow and penguin did).
namespace {

// The optimizer after `iterations` iterations (or where it stopped), stepped as the app's worker steps it.
std::unique_ptr<PatternOptimizer> optimizedFor(const Fixture& f, int iterations) {
  OptimizeOptions oo;
  oo.stopping.maxIterations = iterations;
  auto opt = std::make_unique<PatternOptimizer>(f.scene->target, f.built, f.weights, oo);
  while (opt->step(5) == OptimizeState::Running) {
  }
  return opt;
}

// No panel's outline crosses itself: a maker can cut every panel (the optimizer lists each outline first, in order).
void expectCuttableOutlines(const Pattern& pattern) {
  for (const Panel& panel : pattern.panels) {
    Polygon2 polygon;
    for (int v : outlineVertices(panel)) polygon.push_back(panel.vertices.row(v).transpose());
    EXPECT_FALSE(selfIntersects(polygon)) << panel.name;
  }
}

}  // namespace

TEST(Optimize, FrontBackPenguinAbandonsTrialsThatSnapAndKeepsItsOutlines) {
  const Fixture f = makeFixture("../../bench/designs/penguin-front-back.billow.json", 3000);
  ASSERT_TRUE(f.built.ok());
  const std::unique_ptr<PatternOptimizer> optimized = optimizedFor(f, 20);
  const PatternOptimizer& opt = *optimized;
  const OptimizeTimings& t = opt.timings();
  const auto& h = opt.history();
  int newton = 0;
  for (const auto& r : h) newton += r.equilibriumIterations;
  std::printf(
      "[figures] fb-penguin 3k: %d iterations, %d solves (%d trials refused, %d snapped), %d resettled, Newton %d "
      "accepted, rms %.3f %% -> %.3f %%, %.1f s\n",
      opt.iterations(), t.equilibriumSolves, t.rejectedTrials, t.snappedTrials, t.resettlings, newton,
      100 * h.front().distanceRms, 100 * h.back().distanceRms, t.totalMs / 1000);
  EXPECT_EQ(opt.iterations(), 20) << opt.message();
  EXPECT_GE(t.snappedTrials, 1);
  EXPECT_LT(h.back().distanceRms, 0.5 * h.front().distanceRms);
  expectObjectiveNeverRises(h, 1e-12);
  expectEndsAtItsBest(h);
  expectCuttableOutlines(opt.pattern());
}

// The stuffed toy's outline from the front (the Outline tool's seam, tests/data) runs into thin notches (around the
// thin disc ears): the flattened panels have slits, and steps that made their sides cross were refused until the
// optimizer stopped (after 9 iterations at 2.9 % here). E_gap holds the sides apart, so the steps go along them.
TEST(Optimize, FrontBackStuffedToyGoesOnAlongItsOutlinesThinNotches) {
  const Fixture f = makeFixture("stuffedtoy-front-back.billow.json", 1500);
  ASSERT_TRUE(f.built.ok());
  const std::unique_ptr<PatternOptimizer> optimized = optimizedFor(f, 20);
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
}

// Sec. 5.3: the panels meshed again from their outlines (every 4 iterations here) and the optimization goes
// on from there: no panel is lost, seams keep matching, the shape barely moves across the remesh and keeps
// getting closer to the target afterwards.
TEST(Optimize, RemeshingKeepsPanelsAndSeamsAndGoesOn) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.remeshing.every = 4;
  o.stopping.maxIterations = 30;
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
      "remeshings (%.0f ms)\n",
      after.iteration, 100 * before.distanceRms, 100 * after.distanceRms, 100 * last.distanceRms, last.iteration,
      opt.timings().remeshings, opt.timings().remeshMs);
  EXPECT_EQ(opt.pattern().panels.size(), f.built.pattern.panels.size());
  EXPECT_NEAR(after.distanceRms, before.distanceRms, 0.2 * before.distanceRms);
  EXPECT_LT(last.distanceRms, after.distanceRms);
  EXPECT_LT(last.seamMismatch, 1e-4);
  EXPECT_NO_THROW(sewPattern(opt.pattern()));
  EXPECT_NE(opt.state(), OptimizeState::Failed) << opt.message();
}

// OptimizeRemeshing::every remeshes on a schedule, at most once per iteration and none after the last one.
TEST(Optimize, RemeshingOnItsSchedule) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 6, o.remeshing.maxRemeshings = 100, o.remeshing.every = 3;
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

// The optimizer's state as a pattern (optimize/optimized_pattern.hpp), what the app shows and the CLI inflates
// last: its current panels and stitches, and as "inflated" its shape, so an inflation from it starts exactly where
// the optimizer stands; also after the panels were meshed anew (other vertices than the flattened pattern's).
TEST(Optimize, OptimizedPatternStartsWhereTheOptimizerStands) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 4, o.remeshing.every = 3;
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
  }
  ASSERT_NE(opt.state(), OptimizeState::Failed) << opt.message();
  ASSERT_EQ(opt.timings().remeshings, 1);
  const Pattern p = optimizedPattern(opt);
  ASSERT_EQ(p.panels.size(), f.built.pattern.panels.size());
  ASSERT_EQ(p.inflated.size(), p.panels.size());
  EXPECT_EQ(p.stitches.size(), opt.pattern().stitches.size());
  EXPECT_NE(p.panels[0].vertices.rows(), f.built.pattern.panels[0].vertices.rows()) << "the panels were meshed anew";
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

// The app's stopping rule (optimize/stopping_rule.hpp) sets when to stop and nothing else.
TEST(Optimize, AppStoppingRuleSetsOnlyWhenToStop) {
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

// Outlines that zig-zag below the edge length (free seams, tangent steps, a weak E_smooth) resample into chords
// that differ across a seam. Such a remeshing is refused and the old mesh kept, so every iterate still sews
// (one used to go on with stitched edges 1.5 times apart).
TEST(Optimize, RemeshingThatWouldNotSewKeepsTheOldMesh) {
  const Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.search.tangentSteps = true, o.weights.seam = 0, o.weights.smooth = 0.05;
  o.remeshing.every = 5, o.remeshing.maxRemeshings = 100, o.stopping.maxIterations = 60;
  o.sliding.seamWeight = 0;  // these settings as they are, not those of sliding seams (slidingOptions)
  PatternOptimizer opt(f.scene->target, f.built, f.weights, o);
  while (opt.step(1) == OptimizeState::Running) {
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
TEST(Optimize, StopsWhenTheObjectiveNoLongerDecreasesNoticeably) {
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
    if (!r.projected) E[r.iteration] = r.objective;  // not the final seam-length projection
  const int n = opt.iterations();
  ASSERT_GE(n, 5);
  EXPECT_LT(E[n - 5] - E[n], 0.05 * E[n]);
  for (int k = 5; k < n; ++k) EXPECT_GE(E[k - 5] - E[k], 0.05 * E[k]) << "iteration " << k;
  std::printf("[figures] sphere gores 800: stopped at iteration %d, objective %.4e (5 before: %.4e)\n", n, E[n],
              E[n - 5]);
}

// A window with a remeshing in it is no stall either: the objective there is that of another mesh. With the
// panels meshed anew every 4 iterations every 5-iteration window holds one, and the rule never ends the run
// (without that, this run stopped at iteration 9). Every 5 iterations, a window may start on a fresh mesh and
// is judged as any other.
TEST(Optimize, ObjectiveWindowDoesNotSpanARemeshing) {
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
TEST(Optimize, SlidingSeamsChangeHowTheOptimizerWorks) {
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
  EXPECT_FALSE(held.search.tangentSteps);
  EXPECT_EQ(held.stopping.maxIterations, o.stopping.maxIterations);
  EXPECT_EQ(held.stopping.windowDecrease, o.stopping.windowDecrease);
  EXPECT_EQ(held.remeshing.every, o.remeshing.every);
  EXPECT_EQ(held.search.sobolevLength, o.search.sobolevLength);
  EXPECT_EQ(held.weights.smooth, o.weights.smooth);
  EXPECT_EQ(held.weights.slidingBelow, o.weights.slidingBelow);

  const OptimizeOptions coarse = slidingOptions(o, {1, 0}, 2 * atReference, D);  // coarser than the reference
  EXPECT_TRUE(coarse.search.tangentSteps);
  EXPECT_EQ(coarse.remeshing.every, o.sliding.remeshEvery);
  EXPECT_EQ(coarse.stopping.maxIterations, 2 * o.stopping.maxIterations);  // OptimizeSliding::iterationFactor
  EXPECT_EQ(coarse.stopping.windowDecrease, 0);
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
TEST(Optimize, SlidingSeamsLetTheSphereFitFarBetter) {
  Fixture f = makeFixture("sphere-gores.billow.json", 800);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 110;
  const OptimizeRun held = optimize(f, o, 110, true);
  std::fill(f.weights.begin(), f.weights.end(), 0.0);
  const OptimizeRun sliding = optimize(f, o, 110, true);
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

TEST(Optimize, HeavySeamStaysLightSeamSlides) {
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
TEST(Optimize, RecoversFromAPoorFlattening) {
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

TEST(Optimize, APanelBoundedByOneLoopStaysSmoothWhereTheLoopStarts) {
  // The two-disc sphere: each panel's outline is one seam loop, whose start is its only corner. The optimized
  // outline turns there about as much as anywhere else (it bent into a 58 degree hook when left free).
  const Fixture f = makeFixture("sphere-equator.billow.json", 600);
  ASSERT_TRUE(f.built.ok());
  OptimizeOptions o;
  o.stopping.maxIterations = 60;
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

TEST(Optimize, CoverKeepsTheTargetsSideInView) {
  // Two discs for a sphere, 3k elements: with E_target alone the first rigid alignment already slid the lens
  // towards the sphere's bottom (the inflated shape's points near the target, its top left out: 18.6 % the
  // other way) and the optimizer went on from there; E_cover brings the target's side back. On plain d^2 the
  // first alignment alone did much of that (10.1 %); its robust kernel lets the far top pull little, so the
  // first alignment moves the lens only a little (17.9 %) and the optimizer does the rest.
  const Fixture f = makeFixture("sphere-equator.billow.json", 3000);
  ASSERT_TRUE(f.built.ok());
  double first[2] = {0, 0}, last[2] = {0, 0};
  for (int cover = 0; cover < 2; ++cover) {
    OptimizeOptions o;
    o.stopping.maxIterations = 10;
    o.weights.cover = cover;
    const OptimizeRun r = optimize(f, o, 10);
    first[cover] = r.history.front().targetDistanceRms, last[cover] = r.history.back().targetDistanceRms;
    std::printf(
        "[figures] two-disc sphere, 3k, E_cover weight %d: target to inflated %.2f %% -> %.2f %% (%d iterations)\n",
        cover, 100 * first[cover], 100 * last[cover], r.iterations);
  }
  EXPECT_LT(first[1], first[0]);      // 17.9 % against 18.6 % (plain d^2: 10.1 %)
  EXPECT_LT(last[1], 0.4 * last[0]);  // and then 6.4 % against 19.7 % (plain d^2: 5.2 %)
}

TEST(Optimize, CoverDoesNotPullASmallLoopsLensInward) {
  // One small triangular seam loop on the sphere (what the drawing tests draw): a lens that cannot cover the
  // sphere. With E_cover on plain d^2 the far side of the sphere pulled the lens towards the sphere's middle
  // (after 20 iterations inflated -> target 3.0 % -> 13.7 %) and every iteration took 12x as long (E_target's
  // far fallback for every vertex). The kernel saturates at 6 % of the diagonal: the far target weighs nothing.
  const Fixture f = makeFixture("sphere-lens.billow.json", 1000);
  ASSERT_TRUE(f.built.ok());
  double rms[2] = {0, 0}, msPerIteration[2] = {0, 0};
  for (int cover = 0; cover < 2; ++cover) {
    OptimizeOptions o;
    o.weights.cover = cover;
    const OptimizeRun r = optimize(f, o, 20);
    rms[cover] = r.history.back().distanceRms, msPerIteration[cover] = r.ms / std::max(r.iterations, 1);
    std::printf(
        "[figures] lens on a sphere, 1k, E_cover weight %d: inflated to target %.2f %% -> %.2f %%, target to "
        "inflated %.2f %% -> %.2f %%, %d iterations, %.0f ms each\n",
        cover, 100 * r.history.front().distanceRms, 100 * rms[cover], 100 * r.history.front().targetDistanceRms,
        100 * r.history.back().targetDistanceRms, r.iterations, msPerIteration[cover]);
  }
  EXPECT_LT(rms[1], 1.5 * rms[0] + 0.003);              // plain d^2: 13.7 %
  EXPECT_LT(msPerIteration[1], 4 * msPerIteration[0]);  // plain d^2: 12x
}
