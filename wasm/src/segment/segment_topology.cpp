// Segment labels, wedges and boundary loops (see segment_topology.hpp).
#include "segment/segment_topology.hpp"

#include <algorithm>

#include "util/union_find.hpp"

namespace billow {

namespace {

// For each half-edge (3t + k, from corner k to k+1) the opposite half-edge, or -1. Half-edges are bucketed by their
// edge's lower vertex (flat arrays: with hash maps here and below, labelling took 40 % of a 30k-triangle
// segmentation); on an edge with more than two, each later one pairs with the first and the first with the last.
std::vector<int> twins(const TriMesh& m) {
  const int nh = 3 * m.numTriangles();
  std::vector<int> lower(nh), upper(nh), start(m.numVertices() + 1, 0);
  for (int h = 0; h < nh; ++h) {
    const int a = m.F(h / 3, h % 3), b = m.F(h / 3, (h % 3 + 1) % 3);
    lower[h] = std::min(a, b), upper[h] = std::max(a, b);
    ++start[lower[h] + 1];
  }
  for (int v = 0; v < m.numVertices(); ++v) start[v + 1] += start[v];
  std::vector<int> bucket(nh), fill(start.begin(), start.end() - 1);
  for (int h = 0; h < nh; ++h) bucket[fill[lower[h]]++] = h;  // each bucket in increasing h
  std::vector<int> twin(nh, -1);
  for (int v = 0; v < m.numVertices(); ++v)
    for (int i = start[v]; i < start[v + 1]; ++i)
      for (int j = start[v]; j < i; ++j)
        if (upper[bucket[j]] == upper[bucket[i]]) {  // the first of this edge
          twin[bucket[i]] = bucket[j], twin[bucket[j]] = bucket[i];
          break;
        }
  return twin;
}

}  // namespace

void labelSegments(const CutMesh& cut, Segmentation& out) {
  const TriMesh& m = out.mesh;
  const int nf = m.numTriangles();
  const std::vector<int> twin = twins(m);
  // The seam each half-edge lies on, or -1; looked up only where both ends are seam vertices.
  std::vector<char> onSeam(m.numVertices(), 0);
  for (const auto& [key, seam] : cut.seamEdge) onSeam[key >> 32] = onSeam[key & 0xffffffffu] = 1;
  std::vector<int> seamOf(3 * nf, -1);
  for (int h = 0; h < 3 * nf; ++h) {
    const int a = m.F(h / 3, h % 3), b = m.F(h / 3, (h % 3 + 1) % 3);
    if (!onSeam[a] || !onSeam[b]) continue;
    auto it = cut.seamEdge.find(edgeKey(a, b));
    if (it != cut.seamEdge.end()) seamOf[h] = it->second;
  }
  const auto isBorder = [&](int h) { return twin[h] < 0 || seamOf[h] >= 0; };
  UnionFind faces(nf), corners(3 * nf);
  for (int h = 0; h < 3 * nf; ++h) {
    if (twin[h] < h || seamOf[h] >= 0) continue;
    const int t = h / 3, k = h % 3, s = twin[h] / 3, j = twin[h] % 3;
    faces.unite(t, s);
    corners.unite(3 * t + k, 3 * s + (j + 1) % 3);  // the edge's two ends, seen from both triangles
    corners.unite(3 * t + (k + 1) % 3, 3 * s + j);
  }
  std::vector<int> id(nf, -1);  // segment of each face set's root, numbered as the roots first appear
  out.faceSegment.assign(nf, -1);
  for (int t = 0; t < nf; ++t) {
    int& segment = id[faces.find(t)];
    if (segment < 0) segment = static_cast<int>(out.segments.size()), out.segments.emplace_back();
    out.faceSegment[t] = segment;
    out.segments[segment].triangles.push_back(t);
    out.segments[segment].area += triangleArea(m, t);
  }
  // per segment: wedges (vertices of the opened segment), half-edges, boundary half-edges
  std::vector<int> wedges(out.segments.size(), 0), halfEdges(out.segments.size(), 0), border(out.segments.size(), 0);
  std::vector<char> seenWedge(3 * nf, 0);
  std::vector<int> outgoing(3 * nf, -1);  // wedge root -> the last boundary half-edge leaving it
  for (int h = 0; h < 3 * nf; ++h) {
    const int s = out.faceSegment[h / 3], w = corners.find(h);
    if (!seenWedge[w]) seenWedge[w] = 1, ++wedges[s];
    ++halfEdges[s];
    if (isBorder(h)) ++border[s], outgoing[w] = h;
  }
  for (size_t s = 0; s < out.segments.size(); ++s) {
    Segment& seg = out.segments[s];
    const int edges = (halfEdges[s] + border[s]) / 2;
    seg.eulerCharacteristic = wedges[s] - edges + static_cast<int>(seg.triangles.size());
  }
  // boundary loops: follow boundary half-edges wedge to wedge
  std::vector<char> used(3 * nf, 0);
  for (int h0 = 0; h0 < 3 * nf; ++h0) {
    if (used[h0] || !isBorder(h0)) continue;
    BoundaryLoop loop;
    for (int h = h0, guard = 0; !used[h] && guard < 3 * nf; ++guard) {
      used[h] = 1;
      const int next = 3 * (h / 3) + (h % 3 + 1) % 3;
      loop.vertices.push_back(m.F(h / 3, h % 3));
      loop.seams.push_back(seamOf[h]);
      h = outgoing[corners.find(next)];
      if (h < 0) break;
    }
    out.segments[out.faceSegment[h0 / 3]].loops.push_back(std::move(loop));
  }
  for (Segment& seg : out.segments) {
    const int loops = static_cast<int>(seg.loops.size());
    seg.genus = (2 - seg.eulerCharacteristic - loops) / 2;
    seg.isDisk = seg.eulerCharacteristic == 1 && loops == 1;
  }
}

}  // namespace billow
