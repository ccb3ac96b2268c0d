// Object File Format (OFF, Geomview's; libigl's, CGAL's and the shape benchmarks' meshes come in it) reader, as text:
// an optional header (OFF, COFF, NOFF, CNOFF, STOFF...), the vertex, face and edge counts, one vertex per line (x y z;
// normals, colours or texture coordinates after them are skipped), one face per line (its vertex count, then 0-based
// indices; a colour after them is skipped), split into fans. '#' starts a comment. Malformed input throws
// billow::Error naming the line; binary and 4D OFF are refused with what to do instead.
#pragma once
#include <string_view>

#include "io/obj_reader.hpp"
#include "mesh/tri_mesh.hpp"

namespace billow {

TriMesh readOff(std::string_view text, const MeshReadOptions& options = {});

}  // namespace billow
