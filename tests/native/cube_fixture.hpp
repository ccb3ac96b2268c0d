// A unit cube small enough to reason about by hand, for the seam, funnel and segmentation tests: every
// expected vertex, crossing and turn angle on it can be worked out on paper.
#pragma once
#include <Eigen/Core>

#include "mesh/tri_mesh.hpp"
#include "seams/surface_point.hpp"

namespace billow::test {

// The cube [0, 1]^3 as 12 outward (counterclockwise from outside) triangles; vertex i is at
// (i & 1, i >> 1 & 1, i >> 2 & 1). The three faces at vertex 0 are split by diagonals from vertex 0, so the six
// triangles around it form a fan of 45-degree corners (270 degrees in all):
//   0: (0,3,1) z = 0, y < x    1: (0,2,3) z = 0, y > x    2: (0,1,5) y = 0, z < x    3: (0,5,4) y = 0, z > x
//   4: (0,4,6) x = 0, z > y    5: (0,6,2) x = 0, y > z    6, 7: x = 1    8, 9: y = 1    10, 11: z = 1
// Around vertex 0 the fan runs 1 -> 5 -> 4 -> 3 -> 2 -> 0 -> 1 across the edges to 2, 6, 4, 5, 1 and 3.
inline TriMesh unitCube() {
  TriMesh m;
  m.V.resize(8, 3);
  for (int i = 0; i < 8; ++i) m.V.row(i) << (i & 1), (i >> 1 & 1), (i >> 2 & 1);
  m.F.resize(12, 3);
  m.F << 0, 3, 1, 0, 2, 3, 0, 1, 5, 0, 5, 4, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 2, 6, 7, 2, 7, 3, 4, 5, 7, 4, 7, 6;
  return m;
}

// The surface point of face f at p (a point of that triangle, in 3D).
inline SurfacePoint pointIn(const TriMesh& m, int f, const Eigen::Vector3d& p) {
  SurfacePoint s;
  s.face = f;
  s.bary = closestPointBarycentric(p, m.V.row(m.F(f, 0)).transpose(), m.V.row(m.F(f, 1)).transpose(),
                                   m.V.row(m.F(f, 2)).transpose());
  return s;
}

}  // namespace billow::test
