// The simulation mesh sewn from a pattern (pattern/pattern.hpp): one 3D vertex per group of stitched panel
// vertices (DESIGN.md "The pipeline, as data").
#pragma once
#include <string>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "pattern/pattern.hpp"
#include "simulate/membrane_energy.hpp"

namespace billow {

struct SewnMesh {
  int numVertices = 0;                // simulation vertices
  Triangles triangles;                // #F by 3 simulation vertex indices, outward for outer panels
  std::vector<ElementRest> rest;      // #F rest data (Dm^-1, rest area)
  std::vector<char> outer;            // #F: 1 when the triangle belongs to the outer (pressurized) surface
  std::vector<int> trianglePanel;     // #F panel of each triangle
  std::vector<int> panelVertexStart;  // #panels+1: panel p's vertices are simVertexOf[start[p] ..]
  std::vector<int> simVertexOf;       // panel vertex -> simulation vertex
  std::vector<int> stitchedCount;     // #numVertices: panel vertices merged into each simulation vertex
  // Per panel vertex (as simVertexOf): 1 at a seam corner, where no seam rod bends through (seam_rods.hpp): one
  // its panel marks (Panel::seamCorners), or, on a panel that marks none, where its outline turns by more than 45
  // degrees at rest (the angles of the panel's triangles there, a panel's own stitched copies together).
  std::vector<char> seamCorner;
  double meanEdgeLength = 0;  // rest, over all triangles [m]
  double outerArea = 0;       // rest area of the outer panels [m^2]
  std::vector<PatternWarning> warnings;

  int numTriangles() const { return static_cast<int>(triangles.rows()); }
  int simVertex(int panel, int vertex) const { return simVertexOf[panelVertexStart[panel] + vertex]; }
};

// Validates and sews. Throws billow::Error: pattern.bad-index, pattern.degenerate, pattern.not-boundary,
// pattern.open, pattern.non-manifold, pattern.orientation, pattern.too-large, pattern.empty.
// Sewn edges of different rest length (beyond 1e-3 relative) are reported in SewnMesh::warnings.
SewnMesh sewPattern(const Pattern& pattern, const PatternLimits& limits = {});

// Panel p's seam corners (its vertices with seamCorner 1), as Panel::seamCorners marks them.
std::vector<int> seamCorners(const SewnMesh& mesh, int panel);

// Sewing makes the panels' meshes one surface; it pinches where an edge inside a panel joins two vertices the
// stitches make one point (an inside vertex beside the end of a slit sewn shut, meshed to both its sides) or is
// sewn onto another edge (three panels' triangles on one edge). sewPattern refuses both; the panel mesher does not
// know the stitches to avoid them. Each such edge is flipped to the other diagonal of its two triangles where they
// form a convex quad and that diagonal is a new edge of the sewn surface. Returns the flips made.
int flipPinchingEdges(Pattern& pattern);

// Outer triangles only, as a closed mesh with merged vertices (for OBJ export and the volume).
Triangles outerTriangles(const SewnMesh& mesh);

// Per panel, the positions x (#V by 3, one row per simulation vertex) of its vertices (#v by 3 each): a sewn
// shape as a pattern's "inflated" (stitched copies get the same row).
std::vector<Vertices> panelPositions(const SewnMesh& mesh, const Vertices& x);

}  // namespace billow
