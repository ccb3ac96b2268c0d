#include "optimize/stopping_rule.hpp"

namespace billow {

OptimizeOptions appStoppingRule(OptimizeOptions options) {
  options.maxIterations = 150;
  options.windowIterations = 20;
  options.windowMove = 2e-3;
  options.windowDecrease = 1e-2;
  return options;
}

}  // namespace billow
