// Derivatives for the adjoint (optimize/rest_derivatives.hpp): the element gradient matches the simulator's,
// its derivative in the rest positions matches finite differences in the taut and wrinkled regimes, and the
// assembled exact stiffness matches finite differences of the assembled gradient.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "optimize/rest_derivatives.hpp"
#include "simulate/example_patterns.hpp"

using namespace billow;

namespace {

struct TriangleSetup {
  Eigen::Vector2d X[3];
  Eigen::Vector3d x[3];
};

// Rest triangle with random shape; deformed by F = Q diag(s1, s2) (stretches s1 >= s2) plus a shift.
TriangleSetup makeSetup(double s1, double s2, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  TriangleSetup s;
  s.X[0] = {0.1 * u(rng), 0.1 * u(rng)}, s.X[1] = {1 + 0.1 * u(rng), 0.2 * u(rng)};
  s.X[2] = {0.3 + 0.2 * u(rng), 0.9 + 0.1 * u(rng)};
  const Eigen::Matrix3d Q =
      Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
  Eigen::Matrix<double, 3, 2> D = Eigen::Matrix<double, 3, 2>::Zero();
  D(0, 0) = s1, D(1, 1) = s2;
  const Eigen::Vector3d shift(u(rng), u(rng), u(rng));
  for (int a = 0; a < 3; ++a) s.x[a] = Q * D * s.X[a] + shift;
  return s;
}

MembraneMaterial material() {
  MembraneMaterial m;
  m.youngsModulus = 1e6, m.thickness = 1e-3;
  return m;
}

void checkElement(double s1, double s2, unsigned seed) {
  const TriangleSetup s = makeSetup(s1, s2, seed);
  const MembraneMaterial mat = material();
  Matrix96d J;
  const Vector9d g = membraneElementRestJacobian(s.X[0], s.X[1], s.X[2], s.x[0], s.x[1], s.x[2], mat, &J);
  Vector9d ref;
  ElementOptions exact;
  exact.projectHessian = false;
  membraneElement(makeElementRest(s.X[0], s.X[1], s.X[2]), s.x[0], s.x[1], s.x[2], mat, exact, &ref, nullptr);
  ASSERT_GT(ref.norm(), 0);
  EXPECT_LT((g - ref).norm(), 1e-10 * ref.norm()) << "gradient differs from the simulator's";
  const double eps = 1e-7;
  for (int k = 0; k < 6; ++k) {
    TriangleSetup p = s, m = s;
    p.X[k / 2][k % 2] += eps, m.X[k / 2][k % 2] -= eps;
    const Vector9d gp = membraneElementRestJacobian(p.X[0], p.X[1], p.X[2], p.x[0], p.x[1], p.x[2], mat, nullptr);
    const Vector9d gm = membraneElementRestJacobian(m.X[0], m.X[1], m.X[2], m.x[0], m.x[1], m.x[2], mat, nullptr);
    const Vector9d fd = (gp - gm) / (2 * eps);
    EXPECT_LT((fd - J.col(k)).norm(), 1e-5 * J.norm()) << "rest coordinate " << k << " stretches " << s1 << ", " << s2;
  }
}

// Two small discs sewn together (mylar, 60 triangles) in a slightly stretched, bulged shape: every element
// taut or wrinkled.
struct BulgedDiscs {
  Pattern pattern;
  SewnMesh mesh;
  Eigen::VectorXd X;
  MembraneMaterial material;
  Vertices x;
};

BulgedDiscs bulgedDiscs() {
  ExampleOptions eo;
  eo.triangles = 60, eo.size = 0.1;
  BulgedDiscs d;
  d.pattern = examplePattern("mylar", eo);
  d.mesh = sewPattern(d.pattern);
  d.X = packPattern(d.pattern);
  d.material.youngsModulus = d.pattern.material.youngsModulus, d.material.thickness = d.pattern.material.thickness;
  d.x.resize(d.mesh.numVertices, 3);
  for (size_t p = 0; p < d.pattern.panels.size(); ++p)
    for (int v = 0; v < d.pattern.panels[p].vertices.rows(); ++v) {
      const Eigen::Vector2d P = d.pattern.panels[p].vertices.row(v);
      const double z = (p == 0 ? 1 : -1) * 0.3 * (0.1 * 0.1 - P.squaredNorm()) / 0.1;
      d.x.row(d.mesh.simVertex(int(p), v)) << 1.002 * P.x(), 1.002 * P.y(), z;
    }
  return d;
}

}  // namespace

