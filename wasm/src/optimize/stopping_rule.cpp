#include "optimize/stopping_rule.hpp"

#include <algorithm>
#include <cmath>

namespace billow {

OptimizeOptions appStoppingRule(OptimizeOptions options) {
  options.stopping.maxIterations = 150;
  options.stopping.windowIterations = 20;
  options.stopping.windowMove = 2e-3;
  options.stopping.windowDecrease = 1e-2;
  options.stopping.maxWork = 1600;
  return options;
}

ObjectiveWindow readObjectiveWindow(const std::vector<OptimizeRecord>& history, int iteration, int window,
                                    double decrease, double E) {
  if (iteration < window) return ObjectiveWindow::GoesOn;
  // One pass back to the last remeshing (a window may start with one): the best objective, the best up to the
  // window's start, and around the last resettled branch the best since it and the best before it. The final
  // seam-length projection is no iterate.
  double before = INFINITY, best = INFINITY, bestBefore = INFINITY, bestSince = INFINITY, beforeHeld = INFINITY;
  int resettledAt = -1, held = 0, snapped = 0;
  bool holding = true;
  // Five steps at least: the coarse phase's window is 10, and two held steps ended it on paths that cost more.
  const int heldWindow = std::max(5, window / 4);
  for (size_t j = history.size(); j-- > 0;) {
    const OptimizeRecord& r = history[j];
    if (!r.projected) {
      best = std::min(best, r.objective);
      if (r.iteration <= iteration - window) before = std::min(before, r.objective);
      if (r.iteration <= iteration - heldWindow) beforeHeld = std::min(beforeHeld, r.objective);
      if (holding && r.iteration > iteration - heldWindow) {
        holding = (r.snapLimited || r.cutShort) && !r.resettled && !r.remeshed;
        held += holding, snapped += holding && r.snapLimited;
      }
    }
    if (r.remeshed) break;
    if (r.projected) continue;
    if (resettledAt < 0 && r.resettled)
      resettledAt = r.iteration;
    else if (resettledAt >= 0)
      bestBefore = std::min(bestBefore, r.objective);
    else
      bestSince = std::min(bestSince, r.objective);
  }
  if (std::isfinite(before) && before - best < decrease * std::abs(E)) return ObjectiveWindow::NoDecrease;
  // Most of them after a snap: short steps alone are also L-BFGS in a curved valley (sphere3's iterations 51-57 at
  // alpha 0.002-0.04, then 0.5-11 again), no fold.
  if (held == heldWindow && 2 * snapped > heldWindow && std::isfinite(beforeHeld) &&
      beforeHeld - best < decrease * heldWindow / window * std::abs(E))
    return ObjectiveWindow::HeldAtFold;
  // A resettling may raise the objective and the steps after it bring it down again; the branches that pay come
  // back within a few iterations (the fish: 5 and 7), fb-spot's never did.
  if (resettledAt >= 0 && iteration - resettledAt >= window / 2 && !(bestSince < bestBefore))
    return ObjectiveWindow::SnapsAway;
  return ObjectiveWindow::GoesOn;
}

}  // namespace billow
