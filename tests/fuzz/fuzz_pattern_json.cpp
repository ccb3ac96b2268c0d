// libFuzzer target: readPatternJson (parse, validate, sew) and, for accepted patterns, the write/read round trip.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "io/pattern_json.hpp"

using namespace billow;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  PatternLimits limits;
  limits.maxTriangles = 40'000;
  limits.maxPanels = 200;
  std::vector<PatternWarning> warnings;
  Pattern pattern;
  try {
    pattern = readPatternJson(fuzz::view(data, size), &warnings, limits);
  } catch (const Error&) {
    return 0;
  }
  // What was accepted is written and must read back (a billow::Error here is a finding too).
  const std::string written = writePatternJson(pattern);
  (void)readPatternJson(written, nullptr, limits);
  return 0;
}
