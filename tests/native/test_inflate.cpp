// Pressure term and equilibrium solver: volume derivatives by finite differences, and the Mylar balloon
// (Paulsen 1994) as the validation a designer can trust (DESIGN.md).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "simulate/block_cholesky.hpp"
#include "simulate/enclosed_volume.hpp"
#include "simulate/example_patterns.hpp"
#include "simulate/inflate.hpp"
#include "simulate/initial_shape.hpp"
#include "util/error.hpp"

using namespace billow;

TEST(EnclosedVolume, FiniteDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 5; ++trial) {
    Vector9d x;
    for (int i = 0; i < 9; ++i) x[i] = u(rng);
    auto volume = [](const Vector9d& y) { return triangleVolume(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6)); };
    Vector9d g, gFd;
    Matrix9d H, hFd;
    triangleVolumeDerivatives(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), &g, &H);
    const double h = 1e-6;
    for (int i = 0; i < 9; ++i) {
      Vector9d xp = x, xm = x;
      xp[i] += h;
      xm[i] -= h;
      gFd[i] = (volume(xp) - volume(xm)) / (2 * h);
      Vector9d gp, gm;
      triangleVolumeDerivatives(xp.segment<3>(0), xp.segment<3>(3), xp.segment<3>(6), &gp, nullptr);
      triangleVolumeDerivatives(xm.segment<3>(0), xm.segment<3>(3), xm.segment<3>(6), &gm, nullptr);
      hFd.col(i) = (gp - gm) / (2 * h);
    }
    EXPECT_LT((g - gFd).norm(), 1e-8 * (1 + g.norm()));
    EXPECT_LT((H - hFd).norm(), 1e-7 * (1 + H.norm()));
    EXPECT_LT((H - H.transpose()).norm(), 1e-15);
  }
}

TEST(EnclosedVolume, ClosedSurfaceVolumeDoesNotDependOnTheOrigin) {
  // A unit cube as 12 outward triangles: V = 1 wherever it sits.
  const double p[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  for (const Eigen::Vector3d& shift : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(5, -3, 2)}) {
    double v = 0;
    for (const auto& t : f)
      v += triangleVolume(Eigen::Vector3d(p[t[0]][0], p[t[0]][1], p[t[0]][2]) + shift,
                          Eigen::Vector3d(p[t[1]][0], p[t[1]][1], p[t[1]][2]) + shift,
                          Eigen::Vector3d(p[t[2]][0], p[t[2]][1], p[t[2]][2]) + shift);
    EXPECT_NEAR(v, 1.0, 1e-12);
  }
}

namespace {

// The Mylar balloon at a resolution that runs in well under a second natively (about 770 triangles).
// A stiffer sheet than foil (E x 10) isolates the discretization error from the stretch of the sheet:
// Paulsen's numbers are for an inextensible sheet, and at foil stiffness the sheet's stretch alone moves
// the thickness by about 1 % (measured: 1.1999 at E vs 1.1903 at 100 E on 770 triangles, 1.2128 at E on 3k).
struct MylarRun {
  Pattern pattern;
  SewnMesh mesh;
  std::unique_ptr<InflationSolver> solver;
};

MylarRun runMylar(int triangles, double stiffening) {
  ExampleOptions eo;
  eo.triangles = triangles;
  eo.material.youngsModulus *= stiffening;
  MylarRun run;
  run.pattern = examplePattern("mylar", eo);
  run.mesh = sewPattern(run.pattern);
  run.solver = std::make_unique<InflationSolver>(run.mesh, run.pattern.material, run.pattern.pressure);
  while (run.solver->step(10) == InflateState::Running) {
  }
  return run;
}

}  // namespace

