// The pattern builder (Skouras et al. 2014, Sec. 5.2 and 5.3): turns a segmentation of the target into a
// sewn pattern ready for simulation and optimization.
//   1. every disk segment is cut out of the cut mesh and flattened (Eq. 14, then a Laplacian interior);
//   2. its boundary is split into pieces at corners (seam junctions, seam ends, changes of the neighbouring
//      segment); each piece is shared with exactly one piece of another panel (or of the same panel across a
//      slit) and both are resampled by 2D arc length with the SAME number of segments,
//      N = max(1, round(L / h)), L the piece's length on the target;
//   3. the interior is meshed at edge length h (meshPanel);
//   4. sample k of a piece is stitched to sample N - k of its partner (the two run in opposite directions);
//      corners shared by three or more panels are chained;
//   5. every panel vertex gets its position on the target (barycentric location in the flattened segment,
//      evaluated on the 3D segment): the "inflated" start of the pattern and, for seam vertices, s_j of
//      Eq. 10 (with the seam id);
//   6. every internal connection (Sec. 3.2, Fig. 2) becomes an internal panel: the ruled surface between
//      its two seams, laid flat and sewn to the outer panels' samples along both seams (internal_panels.hpp).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "segment/segmentation.hpp"
#include "simulate/sewn_pattern.hpp"
#include "util/error.hpp"

namespace billow {

// An internal connection (Sec. 3.2): an internal panel spanning seam `seamA` and seam `seamB`.
struct InternalConnection {
  int seamA = -1, seamB = -1;  // seam ids (Segmentation::seamVertices index = the design's seam order)
};

struct PatternBuildOptions {
  // Target edge length h [m] of the simulation mesh. 0: derived from `triangles`.
  double edgeLength = 0;
  // Wanted total triangle count when edgeLength is 0 (met within about 10 %): h is chosen from the total
  // area of the flattened panels, see patternEdgeLength. 3000 gives ~3k triangles on any target (h ~ 1.8 cm
  // on a 0.5 m sphere cut in two).
  int triangles = 3000;
  Material material;                            // foil: 25 um, E = 3 GPa
  double pressure = 1000.0;                     // [Pa]
  std::vector<InternalConnection> connections;  // one internal panel each
  std::vector<std::string> seamNames;           // for problems ("seam 3" when missing or empty)
};

// A boundary piece of a panel: consecutive boundary rows from one corner to the next (wrapping).
struct PanelPiece {
  std::vector<int> rows;     // panel vertex ids, from the start corner to the end corner (N + 1 of them)
  int seam = -1;             // the seam it lies on
  int neighborPanel = -1;    // the panel on the other side (-1: none, e.g. a segment that was not built)
  int neighborPiece = -1;    // its piece there; rows run in the opposite direction
  int neighborSegment = -1;  // the segment on the other side
  double targetLength = 0;   // L: its length on the target [m]
};

// What the optimizer needs per panel, beside the pattern's own panel.
struct BuiltPanel {
  int segment = -1;                       // Segmentation::segments index; -1 for an internal panel
  int connection = -1;                    // internal panel: PatternBuildOptions::connections index
  int boundaryVertices = 0;               // the first rows of the panel are its boundary, CCW
  Vertices targetPosition;                // #v by 3: the panel vertex on the (scaled) target [m]
  std::vector<SurfacePoint> targetPoint;  // #v: the same point on the original target (face, bary); face -1
                                          // inside an internal panel (its points are not on the target)
  std::vector<int> seam;                  // #v: seam of a boundary vertex (outgoing piece at corners), -1 inside
  std::vector<char> corner;               // #v: 1 at corners
  std::vector<PanelPiece> pieces;
  double flattenAreaRatio = 0;  // flattened / 3D area of the segment (Eq. 14 keeps lengths, not area)
  std::string interior;         // how the flattening placed the interior ("ruled" for an internal panel)
};

struct PatternFigures {
  int panels = 0, triangles = 0, vertices = 0, stitches = 0;
  int internalPanels = 0;              // of `panels`
  double edgeLength = 0;               // h used [m]
  double maxSeamLengthMismatch = 0;    // max over piece pairs |L_a - L_b| / mean, panel lengths (2D)
  double maxEdgeLengthMismatch = 0;    // max over stitched edge pairs, relative
  double maxStitchTargetDistance = 0;  // max 3D distance between the target positions of stitched vertices [m]
  double flattenMs = 0, meshMs = 0, totalMs = 0;
};

struct BuiltPattern {
  Pattern pattern;                            // panels, stitches, material, pressure; inflated = target positions
  std::vector<BuiltPanel> panels;             // parallel to pattern.panels
  std::vector<int> segmentPanel;              // per segment: its panel, or -1 when it was not built
  std::vector<int> connectionPanel;           // per internal connection: its panel, or -1 when it was not built
  std::vector<SegmentationProblem> problems;  // segments and connections that could not be built, designer's words
  PatternFigures figures;
  bool ok() const;  // every segment and connection built (no problem of severity "error")
};

// target: the target (in meters) that `segmentation` was computed on (its faces give targetPoint).
// Never throws for a bad segment: such a segment becomes a problem and its neighbours keep open pieces. A
// connection that cannot be built (a seam that does not exist, the same seam twice, seams that cross or do not
// face each other across the inside) is a problem of severity "error" too; the other panels are still built.
BuiltPattern buildPattern(const TriMesh& target, const Segmentation& segmentation,
                          const PatternBuildOptions& options = {});

// The problem of built panels that cannot be sewn (e: sewPattern's), placed at the panel vertex it names.
SegmentationProblem sewingProblem(const BuiltPattern& built, const Segmentation& seg, const Error& e);

// Stitches every sample k of each piece to sample N - k of its partner (chains where three or more panel
// vertices are one point), replacing the pattern's stitches; the mismatch figures are measured again.
void stitchBuiltPattern(BuiltPattern& built);

// Segments per seam curve (the pieces sewn as one, which share N), from a first count each, raised so the sewn
// seams make a simple graph: a closed curve (its two ends one point) gets 3 edges at least, and curves of one edge
// between the same two points get 2 (two such edges would be sewn into one edge with four triangles, a pinch; a
// panel of one or two pieces is the case inside one panel). ends[c]: the sewn points curve c runs between.
void keepSewnSeamsSimple(std::vector<int>& counts, const std::vector<std::array<int, 2>>& ends);

// h: options.edgeLength, else from the wanted triangle count over the total panel area [m^2]:
// h = sqrt((4/3) 4 A / (sqrt(3) triangles)) (the refined meshes hold ~4/3 as many triangles as equilateral ones).
double patternEdgeLength(double panelArea, const PatternBuildOptions& options);

}  // namespace billow
