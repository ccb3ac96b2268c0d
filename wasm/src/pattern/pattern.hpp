// The pattern: flat panels joined by stitches, with their material and pressure (DESIGN.md "The pipeline, as
// data"); what the designer cuts, and what the simulator sews (simulate/sewn_pattern.hpp).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.hpp"

namespace billow {

using PanelVertices = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;  // X  #v by 2 [m]

struct Panel {
  std::string name;
  bool internal = false;  // internal connection: no pressure load, not part of the outer surface
  PanelVertices vertices;
  Triangles triangles;  // #t by 3, counterclockwise in the panel plane = as seen from outside
  // Outline vertices where a seam may kink: no seam rod bends through them (simulate/seam_rods.hpp). Absent: the
  // simulator judges by the outline's turn there. The optimizer writes the corners of the flattened panels, so the
  // cut panels inflate with the seam rods the optimized balloon had.
  std::optional<std::vector<int>> seamCorners;
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

// The panel's outline edges (used by exactly one of its triangles), keyed (min, max) -> (from, to) in triangle order.
std::map<std::pair<int, int>, std::pair<int, int>> outlineEdges(const Panel& panel);

// The panel's vertices on its outline (on an edge of one triangle only), ascending.
std::vector<int> outlineVertices(const Panel& panel);

// Triangles of all panels (the size of the simulation mesh a pattern makes).
long long numTriangles(const Pattern& pattern);

}  // namespace billow