TEST(Inflate, MylarBalloonMatchesPaulsen) {
  const MylarRun run = runMylar(700, 10);
  const InflationSolver& s = *run.solver;
  ASSERT_EQ(s.state(), InflateState::Converged) << s.message();
  EXPECT_LT(s.residual(), 1e-5);
  const MylarShape shape = measureMylar(run.mesh, s.positions());
  const double a = 0.3;
  // At 8 rings per disc the measured errors are +0.12 % (rim) and -0.56 % (thickness); they shrink with
  // refinement (bench). 1 % and 1.5 % leave room for platform round-off, not for a wrong shape: a wrong
  // pressure sign, a missing relaxation (no wrinkling: a fat pillow) or a mis-sewn rim miss by > 5 %.
  EXPECT_NEAR(shape.rimRadius / a, kMylarRimOverDisc, 0.01 * kMylarRimOverDisc);
  EXPECT_NEAR(shape.thickness / shape.rimRadius, kMylarThicknessOverRim, 0.015 * kMylarThicknessOverRim);
}

TEST(Inflate, NewtonStepsNeverIncreaseTheEnergyAndTheResultIsSound) {
  const MylarRun run = runMylar(400, 1);
  const InflationSolver& s = *run.solver;
  ASSERT_EQ(s.state(), InflateState::Converged) << s.message();
  const auto& h = s.energyHistory();
  ASSERT_GE(h.size(), 4u);
  for (size_t i = 0; i + 1 < h.size(); i += 2) EXPECT_LE(h[i + 1], h[i] + 1e-12 * std::abs(h[i])) << "step " << i / 2;
  EXPECT_TRUE(s.positions().allFinite());
  EXPECT_GT(s.volume(), 0);
  // Outward orientation: every outer triangle's normal points away from the balloon's centre.
  const Eigen::RowVector3d centre = s.positions().colwise().mean();
  int inward = 0;
  for (int f = 0; f < run.mesh.numTriangles(); ++f) {
    const Eigen::Vector3d a = s.positions().row(run.mesh.triangles(f, 0)),
                          b = s.positions().row(run.mesh.triangles(f, 1)),
                          c = s.positions().row(run.mesh.triangles(f, 2));
    if ((b - a).cross(c - a).dot((a + b + c) / 3 - centre.transpose()) <= 0) ++inward;
  }
  EXPECT_EQ(inward, 0);
  const InflateResult r = s.result();
  EXPECT_TRUE(r.fields.compression.allFinite());
  EXPECT_TRUE(r.fields.stress.allFinite());
  // The rim of a Mylar balloon wrinkles (Paulsen: no hoop stress): some triangles must say so.
  int wrinkled = 0;
  for (int g : r.fields.regime) wrinkled += g == int(Regime::Wrinkled);
  EXPECT_GT(wrinkled, 0);
}

TEST(Inflate, AFailedSolveSaysSoAndKeepsAFiniteState) {
  ExampleOptions eo;
  eo.triangles = 200;
  const Pattern p = examplePattern("pillow", eo);
  InflateOptions o;
  o.maxIterations = 2;  // cannot converge in two steps
  const InflateResult r = inflate(p, o);
  EXPECT_EQ(r.state, InflateState::Failed);
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.message.empty());
  EXPECT_TRUE(r.positions.allFinite());
}

