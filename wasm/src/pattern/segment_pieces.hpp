// A segment as a mesh of its own, and its boundary as seam pieces (the pattern builder's first stage).
// The cut mesh is glued: a seam vertex is one vertex for every segment around it. A segment is cut open by
// splitting every vertex into its fans of triangles between cut edges, so a slit (a dangling seam inside a
// segment) opens into two boundary pieces and the segment becomes the disk that flattening expects.
// Corners are properties of cut-mesh vertices (seam-graph degree other than 2, a change of seam, or one
// chosen vertex on a corner-free loop), so both panels of a seam split it at the same points.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "segment/segmentation.hpp"

namespace billow {

struct SegmentMesh {
  TriMesh mesh;                // the segment cut open: vertices split at seam edges, CCW triangles
  std::vector<int> vertexCut;  // #mesh.V: the cut-mesh vertex of each vertex
  std::vector<int> faceCut;    // #mesh.F: the cut-mesh triangle of each triangle
};

// The triangles of `segment` as a mesh of their own, opened along its seams.
SegmentMesh extractSegment(const Segmentation& seg, int segment);

// Seam structure of the whole cut mesh, shared by all segments.
struct SeamGraph {
  std::unordered_map<std::uint64_t, int> directedFace;  // directed edge (a, b) -> triangle with edge a -> b
  std::unordered_map<std::uint64_t, int> directedSeam;  // boundary edge a -> b of a segment loop -> seam
  std::vector<char> corner;                             // #cut-mesh V: 1 where boundary pieces start and end
  int seamOf(int a, int b) const;                       // -1 when a -> b is no seam edge
  int neighborSegment(const Segmentation& seg, int a, int b) const;  // segment across a -> b, -1 if none
};

SeamGraph analyzeSeams(const Segmentation& seg);

// A piece of a segment boundary between two corners.
struct BoundaryPiece {
  int start = 0;              // position in the loop of its start corner
  std::vector<int> vertices;  // cut-mesh vertices from the start corner to the end corner
  int seam = -1;
  int neighborSegment = -1;
  double length = 0;  // on the cut mesh [mesh units]
};

// Splits a closed loop of cut-mesh vertices (segment on the left, no repeated closing vertex) at corners.
// A loop with no corner at all is one piece starting at position 0.
std::vector<BoundaryPiece> splitLoop(const Segmentation& seg, const SeamGraph& graph, const std::vector<int>& loop);

}  // namespace billow
