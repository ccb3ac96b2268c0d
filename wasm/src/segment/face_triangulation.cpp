// Constrained triangulation of one triangle (see face_triangulation.hpp). Sizes are tiny (a few to a few
// dozen points per face), so adjacency is found by scanning.
#include "segment/face_triangulation.hpp"

#include <algorithm>
#include <set>

#include "util/vec2.hpp"

namespace billow {

namespace {

using Tri = std::array<int, 3>;

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool inCircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const Vec2 ad = a - d, bd = b - d, cd = c - d;
  const double det = ad.squaredNorm() * (bd.x() * cd.y() - cd.x() * bd.y()) -
                     bd.squaredNorm() * (ad.x() * cd.y() - cd.x() * ad.y()) +
                     cd.squaredNorm() * (ad.x() * bd.y() - bd.x() * ad.y());
  return det > 1e-14 * ad.squaredNorm() * bd.squaredNorm();
}

struct Triangulation {
  const std::vector<Vec2>& p;
  std::vector<Tri> tris;
  std::set<std::pair<int, int>> fixed;  // constrained edges, (min, max)

  // Triangle holding the directed edge a->b, and the corner of a in it; -1 if none.
  int find(int a, int b, int* corner) const {
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
      for (int k = 0; k < 3; ++k)
        if (tris[t][k] == a && tris[t][(k + 1) % 3] == b) return *corner = k, t;
    return -1;
  }
  bool isFixed(int a, int b) const { return fixed.count({std::min(a, b), std::max(a, b)}) > 0; }

  void insert(int i) {
    int best = -1, edge = -1;
    double bestScore = -1e300;
    for (int t = 0; t < static_cast<int>(tris.size()); ++t) {
      double score = 1e300;
      int low = -1;
      for (int k = 0; k < 3; ++k) {
        const Vec2 &a = p[tris[t][k]], &b = p[tris[t][(k + 1) % 3]];
        const double d = orient(a, b, p[i]) / std::max((b - a).norm(), 1e-300);  // signed distance
        if (d < score) score = d, low = k;
      }
      if (score > bestScore) bestScore = score, best = t, edge = low;
    }
    const Tri t = tris[best];
    const double scale = (p[t[0]] - p[t[1]]).norm() + (p[t[1]] - p[t[2]]).norm() + (p[t[2]] - p[t[0]]).norm();
    if (bestScore > 1e-12 * scale) {  // strictly inside: three triangles
      tris[best] = {t[0], t[1], i};
      tris.push_back({t[1], t[2], i});
      tris.push_back({t[2], t[0], i});
      return;
    }
    splitEdge(t[edge], t[(edge + 1) % 3], i);
  }

  // i lies on edge (a, b): split the one or two triangles that hold it.
  void splitEdge(int a, int b, int i) {
    for (const auto& [u, v] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
      int k = 0;
      const int t = find(u, v, &k);
      if (t < 0) continue;
      const int w = tris[t][(k + 2) % 3];
      tris[t] = {u, i, w};
      tris.push_back({i, v, w});
    }
  }

  // Flips the edge a->b (held by t at corner k) when its quadrilateral is strictly convex.
  bool flip(int t, int k) {
    const int a = tris[t][k], b = tris[t][(k + 1) % 3], c = tris[t][(k + 2) % 3];
    int k2 = 0;
    const int s = find(b, a, &k2);
    if (s < 0) return false;
    const int d = tris[s][(k2 + 2) % 3];
    if (orient(p[c], p[d], p[a]) >= 0 || orient(p[c], p[d], p[b]) <= 0) return false;
    if (orient(p[a], p[d], p[c]) <= 0 || orient(p[d], p[b], p[c]) <= 0) return false;
    tris[t] = {a, d, c};
    tris[s] = {d, b, c};
    return true;
  }

