// A coarser copy of a target, for work that needs its shape and not its every triangle (seam suggestions on a scan
// of hundreds of thousands): edges collapsed in the order of the quadric error metric (Garland and Heckbert 1997),
// each collapse made only where the surface stays a manifold of the same topology, no triangle turns over and none
// becomes a needle.
#pragma once
#include <optional>

#include "mesh/tri_mesh.hpp"

namespace billow {

// `mesh` with about `triangles` triangles (never fewer; `mesh` itself when it has no more), oriented as it is; its
// boundary, where it has one, and every vertex on an edge that is not shared by exactly two triangles kept in place.
// Stops short of `triangles` where no collapse is left that keeps the surface as it is.
TriMesh simplifiedCopy(const TriMesh& mesh, int triangles);

// A fine target (a scan or a download, 50,000 to 500,000 triangles) is worked on as a copy simplified to this many
// triangles where it has more than twice as many: the seam suggestion lays, looks at and optimizes its layouts there,
// and the pattern optimizer measures E_target and E_cover there. The copy lies within about 0.1 % of the target's
// diagonal of it, 0.02-0.04 % RMS (bench/README.md "Suggested seam layouts", "The target's resolution").
constexpr int kWorkingTargetTriangles = 10000;

// `target`'s working copy (simplifiedCopy to kWorkingTargetTriangles); nothing where it is not finer than twice that.
std::optional<TriMesh> workingCopy(const TriMesh& target);

}  // namespace billow
