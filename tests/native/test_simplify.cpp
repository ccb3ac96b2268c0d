// The coarser copy of a target (mesh/simplify.hpp): closed and of the same genus, on the surface it copies, facing
// the same way, without needles; a rim left where it is.
#include <gtest/gtest.h>

#include <cmath>

#include "handle_shapes.hpp"
#include "mesh/simplify.hpp"
#include "seams/surface_point.hpp"
#include "test_support.hpp"

namespace billow {
namespace {

// Each vertex of `from`'s distance to `to`'s surface: the largest and the RMS.
std::pair<double, double> vertexDistances(const TriMesh& from, const TriMesh& to) {
  const SurfaceProjector projector(to);
  double largest = 0, sum2 = 0;
  for (int i = 0; i < from.numVertices(); ++i) {
    double d = 0;
    projector.project(from.V.row(i).transpose(), &d);
    largest = std::max(largest, d), sum2 += d * d;
  }
  return {largest, std::sqrt(sum2 / from.numVertices())};
}

double worstShape(const TriMesh& m) {
  double worst = 1;
  for (int f = 0; f < m.numTriangles(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const double edges2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    worst = std::min(worst, 2 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / edges2);
  }
  return worst;
}

TEST(SimplifiedCopy, ATorusStaysClosedOfItsGenusOnItsSurfaceFacingOut) {
  const double R = 1, r = 0.3;
  const TriMesh ring = test::ringMesh(R, r, 240, 80);  // 38,400 triangles
  const TriMesh copy = simplifiedCopy(ring, 2000);
  EXPECT_GE(copy.numTriangles(), 2000);
  EXPECT_LE(copy.numTriangles(), 2002);
  test::expectClosedSurface(copy, 1);
  // Every vertex on the torus to within 2 % of its tube's radius (0.9 % at most when written), every triangle facing
  // away from the tube's middle, none a needle.
  for (int i = 0; i < copy.numVertices(); ++i) {
    const Eigen::Vector3d p = copy.V.row(i);
    EXPECT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - R, p.z()), r, 0.02 * r) << "vertex " << i;
  }
  for (int f = 0; f < copy.numTriangles(); ++f) {
    const Eigen::Vector3d a = copy.V.row(copy.F(f, 0)), b = copy.V.row(copy.F(f, 1)), c = copy.V.row(copy.F(f, 2));
    const Eigen::Vector3d centroid = (a + b + c) / 3;
    const Eigen::Vector3d radial = Eigen::Vector3d(centroid.x(), centroid.y(), 0).normalized();
    EXPECT_GT((b - a).cross(c - a).dot(centroid - R * radial), 0) << "triangle " << f << " faces in";
  }
  EXPECT_GT(worstShape(copy), 0.1);
}

TEST(SimplifiedCopy, AFineScanIsCopiedCloseToItsSurface) {
  // The cow split twice in four (93,696 triangles, the surface unchanged), copied at 2,000, a third of its own.
  const TriMesh spot = test::loadShared("spot.obj");
  const TriMesh fine = test::splitInFour(test::splitInFour(spot));
  const TriMesh copy = simplifiedCopy(fine, 2000);
  EXPECT_LE(copy.numTriangles(), 2002);
  test::expectClosedSurface(copy, 0);
  const double diagonal = test::boxDiagonal(spot);
  const auto [copyLargest, copyRms] = vertexDistances(copy, fine);
  const auto [fineLargest, fineRms] = vertexDistances(fine, copy);
  // When written: 0.25 / 0.45 % of the diagonal at most, 0.06 % RMS either way.
  EXPECT_LT(copyLargest, 5e-3 * diagonal);
  EXPECT_LT(fineLargest, 1e-2 * diagonal);
  EXPECT_LT(copyRms, 1e-3 * diagonal);
  EXPECT_LT(fineRms, 1e-3 * diagonal);
  EXPECT_GT(worstShape(copy), 0.1);
}

TEST(SimplifiedCopy, ARimStaysWhereItIs) {
  // A square sheet of 60 x 60 quads, gently domed: its 240 rim vertices are in the copy as they were.
  const int n = 60;
  TriMesh sheet;
  sheet.V.resize((n + 1) * (n + 1), 3), sheet.F.resize(2 * n * n, 3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = double(i) / n - 0.5, y = double(j) / n - 0.5;
      sheet.V.row(i * (n + 1) + j) = Eigen::Vector3d(x, y, 0.3 * std::cos(test::kPi * x) * std::cos(test::kPi * y));
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j, b = a + n + 1;
      sheet.F.row(2 * (i * n + j)) = Eigen::Vector3i(a, b, b + 1);
      sheet.F.row(2 * (i * n + j) + 1) = Eigen::Vector3i(a, b + 1, a + 1);
    }
  const TriMesh copy = simplifiedCopy(sheet, 1000);
  EXPECT_LE(copy.numTriangles(), 1002);
  int rim = 0;
  for (int i = 0; i < copy.numVertices(); ++i) {
    const Eigen::Vector3d p = copy.V.row(i);
    if (std::abs(std::abs(p.x()) - 0.5) < 1e-12 || std::abs(std::abs(p.y()) - 0.5) < 1e-12) ++rim;
  }
  EXPECT_EQ(rim, 4 * n);
  EXPECT_LT(vertexDistances(copy, sheet).first, 5e-3);
}

TEST(SimplifiedCopy, AMeshNoFinerThanAskedIsItself) {
  const TriMesh spot = test::loadShared("spot.obj");
  const TriMesh copy = simplifiedCopy(spot, spot.numTriangles());
  EXPECT_EQ(copy.V, spot.V);
  EXPECT_EQ(copy.F, spot.F);
}

}  // namespace
}  // namespace billow
