// Boundary flattening of a segment: Newton's method on Eq. 14 (Skouras et al. 2014, Sec. 5.2; Wang 2008)
// with consistent angle targets, from a closed polygon with the target's edge lengths, guarded so that it
// never leaves the set of simple CCW polygons.
#pragma once
#include "flatten/boundary_energy.hpp"

namespace billow {

struct BoundaryNewtonOptions {
  int maxIterations = 50;           // Newton iterations per attempt (a developable segment needs ~3-6)
  double gradientTolerance = 1e-9;  // stop when max |dE/dQ| is below this (E_fl has units of length)
  double armijo = 1e-4;             // sufficient decrease in the backtracking line search
  int maxHalvings = 40;
};

struct BoundaryFlattening {
  Points2 Q;               // #b by 2, CCW
  double energy = 0;       // E_fl(Q)
  int iterations = 0;      // Newton iterations over all attempts
  bool simple = false;     // Q is a simple CCW polygon
  double convexBlend = 0;  // how far the start's turning angles were blended toward a circle to be simple
};

// Eq. 14 with consistent angle targets: the turning angles pi - theta_j of a closed flat polygon sum to 2 pi,
// while on the target they sum to 2 pi - K (Gauss-Bonnet, K the segment's total Gaussian curvature). The
// curvature defect K is spread along the boundary in proportion to arc length (lbar_j), so that the lengths
// can all be kept while the angles absorb the defect. (flattenSegment first moves the curvature to the
// boundary where a conformal map would, FlattenOptions::conformalAngles; what is left here is round-off.)
BoundaryTargets consistentTargets(const BoundaryTargets& targets);

// The target turning angles pi - theta_j (consistent: they sum to 2 pi) blended toward those of a circle
// (2 pi lbar_j / perimeter) by convexBlend in [0, 1]: at 1 every turn is positive, the polygon convex.
Eigen::VectorXd blendedTurning(const BoundaryTargets& consistent, double convexBlend);

// Start: the closed polygon with exactly the target edge lengths whose turning angles are closest to
// `turning` (least squares weighted by lbar_j, as in Eq. 14), by SQP on the edge directions with the two
// closing constraints sum_j l_j (cos phi_j, sin phi_j) = 0. When the SQP stops early, the edges take up what
// is left of the gap in proportion to their lengths.
Points2 closedLengthStart(const BoundaryTargets& targets, const Eigen::VectorXd& turning, int maxIterations = 50);

// Start: the boundary's 3D arc length laid on a circle (convex, always simple).
Points2 circleStart(const BoundaryTargets& targets);

bool isSimpleCcwPolygon(const Points2& Q);

// Minimizes Eq. 14 from start. With keepSimple, a step that would make the polygon self-intersect is
// shortened like a step that does not decrease the energy.
BoundaryFlattening minimizeBoundaryEnergy(const BoundaryTargets& targets, const Points2& start, bool keepSimple,
                                          const BoundaryNewtonOptions& options = {});

// The whole boundary step. Boundary edges shorter than a tenth of the mean are first merged with the next
// (where seams cross the target's triangles near a corner they leave edges of 1e-7 next to edges of 1e-2: their
// direction, so the angles at their ends, means nothing, and their 1 / l_j weight makes Eq. 14 stiff); Newton
// on Eq. 14 with consistent targets, guarded to stay simple, from the closed exact-length start; when that
// start self-intersects (the segment's development overlaps itself), its turning angles are first blended
// toward a circle's until it is simple. The merged vertices are then put back on their edges, in proportion to
// the target arc length, bulging out by a thousandth so that no boundary triangle is flat.
// convexBlend > 0 asks for the start blended at least that far, without Newton (which would undo the blend):
// the lengths are kept, the angles given up for a boundary that is more convex.
BoundaryFlattening flattenBoundary(const BoundaryTargets& targets, const BoundaryNewtonOptions& options = {},
                                   double convexBlend = 0);

}  // namespace billow
