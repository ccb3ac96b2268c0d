// Segment labels, wedges and boundary loops (see segment_topology.hpp).
#include "segment/segment_topology.hpp"

#include <unordered_map>

#include "util/union_find.hpp"

namespace billow {

namespace {

// For each half-edge (3t + k, from corner k to k+1) the opposite half-edge, or -1.
std::vector<int> twins(const TriMesh& m) {
  std::unordered_map<std::uint64_t, int> first;
  first.reserve(m.numTriangles() * 2);
  std::vector<int> twin(3 * m.numTriangles(), -1);
  for (int h = 0; h < 3 * m.numTriangles(); ++h) {
    const int a = m.F(h / 3, h % 3), b = m.F(h / 3, (h % 3 + 1) % 3);
    auto [it, inserted] = first.emplace(edgeKey(a, b), h);
    if (!inserted) twin[h] = it->second, twin[it->second] = h;
  }
  return twin;
}

}  // namespace

void labelSegments(const CutMesh& cut, Segmentation& out) {
  const TriMesh& m = out.mesh;
  const int nf = m.numTriangles();
  const std::vector<int> twin = twins(m);
  auto isSeam = [&](int h) { return cut.seamEdge.count(edgeKey(m.F(h / 3, h % 3), m.F(h / 3, (h % 3 + 1) % 3))) > 0; };
  UnionFind faces(nf), corners(3 * nf);
  for (int h = 0; h < 3 * nf; ++h) {
    if (twin[h] < h || isSeam(h)) continue;
    const int t = h / 3, k = h % 3, s = twin[h] / 3, j = twin[h] % 3;
    faces.unite(t, s);
    corners.unite(3 * t + k, 3 * s + (j + 1) % 3);  // the edge's two ends, seen from both triangles
    corners.unite(3 * t + (k + 1) % 3, 3 * s + j);
  }
  std::unordered_map<int, int> id;
  out.faceSegment.assign(nf, -1);
  for (int t = 0; t < nf; ++t) {
    auto [it, inserted] = id.emplace(faces.find(t), static_cast<int>(id.size()));
    if (inserted) out.segments.emplace_back();
    out.faceSegment[t] = it->second;
    out.segments[it->second].triangles.push_back(t);
    out.segments[it->second].area += triangleArea(m, t);
  }
  // per segment: wedges (vertices of the opened segment), half-edges, boundary half-edges
  std::vector<int> wedges(out.segments.size(), 0), halfEdges(out.segments.size(), 0), border(out.segments.size(), 0);
  std::vector<char> seenWedge(3 * nf, 0);
  std::unordered_map<int, int> outgoing;  // wedge root -> boundary half-edge leaving it
  for (int h = 0; h < 3 * nf; ++h) {
    const int s = out.faceSegment[h / 3], w = corners.find(h);
    if (!seenWedge[w]) seenWedge[w] = 1, ++wedges[s];
    ++halfEdges[s];
    if (twin[h] < 0 || isSeam(h)) ++border[s], outgoing[w] = h;
  }
  for (size_t s = 0; s < out.segments.size(); ++s) {
    Segment& seg = out.segments[s];
    const int edges = (halfEdges[s] + border[s]) / 2;
    seg.eulerCharacteristic = wedges[s] - edges + static_cast<int>(seg.triangles.size());
  }
  // boundary loops: follow boundary half-edges wedge to wedge
  std::vector<char> used(3 * nf, 0);
  for (int h0 = 0; h0 < 3 * nf; ++h0) {
    if (used[h0] || !(twin[h0] < 0 || isSeam(h0))) continue;
    BoundaryLoop loop;
    for (int h = h0, guard = 0; !used[h] && guard < 3 * nf; ++guard) {
      used[h] = 1;
      const int a = m.F(h / 3, h % 3), next = 3 * (h / 3) + (h % 3 + 1) % 3;
      loop.vertices.push_back(a);
      auto it = cut.seamEdge.find(edgeKey(a, m.F(h / 3, (h % 3 + 1) % 3)));
      loop.seams.push_back(it == cut.seamEdge.end() ? -1 : it->second);
      auto o = outgoing.find(corners.find(next));
      if (o == outgoing.end()) break;
      h = o->second;
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