  bool crosses(int u, int v, int a, int b) const {
    if (u == a || u == b || v == a || v == b) return false;
    const double o1 = orient(p[a], p[b], p[u]), o2 = orient(p[a], p[b], p[v]);
    const double o3 = orient(p[u], p[v], p[a]), o4 = orient(p[u], p[v], p[b]);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
  }

  bool hasEdge(int a, int b) const {
    int k = 0;
    return find(a, b, &k) >= 0 || find(b, a, &k) >= 0;
  }

  // The diagonal (c, d) that flipping edge k of t would create; false if its quad is not strictly convex.
  bool flipTarget(int t, int k, int* c, int* d) const {
    const int a = tris[t][k], b = tris[t][(k + 1) % 3];
    int k2 = 0;
    const int s = find(b, a, &k2);
    if (s < 0) return false;
    *c = tris[t][(k + 2) % 3], *d = tris[s][(k2 + 2) % 3];
    return orient(p[*c], p[*d], p[a]) < 0 && orient(p[*c], p[*d], p[b]) > 0;
  }

  // Flips edges that cross a-b until a-b is an edge (Sloan: prefer flips whose new edge no longer crosses,
  // and never undo the previous flip, so the loop cannot cycle between two diagonals).
  bool recover(int a, int b) {
    const int limit = 16 + 4 * static_cast<int>(tris.size() * tris.size());
    std::pair<int, int> last{-1, -1};
    for (int guard = 0; guard < limit && !hasEdge(a, b); ++guard) {
      int bestT = -1, bestK = -1, bestRank = 3;
      for (int t = 0; t < static_cast<int>(tris.size()) && bestRank > 0; ++t)
        for (int k = 0; k < 3 && bestRank > 0; ++k) {
          const int u = tris[t][k], v = tris[t][(k + 1) % 3];
          int c = 0, d = 0;
          if (!crosses(u, v, a, b) || isFixed(u, v) || !flipTarget(t, k, &c, &d)) continue;
          const bool undo = std::minmax(u, v) == std::minmax(last.first, last.second);
          const int rank = crosses(c, d, a, b) ? (undo ? 2 : 1) : 0;
          if (rank < bestRank) bestRank = rank, bestT = t, bestK = k;
        }
      if (bestT < 0) return false;
      int c = 0, d = 0;
      flipTarget(bestT, bestK, &c, &d);
      if (!flip(bestT, bestK)) return false;
      last = {c, d};
    }
    return hasEdge(a, b);
  }

  void delaunay() {
    const int limit = 8 + 4 * static_cast<int>(tris.size() * tris.size());
    for (int round = 0; round < limit; ++round) {
      bool any = false;
      for (int t = 0; t < static_cast<int>(tris.size()); ++t)
        for (int k = 0; k < 3; ++k) {
          const int a = tris[t][k], b = tris[t][(k + 1) % 3], c = tris[t][(k + 2) % 3];
          int k2 = 0;
          if (isFixed(a, b)) continue;
          const int s = find(b, a, &k2);
          if (s < 0 || !inCircle(p[a], p[b], p[c], p[tris[s][(k2 + 2) % 3]])) continue;
          if (flip(t, k)) any = true;
        }
      if (!any) return;
    }
  }
};

}  // namespace

std::vector<Tri> triangulateFace(const std::vector<Vec2>& pts, const std::vector<std::pair<int, int>>& constraints,
                                 int* unrecovered) {
  Triangulation tr{pts, {{0, 1, 2}}, {}};
  for (int i = 3; i < static_cast<int>(pts.size()); ++i) tr.insert(i);
  tr.delaunay();
  int failed = 0;
  for (const auto& [a, b] : constraints) {
    if (a == b) continue;
    if (!tr.recover(a, b)) ++failed;
    tr.fixed.insert({std::min(a, b), std::max(a, b)});
  }
  tr.delaunay();
  if (unrecovered) *unrecovered = failed;
  return tr.tris;
}

}  // namespace billow
