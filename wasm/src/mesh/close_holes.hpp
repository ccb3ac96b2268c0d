// Holes of a designer's mesh closed: a scanned statue open at its base, a model cut off at its neck. Each hole is
// closed by a cap about its rim's edge length, as a pattern maker would close a base with a flat panel; the cap
// lies on the surface the rim spans (flat where the rim is flat).
#pragma once
#include "mesh/tri_mesh.hpp"

namespace billow {

// Closes every hole of an oriented mesh (validateTarget has turned its triangles one way): each boundary loop whose
// vertices it passes once is capped by a membrane over its rim (close_holes.cpp), faced as the mesh's triangles are.
// Every face keeps its index; vertices and faces are appended. A boundary that passes a vertex twice (two holes
// touching) is left open. Returns how many holes it closed.
int closeHoles(TriMesh& mesh);

}  // namespace billow
