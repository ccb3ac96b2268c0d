// Writing a triangle mesh as Wavefront OBJ text (v and f lines, 1-based), e.g. the inflated shape.
#pragma once
#include <string>

#include "mesh/tri_mesh.hpp"

namespace billow {

std::string writeObj(const Vertices& V, const Triangles& F, const std::string& comment = "");

}  // namespace billow
