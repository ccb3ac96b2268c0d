// A mesh the JS layer (web/src/worker/solver-api.js) put on the wasm heap: positions #V*3 doubles, indices #F*3 int32.
#pragma once
#include <cstdint>

#include "mesh/tri_mesh.hpp"

namespace billow::bindings {

inline TriMesh meshFromHeap(uintptr_t positions, int numVertices, uintptr_t indices, int numTriangles) {
  TriMesh mesh;
  mesh.V = Eigen::Map<const Vertices>(reinterpret_cast<const double*>(positions), numVertices, 3);
  mesh.F = Eigen::Map<const Triangles>(reinterpret_cast<const int*>(indices), numTriangles, 3);
  return mesh;
}

}  // namespace billow::bindings
