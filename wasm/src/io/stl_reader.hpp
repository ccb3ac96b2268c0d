// STL reader, binary and ASCII. A binary file is recognised by its size (84 + 50 bytes per triangle),
// even when its header begins with "solid"; otherwise a file beginning with "solid" is read as ASCII.
// STL stores every triangle's corners separately: readStl welds them (see mesh/weld.hpp).
// NaN and infinite coordinates are read as they are, for validation to report. Malformed input throws
// billow::Error naming the line (ASCII) or the byte offset and triangle (binary).
#pragma once
#include <string_view>

#include "io/obj_reader.hpp"
#include "mesh/tri_mesh.hpp"
#include "mesh/weld.hpp"

namespace billow {

// The corners as stored: 3 rows per triangle. Refuses more than options.maxTriangles triangles.
Vertices readStlSoup(std::string_view bytes, const MeshReadOptions& options = {});

// The welded mesh. Refuses more than options.maxTriangles triangles or, after welding, options.maxVertices.
TriMesh readStl(std::string_view bytes, const MeshReadOptions& options = {}, const WeldOptions& weldOptions = {});

}  // namespace billow
