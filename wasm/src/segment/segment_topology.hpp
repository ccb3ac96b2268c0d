// Topology of the segments of a cut mesh (internal to segmentation): labels by flood fill across
// non-seam edges, "wedges" (a vertex split per side of the seams through it), Euler characteristic
// and boundary loops of each segment cut open along its seams.
#pragma once
#include <vector>

#include "segment/segmentation.hpp"

namespace billow {

// Fills faceSegment and segments (triangles, area, topology, loops) of out from out.mesh and seamEdge.
void labelSegments(const CutMesh& cut, Segmentation& out);

}  // namespace billow
