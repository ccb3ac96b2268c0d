// Boundary loop and 3D measurements of a segment for the initial flattening (paper Sec. 5.2, Eq. 14).
#include "flatten/segment_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "util/error.hpp"

namespace billow {
namespace {

using Key = std::int64_t;
Key directedEdgeKey(int i, int j, int n) { return static_cast<Key>(i) * n + j; }

[[noreturn]] void notDisk(const std::string& why) {
  throw Error("flatten.not-disk", "this segment is not a disk: " + why + "; add seams so that it can be unrolled flat");
}

void checkIndicesAndUse(const TriMesh& m) {
  if (m.numTriangles() == 0) throw Error("flatten.empty", "this segment has no triangles: there is nothing to flatten");
  std::vector<char> used(m.numVertices(), 0);
  for (int t = 0; t < m.numTriangles(); ++t)
    for (int c = 0; c < 3; ++c) {
      const int v = m.F(t, c);
      if (v < 0 || v >= m.numVertices())
        throw Error("flatten.non-manifold",
                    "this segment refers to a point that does not exist (triangle " + std::to_string(t) + ")");
      used[v] = 1;
    }
  const auto loose = std::count(used.begin(), used.end(), 0);
  if (loose > 0)
    throw Error("flatten.loose-vertices", "this segment has " + std::to_string(loose) +
                                              " points that belong to no triangle; they cannot be placed on a panel");
}

// Sorted directed edges; a repeated one means an edge shared by more than two triangles or two
// neighbours that disagree on which side is outside.
std::vector<Key> sortedDirectedEdges(const TriMesh& m) {
  const int n = m.numVertices();
  std::vector<Key> e;
  e.reserve(3 * m.numTriangles());
  for (int t = 0; t < m.numTriangles(); ++t)
    for (int c = 0; c < 3; ++c) e.push_back(directedEdgeKey(m.F(t, c), m.F(t, (c + 1) % 3), n));
  std::sort(e.begin(), e.end());
  if (std::adjacent_find(e.begin(), e.end()) != e.end())
    throw Error("flatten.non-manifold",
                "this segment is not a clean surface: an edge is shared by more than two triangles, or two "
                "neighbouring triangles disagree on which side is outside");
  return e;
}

}  // namespace

std::vector<std::vector<int>> findBoundaryLoops(const TriMesh& mesh) {
  checkIndicesAndUse(mesh);
  const int n = mesh.numVertices();
  const std::vector<Key> edges = sortedDirectedEdges(mesh);
  // A boundary half-edge i->j has no twin j->i; next[i] = j walks the boundary with the surface on the left.
  std::vector<int> next(n, -1);
  for (Key k : edges) {
    const int i = static_cast<int>(k / n), j = static_cast<int>(k % n);
    if (std::binary_search(edges.begin(), edges.end(), directedEdgeKey(j, i, n))) continue;
    if (next[i] >= 0)
      throw Error("flatten.non-manifold", "this segment is pinched: two of its borders touch at a single point");
    next[i] = j;
  }
  std::vector<std::vector<int>> loops;
  std::vector<char> seen(n, 0);
  for (int s = 0; s < n; ++s) {
    if (next[s] < 0 || seen[s]) continue;
    std::vector<int> loop;
    for (int v = s; !seen[v]; v = next[v]) seen[v] = 1, loop.push_back(v);
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<int> findBoundaryLoop(const TriMesh& segment) {
  std::vector<std::vector<int>> loops = findBoundaryLoops(segment);
  if (loops.empty()) notDisk("it is closed (it has no boundary)");
  if (loops.size() > 1) notDisk("it has " + std::to_string(loops.size()) + " boundary loops");
  // Euler characteristic V - E + F of a disk is 1; anything else means handles or extra pieces.
  const long long boundaryEdges = static_cast<long long>(loops[0].size());
  const long long numEdges = (3LL * segment.numTriangles() + boundaryEdges) / 2;
  const long long chi = segment.numVertices() - numEdges + segment.numTriangles();
  if (chi != 1) notDisk("it has handles or several pieces (Euler characteristic " + std::to_string(chi) + ")");
  return std::move(loops[0]);
}

BoundaryTargets measureBoundary(const TriMesh& segment, const std::vector<int>& loop) {
  const int nb = static_cast<int>(loop.size());
  std::vector<int> slot(segment.numVertices(), -1);
  for (int j = 0; j < nb; ++j) slot[loop[j]] = j;
  BoundaryTargets t;
  t.length.resize(nb);
  t.angle = Eigen::VectorXd::Zero(nb);
  for (int j = 0; j < nb; ++j) t.length[j] = (segment.V.row(loop[(j + 1) % nb]) - segment.V.row(loop[j])).norm();
  for (int f = 0; f < segment.numTriangles(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int v = segment.F(f, c);
      if (slot[v] < 0) continue;
      const Eigen::Vector3d a = segment.V.row(segment.F(f, (c + 1) % 3)) - segment.V.row(v);
      const Eigen::Vector3d b = segment.V.row(segment.F(f, (c + 2) % 3)) - segment.V.row(v);
      t.angle[slot[v]] += std::atan2(a.cross(b).norm(), a.dot(b));
    }
  return t;
}

}  // namespace billow
