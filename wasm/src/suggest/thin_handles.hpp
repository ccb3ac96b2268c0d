// Thin handles of a target: a boot's lace loops, a chain's links, a jug's wire handle. Each is a handle the surface
// cannot be cut into flat panels without a seam around it, and a tube so thin that no panel can follow it: seamed, it
// would be a sleeve a few of the panels' edges around. The designer can have them cut through instead: each handle's
// tube is cut where it is thinnest and both ends are closed, so the shape keeps its other handles and every face.
#pragma once
#include <vector>

#include "mesh/tri_mesh.hpp"

namespace billow {

// A handle's tube narrower than this share of the target's bounding-box diagonal around is thin: a boot's lace
// loops measure 3-9 % of it, a skull's cheek arches 22 % and 36 %, a torus's tube 44 %.
inline constexpr double kThinHandleLoopRatio = 0.1;

struct ThinHandle {
  std::vector<int> loop;  // the target's vertices around the tube where it is thinnest, in order
  double length = 0;      // the loop's length [mesh units]
};

// The thin handles of a closed, oriented target, the thinnest first: one loop around each of its handles that is
// shorter than maxLengthRatio of its diagonal (the greedy system of loops of loopsAroundHandles, segment_cuts.hpp,
// vertex-disjoint). None on a target of genus 0.
std::vector<ThinHandle> thinHandles(const TriMesh& target, double maxLengthRatio = kThinHandleLoopRatio);

// Cuts the target through each handle's loop and closes both ends with a fan of triangles around a new vertex in
// their middle; each end is drawn back by 0.3 of its next ring of edges so the two do not touch. Every face of the
// target keeps its index (its corners on one side of a cut move to new vertices), so seams drawn on it stay where
// they were; vertices and faces are appended. Each loop cut lowers the genus by one.
void cutThinHandles(TriMesh& target, const std::vector<ThinHandle>& handles);

}  // namespace billow
