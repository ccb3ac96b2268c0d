// libFuzzer target: readDesignJson, strict and lenient; accepted documents are written and read back,
// and an inline target is validated as the app would.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "io/design_json.hpp"

using namespace billow;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text = fuzz::view(data, size);
  for (bool strict : {true, false}) {
    DesignReadOptions options;
    options.strict = strict;
    std::vector<DesignWarning> warnings;
    Design design;
    try {
      design = readDesignJson(text, options, &warnings);
    } catch (const Error&) {
      continue;
    }
    const std::string written = writeDesignJson(design);
    (void)readDesignJson(written, options, nullptr);
    if (design.target.kind == DesignTarget::Inline && design.target.mesh.F.rows() <= 40'000) {
      try {
        fuzz::validateMesh(design.target.mesh);
      } catch (const Error&) {
      }
    }
  }
  return 0;
}
