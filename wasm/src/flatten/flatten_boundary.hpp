// Boundary flattening of a segment: Newton's method on Eq. 14 (Skouras et al. 2014, Sec. 5.2; Wang 2008)
// from a polygon built from the target's turning angles, with a guarded fallback that starts from a circle
// and never leaves the set of simple CCW polygons.
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
  Points2 Q;            // #b by 2, CCW
  double energy = 0;    // E_fl(Q)
  int iterations = 0;   // Newton iterations over all attempts
  bool simple = false;  // Q is a simple CCW polygon
};

// Start: integrate the target's turning angles pi - theta_j, with the excess over 2 pi spread as Eq. 14's
// least squares would (inversely to lbar_j), then close the polygon by spreading the gap along its length.
Points2 turningAngleStart(const BoundaryTargets& targets);
// Start: the boundary's 3D arc length laid on a circle (convex, always simple).
Points2 circleStart(const BoundaryTargets& targets);

bool isSimpleCcwPolygon(const Points2& Q);

// Minimizes Eq. 14 from start. With keepSimple, a step that would make the polygon self-intersect is
// shortened like a step that does not decrease the energy.
BoundaryFlattening minimizeBoundaryEnergy(const BoundaryTargets& targets, const Points2& start, bool keepSimple,
                                          const BoundaryNewtonOptions& options = {});

// The whole boundary step: from the turning-angle start, falling back to the guarded circle start when
// the result is not a simple CCW polygon.
BoundaryFlattening flattenBoundary(const BoundaryTargets& targets, const BoundaryNewtonOptions& options = {});

}  // namespace billow
