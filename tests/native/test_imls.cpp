// IMLS distance to the target (optimize/imls_distance.hpp, Eq. 9 as fixed in DESIGN.md): about zero on the
// target, about the offset along the normal near it, the closest-point fallback far away, and a gradient
// that matches finite differences inside the kernels, in the blend and in the fallback.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "optimize/imls_distance.hpp"
#include "test_support.hpp"

using namespace billow;

namespace {

// The example sphere scaled to radius 0.25 m, centred at the origin.
TriMesh sphere() {
  TriMesh m = readMeshBytes(readFileBytes(std::string(BILLOW_TEST_DATA_DIR) + "/../../web/public/examples/sphere.obj"),
                            "sphere.obj");
  const Eigen::RowVector3d c = m.V.colwise().mean();
  m.V.rowwise() -= c;
  m.V *= 0.25 / m.V.rowwise().norm().maxCoeff();
  return m;
}

}  // namespace

TEST(Imls, SignedDistanceNearTheTarget) {
  const TriMesh T = sphere();
  const ImlsDistance imls(T);
  const double h = imls.supportRadius();
  std::mt19937 rng(1);
  std::normal_distribution<double> n(0, 1);
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d dir = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    for (double off : {-0.3 * h, 0.0, 0.2 * h}) {
      const Eigen::Vector3d x = (0.25 + off) * dir;
      Eigen::Vector3d g;
      const double d = imls.distance(x, &g);
      // The polyhedral sphere sits up to ~0.3 % of r inside the round one; IMLS smooths it.
      EXPECT_NEAR(d, off, 0.004 * 0.25) << "offset " << off;
      EXPECT_GT(g.dot(dir), 0.95);
    }
  }
  // Far from every kernel: the fallback, the distance to the closest target point.
  const Eigen::Vector3d far(0.6, 0.1, -0.05);
  double S = 0, dI = 0;
  EXPECT_FALSE(imls.imls(far, &dI, nullptr, &S));
  EXPECT_NEAR(imls.distance(far), far.norm() - 0.25, 0.01);
}

TEST(Imls, GradientMatchesFiniteDifferences) {
  const TriMesh T = sphere();
  ImlsOptions o;
  o.blendThreshold = 0.5;  // a wide blend, so that some samples fall into it
  const ImlsDistance imls(T, o);
  const double h = imls.supportRadius();
  std::mt19937 rng(2);
  std::normal_distribution<double> n(0, 1);
  int blended = 0, inside = 0, outside = 0;
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector3d dir = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    const double off = (k % 3 == 0 ? 1.3 : 0.6) * h * std::uniform_real_distribution<double>(-1, 1)(rng);
    const Eigen::Vector3d x = (0.25 + off) * dir;
    double S = 0, dI = 0;
    if (!imls.imls(x, &dI, nullptr, &S))
      ++outside;
    else
      (S < o.blendThreshold ? blended : inside)++;
    Eigen::Vector3d g;
    imls.distance(x, &g);
    const double eps = 1e-7 * h;
    for (int c = 0; c < 3; ++c) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[c] = eps;
      const double fd = (imls.distance(x + e) - imls.distance(x - e)) / (2 * eps);
      EXPECT_NEAR(fd, g[c], 1e-5 + 1e-5 * std::abs(g[c])) << "sample " << k;
    }
  }
  EXPECT_GT(inside, 20);
  EXPECT_GT(blended, 5);
  EXPECT_GT(outside, 5);
}
