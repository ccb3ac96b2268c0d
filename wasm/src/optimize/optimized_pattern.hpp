// The optimizer's current state as a pattern: what the app shows and saves, and what the CLI inflates last.
#pragma once
#include "optimize/pattern_optimizer.hpp"

namespace billow {

// The panels and stitches of the last accepted iterate (remeshing may have made new ones), with "inflated"
// their current inflated shape per panel, so an inflation started from it begins in balance.
Pattern optimizedPattern(const PatternOptimizer& optimizer);

}  // namespace billow
