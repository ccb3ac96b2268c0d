#include "seams/surface_distance.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <vector>

#include "mesh/location.hpp"
#include "util/union_find.hpp"

namespace billow {

Eigen::VectorXd signedDistances(const TriMesh& target, const SurfaceProjector& projector, const Vertices& points) {
  Eigen::VectorXd d(points.rows());
  for (int i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose();
    double distance = 0;
    const SurfacePoint p = projector.project(q, &distance);
    const Eigen::Vector3d a = target.V.row(target.F(p.face, 0)).transpose();
    const Eigen::Vector3d b = target.V.row(target.F(p.face, 1)).transpose();
    const Eigen::Vector3d c = target.V.row(target.F(p.face, 2)).transpose();
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    d[i] = (q - position(target, p)).dot(normal) < 0 ? -distance : distance;
  }
  return d;
}

DistanceSummary summarizeDistances(const Eigen::VectorXd& distances, const Triangles& surface, double diagonal) {
  std::vector<char> used(distances.size(), surface.rows() == 0);
  for (int t = 0; t < surface.rows(); ++t)
    for (int k = 0; k < 3; ++k) used[surface(t, k)] = 1;
  DistanceSummary s;
  int n = 0;
  for (int v = 0; v < distances.size(); ++v) {
    if (!used[v]) continue;
    s.rms += distances[v] * distances[v], s.max = std::max(s.max, std::abs(distances[v])), ++n;
  }
  s.rms = n ? std::sqrt(s.rms / n) / diagonal : 0;
  s.max /= diagonal;
  return s;
}

namespace {

// The target's distances to a shape, summarized: RMS weighted by the target vertices' areas, max.
TargetCoverage summarizeCoverage(const TriMesh& target, Eigen::VectorXd distances, double diagonal) {
  TargetCoverage c;
  c.distances = std::move(distances);
  if (target.numVertices() == 0) return c;
  Eigen::VectorXd area = Eigen::VectorXd::Zero(target.numVertices());
  for (int f = 0; f < target.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) area[target.F(f, k)] += triangleArea(target, f) / 3;
  const double total = area.sum();
  if (total > 0) c.summary.rms = std::sqrt(area.dot(c.distances.cwiseAbs2()) / total) / diagonal;
  c.summary.max = c.distances.maxCoeff() / diagonal;
  return c;
}

// targetCoverage against the shape's projector.
TargetCoverage coverage(const TriMesh& target, const SurfaceProjector& shapeProjector, double diagonal) {
  Eigen::VectorXd distances = Eigen::VectorXd::Zero(target.numVertices());
  for (int v = 0; v < target.numVertices(); ++v) shapeProjector.project(target.V.row(v).transpose(), &distances[v]);
  return summarizeCoverage(target, std::move(distances), diagonal);
}

}  // namespace

TargetCoverage targetCoverage(const TriMesh& target, const Vertices& points, const Triangles& surface,
                              double diagonal) {
  if (surface.rows() == 0) {
    TargetCoverage c;
    c.distances = Eigen::VectorXd::Zero(target.numVertices());
    return c;
  }
  const TriMesh shape{points, surface};
  return coverage(target, SurfaceProjector(shape), diagonal);
}

std::vector<UncoveredRegion> uncoveredRegions(const TriMesh& target, const Eigen::VectorXd& distances, double diagonal,
                                              const UpAxis& up, double threshold, double minAreaFraction) {
  const int nf = target.numTriangles();
  const double limit = threshold * diagonal;
  std::vector<char> far(nf, 0);
  for (int f = 0; f < nf; ++f)
    far[f] =
        distances[target.F(f, 0)] > limit && distances[target.F(f, 1)] > limit && distances[target.F(f, 2)] > limit;
  // Far triangles sharing a vertex belong together (edges would split a region along a thin waist).
  UnionFind groups(target.numVertices());
  for (int f = 0; f < nf; ++f)
    if (far[f]) groups.unite(target.F(f, 0), target.F(f, 1)), groups.unite(target.F(f, 0), target.F(f, 2));
  double total = 0;
  std::vector<double> area(target.numVertices(), 0.0);
  for (int f = 0; f < nf; ++f) {
    const double a = triangleArea(target, f);
    total += a;
    if (far[f]) area[groups.find(target.F(f, 0))] += a;
  }
  const Eigen::Vector3d lo = target.V.colwise().minCoeff().transpose(), hi = target.V.colwise().maxCoeff().transpose();
  std::vector<UncoveredRegion> regions;
  std::vector<int> regionOf(target.numVertices(), -1);
  for (int f = 0; f < nf; ++f) {
    if (!far[f]) continue;
    const int root = groups.find(target.F(f, 0));
    if (!(area[root] >= minAreaFraction * total)) continue;
    if (regionOf[root] < 0) {
      regionOf[root] = int(regions.size());
      regions.emplace_back().areaFraction = area[root] / total;
      regions.back().maxDistance = -1;
    }
    UncoveredRegion& r = regions[regionOf[root]];
    r.triangles.push_back(f);
    for (int k = 0; k < 3; ++k) {
      const int v = target.F(f, k);
      if (distances[v] > r.maxDistance) r.maxDistance = distances[v], r.farthest = target.V.row(v).transpose();
    }
  }
  // The ball about the farthest vertex that holds each region, for a view to frame it.
  for (int f = 0; f < nf; ++f) {
    if (!far[f]) continue;
    const int i = regionOf[groups.find(target.F(f, 0))];
    if (i < 0) continue;
    for (int k = 0; k < 3; ++k)
      regions[i].radius =
          std::max(regions[i].radius, (target.V.row(target.F(f, k)).transpose() - regions[i].farthest).norm());
  }
  for (UncoveredRegion& r : regions) r.maxDistance /= diagonal, r.where = describeLocation(r.farthest, lo, hi, up);
  // Parts that read the same (an elephant's two feet, both "near the bottom") are one message: the designer
  // could not tell two of them apart. The merged ball holds both balls.
  std::vector<UncoveredRegion> merged;
  for (UncoveredRegion& r : regions) {
    const auto same =
        std::find_if(merged.begin(), merged.end(), [&](const UncoveredRegion& m) { return m.where == r.where; });
    if (same == merged.end()) {
      merged.push_back(std::move(r));
      continue;
    }
    UncoveredRegion& m = *same;
    const Eigen::Vector3d apex = r.maxDistance > m.maxDistance ? r.farthest : m.farthest;
    m.radius = std::max(m.radius + (m.farthest - apex).norm(), r.radius + (r.farthest - apex).norm());
    m.farthest = apex;
    m.maxDistance = std::max(m.maxDistance, r.maxDistance);
    m.areaFraction += r.areaFraction;
    m.parts += r.parts;
    m.triangles.insert(m.triangles.end(), r.triangles.begin(), r.triangles.end());
  }
  std::sort(merged.begin(), merged.end(),
            [](const UncoveredRegion& a, const UncoveredRegion& b) { return a.areaFraction > b.areaFraction; });
  return merged;
}

namespace {

// What helps a region: one rule for the message and the pane's hint.
enum class Remedy { InternalConnection, Gusset, MoreSeams, SeamAround };

Remedy remedyOf(const UncoveredRegion& r) {
  if (r.insideFraction > 0.5) return Remedy::InternalConnection;
  if (r.offFlatSide) return Remedy::Gusset;
  // Much of the target missed is no part left out but panels that cannot take its shape.
  if (r.areaFraction > 0.3) return Remedy::MoreSeams;
  return Remedy::SeamAround;
}

}  // namespace

std::string uncoveredRemedy(const UncoveredRegion& r) {
  switch (remedyOf(r)) {
    case Remedy::InternalConnection:
      return "an internal connection there";
    case Remedy::Gusset:
      return r.gusseted ? "a wider gusset or more panels" : "a gusset or more panels";
    case Remedy::MoreSeams:
      return "more seams";
    case Remedy::SeamAround:
      break;
  }
  return r.parts > 1 ? "a seam around each part" : "a seam around that part";
}

std::string uncoveredMessage(const UncoveredRegion& r) {
  const auto percent = [](double f) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f %%", 100 * f);
    return std::string(buf);
  };
  const Remedy remedy = remedyOf(r);
  if (remedy == Remedy::InternalConnection)
    return (r.flatTarget ? "The inflated shape bulges past a flat side of the target "
                         : "The inflated shape bulges over a hollow of the target ") +
           r.where + ": " + percent(r.areaFraction) + " of its surface, up to " + percent(r.maxDistance) +
           " of its size inside the balloon. An internal connection there (a strip inside sewn to both sides) "
           "pulls the surface in.";
  if (remedy == Remedy::Gusset)
    return "The inflated shape is too flat for part of the target " + r.where + ": " + percent(r.areaFraction) +
           " of its surface lies up to " + percent(r.maxDistance) + " of its size outside the balloon. " +
           (r.gusseted ? "A wider gusset (the strip sewn in along the seam)"
                       : "A gusset (a strip sewn in along the seam)") +
           " or more panels let the balloon grow thicker.";
  if (remedy == Remedy::MoreSeams)
    return "The inflated shape falls short of much of the target: " + percent(r.areaFraction) +
           " of its surface lies up to " + percent(r.maxDistance) + " of its size away, farthest " + r.where +
           ". More seams let the panels follow its shape.";
  if (r.parts > 1)
    return "The inflated shape leaves out " + std::to_string(r.parts) + " parts of the target " + r.where + ": " +
           percent(r.areaFraction) + " of its surface together, up to " + percent(r.maxDistance) +
           " of its size away. A seam around each part, or panels of their own, lets the balloon reach them.";
  return "The inflated shape leaves out part of the target " + r.where + ": " + percent(r.areaFraction) +
         " of its surface, up to " + percent(r.maxDistance) +
         " of its size away. A seam around that part, or a panel of its own, lets the balloon reach it.";
}

