// The triangle mesh shared by every stage: a target, a simulation mesh or a panel (z = 0).
#pragma once
#include <Eigen/Dense>
#include <algorithm>
#include <cstdint>

namespace billow {

using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;  // V  #V by 3
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;  // F  #F by 3, 0-based, CCW seen from outside

struct TriMesh {
  Vertices V;
  Triangles F;
  int numVertices() const { return static_cast<int>(V.rows()); }
  int numTriangles() const { return static_cast<int>(F.rows()); }
};

// The key of the undirected edge {a, b} (vertex indices >= 0), for hashing and sorting edges.
inline std::uint64_t edgeKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

// The key of the directed edge a -> b, for hashing.
inline std::uint64_t directedKey(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// The diagonal of the mesh's bounding box: the model size relative tolerances are measured in (0 for no vertices).
inline double boundingDiagonal(const TriMesh& m) {
  return m.V.rows() ? (m.V.colwise().maxCoeff() - m.V.colwise().minCoeff()).norm() : 0.0;
}

inline double triangleArea(const TriMesh& m, int f) {
  const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
  return 0.5 * (b - a).cross(c - a).norm();
}

}  // namespace billow
