// Wavefront OBJ reader: vertices and faces only (polygons are split into fans), 1-based and negative
// indices, v/vt/vn corners. Malformed input throws billow::Error naming the line.
#pragma once
#include <string>
#include <string_view>

#include "mesh/tri_mesh.hpp"
#include "util/error.hpp"

namespace billow {

struct MeshReadOptions {
  long long maxVertices = 5'000'000;  // refuse larger inputs with a message instead of exhausting memory
  long long maxTriangles = 10'000'000;
};

TriMesh readObj(std::string_view text, const MeshReadOptions& options = {});

// What every reader throws past options.maxTriangles or maxVertices (format: "OBJ", "STL", "PLY", "OFF"; what:
// "triangles", "vertices", "distinct vertices"), with the file's own count where it is known before reading on (a
// binary STL's header), else -1 (util/text.hpp's tooLargeMessage).
Error meshTooLarge(const std::string& format, const std::string& what, long long limit, long long count = -1);

}  // namespace billow