TEST(Inflate, ASolveEndsWhereItsNewtonStepIsTooShortForPiToResolve) {
  // The optimizer's trials restart a solver with new rest shapes from a shape near their equilibrium. Some then
  // reach a shape where the unshifted Newton step is a millionth of a radius yet raises Pi beyond its round-off;
  // they used to halve steps of 1e-9 radii until their Newton budget ran out (InflateOptions::settledStep). Such a
  // solve now ends there: at the shape a solve to the force tolerance reaches, in no more iterations.
  BILLOW_NATIVE_ONLY_LONG_RUN();
  ExampleOptions eo;
  eo.triangles = 1200;
  int settled = 0, newton[2] = {0, 0};
  for (const char* name : {"letter-C", "star"}) {
    const Pattern p = examplePattern(name, eo);
    const InflateResult base = inflate(p);
    ASSERT_TRUE(base.converged) << name << ": " << base.message;
    const SewnMesh mesh = sewPattern(p);
    const double radius = std::cbrt(3 * base.volume / (4 * M_PI));
    std::mt19937 rng(1);
    std::normal_distribution<double> normal(0, 1);
    for (int trial = 0; trial < 6; ++trial) {
      Pattern q = p;
      for (auto& panel : q.panels) {
        panel.vertices.col(0) *= 1 + 0.04 * normal(rng);
        panel.vertices.col(1) *= 1 + 0.04 * normal(rng);
      }
      const SewnMesh changed = sewPattern(q);
      Vertices x[2];
      bool bySettledStep = false;
      for (int rule : {0, 1}) {
        InflateOptions o;
        if (!rule) o.settledStep = 0;
        InflationSolver s(mesh, p.material, p.pressure, o, base.positions);
        s.restartWithRest(changed.rest, base.positions);
        while (s.step(50) == InflateState::Running) {
        }
        ASSERT_EQ(s.state(), InflateState::Converged) << name << " " << trial << ": " << s.message();
        x[rule] = s.positions();
        newton[rule] += s.iterations();
        if (rule) bySettledStep = s.residual() >= o.tolerance;  // converged, yet above the force tolerance
      }
      settled += bySettledStep;
      EXPECT_LT((x[1] - x[0]).rowwise().norm().maxCoeff(), 1e-5 * radius) << name << " " << trial;
    }
  }
  std::printf("[figures] letter C and star, 1.2k, 12 restarts: %d ended by the short step, Newton %d -> %d\n", settled,
              newton[0], newton[1]);
  EXPECT_GE(settled, 1);
  EXPECT_LE(newton[1], newton[0]);
}

TEST(Inflate, StartsFromACallerShapeAndReusesTheFactorizationOnRestart) {
  ExampleOptions eo;
  eo.triangles = 300;
  const Pattern p = examplePattern("sphere3", eo);
  InflateResult first = inflate(p);
  ASSERT_TRUE(first.converged) << first.message;
  // A converged shape handed back as the start converges at once.
  SewnMesh mesh = sewPattern(p);
  InflationSolver s(mesh, p.material, p.pressure, {}, first.positions);
  EXPECT_EQ(s.step(5), InflateState::Converged);
  EXPECT_LE(s.iterations(), 1);
  // The three-gore sphere is close to round: volume near that of a sphere of the gores' length / pi.
  const double R = 0.3, sphere = 4.0 / 3.0 * M_PI * R * R * R;
  EXPECT_NEAR(first.volume / sphere, 0.9, 0.1);
  s.restart(first.positions, 2 * p.pressure);  // a different pressure: runs again from there
  while (s.step(10) == InflateState::Running) {
  }
  EXPECT_EQ(s.state(), InflateState::Converged);
  EXPECT_GT(s.volume(), first.volume);
}

TEST(Inflate, RestartWithNewRestShapesMatchesAFreshSolver) {
  // The pattern optimizer keeps one solver per mesh and hands it new rest shapes: the equilibrium must be
  // the one a new solver finds for those panels.
  ExampleOptions eo;
  eo.triangles = 600;
  const Pattern p = examplePattern("sphere3", eo);
  const SewnMesh mesh = sewPattern(p);
  InflationSolver kept(mesh, p.material, p.pressure);
  while (kept.step(50) == InflateState::Running) {
  }
  ASSERT_EQ(kept.state(), InflateState::Converged);
  const double volumeBefore = kept.volume();
  // The panels 2 % larger across the gores (x), the same along them.
  SewnMesh wider = mesh;
  Pattern q = p;
  for (auto& panel : q.panels) panel.vertices.col(0) *= 1.02;
  const SewnMesh widerMesh = sewPattern(q);
  wider.rest = widerMesh.rest;
  kept.restartWithRest(wider.rest, kept.positions());
  while (kept.step(50) == InflateState::Running) {
  }
  ASSERT_EQ(kept.state(), InflateState::Converged) << kept.message();
  InflationSolver fresh(wider, p.material, p.pressure, {}, kept.positions());
  while (fresh.step(50) == InflateState::Running) {
  }
  ASSERT_EQ(fresh.state(), InflateState::Converged);
  EXPECT_LE(fresh.iterations(), 1);  // already at its equilibrium
  EXPECT_NEAR(kept.volume(), fresh.volume(), 1e-9 * fresh.volume());
  EXPECT_GT(kept.volume(), 1.02 * volumeBefore);  // wider gores hold more
  EXPECT_THROW(kept.restartWithRest(std::vector<ElementRest>(3), kept.positions()), Error);
}

