// A coarser copy of a target, for work that needs its shape and not its every triangle (seam suggestions on a scan
// of hundreds of thousands): edges collapsed in the order of the quadric error metric (Garland and Heckbert 1997),
// each collapse made only where the surface stays a manifold of the same topology, no triangle turns over and none
// becomes a needle.
#pragma once
#include "mesh/tri_mesh.hpp"

namespace billow {

// `mesh` with about `triangles` triangles (never fewer; `mesh` itself when it has no more), oriented as it is; its
// boundary, where it has one, and every vertex on an edge that is not shared by exactly two triangles kept in place.
// Stops short of `triangles` where no collapse is left that keeps the surface as it is.
TriMesh simplifiedCopy(const TriMesh& mesh, int triangles);

}  // namespace billow