TEST(RestDerivative, ElementTautMatchesFiniteDifferences) {
  for (unsigned seed = 1; seed <= 4; ++seed) checkElement(1.05, 1.02, seed);
}

TEST(RestDerivative, ElementWrinkledMatchesFiniteDifferences) {
  for (unsigned seed = 1; seed <= 4; ++seed) checkElement(1.1, 0.8, seed);
}

TEST(RestDerivative, SlackElementHasNoForce) {
  const TriangleSetup s = makeSetup(0.9, 0.8, 3);
  Matrix96d J;
  const Vector9d g = membraneElementRestJacobian(s.X[0], s.X[1], s.X[2], s.x[0], s.x[1], s.x[2], material(), &J);
  EXPECT_EQ(g.norm(), 0);
  EXPECT_EQ(J.norm(), 0);
}

// K = dg/dx on a small sewn pattern (two discs) against central differences of the assembled gradient.
TEST(RestDerivative, StiffnessMatchesFiniteDifferences) {
  const auto [pattern, mesh, X, mat, bulged] = bulgedDiscs();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Vertices x = bulged;
  for (int v = 0; v < x.rows(); ++v) x.row(v) += 1e-4 * Eigen::RowVector3d(u(rng), u(rng), u(rng));
  const Eigen::SparseMatrix<double> K = assembleStiffness(mesh, x, mat, pattern.pressure);
  const Eigen::MatrixXd Kd = K;
  EXPECT_LT((Kd - Kd.transpose()).norm(), 1e-9 * Kd.norm());
  const double eps = 1e-8;
  double worst = 0;
  for (int dof = 0; dof < 3 * mesh.numVertices; dof += 7) {
    Vertices xp = x, xm = x;
    xp(dof / 3, dof % 3) += eps, xm(dof / 3, dof % 3) -= eps;
    const Eigen::VectorXd fd = (equilibriumGradient(mesh, pattern, X, xp, mat, pattern.pressure) -
                                equilibriumGradient(mesh, pattern, X, xm, mat, pattern.pressure)) /
                               (2 * eps);
    worst = std::max(worst, (fd - Kd.col(dof)).norm() / Kd.col(dof).norm());
  }
  EXPECT_LT(worst, 1e-4);
}

// dg/dX dX (the optimizer's prediction of the next equilibrium) against central differences of the assembled
// gradient in X, and consistent with the adjoint's transpose product: lambda . (J dX) = (J^T lambda) . dX.
TEST(RestDerivative, JacobianProductMatchesFiniteDifferencesAndTranspose) {
  const auto [pattern, mesh, X, mat, x] = bulgedDiscs();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd dX(X.size()), lambda(3 * mesh.numVertices);
  for (int i = 0; i < dX.size(); ++i) dX[i] = u(rng);
  for (int i = 0; i < lambda.size(); ++i) lambda[i] = u(rng);
  Eigen::VectorXd product = Eigen::VectorXd::Zero(3 * mesh.numVertices);
  addRestJacobianProduct(mesh, pattern, X, x, dX, mat, product);
  const double eps = 1e-8;
  const Eigen::VectorXd fd = (equilibriumGradient(mesh, pattern, X + eps * dX, x, mat, pattern.pressure) -
                              equilibriumGradient(mesh, pattern, X - eps * dX, x, mat, pattern.pressure)) /
                             (2 * eps);
  ASSERT_GT(product.norm(), 0);
  EXPECT_LT((fd - product).norm(), 1e-5 * product.norm());
  Eigen::VectorXd transposed = Eigen::VectorXd::Zero(X.size());
  addRestGradientProduct(mesh, pattern, X, x, lambda, mat, transposed);
  EXPECT_NEAR(lambda.dot(product), transposed.dot(dX), 1e-10 * std::abs(lambda.dot(product)));
  // The kept element blocks give the same products, to the bit: the Gauss-Newton direction's CG relies on them.
  const RestJacobian kept(mesh, pattern, X, x, mat);
  Eigen::VectorXd keptProduct = Eigen::VectorXd::Zero(product.size()), keptTransposed = Eigen::VectorXd::Zero(X.size());
  kept.addProduct(dX, keptProduct);
  kept.addTransposedProduct(lambda, keptTransposed);
  EXPECT_EQ(keptProduct, product);
  EXPECT_EQ(keptTransposed, transposed);
}

