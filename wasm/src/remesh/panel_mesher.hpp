// The simulation mesh of a panel (Sec. 5.3 "Remeshing"): resample the boundary to about the target edge
// length h between corners (seam junctions), keeping the same number of points per seam piece on both
// panels of a seam, then fill the interior with well-shaped triangles of size about h (CDT + Delaunay
// refinement that never adds boundary points). barycentricLocate carries inflated and target positions from
// the old panel mesh to the new one.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "remesh/cdt.hpp"

namespace billow {

// Number of segments for a boundary piece of the given length at target edge length h: max(1, round(L / h)).
int segmentCountFor(double length, double h);

// Resamples an open polyline (#P by 2, P >= 2) into exactly `segments` pieces of equal arc length. Returns
// segments + 1 points; the first and last are the polyline's end points exactly. If params is given it
// receives, per output point, its place on the input: i + s for the point at fraction s of edge (i, i + 1).
Points2 resamplePolyline(const Points2& polyline, int segments, Eigen::VectorXd* params = nullptr);

struct ResampledBoundary {
  Points2 points;                     // closed boundary, no repeated closing point, corners kept exactly
  Eigen::VectorXd param;              // per point: place on the input polygon, i + s on edge (i, i + 1 mod n)
  Eigen::VectorXi piece;              // per point: the piece it lies on (piece k runs from corner k to k + 1)
  std::vector<int> cornerRows;        // row of each corner in points (corners sorted by input index)
  std::vector<int> segmentsPerPiece;  // segments on each piece
};

// Splits the closed polygon (#P by 2) at the corners (input vertex indices, any order; none = vertex 0 is
// the only corner) and resamples every piece by arc length to about h. The partner panel across a seam
// must use the same count on its piece (it runs the other way round): pass it to the overload below.
ResampledBoundary resampleBoundary(const Points2& polygon, const std::vector<int>& corners, double h);
// Same, with the number of segments of each piece given (pieces ordered by sorted corner index).
ResampledBoundary resampleBoundary(const Points2& polygon, const std::vector<int>& corners,
                                   const std::vector<int>& segmentsPerPiece);

struct PanelMeshOptions {
  double minAngleDeg = 28;      // refinement quality bound for interior triangles
  double maxEdgeFactor = 1.25;  // interior edges longer than maxEdgeFactor * h are refined
  int smoothingIterations = 4;  // Laplacian smoothing sweeps of interior vertices (only if no angle gets worse)
  int maxSteinerPoints = 2000000;
};

// Meshes the interior of a closed simple polygon (#P by 2, counter-clockwise, e.g. ResampledBoundary::points)
// with triangles of edge length about h, leaving out `holes` (closed polygons inside it, clockwise: a ring
// panel). Returns V (z = 0) whose first rows are exactly the boundary points in order, then each hole's in
// order, then interior points; F counter-clockwise. No point is added on the boundary or the holes.
// Errors: "panel.bad-input" (fewer than 3 points, h <= 0), "panel.clockwise", "panel.repeated-vertex",
// "panel.self-intersecting", "panel.bad-hole".
TriMesh meshPanel(const Points2& boundary, double h, const PanelMeshOptions& options = {},
                  const std::vector<Points2>& holes = {});

// Where a closed polygon (#P by 2) crosses or touches itself: the index i of its first edge (i, i + 1 mod P)
// that meets an edge other than its neighbours, or -1 when it is simple. For saying where a panel that
// meshPanel refuses overlaps itself.
int outlineCrossing(const Points2& polygon);

// Where a point lies on a 2D triangle mesh (z ignored): triangle and barycentric weights (sum 1, mesh
// vertex order). Outside the mesh: the closest point of the closest triangle (inside = false).
struct BarycentricPoint {
  int triangle = -1;
  Eigen::Vector3d weights = Eigen::Vector3d::Zero();
  bool inside = false;
  double distance = 0;  // from the point to the mesh (0 inside)
};

// A uniform grid over the triangles' bounding boxes: about O(1) per query on meshes of even size.
class TriangleLocator {
 public:
  explicit TriangleLocator(const TriMesh& mesh2d);
  BarycentricPoint locate(const Eigen::Vector2d& p) const;

 private:
  BarycentricPoint closestIn(int cell, const Eigen::Vector2d& p, BarycentricPoint best) const;
  const TriMesh& mesh_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<int> start_;  // CSR: triangles of cell c are items_[start_[c] .. start_[c + 1])
  std::vector<int> items_;
};

// One-shot location (builds a TriangleLocator; keep one for many queries).
BarycentricPoint barycentricLocate(const TriMesh& mesh2d, const Eigen::Vector2d& p);

}  // namespace billow
