// Seam stiffness (simulate/seam_rods.hpp): the rods' energy, gradient and Hessian by finite differences,
// which seam vertices carry a rod, and what they are for: without them the Mylar balloon's rim crimps at the
// scale of the mesh and refinement moves the shape away from Paulsen's; with them it converges.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "simulate/example_patterns.hpp"
#include "simulate/inflate.hpp"
#include "simulate/seam_rods.hpp"

using namespace billow;

namespace {

SewnMesh exampleMesh(const std::string& name, int triangles) {
  ExampleOptions eo;
  eo.triangles = triangles;
  return sewPattern(examplePattern(name, eo));
}

int rimVertices(const SewnMesh& mesh) {
  int n = 0;
  for (int v = 0; v < mesh.numVertices; ++v) n += mesh.stitchedCount[v] >= 2;
  return n;
}

}  // namespace

TEST(SeamRods, EnergyGradientAndHessianAgreeWithFiniteDifferences) {
  const SewnMesh mesh = exampleMesh("sphere3", 300);
  const SeamRods rods = makeSeamRods(mesh, 3.7);
  ASSERT_FALSE(rods.empty());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd x(mesh.numVertices, 3);
  for (int i = 0; i < x.rows(); ++i)
    for (int j = 0; j < 3; ++j) x(i, j) = u(rng);
  const int n = 3 * mesh.numVertices;
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  rods.addGradient(x, g);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  rods.forEachHessianEntry([&](int r, int c, double v) { H(r, c) += v; });
  EXPECT_LT((H - H.transpose()).norm(), 1e-12 * H.norm());
  const double h = 1e-6;
  double worstG = 0, worstH = 0;
  for (int k = 0; k < n; ++k) {
    Eigen::MatrixXd xp = x, xm = x;
    xp(k / 3, k % 3) += h, xm(k / 3, k % 3) -= h;
    worstG = std::max(worstG, std::abs((rods.energy(xp) - rods.energy(xm)) / (2 * h) - g[k]));
    Eigen::VectorXd gp = Eigen::VectorXd::Zero(n), gm = Eigen::VectorXd::Zero(n);
    rods.addGradient(xp, gp), rods.addGradient(xm, gm);
    worstH = std::max(worstH, ((gp - gm) / (2 * h) - H.col(k)).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worstG, 1e-6 * g.cwiseAbs().maxCoeff());
  EXPECT_LT(worstH, 1e-6 * H.cwiseAbs().maxCoeff());
  // A rigid motion costs nothing.
  Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::MatrixXd moved = (x * R.transpose()).rowwise() + Eigen::RowVector3d(0.3, -2, 5);
  EXPECT_NEAR(rods.energy(moved), rods.energy(x), 1e-10 * rods.energy(x));
}

TEST(SeamRods, EverySmoothSeamVertexCarriesOneRodAndCornersNone) {
  // The Mylar balloon's rim is one smooth seam: one rod per rim vertex (not one per panel side).
  const SewnMesh mylar = exampleMesh("mylar", 700);
  EXPECT_EQ(int(makeSeamRods(mylar, 1).triples.size()), rimVertices(mylar));
  // The pillow's seam turns by 90 degrees at the square's four corners: no rod is centred there.
  const SewnMesh pillow = exampleMesh("pillow", 700);
  const SeamRods rods = makeSeamRods(pillow, 1);
  EXPECT_EQ(int(rods.triples.size()), rimVertices(pillow) - 4);
  // The three-gore sphere's poles, where three gore tips meet, carry none either.
  const SewnMesh sphere = exampleMesh("sphere3", 700);
  for (const auto& t : makeSeamRods(sphere, 1).triples) EXPECT_EQ(sphere.stitchedCount[t[1]], 2);
  // A seam shared by three panels (the internal gore sewn into two seams) does, along its length: every
  // vertex where the internal panel is sewn in, except the two ends where its sides turn away.
  const SewnMesh internal = exampleMesh("sphere3-internal", 700);
  int tripleSeam = 0, withRod = 0;
  const SeamRods internalRods = makeSeamRods(internal, 1);
  std::vector<char> centred(internal.numVertices, 0);
  for (const auto& t : internalRods.triples) centred[t[1]] = 1;
  for (int v = 0; v < internal.numVertices; ++v)
    if (internal.stitchedCount[v] == 3) ++tripleSeam, withRod += centred[v];
  EXPECT_GT(tripleSeam, 10);
  EXPECT_GE(withRod, tripleSeam - 4);
  // No stiffness, no rods.
  EXPECT_TRUE(makeSeamRods(mylar, 0).empty());
  EXPECT_EQ(seamRodCoefficient(mylar, 1000, 0), 0);
}

// A pattern may mark its seam corners (the optimizer does, so the cut panels keep the rods it optimized with):
// the marks replace the 45-degree rule, panel by panel; the rule's own marks give the same rods as the rule.
TEST(SeamRods, CornersThePatternMarksReplaceTheTurnRule) {
  ExampleOptions eo;
  eo.triangles = 700;
  Pattern pillow = examplePattern("pillow", eo);
  const int rim = rimVertices(sewPattern(pillow));
  const SewnMesh byTurn = sewPattern(pillow);
  for (size_t p = 0; p < pillow.panels.size(); ++p) {
    pillow.panels[p].seamCorners = seamCorners(byTurn, int(p));
    EXPECT_EQ(pillow.panels[p].seamCorners->size(), 4u) << "the square's corners";
  }
  EXPECT_EQ(int(makeSeamRods(sewPattern(pillow), 1).triples.size()), rim - 4);
  for (Panel& panel : pillow.panels) panel.seamCorners->clear();  // marked: no corner at all
  EXPECT_EQ(int(makeSeamRods(sewPattern(pillow), 1).triples.size()), rim);
  // A corner marked on one side of a smooth seam only: the other side's rod still bends through it.
  Pattern mylar = examplePattern("mylar", eo);
  const SewnMesh unmarked = sewPattern(mylar);
  const int rimVertex = outlineVertices(mylar.panels[0]).front();
  mylar.panels[0].seamCorners = std::vector<int>{rimVertex};
  EXPECT_EQ(makeSeamRods(sewPattern(mylar), 1).triples.size(), makeSeamRods(unmarked, 1).triples.size());
  mylar.panels[1].seamCorners = seamCorners(unmarked, 1);
  ASSERT_TRUE(mylar.panels[1].seamCorners->empty());
  for (const Stitch& s : mylar.stitches)
    if (s.panelA == 0 && s.vertexA == rimVertex)
      mylar.panels[1].seamCorners->push_back(s.vertexB);
    else if (s.panelB == 0 && s.vertexB == rimVertex)
      mylar.panels[1].seamCorners->push_back(s.vertexA);
  ASSERT_EQ(mylar.panels[1].seamCorners->size(), 1u);
  EXPECT_EQ(int(makeSeamRods(sewPattern(mylar), 1).triples.size()), rimVertices(unmarked) - 1);
}

namespace {

struct RimFigures {
  double rim = 0, thickness = 0;  // rim / disc radius, thickness / rim
  double rimSpread = 0;           // standard deviation of the rim vertices' radius, relative to their mean
  int iterations = 0;
};

RimFigures inflateMylar(int triangles, double seamStiffness) {
  ExampleOptions eo;
  eo.triangles = triangles;
  const Pattern p = examplePattern("mylar", eo);
  InflateOptions o;
  o.seamStiffness = seamStiffness;
  InflationSolver s(sewPattern(p), p.material, p.pressure, o);
  while (s.step(50) == InflateState::Running) {
  }
  EXPECT_EQ(s.state(), InflateState::Converged) << s.message();
  const MylarShape shape = measureMylar(s.mesh(), s.positions());
  RimFigures out;
  out.rim = shape.rimRadius / 0.3;
  out.thickness = shape.thickness / shape.rimRadius;
  out.iterations = s.iterations();
  // Rim radius about the rim's centre, in the rim plane (the balloon's axis is z by construction).
  Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
  int n = 0;
  for (int v = 0; v < s.mesh().numVertices; ++v)
    if (s.mesh().stitchedCount[v] >= 2) c += s.positions().row(v), ++n;
  c /= n;
  double sum = 0, sum2 = 0;
  for (int v = 0; v < s.mesh().numVertices; ++v) {
    if (s.mesh().stitchedCount[v] < 2) continue;
    const double r = (s.positions().row(v) - c).head<2>().norm();
    sum += r, sum2 += r * r;
  }
  const double mean = sum / n;
  out.rimSpread = std::sqrt(std::max(0.0, sum2 / n - mean * mean)) / mean;
  return out;
}

}  // namespace

// Issue 3: the Mylar balloon within 0.5 % (rim) and 1 % (thickness) of Paulsen at about 3,000 triangles with
// foil defaults, converging under refinement. Measured: rim +0.41 / +0.34 / +0.30 % and thickness -0.35 /
// +0.01 / +0.02 % at 1.5k / 3k / 6k triangles (+0.26 % and +0.15 % at 15k, bench/README.md).
TEST(SeamRods, TheMylarBalloonConvergesToPaulsenUnderRefinement) {
  double lastRimError = 1;
  for (int triangles : {1500, 3000, 6000}) {
    const RimFigures f = inflateMylar(triangles, InflateOptions{}.seamStiffness);
    const double rimError = f.rim / kMylarRimOverDisc - 1, thicknessError = f.thickness / kMylarThicknessOverRim - 1;
    std::printf(
        "[figures] Mylar %d triangles with seam stiffness: rim %+.3f %%, thickness %+.3f %%, rim spread "
        "%.2f %%, %d iterations\n",
        triangles, 100 * rimError, 100 * thicknessError, 100 * f.rimSpread, f.iterations);
    EXPECT_LT(std::abs(rimError), 0.005) << triangles;
    EXPECT_LT(std::abs(thicknessError), 0.01) << triangles;
    EXPECT_LT(std::abs(rimError), lastRimError + 1e-4) << "refinement moved the rim away from Paulsen's";
    lastRimError = std::abs(rimError);
  }
}

// Without the seams' stiffness the rim crimps (its radius zig-zags from vertex to vertex) and the thickness
// drifts away from Paulsen's as the mesh is refined (measured: +0.15 % at 700 triangles, +1.18 % at 3k).
TEST(SeamRods, WithoutSeamStiffnessTheRimCrimps) {
  const RimFigures without = inflateMylar(3000, 0), with = inflateMylar(3000, InflateOptions{}.seamStiffness);
  std::printf(
      "[figures] Mylar 3k: rim spread %.2f %% without seam stiffness, %.2f %% with; thickness %+.3f %% / "
      "%+.3f %%; %d / %d iterations\n",
      100 * without.rimSpread, 100 * with.rimSpread, 100 * (without.thickness / kMylarThicknessOverRim - 1),
      100 * (with.thickness / kMylarThicknessOverRim - 1), without.iterations, with.iterations);
  EXPECT_GT(without.rimSpread, 2 * with.rimSpread);
  EXPECT_GT(without.thickness / kMylarThicknessOverRim - 1, 0.01);
  EXPECT_LT(with.iterations, without.iterations);
}