// The pattern optimizer's seam rods follow the panels (seamRodCoefficientAt): their coefficient at X is the one the
// cut panels' own mesh gives, and its derivative, with the rods' parts of dg/dX, matches central differences.
TEST(RestDerivative, SeamRodCoefficientFollowsThePanels) {
  const BulgedDiscs discs = bulgedDiscs();  // named members: a lambda below uses them (no structured bindings)
  const Pattern& pattern = discs.pattern;
  const SewnMesh& mesh = discs.mesh;
  const Vertices& x = discs.x;
  const Eigen::VectorXd& X0 = discs.X;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd X = 1.1 * X0, dX(X.size()), lambda(3 * mesh.numVertices);
  for (int i = 0; i < X.size(); ++i) X[i] += 1e-3 * u(rng), dX[i] = u(rng);
  for (int i = 0; i < lambda.size(); ++i) lambda[i] = u(rng);
  const double beta = 5e-4, p = pattern.pressure;
  Pattern grown = pattern;
  unpackPattern(X, grown);
  const double own = seamRodCoefficient(sewPattern(grown), p, beta);
  Eigen::VectorXd dcdX;
  const double c = seamRodCoefficientAt(mesh, pattern, X, p, beta, &dcdX);
  ASSERT_GT(c, 0);
  EXPECT_NEAR(c, own, 1e-12 * own);
  EXPECT_GT(c, 1.05 * seamRodCoefficient(mesh, p, beta));  // c grows with the panels (R^4 / l^3)
  const double eps = 1e-7;
  const double fd = (seamRodCoefficientAt(mesh, pattern, X + eps * dX, p, beta) -
                     seamRodCoefficientAt(mesh, pattern, X - eps * dX, p, beta)) /
                    (2 * eps);
  EXPECT_NEAR(dcdX.dot(dX), fd, 1e-6 * std::abs(fd));

  SeamRods rods = makeSeamRods(mesh, c);
  ASSERT_FALSE(rods.empty());
  const auto rodForces = [&](const Eigen::VectorXd& at) {
    SeamRods r = rods;
    r.coefficient = seamRodCoefficientAt(mesh, pattern, at, p, beta);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * mesh.numVertices);
    r.addGradient(x, g);
    return g;
  };
  const Eigen::VectorXd fdForces = (rodForces(X + eps * dX) - rodForces(X - eps * dX)) / (2 * eps);
  Eigen::VectorXd product = Eigen::VectorXd::Zero(3 * mesh.numVertices), transposed = Eigen::VectorXd::Zero(X.size());
  addRodJacobianProduct(rods, x, dcdX, dX, product);
  ASSERT_GT(product.norm(), 0);
  EXPECT_LT((fdForces - product).norm(), 1e-6 * product.norm());
  addRodGradientProduct(rods, x, dcdX, lambda, transposed);
  EXPECT_NEAR(lambda.dot(product), transposed.dot(dX), 1e-10 * std::abs(lambda.dot(product)));
}
