// The target cut along seam curves (paper Sec. 5.2: seams become "sets of edge vectors, defining a
// segmentation of the target mesh"). Curves cross triangles freely; every triangle they touch is
// re-triangulated with the seam pieces, their crossings and T-junctions as edges, so the seam network
// is exactly a set of edges of the cut mesh. Points on an original edge get one vertex shared by both
// triangles, so the cut mesh stays a closed surface.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/mesh_topology.hpp"
#include "seams/seam_curve.hpp"

namespace billow {

struct CutMesh {
  TriMesh mesh;                                     // vertices: the target's first, then seam points
  std::vector<SurfacePoint> vertexOrigin;           // #mesh.V: where each vertex is on the target
  std::vector<int> faceOrigin;                      // #mesh.F: the target triangle each triangle lies in
  std::unordered_map<std::uint64_t, int> seamEdge;  // edgeKey(u, v) -> seam index, for every seam edge
  std::vector<std::vector<int>> seamVertices;       // per seam: the vertices of its points, in order
  struct Crossing {
    int seam;
    Eigen::Vector3d position;
  };
  std::vector<Crossing> selfCrossings;  // a seam crossing or touching itself
  int unrecoveredPieces = 0;            // seam pieces the triangulation could not insert (should stay 0)
};

CutMesh cutAlongSeams(const TriMesh& target, const MeshTopology& topo, const std::vector<SeamCurve>& seams,
                      double tol = kSeamPointTolerance);

}  // namespace billow
