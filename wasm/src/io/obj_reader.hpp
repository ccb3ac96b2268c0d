// Wavefront OBJ reader: vertices and faces only (polygons are split into fans), 1-based and negative
// indices, v/vt/vn corners. Malformed input throws billow::Error naming the line.
#pragma once
#include <string_view>

#include "mesh/tri_mesh.hpp"

namespace billow {

struct MeshReadOptions {
  long long maxVertices = 5'000'000;   // refuse larger inputs with a message instead of exhausting memory
  long long maxTriangles = 10'000'000;
};

TriMesh readObj(std::string_view text, const MeshReadOptions& options = {});

}  // namespace billow
