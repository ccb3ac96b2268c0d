// libFuzzer target: the OFF reader (direct and through readMeshBytes), then validateTarget on what it read.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_common.hpp"
#include "io/mesh_file.hpp"
#include "io/off_reader.hpp"

using namespace billow;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text = fuzz::view(data, size);
  TriMesh mesh;
  try {
    mesh = readOff(text, fuzz::smallMeshOptions());
  } catch (const Error&) {
    return 0;  // refused with a message: expected
  }
  // readMeshBytes must accept it too: the same triangles, over the file's vertices welded (as many or fewer).
  TriMesh again = readMeshBytes(text, "file.off", fuzz::smallMeshOptions());
  if (again.F.rows() != mesh.F.rows() || again.V.rows() > mesh.V.rows()) __builtin_trap();
  try {
    fuzz::validateMesh(mesh);
  } catch (const Error&) {
  }
  return 0;
}
