// IMLS distance to the target (optimize/imls_distance.hpp, Eq. 9 as fixed in DESIGN.md): about zero on the
// target, about the offset along the normal near it, the closest-point fallback far away, and a gradient
// that matches finite differences inside the kernels, in the blend and in the fallback.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "optimize/imls_distance.hpp"
#include "seams/surface_point.hpp"
#include "test_support.hpp"

using namespace billow;

namespace {

// The example sphere scaled to radius 0.25 m, centred at the origin.
TriMesh sphere() {
  TriMesh m = readMeshBytes(readFileBytes(test::examplesDir() + "/sphere.obj"), "sphere.obj");
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

namespace {

// Eq. 9 summed over every target vertex, as in the header (no grid): the reference for the grid's search.
struct BruteForceImls {
  const TriMesh& T;
  const Vertices& normals;
  double h;
  std::vector<double> bias;

  BruteForceImls(const TriMesh& target, const ImlsDistance& imls)
      : T(target), normals(imls.vertexNormals()), h(imls.supportRadius()), bias(target.numVertices(), 0.0) {
    std::vector<double> b(T.numVertices(), 0.0);
    for (int v = 0; v < T.numVertices(); ++v) {
      double S = 0;
      Eigen::Vector3d g;
      b[v] = eval(T.V.row(v).transpose(), &S, &g);
    }
    bias = b;
  }
  // d (0 when no kernel reaches x); S = sum phi and grad = dd/dx.
  double eval(const Eigen::Vector3d& x, double* S, Eigen::Vector3d* grad) const {
    double N = 0, D = 0;
    Eigen::Vector3d gN = Eigen::Vector3d::Zero(), gD = Eigen::Vector3d::Zero();
    for (int v = 0; v < T.numVertices(); ++v) {
      const Eigen::Vector3d r = x - T.V.row(v).transpose(), n = normals.row(v).transpose();
      const double s = 1 - r.squaredNorm() / (h * h);
      if (s <= 0) continue;
      const double phi = std::pow(s, 4), nr = n.dot(r) - bias[v];
      const Eigen::Vector3d gphi = -8 * std::pow(s, 3) / (h * h) * r;
      N += nr * phi, D += phi, gN += phi * n + nr * gphi, gD += gphi;
    }
    *S = D;
    if (D <= 0) return 0;
    *grad = (gN - N / D * gD) / D;
    return N / D;
  }
};

// Random points within 1.5 h of the target's vertices, and the vertices themselves.
std::vector<Eigen::Vector3d> samplesNear(const TriMesh& T, double h, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> vertex(0, T.numVertices() - 1);
  std::uniform_real_distribution<double> u(-1.5 * h, 1.5 * h);
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d c = T.V.row(vertex(rng)).transpose();
    out.push_back(k % 10 == 0 ? c : Eigen::Vector3d(c + Eigen::Vector3d(u(rng), u(rng), u(rng))));
  }
  return out;
}

void expectMatchesBruteForce(const TriMesh& T) {
  const ImlsDistance imls(T);
  const BruteForceImls reference(T, imls);
  const double h = imls.supportRadius();
  int reached = 0;
  for (const Eigen::Vector3d& x : samplesNear(T, h, 400, 3)) {
    double S0 = 0, d = 0, S = 0;
    Eigen::Vector3d g0 = Eigen::Vector3d::Zero(), g, gS;
    const double d0 = reference.eval(x, &S0, &g0);
    const bool inside = imls.imls(x, &d, &g, &S, &gS);
    ASSERT_EQ(inside, S0 > 0);
    EXPECT_NEAR(S, S0, 1e-12 * S0);
    if (!inside) continue;
    ++reached;
    // The sums run in another order: round-off only.
    EXPECT_NEAR(d, d0, 1e-12 * h);
    EXPECT_NEAR((g - g0).norm(), 0, 1e-9 * (1 + g0.norm()));
    // Without gradients, the same value to the bit.
    double d1 = 0, S1 = 0;
    EXPECT_TRUE(imls.imls(x, &d1, nullptr, &S1));
    EXPECT_EQ(d1, d);
    EXPECT_EQ(S1, S);
    EXPECT_EQ(imls.distance(x), imls.distance(x, &g));
  }
  // Most samples lie within h of a kernel (the count depends on the standard library's random numbers:
  // about 310 of 400 natively, 275-295 in wasm).
  EXPECT_GT(reached, 200);
}

// A thin tube lying along the diagonal: its bounding box holds far more cells of size h than it has
// vertices, so the grid takes coarser cells.
TriMesh diagonalTube(int segments) {
  const int around = 8;
  const double e = 0.01, radius = around * e / (2 * M_PI);
  const Eigen::Vector3d axis = Eigen::Vector3d::Ones().normalized(),
                        u = axis.cross(Eigen::Vector3d::UnitX()).normalized(), w = axis.cross(u);
  TriMesh m;
  m.V.resize((segments + 1) * around, 3);
  m.F.resize(2 * segments * around, 3);
  for (int s = 0; s <= segments; ++s)
    for (int a = 0; a < around; ++a) {
      const double t = 2 * M_PI * a / around;
      m.V.row(s * around + a) = (s * e * axis + radius * (std::cos(t) * u + std::sin(t) * w)).transpose();
    }
  for (int s = 0; s < segments; ++s)
    for (int a = 0; a < around; ++a) {
      const int p = s * around + a, q = s * around + (a + 1) % around;
      m.F.row(2 * (s * around + a)) << p, q, q + around;
      m.F.row(2 * (s * around + a) + 1) << p, q + around, p + around;
    }
  return m;
}

}  // namespace

TEST(Imls, GridFindsEveryKernel) { expectMatchesBruteForce(sphere()); }

TEST(Imls, GridFindsEveryKernelWithCoarseCells) { expectMatchesBruteForce(diagonalTube(150)); }

TEST(Imls, NoKernelReachesFarOrNonFinitePoints) {
  const ImlsDistance imls(sphere());
  double d = 0, S = 1;
  EXPECT_FALSE(imls.imls(Eigen::Vector3d(1e30, 0, 0), &d, nullptr, &S));
  EXPECT_EQ(S, 0);
  EXPECT_FALSE(imls.imls(Eigen::Vector3d(NAN, 0, 0), &d, nullptr, &S));
  EXPECT_FALSE(imls.imls(Eigen::Vector3d(0, -INFINITY, 0), &d, nullptr, &S));
}

// The closest-face hint (SurfaceProjector::project) only speeds the search up: from any hint, a right or a wrong
// one, the same distance as without.
TEST(Imls, TheClosestFaceHintChangesNoDistance) {
  const TriMesh T = sphere();
  const SurfaceProjector projector(T);
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, 1);
  std::uniform_int_distribution<int> face(0, T.numTriangles() - 1);
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector3d x = (0.25 + 0.2 * std::abs(n(rng))) * Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    double plain = 0;
    const SurfacePoint p = projector.project(x, &plain);
    for (int hint : {-1, face(rng), p.face, T.numTriangles() + 5}) {
      double d = 0;
      const SurfacePoint q = projector.project(x, &d, hint);
      EXPECT_NEAR(d, plain, 1e-15) << "hint " << hint;
      EXPECT_NEAR((position(T, q) - position(T, p)).norm(), 0, 1e-12);
    }
  }
}

