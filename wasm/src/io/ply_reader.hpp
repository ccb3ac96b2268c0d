// PLY reader: ascii, binary_little_endian and binary_big_endian. Reads x, y, z of the "vertex" element
// (any scalar type; other vertex properties are skipped) and the "vertex_indices" (or "vertex_index") list
// of the "face" element, splitting polygons into fans. Other elements and properties are skipped.
// Malformed input throws billow::Error naming the header line, the body line (ascii) or byte offset
// (binary), and the element concerned.
#pragma once
#include <string_view>

#include "io/obj_reader.hpp"
#include "mesh/tri_mesh.hpp"

namespace billow {

TriMesh readPly(std::string_view bytes, const MeshReadOptions& options = {});

}  // namespace billow
