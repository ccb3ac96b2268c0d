// Signed distance from points to a closed target surface, for the "distance to target" view of an
// inflated shape: positive outside the target (the shape bulges), negative inside (it falls short).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "mesh/up_axis.hpp"
#include "seams/surface_point.hpp"

namespace billow {

// Per row of `points`: the distance to the closest point of `target`, signed by the side of the closest
// triangle's plane the point is on (outward normals: the target is a closed, outward-oriented mesh).
// Exact in magnitude; the sign is the closest triangle's, which can only err within a hair of an edge.
Eigen::VectorXd signedDistances(const TriMesh& target, const SurfaceProjector& projector, const Vertices& points);

struct DistanceSummary {
  double rms = 0, max = 0;  // of |d|, over the diagonal given
};

// RMS and max of |distances| over the points that are corners of `surface` (all points when it has no
// rows: the outer surface of an inflated shape, since internal panels are not meant to lie on the target),
// divided by `diagonal` (the target's bounding-box diagonal).
DistanceSummary summarizeDistances(const Eigen::VectorXd& distances, const Triangles& surface, double diagonal);

// The other way round: how far each target vertex lies from a shape's surface. Measured one way only, a shape
// that leaves out a whole wing reads close, since every point it has lies on the target.
struct TargetCoverage {
  Eigen::VectorXd distances;  // per target vertex, unsigned, in the target's units
  DistanceSummary summary;    // RMS weighted by the vertices' areas (so the figure does not follow the meshing), max
};

// Distances from the target's vertices to the triangles `surface` of `points` (all in the target's units).
TargetCoverage targetCoverage(const TriMesh& target, const Vertices& points, const Triangles& surface, double diagonal);

// A part of the target the shape leaves out: target triangles whose corners all lie farther than a threshold
// from the shape, joined where they share a vertex.
struct UncoveredRegion {
  double areaFraction = 0;                             // of the target's area
  double maxDistance = 0;                              // over the diagonal
  Eigen::Vector3d farthest = Eigen::Vector3d::Zero();  // its vertex farthest from the shape (target units)
  double radius = 0;                                   // of the ball about `farthest` holding the region (target units)
  std::string where;                                   // "near the top left of the shape"
  int parts = 1;                                       // separate parts that read the same `where`, merged
  // Share of its vertices inside the shape (measureDistance; 0 unknown): the shape spans over a hollow of the
  // target there rather than falling short of a part, which says what helps (uncoveredMessage).
  double insideFraction = 0;
  // The shape is flat (a two-piece balloon) and this is a broad part of the target off its flat side: the
  // balloon is too thin there (measureDistance).
  bool offFlatSide = false;
  // The target is flat there (its triangles all face one way: a box's side): with insideFraction, the balloon bulges
  // past a flat side rather than over a hollow (measureDistance).
  bool flatTarget = false;
  // The balloon has a gusset already (measureDistance's caller knows the design): too flat, a wider one helps.
  bool gusseted = false;
  std::vector<int> triangles;  // rows of the target's F: what is left out, to draw
};

// What a designer reads about a region: where, how much, and what helps, judged from the shape: over a hollow,
// an internal connection pulls the surface in; off the flat side of a flat balloon (a two-piece balloon too thin
// for a round body), a gusset or more panels; short of a part (a limb, a wing), a seam around it.
std::string uncoveredMessage(const UncoveredRegion& region);
// What helps, in a few words ("a gusset or more panels"), for the inflated pane's one-line hint.
std::string uncoveredRemedy(const UncoveredRegion& region);

// What counts as left out: farther than 6 % of the diagonal, over at least 1 % of the target's area. Good
// designs stay within it (the three-gore sphere falls 5.0 % short between its seams, the optimized teddy 5.5 %
// at its worst); a missing wing or leg lies far beyond.
constexpr double kUncoveredDistance = 0.06, kUncoveredArea = 0.01;

// The parts of the target farther than `threshold` (a fraction of the diagonal) from the shape, largest first,
// those smaller than `minAreaFraction` of the target's area left out, each placed ("near the left") as the
// target stands on `up`. distances: TargetCoverage's.
std::vector<UncoveredRegion> uncoveredRegions(const TriMesh& target, const Eigen::VectorXd& distances, double diagonal,
                                              const UpAxis& up, double threshold = kUncoveredDistance,
                                              double minAreaFraction = kUncoveredArea);

// A shape against its target both ways, as every figure of the app, the CLI and the bench reads it.
struct TwoWayDistance {
  Eigen::VectorXd signedDistances;   // per point of the shape (signedDistances), target units
  DistanceSummary inflatedToTarget;  // over the corners of the surface
  TargetCoverage targetToInflated;   // empty when there is no surface
  std::vector<UncoveredRegion> uncovered;
  double diagonal = 0;  // of the target's box, target units
  // The worse way, which leads wherever one figure is shown.
  DistanceSummary worse() const;
};

// points: the shape in the target's units; surface: its outer triangles (none: one way only, over every point);
// up: how the target stands, for the places of the parts left out; targetDistances: the other way, per target
// vertex, when already measured on this shape (PatternOptimizer::targetDistances, in the target's units);
// gusseted: the design has a gusset band (UncoveredRegion::gusseted).
TwoWayDistance measureDistance(const TriMesh& target, const SurfaceProjector& projector, const Vertices& points,
                               const Triangles& surface, const UpAxis& up,
                               const Eigen::VectorXd* targetDistances = nullptr, bool gusseted = false);

}  // namespace billow
