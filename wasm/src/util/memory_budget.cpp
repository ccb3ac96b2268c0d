#include "util/memory_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/error.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/heap.h>
#include <malloc.h>
#else
#include <unistd.h>
#endif

namespace billow {
namespace {

constexpr double kKiB = 1024.0;
constexpr double kMiB = 1024.0 * 1024.0;

double log2Size(long long n) { return std::log2(std::max<double>(2.0, static_cast<double>(n))); }

}  // namespace

double inflationBytes(long long triangles) {
  // Measured peaks of `billow inflate` (native RSS, Release, the pattern file's JSON included): 15 MB at
  // 3k, 65 MB at 15k, 155 MB at 30k, 321 MB at 60k triangles. 16 MB + (2.2 + 0.27 log2 n) kB per triangle
  // lies 24-28 % above them from 15k up (the range where the budget matters).
  const double n = static_cast<double>(std::max<long long>(triangles, 0));
  return 16 * kMiB + n * (2.2 + 0.27 * log2Size(triangles)) * kKiB;
}

double optimizationBytes(long long patternTriangles, long long targetTriangles) {
  // Measured peaks of `billow design` on the sphere gores (1,280-triangle target): 14 MB at 1k, 22 MB at
  // 3k, 91 MB at 8k, 196 MB at 15k pattern triangles (the model: 80, 152, 258 MB). The optimizer keeps
  // the inflation's factor and adds the adjoint's, the rest derivatives and the distance queries: about
  // 2.5 times the inflation.
  const double target = static_cast<double>(std::max<long long>(targetTriangles, 0));
  return 2.5 * inflationBytes(patternTriangles) + target * 0.5 * kKiB;
}

double availableBytes() {
#ifdef __EMSCRIPTEN__
  const double max = static_cast<double>(emscripten_get_heap_max());
  const struct mallinfo info = mallinfo();
  return std::max(0.0, max - static_cast<double>(info.uordblks));
#else
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return 1e15;  // unknown: do not refuse
  return static_cast<double>(pages) * static_cast<double>(pageSize);
#endif
}

double bytesInUse() {
#ifdef __EMSCRIPTEN__
  return static_cast<double>(mallinfo().uordblks);
#else
  return 0;
#endif
}

std::string formatBytes(double bytes) {
  char text[32];
  if (bytes >= 1024 * kMiB)
    std::snprintf(text, sizeof text, "%.1f GB", bytes / (1024 * kMiB));
  else
    std::snprintf(text, sizeof text, "%.0f MB", std::ceil(bytes / kMiB));
  return text;
}

std::string budgetDescription(double budgetBytes) {
#ifdef __EMSCRIPTEN__
  return "a browser tab gives Billow about " + formatBytes(budgetBytes);
#else
  return "this computer has " + formatBytes(budgetBytes);
#endif
}

void requireMemory(double needed, double budget, const std::string& what, const std::string& remedy) {
  if (needed <= budget) return;
  throw Error("memory.budget", what + " needs about " + formatBytes(needed) + " of memory, and " +
                                   budgetDescription(budget) + ". " + remedy);
}

}  // namespace billow
