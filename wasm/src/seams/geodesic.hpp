// Approximately shortest paths between two surface points (paper Sec. 3.2: "connects seam points by taking
// an approximately shortest path on the surface"). Method: Dijkstra on the edge graph gives a vertex path;
// the triangles on its left form a corridor; the funnel algorithm (Lee & Preparata 1984) straightens the
// path inside the unfolded corridor; wherever the straightened path wraps a vertex whose angle on the
// other side is below pi, the corridor is moved to that side (the vertex "flip out" of Sharp & Crane 2020,
// "You Can Find Geodesic Paths in Triangle Meshes by Just Flipping Edges") and straightened again. Every
// step shortens the path, and the number of steps is bounded, so a query always ends.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/mesh_topology.hpp"
#include "seams/surface_point.hpp"

namespace billow {

// A point of a path: the end points anywhere, interior points on a mesh edge (edge, t) or a vertex.
struct PathPoint {
  SurfacePoint point;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  int vertex = -1;  // >= 0 when the point is a mesh vertex
  int edge = -1;    // >= 0 when the point is inside a mesh edge
  double t = 0;     // on edge: from E(edge,0) (0) to E(edge,1) (1)
};

struct GeodesicPath {
  std::vector<PathPoint> points;  // from the start to the end
  std::vector<int> faces;         // #points-1: a face containing both ends of each piece
  double length = 0;
  int iterations = 0;  // straightening rounds used
};

struct GeodesicOptions {
  int maxIterations = 64;  // straightening rounds (each reroutes every improvable vertex at once)
};

// Holds the target and its topology (both must outlive the solver); queries are independent and const.
class GeodesicSolver {
 public:
  GeodesicSolver(const TriMesh& mesh, const MeshTopology& topology);
  GeodesicPath path(const SurfacePoint& a, const SurfacePoint& b, const GeodesicOptions& options = {}) const;
  // Length of the shortest path along mesh edges between two vertices (a reference for tests).
  double edgeGraphDistance(int v0, int v1) const;
  const TriMesh& mesh() const { return mesh_; }
  const MeshTopology& topology() const { return topo_; }

 private:
  // Dijkstra from a's face corners to b's face corners (or to onlyVertex alone, when >= 0).
  std::vector<int> vertexPath(const SurfacePoint& a, const SurfacePoint& b, int onlyVertex = -1) const;
  std::vector<int> corridor(const SurfacePoint& a, const SurfacePoint& b) const;
  const TriMesh& mesh_;
  const MeshTopology& topo_;
};

}  // namespace billow
