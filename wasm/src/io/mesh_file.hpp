// Reading a target mesh from a file's bytes, by its name's extension (OBJ, STL, PLY, OFF): the one reader of mesh files, for
// the command line and the app alike.
#pragma once
#include <string>
#include <string_view>

#include "io/obj_reader.hpp"

namespace billow {

// Reads the whole file; throws billow::Error("io.cannot-read") with the path when it cannot.
std::string readFileBytes(const std::string& path, size_t maxBytes = size_t{1} << 30);

// Parses bytes named `fileName` (its extension picks the format); corners at one place become one vertex
// (mesh/weld.hpp).
TriMesh readMeshBytes(std::string_view bytes, const std::string& fileName, const MeshReadOptions& options = {});

}  // namespace billow
