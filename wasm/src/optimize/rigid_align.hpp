// Rigid placement of the inflated shape. The equilibrium x(X) is only defined up to a rigid motion (the
// simulator pins one); E_target, E_cover and E_seam are not rigid-invariant. We place x at the rigid motion that
// minimizes E_target + E_cover + E_seam (Levenberg-damped Gauss-Newton over a rotation vector and a translation).
// At that minimum dE/dx is orthogonal to the rigid motions, so the adjoint gradient does not depend on the
// pins (adjoint.hpp) and, by the envelope theorem, the optimizer sees the best-aligned shape's energy.
#pragma once
#include <limits>

#include "optimize/objectives.hpp"

namespace billow {

// How the alignment steps, per run. The defaults are plain Gauss-Newton, which held seams keep; a design with sliding
// seams, on a nearly rotation-invariant target, needs the other two (PatternOptimizer's slidingOptions; bench/README.md
// "The rigid alignment").
struct RigidAlignOptions {
  // After this many steps, E's own Hessian (by differences of its gradient) instead of J^T J: E_target and E_cover
  // pull against each other along a rotation, where J^T J overstates E's curvature up to hundreds of times and the
  // steps shrink linearly.
  int gaussNewtonSteps = std::numeric_limits<int>::max();
  // A step the model gives a hair of E (1e-9) that raises E a thousand times more ends the alignment: E jumps
  // there (E_cover's closest point is walked to from its tracked triangle, and the walk can end elsewhere once
  // the shape moves a hair), and ever shorter steps would only approach the jump.
  bool stopAtJump = false;
};

// Moves x (the inflated shape of pattern X) in place; returns the steps taken. Stops when the
// step is below tolerance x D, or lowered E by less than relativeDecrease x E (0: never). The adjoint gradient
// needs the minimum itself: on a nearly rotation-invariant target (a sphere) 30 steps left the reduced gradient
// 1-2 % off (tests/native/test_adjoint.cpp). A line-search trial needs only E: there the steps along the nearly
// free rotation (5e-5 of the size, each lowering E by 1e-10 relative, a hundred of them) are not worth taking.
int alignRigid(const PatternObjective& objective, const Eigen::VectorXd& X, Vertices& x, int maxIterations = 300,
               double tolerance = 1e-12, double relativeDecrease = 0, const RigidAlignOptions& options = {});

}  // namespace billow
