// The triangle mesh shared by every stage: a target, a simulation mesh or a panel (z = 0).
#pragma once
#include <Eigen/Dense>

namespace billow {

using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;  // V  #V by 3
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;    // F  #F by 3, 0-based, CCW seen from outside

struct TriMesh {
  Vertices V;
  Triangles F;
  int numVertices() const { return static_cast<int>(V.rows()); }
  int numTriangles() const { return static_cast<int>(F.rows()); }
};

}  // namespace billow
