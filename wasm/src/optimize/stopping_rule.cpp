#include "optimize/stopping_rule.hpp"

namespace billow {

OptimizeOptions appStoppingRule(OptimizeOptions options) {
  options.stopping.maxIterations = 150;
  options.stopping.windowIterations = 20;
  options.stopping.windowMove = 2e-3;
  options.stopping.windowDecrease = 1e-2;
  return options;
}

}  // namespace billow
