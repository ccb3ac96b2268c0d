// Wall-clock timings for the reports (inflation, pattern, scene) and the time limits of long runs.
#pragma once
#include <chrono>

namespace billow {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

}  // namespace billow