TEST(Inflate, AnInternalPanelPullsTwoSeamsTogether) {
  ExampleOptions eo;
  eo.triangles = 400;
  const InflateResult plain = inflate(examplePattern("sphere3", eo));
  const Pattern p = examplePattern("sphere3-internal", eo);
  const SewnMesh mesh = sewPattern(p);
  const InflateResult r = inflate(p);
  ASSERT_TRUE(plain.converged) << plain.message;
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_TRUE(r.positions.allFinite());
  // The internal panel carries no pressure but holds the two seams at most its width apart, so the balloon
  // encloses less air than the plain three-gore sphere.
  EXPECT_GT(r.volume, 0);
  EXPECT_LT(r.volume, 0.97 * plain.volume);
  int internalTaut = 0;
  for (int f = 0; f < mesh.numTriangles(); ++f) internalTaut += !mesh.outer[f] && r.fields.regime[f] != 0;
  EXPECT_GT(internalTaut, 0);  // the internal panel is under tension
}

TEST(Inflate, AnInternalPanelWithFloppyFreeTipsSettles) {
  // The internal gore sewn only along its middle 60 %: its tips hang free, with a genuine stiffness far
  // below the pressure stiffness. Newton used to creep there at residual ~3e-5 until the iteration limit
  // (500, 600 and 1000 triangles), moving the tips a thousandth of the way per step.
  for (int triangles : {500, 600, 1000}) {
    ExampleOptions eo;
    eo.triangles = triangles;
    Pattern p = examplePattern("sphere3-internal", eo);
    const int internal = 3;
    const auto& V = p.panels[internal].vertices;
    const double lo = V.col(0).minCoeff(), hi = V.col(0).maxCoeff();
    std::vector<Stitch> kept;
    for (const Stitch& s : p.stitches) {
      const bool tipA = s.panelA == internal && std::abs(V(s.vertexA, 0) - (lo + hi) / 2) > 0.3 * (hi - lo);
      const bool tipB = s.panelB == internal && std::abs(V(s.vertexB, 0) - (lo + hi) / 2) > 0.3 * (hi - lo);
      if (!tipA && !tipB) kept.push_back(s);
    }
    ASSERT_LT(kept.size(), p.stitches.size());
    p.stitches = kept;
    const InflateResult r = inflate(p);
    EXPECT_TRUE(r.converged) << triangles << " triangles: " << r.message << " residual " << r.residual;
    EXPECT_LT(r.iterations, 600) << triangles;
    EXPECT_TRUE(r.positions.allFinite());
  }
}

namespace {

// Lower triangle of a random symmetric matrix with the vertex-block pattern of a sewn mesh, made positive
// definite by a diagonal shift (or indefinite by a negative one).
Eigen::SparseMatrix<double> blockPatternMatrix(const SewnMesh& mesh, double diagonal, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Triplet<double>> trip;
  const int n = 3 * mesh.numVertices;
  for (int f = 0; f < mesh.numTriangles(); ++f)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const int r = 3 * mesh.triangles(f, a) + i, c = 3 * mesh.triangles(f, b) + j;
            if (r > c) trip.emplace_back(r, c, u(rng));
          }
  for (int i = 0; i < n; ++i) trip.emplace_back(i, i, diagonal);
  Eigen::SparseMatrix<double> H(n, n);
  H.setFromTriplets(trip.begin(), trip.end());
  return H;
}

}  // namespace

