// Relaxed membrane energy: finite differences in every regime and smoothing band, zero energy at rest and
// in compression, continuity across the band edges, symmetric positive semi-definite projected Hessians.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "simulate/membrane_energy.hpp"

using namespace billow;

namespace {

struct Triangle {
  ElementRest rest;
  Eigen::Vector3d x[3];
};

// A rest triangle deformed by F = Q diag(sqrt(l1), sqrt(l2)) V^T with random rotations Q (3D) and V (2D),
// so that C = F^T F has exactly the eigenvalues l1, l2.
Triangle makeTriangle(double l1, double l2, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::Vector2d X[3] = {
      {0.1 * u(rng), 0.1 * u(rng)}, {1 + 0.1 * u(rng), 0.2 * u(rng)}, {0.3 + 0.2 * u(rng), 0.9 + 0.1 * u(rng)}};
  const double phi = 3 * u(rng);
  Eigen::Matrix2d V;
  V << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  const Eigen::Matrix3d Q =
      Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
  Eigen::Matrix<double, 3, 2> D = Eigen::Matrix<double, 3, 2>::Zero();
  D(0, 0) = std::sqrt(l1);
  D(1, 1) = std::sqrt(l2);
  const Eigen::Matrix<double, 3, 2> F = Q * D * V.transpose();
  Triangle t;
  t.rest = makeElementRest(X[0], X[1], X[2]);
  const Eigen::Vector3d shift(u(rng), u(rng), u(rng));
  for (int a = 0; a < 3; ++a) t.x[a] = F * X[a] + shift;
  return t;
}

MembraneMaterial testMaterial(double band) {
  MembraneMaterial m;
  m.youngsModulus = 6.0;  // kappa = 1: energies of order one, absolute tolerances make sense
  m.thickness = 1.0;
  m.band = band;
  return m;
}

double energyAt(const Triangle& t, const Vector9d& x, const MembraneMaterial& m) {
  return membraneElementEnergy(t.rest, x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), m);
}

Vector9d gradAt(const Triangle& t, const Vector9d& x, const MembraneMaterial& m) {
  Vector9d g;
  ElementOptions o;
  o.wantHessian = false;
  membraneElement(t.rest, x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), m, o, &g, nullptr);
  return g;
}

// tol: relative. In the default narrow band the energy is ~1e-9 of kappa, so round-off limits central
// differences to about 1e-4 relative there (h^2 psi''' ~ eps psi / h at best).
void checkFiniteDifferences(double l1, double l2, double band, const char* what, double tol = 1e-5) {
  const MembraneMaterial m = testMaterial(band);
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Triangle t = makeTriangle(l1, l2, seed);
    Vector9d x;
    for (int a = 0; a < 3; ++a) x.segment<3>(3 * a) = t.x[a];
    Vector9d g;
    Matrix9d H;
    ElementOptions exact;
    exact.projectHessian = false;
    const double e = membraneElement(t.rest, t.x[0], t.x[1], t.x[2], m, exact, &g, &H);
    EXPECT_NEAR(e, energyAt(t, x, m), 1e-14 * (1 + std::abs(e))) << what;
    // Central differences, step well inside the band so the difference never straddles a band edge.
    const double h = std::min(1e-6, band * 1e-3);
    Vector9d gFd;
    Matrix9d hFd;
    for (int i = 0; i < 9; ++i) {
      Vector9d xp = x, xm = x;
      xp[i] += h;
      xm[i] -= h;
      gFd[i] = (energyAt(t, xp, m) - energyAt(t, xm, m)) / (2 * h);
      hFd.col(i) = (gradAt(t, xp, m) - gradAt(t, xm, m)) / (2 * h);
    }
    const double gScale = std::max(g.norm(), 1e-8), hScale = std::max(H.norm(), 1e-6);
    EXPECT_LT((g - gFd).norm(), tol * gScale + 1e-12) << what << " seed " << seed << "\n"
                                                      << g.transpose() << "\n"
                                                      << gFd.transpose();
    EXPECT_LT((H - hFd).norm(), tol * hScale + 1e-9) << what << " seed " << seed;
    EXPECT_LT((H - H.transpose()).norm(), 1e-12 * hScale) << what;
  }
}

}  // namespace

