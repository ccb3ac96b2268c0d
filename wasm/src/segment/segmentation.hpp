// Segmentation of the target by the seam network (paper Sec. 3.2 and 5.2): the cut mesh, its segments
// (connected across non-seam edges), their topology (Euler characteristic, boundary loops; a segment must
// be a topological disk to be flattened), the seam graph's junctions, and problems in a designer's words.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/up_axis.hpp"
#include "segment/cut_mesh.hpp"

namespace billow {

struct SegmentationOptions {
  double minSegmentAreaRatio = 1e-3;   // a segment below this share of the target's area is a sliver
  double minSegmentWidthRatio = 5e-3;  // a segment narrower on average than this share of the diagonal is thin
  double minFlatShare = 0.25;  // a disk segment of which a flat panel inside its seam covers less is too big for it
  double tolerance = kSeamPointTolerance;  // barycentric merge tolerance for seam points (cut_mesh.hpp)
  UpAxis up;                               // the problems' places ("near the top left") as the target stands
};

struct BoundaryLoop {
  std::vector<int> vertices;  // cut-mesh vertices, in order (the segment on the left)
  std::vector<int> seams;     // seam of the edge vertices[i] -> vertices[i+1] (wrapping)
};

struct Segment {
  std::vector<int> triangles;  // rows of Segmentation::mesh.F
  double area = 0;
  int eulerCharacteristic = 0;  // V - E + F of the segment cut open along every seam
  int genus = 0;
  bool isDisk = false;  // eulerCharacteristic == 1 with one boundary loop
  std::vector<BoundaryLoop> loops;
  // Where the segment is shown and named ("Segment 3" on the model; its problems are located there): on the
  // surface, in the middle of the segment, as far from its seams as it reaches.
  Eigen::Vector3d labelPoint = Eigen::Vector3d::Zero();
};

struct SeamJunction {
  int vertex = -1;  // cut-mesh vertex
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  int segments = 0;   // distinct segments around it
  int seamEdges = 0;  // seam edges at it: 1 = a dangling end, 3 or more = a junction
};

struct SegmentationProblem {
  std::string code;      // "segment.not-disk", "segment.sliver", "segment.thin", "seam.self-crossing", ...
  std::string severity;  // "error" (cannot be flattened) or "warning"
  std::string message;   // the designer's words
  int segment = -1, seam = -1;
  Eigen::Vector3d location = Eigen::Vector3d::Zero();
};

struct Segmentation {
  TriMesh mesh;                            // the target with every seam piece as edges (closed, glued)
  std::vector<SurfacePoint> vertexOrigin;  // #mesh.V
  std::vector<int> faceOrigin;             // #mesh.F
  std::vector<int> faceSegment;            // #mesh.F
  std::vector<Segment> segments;
  std::vector<SeamJunction> junctions;
  std::vector<std::vector<int>> seamVertices;  // per seam: cut-mesh vertices of its points, in order
  std::vector<SegmentationProblem> problems;
  bool ok() const;  // no problem of severity "error"
  // A place on the target in a designer's words ("near the top left of the shape"), as it stands on
  // SegmentationOptions::up: for the problems of the later stages too.
  std::string where(const Eigen::Vector3d& p) const;
  Eigen::Vector3d boxMin = Eigen::Vector3d::Zero(), boxMax = Eigen::Vector3d::Zero();  // of the target
  UpAxis up;
};

// The length of a segment's boundary loop on the cut mesh `m` (Segmentation::mesh).
double loopLength(const TriMesh& m, const BoundaryLoop& loop);

Segmentation segmentTarget(const TriMesh& target, const MeshTopology& topo, const std::vector<SeamCurve>& seams,
                           const SegmentationOptions& options = {});

}  // namespace billow