// A point that wanders, mostly by less than its cache's reach and now and then farther, gets from its cache the
// distance and gradient a fresh search gives, to the bit, at every step: outside the sphere, and near its centre, where
// every face is nearly as close as the closest and a small move makes another one the closest.
TEST(Imls, TheFallbackCacheChangesNoDistance) {
  const TriMesh T = sphere();
  const ImlsDistance imls(T);
  const double h = imls.supportRadius();
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  ClosestFaceCache cache;
  Eigen::Vector3d x(0.4, 0.05, -0.02);
  int fromCache = 0, renewed = 0;
  for (int k = 0; k < 4000; ++k) {
    const double step = u(rng) < 0.9 ? 0.005 * h : 0.5 * h;
    x += step * Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    if (k == 2000) x.setZero();  // the second half near the centre
    if (k < 2000 && (x.norm() < 0.25 + 2 * h || x.norm() > 0.6)) x = (0.25 + 2 * h + 0.3 * u(rng)) * x.normalized();
    if (k >= 2000 && x.norm() > 0.05) x *= 0.05 / x.norm();
    const bool within = cache.reach >= 0 && (x - cache.center).norm() <= cache.reach;
    Eigen::Vector3d g0, g;
    const double d0 = imls.fallback(x, &g0);
    const double d = imls.fallback(x, &g, &cache);
    EXPECT_EQ(d, d0);  // to the bit: the same face, ties to the lowest index either way
    EXPECT_EQ(g, g0);
    fromCache += within;
    renewed += !within;
  }
  EXPECT_GT(fromCache, 2000);
  EXPECT_GT(renewed, 200);
  EXPECT_LT(cache.faces.size(), size_t(T.numTriangles()) / 2);  // a cache of candidates, not the whole target
  // At the edge of a cache's reach, near the centre: the closest face is among the candidates.
  for (int k = 0; k < 200; ++k) {
    ClosestFaceCache fresh;
    const Eigen::Vector3d c = 0.01 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    imls.fallback(c, nullptr, &fresh);
    ASSERT_GT(fresh.reach, 0);
    const Eigen::Vector3d q = c + 0.999 * fresh.reach * Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    EXPECT_NEAR(imls.fallback(q, nullptr, &fresh), imls.fallback(q, nullptr), 1e-15);
    EXPECT_EQ(fresh.center, c);  // answered from the candidates, not renewed
  }
}

