// flattenSegment: Skouras et al. 2014, Sec. 5.2 (Eq. 14, after Wang 2008) end to end.
#include "flatten/flatten.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "flatten/segment_boundary.hpp"

namespace billow {
namespace {

double area3(const TriMesh& m) {
  double a = 0;
  for (int f = 0; f < m.numTriangles(); ++f)
    a += 0.5 * (m.V.row(m.F(f, 1)) - m.V.row(m.F(f, 0))).cross(m.V.row(m.F(f, 2)) - m.V.row(m.F(f, 0))).norm();
  return a;
}

// Signed triangle areas and centroids of the panel.
void panelMoments(const Triangles& F, const Points2& uv, double& area, Eigen::Vector2d& centroid,
                  Eigen::Matrix2d& second) {
  area = 0;
  centroid.setZero();
  second.setZero();
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::Vector2d a = uv.row(F(f, 0)), b = uv.row(F(f, 1)), c = uv.row(F(f, 2));
    const Eigen::Vector2d e = b - a, g = c - a;
    const double s = 0.5 * (e.x() * g.y() - e.y() * g.x());
    const Eigen::Vector2d m = (a + b + c) / 3;
    area += s;
    centroid += s * m;
    // Exact second moment of a triangle about the origin: (A / 12) (sum p p^T + 9 m m^T).
    second += s / 12 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + 9 * m * m.transpose());
  }
  if (area != 0) centroid /= area;
}

// Centre at the area centroid and turn the principal (largest-variance) axis onto x. A rotation, so
// CCW triangles stay CCW.
void placeOnPrincipalAxis(const Triangles& F, Points2& uv) {
  double area;
  Eigen::Vector2d c;
  Eigen::Matrix2d S;
  panelMoments(F, uv, area, c, S);
  if (!(area > 0)) return;
  const Eigen::Matrix2d cov = S / area - c * c.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  Eigen::Vector2d x = eig.eigenvectors().col(1);  // eigenvalues ascending
  if (x.x() < 0 || (x.x() == 0 && x.y() < 0)) x = -x;
  const Eigen::Vector2d y(-x.y(), x.x());
  for (int v = 0; v < uv.rows(); ++v) {
    const Eigen::Vector2d p = uv.row(v).transpose() - c;
    uv.row(v) << p.dot(x), p.dot(y);
  }
}

// Interior by one Laplacian solve; falls back to uniform weights, then to the local repair.
void placeInterior(const TriMesh& segment, const std::vector<int>& next, InteriorLaplacian& laplacian,
                   const FlattenOptions& o, int sweeps, FlattenResult& r) {
  r.interior = o.weights == LaplacianWeights::Cotangent ? "cotangent" : "uniform";
  laplacian.solve(o.weights, r.uv);
  r.flippedTriangles = countFolds(segment.F, r.uv, next);
  if (r.flippedTriangles > 0 && o.weights == LaplacianWeights::Cotangent) {
    Points2 uniform = r.uv;
    laplacian.solve(LaplacianWeights::Uniform, uniform);
    const int flips = countFolds(segment.F, uniform, next);
    if (flips < r.flippedTriangles) {
      r.uv = uniform;
      r.flippedTriangles = flips;
      r.interior = "uniform";
    }
  }
  if (r.flippedTriangles > 0 && sweeps > 0) {
    r.flippedTriangles = untangle(segment.F, next, sweeps, r.uv);
    r.interior += "+repair";
  }
}

}  // namespace

FlattenResult flattenSegment(const TriMesh& segment, const FlattenOptions& options) {
  FlattenResult r;
  r.boundary = findBoundaryLoop(segment);
  BoundaryTargets targets = measureBoundary(segment, r.boundary);
  const int nb = static_cast<int>(r.boundary.size());
  std::vector<char> isBoundary(segment.numVertices(), 0);
  for (int j = 0; j < nb; ++j) isBoundary[r.boundary[j]] = 1;
  const std::vector<int> next = boundaryNext(segment.F, segment.numVertices());
  InteriorLaplacian laplacian(segment, isBoundary, options.cotangentClamp);
  if (options.conformalAngles) {
    const Eigen::VectorXd shift = laplacian.conformalAngleShift();
    for (int j = 0; j < nb; ++j) targets.angle[j] += shift[r.boundary[j]];
  }
  // Eq. 14, then the interior; when the boundary is so far from convex that the interior cannot be placed
  // without a flipped triangle, the boundary's turning angles are blended toward a circle's (lengths kept).
  for (const double blend : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const BoundaryFlattening b = flattenBoundary(targets, options.newton, blend);
    r.newtonIterations += b.iterations;
    r.boundaryEnergy = b.energy;
    r.convexBlend = b.convexBlend;
    r.uv = Points2::Zero(segment.numVertices(), 2);
    for (int j = 0; j < nb; ++j) r.uv.row(r.boundary[j]) = b.Q.row(j);
    r.maxBoundaryLengthError = 0;
    for (int j = 0; j < nb; ++j) {
      const double L = (b.Q.row((j + 1) % nb) - b.Q.row(j)).norm();
      r.maxBoundaryLengthError =
          std::max(r.maxBoundaryLengthError, std::abs(L - targets.length[j]) / targets.length[j]);
    }
    // A short repair while a more convex boundary remains to be tried; the full one on the last.
    const bool last = b.convexBlend >= 1 || options.untangleSweeps == 0;
    placeInterior(segment, next, laplacian, options,
                  last ? options.untangleSweeps : std::min(options.untangleSweeps, options.sweepsBeforeBlending), r);
    if (r.flippedTriangles == 0 || last) break;
  }
  if (r.convexBlend > 0) r.interior += "+convex";
  if (options.placeOnPrincipalAxis) placeOnPrincipalAxis(segment.F, r.uv);

  double area2 = 0;
  Eigen::Vector2d c;
  Eigen::Matrix2d S;
  panelMoments(segment.F, r.uv, area2, c, S);
  r.areaRatio = area2 / area3(segment);
  return r;
}

}  // namespace billow
