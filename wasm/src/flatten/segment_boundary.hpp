// The boundary of a segment (a disk-topology piece of the target) and what Eq. 14 of Skouras et al. 2014
// measures on it in 3D: boundary edge lengths l_ij and interior angle sums theta_j.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mesh/tri_mesh.hpp"

namespace billow {

// What Eq. 14 preserves, per boundary vertex j of a loop b (edge j runs from b[j] to b[j+1 mod n]).
struct BoundaryTargets {
  Eigen::VectorXd length;  // n: l_j, 3D length of edge j
  Eigen::VectorXd angle;   // n: theta_j, sum of the interior angles of the triangles incident to b[j]
};

// The single boundary loop of a disk-topology segment, in the direction of its triangles' edges, so that
// a panel drawn with CCW triangles has a CCW boundary. Throws billow::Error ("flatten.not-disk",
// "flatten.non-manifold", "flatten.empty", "flatten.loose-vertices") when the segment cannot be unrolled.
std::vector<int> findBoundaryLoop(const TriMesh& segment);

// Every boundary loop of a triangle mesh, each in the direction of its triangles' edges (so a flat mesh with
// CCW triangles has a CCW outline and clockwise holes), in the order of their smallest-indexed start vertex.
// Throws as findBoundaryLoop does for a mesh that is pinched, non-manifold, empty or has loose vertices; a
// closed mesh has none.
std::vector<std::vector<int>> findBoundaryLoops(const TriMesh& mesh);

BoundaryTargets measureBoundary(const TriMesh& segment, const std::vector<int>& loop);

}  // namespace billow