// FewerFlops takes the cheaper ordering: the coordinate bisection on a round shape, AMD on a flat pillow (the two
// sheets lie on top of each other, and a plane cuts both; at 3k AMD needs about half the work).
TEST(BlockCholesky, FewerFlopsTakesTheCheaperOrdering) {
  for (const char* name : {"sphere3", "pillow"}) {
    ExampleOptions eo;
    eo.triangles = 3000;
    const Pattern pattern = examplePattern(name, eo);
    const SewnMesh mesh = sewPattern(pattern);
    const InflateResult inflated = inflate(pattern);
    ASSERT_TRUE(inflated.converged) << name;
    std::mt19937 rng(7);
    const Eigen::SparseMatrix<double> H = blockPatternMatrix(mesh, 80.0, rng);
    double flops[3];
    int k = 0;
    for (auto ordering : {BlockCholesky::Ordering::NestedDissection, BlockCholesky::Ordering::Amd,
                          BlockCholesky::Ordering::FewerFlops}) {
      BlockCholesky chol;
      chol.analyze(H, inflated.positions, ordering);
      flops[k++] = chol.factorFlops();
    }
    std::printf("[figures] %s at %d triangles: nested dissection %.1f, AMD %.1f, the fewer %.1f Mflop\n", name,
                mesh.numTriangles(), 1e-6 * flops[0], 1e-6 * flops[1], 1e-6 * flops[2]);
    EXPECT_EQ(flops[2], std::min(flops[0], flops[1])) << name;
    if (std::string(name) == "pillow") {
      EXPECT_LT(flops[1], 0.75 * flops[0]);
    }
  }
}

TEST(BlockCholesky, SolvesLikeEigenWithBothOrderings) {
  ExampleOptions eo;
  eo.triangles = 600;
  const SewnMesh mesh = sewPattern(examplePattern("sphere3", eo));
  std::mt19937 rng(7);
  // Diagonally dominant: each row has at most ~ 3 x 7 x 3 off-diagonal entries in [-1, 1].
  const Eigen::SparseMatrix<double> H = blockPatternMatrix(mesh, 80.0, rng);
  const Eigen::MatrixXd points = sphericalStart(mesh);
  Eigen::VectorXd b = Eigen::VectorXd::Random(H.rows());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ref(H);
  const Eigen::VectorXd expected = ref.solve(b);
  for (auto ordering : {BlockCholesky::Ordering::NestedDissection, BlockCholesky::Ordering::Amd}) {
    BlockCholesky chol;
    chol.analyze(H, points, ordering);
    ASSERT_TRUE(chol.factorize(H));
    Eigen::VectorXd x = b;
    chol.solve(x);
    EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
    const Eigen::VectorXd residual = H.selfadjointView<Eigen::Lower>() * x - b;
    EXPECT_LT(residual.norm(), 1e-10 * b.norm());
    EXPECT_GE(chol.factorNonZeros(), double(H.nonZeros()));
    // Refactorizing new values on the same pattern works too; an indefinite matrix is refused.
    Eigen::SparseMatrix<double> H2 = H;
    for (int k = 0; k < H2.nonZeros(); ++k) H2.valuePtr()[k] *= 2;
    ASSERT_TRUE(chol.factorize(H2));
    x = b;
    chol.solve(x);
    EXPECT_LT((x - 0.5 * expected).norm(), 1e-10 * expected.norm());
    Eigen::SparseMatrix<double> bad = H;
    bad.coeffRef(7, 7) = -100;
    EXPECT_FALSE(chol.factorize(bad));
  }
}
