// A target's creases (a box's edges, a drum's rims, an extruded letter's outlines), for layouts that seam along them,
// as a pattern maker chalks a cushion's or a gusseted letter's (issue 27): an inflated panel is round everywhere but
// along its seams, so a sharp fold of the target is followed only by a seam in it.
//
// A crease is a chain of mesh edges across which the surface turns by kCreaseTurn or more while it is smooth on either
// side, or the middle row of a bevel that turns as much over a few rows of edges (a modeller's rounded edge). Only the
// chains that close on themselves or end on other creases are kept (a crease that fades into a smooth surface would be
// a slit in a panel), and of those only the ones long enough to be a designer's fold.
#pragma once
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/mesh_topology.hpp"
#include "seams/plane_section.hpp"

namespace billow {

// The least turn of the surface across a crease's edges [rad] (40 degrees; a box's edges turn 90). An organic mesh of
// a few thousand triangles turns that much at a few hundred edges too (the bunny at 278 of 9,897), but as much at the
// edges beside them: kSmoothBeside (creases.cpp) tells those apart.
constexpr double kCreaseTurn = 0.698;

struct Crease {
  // Its target vertices in order. Closed: the last joins the first. Open: from one junction (where three creases or
  // more meet: a box's corner) to another, both ends junctions.
  std::vector<int> vertices;
  bool closed = false;
  double length = 0;  // [target units]
};

// A set of creases, longest first, and how many panels seams along all of them make (the regions they bound).
struct Creases {
  std::vector<Crease> creases;
  int panels = 1;
};
// The target's creases, then fewer of them (the shortest left out one at a time, as a designer would leave out a star
// prism's short creases across its side for one gusset strip), panels fewer with each; empty where it has none. With a
// mirror plane {p[axis] = mid}, of creases as short the one farthest from it is left out first (its twin next), so the
// sets after each pair are their own mirror image and those the plane runs through stay longest.
std::vector<Creases> findCreases(const TriMesh& target, int axis = -1, double mid = 0);

// Whether the creases are their own mirror image across the plane {p[axis] = mid}: each of their vertices reflected
// lies within `tolerance` [target units] of one of them.
bool mirrorSymmetric(const TriMesh& target, const std::vector<Crease>& creases, int axis, double mid, double tolerance);

// The mesh edges along the crease, in order (a closed one's last from its last vertex back to its first).
std::vector<int> creaseEdges(const MeshTopology& topology, const Crease& crease);

// The crease as a loop (closed, or open from a junction round to itself, without its last point) or a path (open) of
// section points, each in a face that holds the edge to the point before it, as plane sections walk
// (seams/plane_section.hpp).
SectionLoop creasePath(const TriMesh& target, const MeshTopology& topology, const Crease& crease);

}  // namespace billow
