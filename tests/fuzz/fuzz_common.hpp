// Shared by the fuzz targets: small limits (no input may make a reader allocate gigabytes) and the rule
// that billow::Error is the expected way to refuse an input while anything else is a finding.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/obj_reader.hpp"
#include "mesh/tri_mesh.hpp"
#include "mesh/validate.hpp"
#include "util/error.hpp"

namespace billow::fuzz {

inline std::string_view view(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

inline MeshReadOptions smallMeshOptions() {
  MeshReadOptions o;
  o.maxVertices = 20'000;
  o.maxTriangles = 40'000;
  return o;
}

// Validates a mesh a reader accepted (the readers' output is what validateTarget receives in the app),
// then checks the report serialises. Any billow::Error is expected.
inline void validateMesh(TriMesh& mesh) {
  ValidationOptions vo;
  vo.maxTriangles = 40'000;
  ValidationReport r = validateTarget(mesh, vo);
  (void)toJson(r);
}

}  // namespace billow::fuzz