namespace {

// How much the region's triangles face one way: the length of their area-weighted mean normal over their area (1: all
// one way, a flat patch; 0 when empty).
double facingShare(const TriMesh& target, const UncoveredRegion& r) {
  Eigen::Vector3d facing = Eigen::Vector3d::Zero();
  double area = 0;
  for (int f : r.triangles) {
    const Eigen::Vector3d a = target.V.row(target.F(f, 0)), b = target.V.row(target.F(f, 1)),
                          c = target.V.row(target.F(f, 2));
    facing += 0.5 * (b - a).cross(c - a);
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area > 0 ? facing.norm() / area : 0;
}

// The share of a region's vertices (at most 64, spread over it) inside the shape: negative signed distance to
// it (signedDistances, as the inflated shape's own is read against the target).
double insideFraction(const TriMesh& target, const UncoveredRegion& r, const TriMesh& shape,
                      const SurfaceProjector& shapeProjector) {
  std::vector<int> vertices;
  for (int f : r.triangles)
    for (int k = 0; k < 3; ++k) vertices.push_back(target.F(f, k));
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  if (vertices.empty()) return 0;
  const size_t stride = std::max<size_t>(1, vertices.size() / 64);
  Vertices samples((vertices.size() + stride - 1) / stride, 3);
  for (size_t i = 0; i < vertices.size(); i += stride) samples.row(i / stride) = target.V.row(vertices[i]);
  const Eigen::VectorXd d = signedDistances(shape, shapeProjector, samples);
  return double((d.array() < 0).count()) / double(d.size());
}

// Whether the region is a broad part of the target off the flat side of a flat shape. Flat: the shape's
// thinnest principal extent under 0.7 of its middle one (inflated two-piece penguins and fish: 0.6-0.65). Off
// its flat side: the farthest vertex lies from the shape along that thin axis (within 45 degrees). Broad: at
// least 3 % of the target, its triangles facing one way, as the cap of a body does (their area-weighted mean
// normal at least 0.3 of their area: a penguin's back left out by a balloon cut from the front 0.42, a cap up
// to 115 degrees across); a fin, an ear or a leg faces both ways or all round (a fish's fins 0.17, a bunny's
// ears 0.09).
bool offFlatSide(const TriMesh& target, const UncoveredRegion& r, const TriMesh& shape,
                 const SurfaceProjector& projector) {
  const Vertices& points = shape.V;
  if (points.rows() < 4 || r.triangles.empty() || r.areaFraction < 0.03) return false;
  const Eigen::RowVector3d mean = points.colwise().mean();
  const Eigen::Matrix3d C = (points.rowwise() - mean).transpose() * (points.rowwise() - mean);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(C);
  if (!(axes.eigenvalues()[0] < 0.5 * axes.eigenvalues()[1])) return false;  // variances: extents squared
  const Eigen::Vector3d thin = axes.eigenvectors().col(0);
  const Eigen::Vector3d away = r.farthest - position(shape, projector.project(r.farthest));
  if (!(std::abs(away.dot(thin)) > std::sqrt(0.5) * away.norm())) return false;
  return facingShare(target, r) >= 0.3;
}

// Whether the region's triangles all face one way (their area-weighted mean normal 0.98 of their area or more, as a
// spherical cap's within 16 degrees of its middle): a flat side of the target, not a hollow.
bool flatTarget(const TriMesh& target, const UncoveredRegion& r) { return facingShare(target, r) >= 0.98; }

}  // namespace

DistanceSummary TwoWayDistance::worse() const {
  return {std::max(inflatedToTarget.rms, targetToInflated.summary.rms),
          std::max(inflatedToTarget.max, targetToInflated.summary.max)};
}

TwoWayDistance measureDistance(const TriMesh& target, const SurfaceProjector& projector, const Vertices& points,
                               const Triangles& surface, const UpAxis& up, const Eigen::VectorXd* targetDistances,
                               bool gusseted) {
  TwoWayDistance d;
  d.diagonal = (target.V.colwise().maxCoeff() - target.V.colwise().minCoeff()).norm();
  d.signedDistances = signedDistances(target, projector, points);
  d.inflatedToTarget = summarizeDistances(d.signedDistances, surface, d.diagonal);
  if (surface.rows() == 0) return d;
  const TriMesh shape{points, surface};
  std::optional<SurfaceProjector> shapeProjector;
  if (!targetDistances) shapeProjector.emplace(shape);
  d.targetToInflated = targetDistances ? summarizeCoverage(target, *targetDistances, d.diagonal)
                                       : coverage(target, *shapeProjector, d.diagonal);
  d.uncovered = uncoveredRegions(target, d.targetToInflated.distances, d.diagonal, up);
  if (!d.uncovered.empty() && !shapeProjector) shapeProjector.emplace(shape);
  for (UncoveredRegion& r : d.uncovered) {
    r.insideFraction = insideFraction(target, r, shape, *shapeProjector);
    r.offFlatSide = offFlatSide(target, r, shape, *shapeProjector);
    r.flatTarget = flatTarget(target, r);
    r.gusseted = gusseted;
  }
  return d;
}

}  // namespace billow
