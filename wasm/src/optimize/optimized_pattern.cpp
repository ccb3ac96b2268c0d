#include "optimize/optimized_pattern.hpp"

namespace billow {

Pattern optimizedPattern(const PatternOptimizer& optimizer) {
  Pattern pattern = optimizer.pattern();
  pattern.inflated = panelPositions(optimizer.mesh(), optimizer.inflated());
  return pattern;
}

}  // namespace billow
