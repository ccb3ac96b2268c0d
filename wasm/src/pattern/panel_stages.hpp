// The per-panel stages of the pattern builder (internal to pattern/): a flattened segment with its boundary
// pieces, and its simulation mesh with the target position of every vertex.
#pragma once
#include <vector>

#include "flatten/flatten.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/segment_pieces.hpp"
#include "util/error.hpp"

namespace billow {

struct FlatSegment {
  int segment = -1;
  SegmentMesh sub;                    // the segment opened along its seams (3D, cut-mesh units)
  FlattenResult flat;                 // uv of sub's vertices, boundary loop CCW
  std::vector<BoundaryPiece> pieces;  // of the loop flat.boundary mapped to cut-mesh vertices; start = position
  std::vector<int> segments;          // per piece: N, the same as on its partner piece
};

// Cuts out and flattens one disk segment; throws billow::Error when flattening fails.
FlatSegment flattenForPattern(const Segmentation& seg, const SeamGraph& graph, int segment,
                              const FlattenOptions& options = {});

// Resamples the flattened boundary with flat.segments per piece, meshes the interior at edge length h, and
// locates every vertex on the target. Fills panel (vertices, triangles) and built (all but pieces'
// neighbours). Throws billow::Error (remesh codes) when the resampled outline is not a simple polygon.
void meshFlatSegment(const TriMesh& target, const Segmentation& seg, const FlatSegment& fs, double h, Panel& panel,
                     BuiltPanel& built);

// The point of cut-mesh triangle t with weights w, as a surface point of the target.
SurfacePoint targetPointOf(const TriMesh& target, const Segmentation& seg, int t, const Eigen::Vector3d& w);

// The problem of a flattened segment the panel mesher refused (e: its error). An outline that overlaps itself
// in the plane (a long curling part laid flat runs into itself) is placed where it first meets itself.
SegmentationProblem meshProblem(const Segmentation& seg, const FlatSegment& fs, const Error& e);

}  // namespace billow