TEST(MembraneEnergy, FiniteDifferencesTaut) { checkFiniteDifferences(1.3, 1.1, 0.02, "taut"); }
TEST(MembraneEnergy, FiniteDifferencesTautIsotropic) { checkFiniteDifferences(1.2, 1.2, 0.02, "isotropic"); }
TEST(MembraneEnergy, FiniteDifferencesWrinkled) { checkFiniteDifferences(1.3, 0.6, 0.02, "wrinkled"); }
TEST(MembraneEnergy, FiniteDifferencesSlackIsZero) { checkFiniteDifferences(0.9, 0.5, 0.02, "slack"); }
TEST(MembraneEnergy, FiniteDifferencesInSlackWrinkledBand) {
  checkFiniteDifferences(1.005, 0.6, 0.02, "lambda1 band, upper half");
  checkFiniteDifferences(0.992, 0.6, 0.02, "lambda1 band, lower half");
}
TEST(MembraneEnergy, FiniteDifferencesInWrinkledTautBand) {
  const double l1 = 1.3, t = 1 / std::sqrt(l1);
  checkFiniteDifferences(l1, t + 0.007, 0.02, "lambda2 band, taut side");
  checkFiniteDifferences(l1, t - 0.011, 0.02, "lambda2 band, wrinkled side");
}
TEST(MembraneEnergy, FiniteDifferencesNearTheCornerOfAllThreeRegimes) {
  checkFiniteDifferences(1.01, 0.985, 0.02, "both bands");
}
TEST(MembraneEnergy, FiniteDifferencesWithTheDefaultNarrowBand) {
  const double band = MembraneMaterial{}.band;
  checkFiniteDifferences(1 + 0.3 * band, 0.9, band, "narrow lambda1 band", 1e-3);
  checkFiniteDifferences(1.004, 1 / std::sqrt(1.004) + 0.4 * band, band, "narrow lambda2 band", 1e-3);
  checkFiniteDifferences(1.004, 1.003, band, "taut at foil strains", 1e-3);
}

TEST(MembraneEnergy, ZeroAtRestAndUnderPureCompression) {
  const MembraneMaterial m = testMaterial(1e-4);
  for (const auto& [l1, l2] : {std::pair{1.0, 1.0}, {0.99, 0.5}, {0.8, 0.8}, {0.9, 0.1}}) {
    const Triangle t = makeTriangle(l1, l2, 7);
    EXPECT_NEAR(membraneElementEnergy(t.rest, t.x[0], t.x[1], t.x[2], m), 0, 1e-15) << l1 << " " << l2;
  }
}

TEST(MembraneEnergy, MatchesEquationFourOutsideTheBands) {
  const MembraneMaterial m = testMaterial(1e-3);
  const double k = m.kappa();
  const Triangle taut = makeTriangle(1.2, 1.1, 3), wrinkled = makeTriangle(1.2, 0.5, 3);
  const double areaTaut = taut.rest.area, areaWr = wrinkled.rest.area;
  EXPECT_NEAR(membraneElementEnergy(taut.rest, taut.x[0], taut.x[1], taut.x[2], m),
              areaTaut * k * (1.2 + 1.1 + 1 / (1.2 * 1.1) - 3), 1e-12);
  EXPECT_NEAR(membraneElementEnergy(wrinkled.rest, wrinkled.x[0], wrinkled.x[1], wrinkled.x[2], m),
              areaWr * k * (1.2 + 2 / std::sqrt(1.2) - 3), 1e-12);
}

TEST(MembraneEnergy, ContinuousAcrossTheBandEdges) {
  // Energy, gradient and (C2 smoothing) Hessian just inside and just outside each band edge agree.
  const double band = 0.02, eps = 1e-9;
  const MembraneMaterial m = testMaterial(band);
  const double l1 = 1.3, t = 1 / std::sqrt(l1);
  const std::pair<double, double> edges[] = {{1 - band, 0.5}, {1 + band, 0.5}, {l1, t - band}, {l1, t + band}};
  for (const auto& [a, b] : edges) {
    for (int dir = 0; dir < 2; ++dir) {
      const double da = dir == 0 ? eps : 0, db = dir == 1 ? eps : 0;
      const Triangle lo = makeTriangle(a - da, b - db, 5), hi = makeTriangle(a + da, b + db, 5);
      Vector9d gLo, gHi;
      Matrix9d hLo, hHi;
      ElementOptions exact;
      exact.projectHessian = false;
      const double eLo = membraneElement(lo.rest, lo.x[0], lo.x[1], lo.x[2], m, exact, &gLo, &hLo);
      const double eHi = membraneElement(hi.rest, hi.x[0], hi.x[1], hi.x[2], m, exact, &gHi, &hHi);
      EXPECT_NEAR(eLo, eHi, 1e-7) << a << " " << b;
      EXPECT_LT((gLo - gHi).norm(), 1e-6 * (1 + gHi.norm())) << a << " " << b;
      EXPECT_LT((hLo - hHi).norm(), 1e-4 * (1 + hHi.norm())) << a << " " << b;
    }
  }
}

TEST(MembraneEnergy, ProjectedHessianIsSymmetricPositiveSemiDefinite) {
  const MembraneMaterial m = testMaterial(0.02);
  const std::pair<double, double> states[] = {{1.3, 1.1}, {1.3, 0.6}, {1.005, 0.6}, {1.3, 0.88}, {1.01, 0.985}};
  for (const auto& [a, b] : states) {
    const Triangle t = makeTriangle(a, b, 11);
    Vector9d g;
    Matrix9d H;
    membraneElement(t.rest, t.x[0], t.x[1], t.x[2], m, ElementOptions{}, &g, &H);
    EXPECT_LT((H - H.transpose()).norm(), 1e-12 * (1 + H.norm()));
    const double minEig = Eigen::SelfAdjointEigenSolver<Matrix9d>(H).eigenvalues().minCoeff();
    EXPECT_GT(minEig, -1e-10 * (1 + H.norm())) << a << " " << b;
  }
}

