// Welding a triangle soup (each triangle stores its own three corners, as STL does) into an indexed mesh.
#pragma once
#include "mesh/tri_mesh.hpp"

namespace billow {

struct WeldOptions {
  // Corners closer than relativeTolerance * (bounding-box diagonal) become one vertex. Exactly equal corners
  // always merge (0.0 and -0.0 are equal); 0 merges only those. Corners with a NaN or infinite coordinate
  // never merge: they are kept as they are for validation to report. 1e-7 is about a single-precision coordinate's
  // rounding (STL files and the app's own positions are single precision), far below any edge of a target.
  double relativeTolerance = 1e-7;
};

// soup has 3 rows per triangle (rows 3t, 3t+1, 3t+2 are the corners of triangle t, in order). Returns the
// same triangles, in the same order, over the merged vertices; vertices keep the order in which they are
// first seen, and each takes the coordinates of its first occurrence. Triangles that collapse (two merged
// corners) are kept for validation to report. Expected O(n log n): a sort, then a hash grid.
TriMesh weld(const Vertices& soup, const WeldOptions& options = {});

}  // namespace billow
