// When the optimization stops. The CLI and the native bench go on to full convergence (OptimizeOptions'
// defaults); the app stops once the designer would see no more change, so a layout's result comes in
// seconds (bench/README.md).
#pragma once
#include "optimize/pattern_optimizer.hpp"

namespace billow {

// The app's rule, over `options`: stop once no inflated vertex moved by 0.2 % of the model size over 20
// iterations, or the objective fell by less than 1 % over 20 iterations, or after 150 iterations (300 when
// seams slide: OptimizeSliding::iterationFactor, as they keep visibly improving the shape for longer).
OptimizeOptions appStoppingRule(OptimizeOptions options = {});

}  // namespace billow