TEST(MembraneEnergy, CompressionFieldAndStress) {
  const MembraneMaterial m = testMaterial(1e-4);
  const Triangle wr = makeTriangle(1.2, 0.5, 9);
  const ElementState s = membraneElementState(wr.rest, wr.x[0], wr.x[1], wr.x[2], m);
  EXPECT_EQ(s.regime, Regime::Wrinkled);
  EXPECT_NEAR(s.compression, 1 - std::sqrt(0.5 * std::sqrt(1.2)), 1e-12);
  // The compression direction is perpendicular to the taut direction and lies in the triangle's plane.
  const Eigen::Vector3d n = (wr.x[1] - wr.x[0]).cross(wr.x[2] - wr.x[0]).normalized();
  EXPECT_NEAR(s.direction.norm(), 1, 1e-12);
  EXPECT_NEAR(s.direction.dot(n), 0, 1e-12);
  EXPECT_GT(s.stress, 0);
  const Triangle taut = makeTriangle(1.2, 1.2, 9);
  const ElementState st = membraneElementState(taut.rest, taut.x[0], taut.x[1], taut.x[2], m);
  EXPECT_EQ(st.regime, Regime::Taut);
  EXPECT_EQ(st.compression, 0);
  // Isotropic stretch: S = 2 kappa (1 - 1/(l^3)) I... sigma = l S_11 with l = 1.2.
  const double l = 1.2, S = 2 * m.kappa() * (1 - 1 / (l * l * l));
  EXPECT_NEAR(st.stress, S * l, 1e-9);
  EXPECT_NEAR(st.tension, S * l * m.thickness / l, 1e-9);
  const Triangle slack = makeTriangle(0.9, 0.8, 9);
  EXPECT_EQ(membraneElementState(slack.rest, slack.x[0], slack.x[1], slack.x[2], m).regime, Regime::Slack);
}

TEST(MembraneEnergy, CornerPartsEqualTheFullElementsInEveryRegime) {
  // membraneElementCorner (the smoother's) against the corner's rows and diagonal block of membraneElement:
  // taut, wrinkled, slack and inside both bands, projected and exact.
  const double cases[][2] = {{1.3, 1.1}, {1.3, 0.6}, {0.9, 0.5}, {1.01, 0.5}, {1.3, 1 / std::sqrt(1.3) + 0.005}};
  for (const bool project : {true, false}) {
    ElementOptions o;
    o.projectHessian = project;
    for (const auto& c : cases) {
      const MembraneMaterial m = testMaterial(0.02);
      const Triangle t = makeTriangle(c[0], c[1], 7);
      Vector9d g;
      Matrix9d H;
      const double e = membraneElement(t.rest, t.x[0], t.x[1], t.x[2], m, o, &g, &H);
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d gk;
        Eigen::Matrix3d hk;
        const double ek = membraneElementCorner(t.rest, t.x[0], t.x[1], t.x[2], m, k, o, &gk, &hk);
        const double scale = 1e-12 * (1 + H.norm());
        EXPECT_NEAR(ek, e, 1e-14 * (1 + std::abs(e)));
        EXPECT_LT((gk - g.segment<3>(3 * k)).norm(), scale) << c[0] << " " << c[1] << " corner " << k;
        EXPECT_LT((hk - H.block<3, 3>(3 * k, 3 * k)).norm(), scale) << c[0] << " " << c[1] << " corner " << k;
      }
      if (c[0] < 1 - 0.02)
        EXPECT_EQ(e, 0.0);
      else
        EXPECT_GT(g.norm(), 0.0);
    }
  }
}

TEST(MembraneEnergy, EnergyAloneEqualsTheDensityWithDerivativesToTheBit) {
  // The line search's energies (relaxedEnergyDensity) and the Newton step's (relaxedDensity) must agree exactly, or a
  // step that lowers one could raise the other: every regime, both bands, the isotropic fallback, random C.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> l(0.85, 1.35), angle(0, M_PI);
  int regimes[3] = {0, 0, 0};
  for (const double band : {0.02, 1e-3})
    for (int i = 0; i < 4000; ++i) {
      double l1 = l(rng), l2 = l(rng);
      if (i % 500 == 0) l2 = l1;  // isotropic
      if (l1 < l2) std::swap(l1, l2);
      const double phi = angle(rng), cs = std::cos(phi), sn = std::sin(phi);
      const Eigen::Vector3d c(l1 * cs * cs + l2 * sn * sn, l1 * sn * sn + l2 * cs * cs, (l1 - l2) * cs * sn);
      const double kappa = 1.7e6;
      const Density d = relaxedDensity(c, kappa, band);
      ASSERT_EQ(relaxedEnergyDensity(c, kappa, band), d.psi) << c.transpose() << " band " << band;
      ++regimes[l1 <= 1 - band ? 0 : (l1 >= 1 + band && l2 - 1 / std::sqrt(l1) >= band ? 2 : 1)];
    }
  EXPECT_GT(regimes[0], 100);
  EXPECT_GT(regimes[1], 100);
  EXPECT_GT(regimes[2], 100);
}
