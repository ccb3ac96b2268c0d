#include "pattern/segment_pieces.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_set>

#include "util/union_find.hpp"

namespace billow {

SegmentMesh extractSegment(const Segmentation& seg, int segment) {
  const Segment& s = seg.segments[segment];
  const Triangles& F = seg.mesh.F;
  const int nt = static_cast<int>(s.triangles.size());
  // Cut edges of this segment: every edge of its loops (a slit's edges appear twice, once per side).
  std::unordered_set<std::uint64_t> cut;
  for (const BoundaryLoop& l : s.loops)
    for (size_t i = 0; i < l.vertices.size(); ++i)
      cut.insert(edgeKey(l.vertices[i], l.vertices[(i + 1) % l.vertices.size()]));
  // Triangle corners 3t + k are joined across every uncut edge shared by two triangles of the segment.
  std::unordered_map<std::uint64_t, std::pair<int, int>> open;  // undirected edge -> (t, k) seen first
  UnionFind corners(3 * nt);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = F(s.triangles[t], k), b = F(s.triangles[t], (k + 1) % 3);
      const std::uint64_t key = edgeKey(a, b);
      if (cut.count(key)) continue;
      const auto it = open.find(key);
      if (it == open.end()) {
        open.emplace(key, std::make_pair(t, k));
        continue;
      }
      const auto [t2, k2] = it->second;  // runs b -> a in t2: corner k2 is b, k2 + 1 is a
      corners.unite(3 * t + k, 3 * t2 + (k2 + 1) % 3);
      corners.unite(3 * t + (k + 1) % 3, 3 * t2 + k2);
      open.erase(it);
    }
  SegmentMesh out;
  out.mesh.F.resize(nt, 3);
  std::vector<int> local(3 * nt, -1);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int r = corners.find(3 * t + k);
      if (local[r] < 0) {
        local[r] = static_cast<int>(out.vertexCut.size());
        out.vertexCut.push_back(F(s.triangles[t], k));
      }
      out.mesh.F(t, k) = local[r];
    }
  out.mesh.V.resize(static_cast<Eigen::Index>(out.vertexCut.size()), 3);
  for (size_t v = 0; v < out.vertexCut.size(); ++v) out.mesh.V.row(v) = seg.mesh.V.row(out.vertexCut[v]);
  out.faceCut = s.triangles;
  return out;
}

int SeamGraph::seamOf(int a, int b) const {
  auto it = directedSeam.find(directedKey(a, b));
  if (it == directedSeam.end()) it = directedSeam.find(directedKey(b, a));
  return it == directedSeam.end() ? -1 : it->second;
}

int SeamGraph::neighborSegment(const Segmentation& seg, int a, int b) const {
  const auto it = directedFace.find(directedKey(b, a));
  return it == directedFace.end() ? -1 : seg.faceSegment[it->second];
}

SeamGraph analyzeSeams(const Segmentation& seg) {
  SeamGraph g;
  const Triangles& F = seg.mesh.F;
  g.directedFace.reserve(3 * F.rows());
  for (int t = 0; t < F.rows(); ++t)
    for (int k = 0; k < 3; ++k) g.directedFace[directedKey(F(t, k), F(t, (k + 1) % 3))] = t;
  for (const Segment& s : seg.segments)
    for (const BoundaryLoop& l : s.loops)
      for (size_t i = 0; i < l.vertices.size(); ++i)
        g.directedSeam[directedKey(l.vertices[i], l.vertices[(i + 1) % l.vertices.size()])] =
            i < l.seams.size() ? l.seams[i] : -1;
  // Seam edges around each vertex (undirected, once each) and their seams.
  std::unordered_set<std::uint64_t> seen;
  std::vector<std::vector<int>> seamsAt(seg.mesh.numVertices());
  for (const auto& [key, seam] : g.directedSeam) {
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    if (!seen.insert(edgeKey(a, b)).second) continue;
    seamsAt[a].push_back(seam);
    seamsAt[b].push_back(seam);
  }
  g.corner.assign(seg.mesh.numVertices(), 0);
  for (int v = 0; v < seg.mesh.numVertices(); ++v) {
    const auto& s = seamsAt[v];
    // Junctions and seam ends (degree != 2), and a vertex where one seam ends and the next begins.
    g.corner[v] = !s.empty() && (s.size() != 2 || s[0] != s[1]);
  }
  for (const SeamJunction& j : seg.junctions)
    if (j.vertex >= 0 && j.vertex < seg.mesh.numVertices()) g.corner[j.vertex] = 1;
  // A loop without any corner (a closed seam alone, like an equator): both sides start at its lowest vertex.
  for (const Segment& s : seg.segments)
    for (const BoundaryLoop& l : s.loops) {
      if (l.vertices.empty()) continue;
      bool any = false;
      for (int v : l.vertices) any = any || g.corner[v];
      if (!any) g.corner[*std::min_element(l.vertices.begin(), l.vertices.end())] = 1;
    }
  return g;
}

std::vector<BoundaryPiece> splitLoop(const Segmentation& seg, const SeamGraph& graph, const std::vector<int>& loop) {
  const int n = static_cast<int>(loop.size());
  std::vector<int> corners;
  for (int i = 0; i < n; ++i)
    if (graph.corner[loop[i]]) corners.push_back(i);
  if (corners.empty()) corners.push_back(0);
  std::vector<BoundaryPiece> pieces;
  for (size_t c = 0; c < corners.size(); ++c) {
    BoundaryPiece p;
    p.start = corners[c];
    const int end = c + 1 < corners.size() ? corners[c + 1] : corners[0] + n;
    for (int i = corners[c]; i <= end; ++i) p.vertices.push_back(loop[i % n]);
    p.seam = graph.seamOf(p.vertices[0], p.vertices[1]);
    p.neighborSegment = graph.neighborSegment(seg, p.vertices[0], p.vertices[1]);
    for (size_t i = 0; i + 1 < p.vertices.size(); ++i)
      p.length += (seg.mesh.V.row(p.vertices[i + 1]) - seg.mesh.V.row(p.vertices[i])).norm();
    pieces.push_back(std::move(p));
  }
  return pieces;
}

}  // namespace billow
