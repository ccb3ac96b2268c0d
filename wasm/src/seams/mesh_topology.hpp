// Edge connectivity of a closed, oriented target, and where a SurfacePoint sits (vertex, edge or face).
// Geodesics walk triangle strips over it and segmentation uses it to give a point on an edge one
// identity in both triangles that share the edge.
#pragma once
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/surface_point.hpp"

namespace billow {

struct MeshTopology {
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> E;          // #E by 2, E(e,0) < E(e,1)
  Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> faceEdges;  // #F by 3, edge from corner k to k+1
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> edgeFaces;  // #E by 2, the two faces of an edge
  std::vector<std::vector<std::pair<int, int>>> neighbors;           // per vertex: (other vertex, edge)
  std::vector<int> vertexFace;                                       // one face per vertex
  std::vector<double> angleSum;                                      // per vertex: sum of corner angles

  int numEdges() const { return static_cast<int>(E.rows()); }
  int edgeBetween(int a, int b) const;                    // -1 when a and b are not adjacent
  int cornerOf(const TriMesh& mesh, int f, int v) const;  // k with F(f,k) == v, or -1
  // The next face around vertex v from face f: dir = +1 crosses the edge from v to its successor in f,
  // dir = -1 the edge from its predecessor to v.
  int rotate(const TriMesh& mesh, int f, int v, int dir) const;
};

// Throws billow::Error("seams.not-closed") when an edge does not have exactly two faces.
MeshTopology buildTopology(const TriMesh& mesh);

// Where a surface point is, up to a tolerance on the barycentric weights.
struct SurfaceLocation {
  enum Kind { Vertex, Edge, Face } kind = Face;
  int vertex = -1;  // Vertex
  int edge = -1;    // Edge
  double t = 0;     // Edge: position from E(edge,0) (t = 0) to E(edge,1) (t = 1)
  int face = -1;    // Face (and the face the point was given in)
};
SurfaceLocation locate(const TriMesh& mesh, const MeshTopology& topo, const SurfacePoint& p, double tol = 1e-9);

// The same point expressed in face f, when it lies on f's closure (false otherwise).
bool expressInFace(const TriMesh& mesh, const MeshTopology& topo, const SurfacePoint& p, int f, SurfacePoint& out,
                   double tol = 1e-9);

SurfacePoint vertexPoint(const TriMesh& mesh, const MeshTopology& topo, int v);
SurfacePoint edgePoint(const TriMesh& mesh, const MeshTopology& topo, int e, double t);

}  // namespace billow