// Beyond a sharp tip every face around it is equally close, and a face of the far side faces away from the point:
// the fallback's sign comes from the tip's angle-weighted normal, so it is right whichever face the search names.
TEST(Imls, TheFallbackSignIsRightAtASharpTipWhicheverFaceIsNamed) {
  TriMesh spike;  // a square pyramid 2 cm wide and 30 cm tall, closed, faces outward
  spike.V.resize(5, 3);
  spike.V << -0.01, -0.01, 0, 0.01, -0.01, 0, 0.01, 0.01, 0, -0.01, 0.01, 0, 0, 0, 0.3;
  spike.F.resize(6, 3);
  spike.F << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4, 0, 2, 1, 0, 3, 2;
  const ImlsDistance imls(spike);
  const Eigen::Vector3d tip = spike.V.row(4).transpose();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> weight(0.05, 1);
  int facingAway = 0;
  for (int k = 0; k < 50; ++k) {
    // A direction in the tip's normal cone: a positive mix of its four faces' normals.
    Eigen::Vector3d dir = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> normals;
    for (int f = 0; f < 4; ++f) {
      const Eigen::Vector3d a = spike.V.row(spike.F(f, 0)), b = spike.V.row(spike.F(f, 1)),
                            c = spike.V.row(spike.F(f, 2));
      normals.push_back((b - a).cross(c - a).normalized());
      dir += weight(rng) * normals.back();
    }
    const Eigen::Vector3d x = tip + 0.05 * dir.normalized();
    for (int f = 0; f < 4; ++f) {
      ClosestFaceCache named;  // the search's candidates: this face alone
      named.center = x, named.reach = 1, named.faces = {f};
      Eigen::Vector3d g;
      const double d = imls.fallback(x, &g, &named);
      EXPECT_NEAR(d, 0.05, 1e-12) << "named face " << f;
      EXPECT_NEAR((g - dir.normalized()).norm(), 0, 1e-9);
      facingAway += normals[size_t(f)].dot(x - tip) < 0;
    }
  }
  EXPECT_GT(facingAway, 20);  // the case the face's own side gets wrong
}
