// The sewn pattern: flat panels joined by stitches, and the simulation mesh built from it
// (one 3D vertex per group of stitched panel vertices; DESIGN.md "The pipeline, as data").
#pragma once
#include <string>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "simulate/membrane_energy.hpp"

namespace billow {

using PanelVertices = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;  // X  #v by 2 [m]

struct Panel {
  std::string name;
  bool internal = false;  // internal connection: no pressure load, not part of the outer surface
  PanelVertices vertices;
  Triangles triangles;  // #t by 3, counterclockwise in the panel plane = as seen from outside
};

// Panel vertex `vertexA` of panel `panelA` is sewn to `vertexB` of `panelB`. Stitches chain: a corner where
// three panels meet is two stitches.
struct Stitch {
  int panelA = 0, vertexA = 0, panelB = 0, vertexB = 0;
};

struct Material {
  std::string name = "foil";
  double thickness = 25e-6;      // h [m]
  double youngsModulus = 3.0e9;  // E [Pa]
  double density = -1;           // [kg/m^3], negative when unknown (not used by the simulation)
};

struct Pattern {
  std::vector<Panel> panels;
  std::vector<Stitch> stitches;
  Material material;
  double pressure = 1000.0;  // over-pressure p [Pa]
  // Optional start positions, one #v by 3 block per panel (empty when absent). Stitched panel vertices
  // are averaged. The optimizer passes the target shape here.
  std::vector<Vertices> inflated;
};

struct PatternLimits {
  long long maxTriangles = 2'000'000;
  long long maxPanels = 10'000;
};

struct PatternWarning {
  std::string code;  // "pattern.seam-length"
  std::string message;
  double mismatch = 0;  // relative length difference of the sewn edges
};

struct SewnMesh {
  int numVertices = 0;                // simulation vertices
  Triangles triangles;                // #F by 3 simulation vertex indices, outward for outer panels
  std::vector<ElementRest> rest;      // #F rest data (Dm^-1, rest area)
  std::vector<char> outer;            // #F: 1 when the triangle belongs to the outer (pressurized) surface
  std::vector<int> trianglePanel;     // #F panel of each triangle
  std::vector<int> panelVertexStart;  // #panels+1: panel p's vertices are simVertexOf[start[p] ..]
  std::vector<int> simVertexOf;       // panel vertex -> simulation vertex
  std::vector<int> stitchedCount;     // #numVertices: panel vertices merged into each simulation vertex
  double meanEdgeLength = 0;          // rest, over all triangles [m]
  double outerArea = 0;               // rest area of the outer panels [m^2]
  std::vector<PatternWarning> warnings;

  int numTriangles() const { return static_cast<int>(triangles.rows()); }
  int simVertex(int panel, int vertex) const { return simVertexOf[panelVertexStart[panel] + vertex]; }
};

// Validates and sews. Throws billow::Error: pattern.bad-index, pattern.degenerate, pattern.not-boundary,
// pattern.open, pattern.non-manifold, pattern.orientation, pattern.too-large, pattern.empty.
// Sewn edges of different rest length (beyond 1e-3 relative) are reported in SewnMesh::warnings.
SewnMesh sewPattern(const Pattern& pattern, const PatternLimits& limits = {});

// The panel's vertices on its outline (on an edge of one triangle only), ascending.
std::vector<int> outlineVertices(const Panel& panel);

// Triangles of all panels (the size of the simulation mesh a pattern makes).
long long numTriangles(const Pattern& pattern);

// Outer triangles only, as a closed mesh with merged vertices (for OBJ export and the volume).
Triangles outerTriangles(const SewnMesh& mesh);

// Per panel, the positions x (#V by 3, one row per simulation vertex) of its vertices (#v by 3 each): a sewn
// shape as a pattern's "inflated" (stitched copies get the same row).
std::vector<Vertices> panelPositions(const SewnMesh& mesh, const Vertices& x);

}  // namespace billow
