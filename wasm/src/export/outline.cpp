#include "export/outline.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "util/error.hpp"
#include "util/union_find.hpp"

namespace billow {
namespace {

// The boundary of a triangle mesh with counterclockwise triangles, as one counterclockwise vertex loop.
std::vector<int> boundaryLoop(const Panel& panel) {
  std::map<std::pair<int, int>, int> count;
  for (int t = 0; t < panel.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = panel.triangles(t, k), b = panel.triangles(t, (k + 1) % 3);
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<int> next(panel.vertices.rows(), -1);
  int edges = 0, start = -1;
  for (int t = 0; t < panel.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = panel.triangles(t, k), b = panel.triangles(t, (k + 1) % 3);
      if (count[{std::min(a, b), std::max(a, b)}] != 1) continue;
      if (next[a] != -1)
        throw Error("export.panel-shape", "The panel '" + panel.name + "' has a pinched corner in its outline.");
      next[a] = b, ++edges;
      if (start < 0 || a < start) start = a;
    }
  std::vector<int> loop;
  for (int v = start; v >= 0 && (loop.empty() || v != start) && int(loop.size()) <= edges; v = next[v])
    loop.push_back(v);
  if (start < 0 || int(loop.size()) != edges)
    throw Error("export.panel-shape",
                "The panel '" + panel.name + "' has a hole or several pieces; cut outputs need one outline per panel.");
  return loop;
}

struct EdgeRef {
  int panel = -1, edge = -1;
  bool operator==(const EdgeRef& o) const { return panel == o.panel && edge == o.edge; }
};

}  // namespace

Polygon2 PanelOutline::points(const Panel& panel, double scale) const {
  Polygon2 p;
  for (int v : loop) p.push_back(scale * Vec2(panel.vertices(v, 0), panel.vertices(v, 1)));
  return p;
}

Outlines buildOutlines(const Pattern& pattern) {
  const int np = int(pattern.panels.size());
  Outlines out;
  out.panels.resize(np);
  std::vector<int> firstVertex(np + 1, 0);
  for (int p = 0; p < np; ++p) firstVertex[p + 1] = firstVertex[p] + int(pattern.panels[p].vertices.rows());
  UnionFind groups(firstVertex[np]);
  for (const Stitch& s : pattern.stitches)
    groups.unite(firstVertex[s.panelA] + s.vertexA, firstVertex[s.panelB] + s.vertexB);
  auto group = [&](int p, int v) { return groups.find(firstVertex[p] + v); };

  std::vector<std::vector<int>> loops(np);
  for (int p = 0; p < np; ++p) loops[p] = boundaryLoop(pattern.panels[p]);
  auto edgeGroups = [&](const EdgeRef& e) {
    const auto& l = loops[e.panel];
    return std::pair{group(e.panel, l[e.edge]), group(e.panel, l[(e.edge + 1) % l.size()])};
  };

  // Sewn edges: boundary edges whose two ends are stitched to the two ends of another boundary edge. Pair
  // them up, preferring outer panels and opposite directions (a correctly mirrored pair); a third edge on
  // the same sewn points (an internal panel on a seam) gets a one-way partner.
  std::map<std::pair<int, int>, std::vector<EdgeRef>> buckets;
  for (int p = 0; p < np; ++p)
    for (int e = 0; e < int(loops[p].size()); ++e) {
      const auto [ga, gb] = edgeGroups({p, e});
      if (ga != gb) buckets[{std::min(ga, gb), std::max(ga, gb)}].push_back({p, e});
    }
  std::vector<std::vector<EdgeRef>> partner(np);
  for (int p = 0; p < np; ++p) partner[p].assign(loops[p].size(), EdgeRef{});
  for (const auto& [key, edges] : buckets) {
    if (edges.size() < 2) continue;
    std::vector<std::tuple<int, size_t, size_t>> pairs;  // (preference, i, j), smaller is better
    for (size_t i = 0; i < edges.size(); ++i)
      for (size_t j = i + 1; j < edges.size(); ++j) {
        const bool same = edgeGroups(edges[i]) == edgeGroups(edges[j]);
        const int internals = pattern.panels[edges[i].panel].internal + pattern.panels[edges[j].panel].internal;
        pairs.emplace_back(4 * internals + 2 * same, i, j);
      }
    std::stable_sort(pairs.begin(), pairs.end());
    auto& P = partner;
    for (const auto& [score, i, j] : pairs) {
      const EdgeRef a = edges[i], b = edges[j];
      if (P[a.panel][a.edge].panel < 0 && P[b.panel][b.edge].panel < 0) P[a.panel][a.edge] = b, P[b.panel][b.edge] = a;
    }
    for (const auto& [score, i, j] : pairs) {
      const EdgeRef a = edges[i], b = edges[j];
      if (P[a.panel][a.edge].panel < 0) P[a.panel][a.edge] = b;
      if (P[b.panel][b.edge].panel < 0) P[b.panel][b.edge] = a;
    }
  }

  // Two consecutive loop edges belong to one seam when their partners are consecutive edges of one loop
  // (and the seam does not fold back on itself, as at a cone's apex).
  auto continues = [&](int p, int e, int f) {
    const EdgeRef pe = partner[p][e], pf = partner[p][f];
    if (pe.panel < 0 || pe.panel != pf.panel) return false;
    if (pe.panel == p && (pe.edge == f || pf.edge == e)) return false;
    const int n = int(loops[pe.panel].size());
    const int step = ((pf.edge - pe.edge) % n + n) % n;
    return step == 1 || step == n - 1;
  };

  // Rotate each loop to start at its first junction so that no seam wraps around loop[0].
  for (int p = 0; p < np; ++p) {
    const int n = int(loops[p].size());
    int start = -1;
    for (int e = 0; e < n; ++e) {
      const int prev = (e + n - 1) % n;
      const bool junction = (partner[p][prev].panel >= 0) != (partner[p][e].panel >= 0) ||
                            (partner[p][e].panel >= 0 && !continues(p, prev, e));
      if (junction && (start < 0 || loops[p][e] < loops[p][start])) start = e;
    }
    if (start < 0) start = int(std::min_element(loops[p].begin(), loops[p].end()) - loops[p].begin());
    if (start == 0) continue;
    // Partners refer to edge indices; remap every reference into this panel.
    for (auto& list : partner)
      for (EdgeRef& r : list)
        if (r.panel == p) r.edge = (r.edge - start + n) % n;
    std::rotate(loops[p].begin(), loops[p].begin() + start, loops[p].end());
    std::rotate(partner[p].begin(), partner[p].begin() + start, partner[p].end());
  }

  for (int p = 0; p < np; ++p) {
    out.panels[p].loop = loops[p];
    out.panels[p].edgeSeam.assign(loops[p].size(), -1);
  }
  auto edgeLength = [&](int p, int e) {
    const auto& l = loops[p];
    return (pattern.panels[p].vertices.row(l[(e + 1) % l.size()]) - pattern.panels[p].vertices.row(l[e])).norm();
  };
  for (int p = 0; p < np; ++p) {
    const int n = int(loops[p].size());
    for (int e = 0; e < n; ++e) {
      if (partner[p][e].panel < 0 || out.panels[p].edgeSeam[e] >= 0) continue;
      Seam seam;
      seam.id = int(out.seams.size());
      seam.a.panel = p;
      seam.b.panel = partner[p][e].panel;
      for (int f = e; f < n && out.panels[p].edgeSeam[f] < 0 && (f == e || continues(p, f - 1, f)); ++f) {
        seam.a.edges.push_back(f);
        seam.b.edges.push_back(partner[p][f].edge);
        out.panels[p].edgeSeam[f] = seam.id;
      }
      seam.closed = int(seam.a.edges.size()) == n && continues(p, n - 1, 0);
      const auto [ga, gb] = edgeGroups({p, e});
      seam.b.forward = edgeGroups(partner[p][e]) == std::pair{ga, gb};
      for (size_t k = 0; k < seam.a.edges.size(); ++k) {
        const EdgeRef pk = partner[p][seam.a.edges[k]];
        seam.shared = seam.shared && partner[pk.panel][pk.edge] == EdgeRef{p, seam.a.edges[k]};
        seam.a.length += edgeLength(p, seam.a.edges[k]);
        seam.b.length += edgeLength(pk.panel, pk.edge);
      }
      if (seam.shared)
        for (int f : seam.b.edges) out.panels[seam.b.panel].edgeSeam[f] = seam.id;
      out.maxMismatch = std::max(out.maxMismatch, seam.mismatch());
      out.seams.push_back(std::move(seam));
    }
  }
  return out;
}

SidePoint pointAlongSide(const Pattern& pattern, const Outlines& outlines, const SeamSide& side, double s) {
  const Panel& panel = pattern.panels[side.panel];
  const auto& loop = outlines.panels[side.panel].loop;
  const int n = int(loop.size());
  auto pos = [&](int i) { return Vec2(panel.vertices(loop[i % n], 0), panel.vertices(loop[i % n], 1)); };
  SidePoint out;
  for (size_t k = 0; k < side.edges.size(); ++k) {
    const int e = side.edges[k];
    const Vec2 from = side.forward ? pos(e) : pos(e + 1), to = side.forward ? pos(e + 1) : pos(e);
    const double len = (to - from).norm();
    if (s <= len || k + 1 == side.edges.size()) {
      const double t = len > 0 ? std::clamp(s / len, 0.0, 1.0) : 0.0;
      const Vec2 d = (pos(e + 1) - pos(e)).normalized();  // counterclockwise: outside is on the right
      out.point = from + t * (to - from);
      out.normal = Vec2(d.y(), -d.x());
      out.edge = e;
      return out;
    }
    s -= len;
  }
  return out;
}

}  // namespace billow
