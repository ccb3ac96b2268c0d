// Cuts that open a segment that is not a disk, as a designer answers the segmentation's "add a seam from one loop to
// the other" and "add a seam across it": paths through the segment that join its seam loops (a tube, a part with
// holes), and a loop around a handle (a skull's cheek arch, a mug's handle), whose two sides then bound the segment as
// two more loops for the cuts to join.
#pragma once
#include <vector>

#include "segment/segmentation.hpp"

namespace billow {

// Paths through the inside of `segment` (on Segmentation::mesh) that join all its seam loops: loops - 1 of them, each
// the shortest between two loops not yet joined (two between the same loops would cut a piece off between them).
// Each is cut-mesh vertices from a vertex of one loop to a vertex of another.
std::vector<std::vector<int>> cutsJoiningLoops(const Segmentation& segmentation, int segment);

// The shortest loop found through the inside of `segment` (on Segmentation::mesh, off its seams) that does not
// separate it: of Erickson and Whittlesey's greedy system of loops (2005) from `roots` roots spread over the segment,
// the shortest. Cut-mesh vertices in order, the first not repeated at the end; empty when the segment has no handle
// or every such loop would touch its seams.
std::vector<int> loopAroundHandle(const Segmentation& segmentation, int segment, int roots = 8);

}  // namespace billow
