// When the optimization stops. The CLI and the native bench go on to full convergence (OptimizeOptions'
// defaults); the app stops once the designer would see no more change, so a layout's result comes in
// seconds (bench/README.md).
#pragma once
#include "optimize/pattern_optimizer.hpp"

namespace billow {

// The app's rule, over `options`: stop once no inflated vertex moved by 0.2 % of the model size over 20
// iterations, or the objective fell by less than 1 % over 20 iterations (or 0.25 % over five steps that each came
// after a trial that snapped or were cut short: HeldAtFold below), or after 150 iterations (300 when
// seams slide: OptimizeSliding::iterationFactor, as they keep visibly improving the shape for longer), or once its
// work reached 1,600 Newton iterations' worth (OptimizeStopping::maxWork: beyond it the cut panels came no closer).
OptimizeOptions appStoppingRule(OptimizeOptions options = {});

// The objective window (OptimizeStopping::windowDecrease), read from a run's history after `iteration`, E the
// current objective, over the last `window` iterations of the current mesh:
// - NoDecrease: the best objective fell by less than decrease x |E| (only new bests count, so snapping back and
//   forth between two equilibria ends the run too; never across a remeshing, the objective of another mesh);
// - SnapsAway: the last resettled branch has not come below the best iterate before it within half a window;
// - HeldAtFold: each of the last quarter window's steps (at least five) came after a trial that snapped or was cut
//   to a tenth of its direction's (OptimizeRecord::cutShort), most of them after a snap, and the best objective
//   fell by less than their share of `decrease` over them: NoDecrease's rate, on steps that cannot grow, since
//   longer ones cross the fold.
enum class ObjectiveWindow { GoesOn, NoDecrease, SnapsAway, HeldAtFold };
ObjectiveWindow readObjectiveWindow(const std::vector<OptimizeRecord>& history, int iteration, int window,
                                    double decrease, double E);

}  // namespace billow
