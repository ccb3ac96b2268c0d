// Helpers shared by the native and wasm GoogleTest suites.
#pragma once
#include <string>

#include "io/mesh_file.hpp"
#include "mesh/tri_mesh.hpp"

namespace billow::test {

inline std::string meshPath(const std::string& name) { return std::string(BILLOW_MESH_DIR) + "/" + name; }

inline TriMesh loadShared(const std::string& name) {
  return readMeshBytes(readFileBytes(meshPath(name)), name);
}

}  // namespace billow::test
