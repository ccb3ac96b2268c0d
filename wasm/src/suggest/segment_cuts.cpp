#include "suggest/segment_cuts.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <set>
#include <unordered_map>

#include "util/union_find.hpp"

namespace billow {
namespace {

// The segment capped: every boundary loop closed by a cone over it, so that it is a closed surface of the segment's
// genus, whose loops that do not separate it are those of the segment. Edges that touch a seam, and the cones', weigh
// `far`, so no loop shorter than that runs along or across a seam.
struct CappedSegment {
  struct Edge {
    int a = -1, b = -1;
    double weight = 0;
    int faceA = -1, faceB = -1;
  };
  std::vector<int> cutVertex;  // local vertex -> cut-mesh vertex; -1 for a cone
  std::vector<char> onSeam;    // local vertex on one of the segment's loops
  std::vector<Edge> edges;
  std::vector<std::vector<std::pair<int, int>>> around;  // local vertex -> (neighbour, edge)
  int faces = 0;  // the segment's triangles (in Segment::triangles order), then the cones'

  double far = 0;
};

CappedSegment capSegment(const Segmentation& sg, int s) {
  const Segment& segment = sg.segments[size_t(s)];
  const TriMesh& m = sg.mesh;
  CappedSegment c;
  std::unordered_map<int, int> local;
  const auto localOf = [&](int v) {
    const auto [it, added] = local.emplace(v, int(c.cutVertex.size()));
    if (added) c.cutVertex.push_back(v);
    return it->second;
  };
  for (int t : segment.triangles)
    for (int k = 0; k < 3; ++k) localOf(m.F(t, k));
  c.onSeam.assign(c.cutVertex.size(), 0);
  std::map<std::pair<int, int>, int> loopEdge;  // directed (segment on its left) -> edge
  std::map<std::pair<int, int>, int> inside;    // undirected -> edge
  const double diagonal = (m.V.colwise().maxCoeff() - m.V.colwise().minCoeff()).norm();
  c.far = 1e6 * std::max(diagonal, 1e-12);
  const auto length = [&](int a, int b) { return (m.V.row(c.cutVertex[a]) - m.V.row(c.cutVertex[b])).norm(); };
  const int triangles = int(segment.triangles.size());
  c.faces = triangles;
  for (const BoundaryLoop& loop : segment.loops) {
    const int cone = int(c.cutVertex.size()), n = int(loop.vertices.size()), first = c.faces;
    c.cutVertex.push_back(-1), c.onSeam.push_back(1);
    for (int i = 0; i < n; ++i) {
      const int a = local.at(loop.vertices[size_t(i)]), b = local.at(loop.vertices[size_t((i + 1) % n)]);
      c.onSeam[size_t(a)] = 1;
      loopEdge[{a, b}] = int(c.edges.size());
      c.edges.push_back({a, b, c.far, -1, first + i});
      c.edges.push_back({cone, a, c.far, first + (i + n - 1) % n, first + i});  // between two cone faces
    }
    c.faces += n;
  }
  for (int i = 0; i < triangles; ++i) {
    const int t = segment.triangles[size_t(i)];
    for (int k = 0; k < 3; ++k) {
      const int a = local.at(m.F(t, k)), b = local.at(m.F(t, (k + 1) % 3));
      if (const auto along = loopEdge.find({a, b}); along != loopEdge.end()) {
        c.edges[size_t(along->second)].faceA = i;
        continue;
      }
      const auto [it, added] = inside.emplace(std::minmax(a, b), int(c.edges.size()));
      if (added) {
        const bool touches = c.onSeam[size_t(a)] || c.onSeam[size_t(b)];
        c.edges.push_back({a, b, touches ? c.far : length(a, b), i, -1});
      } else {
        c.edges[size_t(it->second)].faceB = i;
      }
    }
  }
  c.around.resize(c.cutVertex.size());
  for (int e = 0; e < int(c.edges.size()); ++e) {
    c.around[size_t(c.edges[size_t(e)].a)].push_back({c.edges[size_t(e)].b, e});
    c.around[size_t(c.edges[size_t(e)].b)].push_back({c.edges[size_t(e)].a, e});
  }
  return c;
}

struct Tree {
  std::vector<double> distance;
  std::vector<int> parentEdge, depth;
};

Tree shortestPaths(const CappedSegment& c, int root) {
  const size_t n = c.cutVertex.size();
  Tree t{std::vector<double>(n, INFINITY), std::vector<int>(n, -1), std::vector<int>(n, 0)};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  t.distance[size_t(root)] = 0;
  queue.push({0, root});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > t.distance[size_t(v)]) continue;
    for (const auto& [w, e] : c.around[size_t(v)])
      if (const double dw = d + c.edges[size_t(e)].weight; dw < t.distance[size_t(w)]) {
        t.distance[size_t(w)] = dw, t.parentEdge[size_t(w)] = e, t.depth[size_t(w)] = t.depth[size_t(v)] + 1;
        queue.push({dw, w});
      }
  }
  return t;
}

// The loop one edge closes in the tree: from a up to where the paths from a and b meet, and down to b.
std::vector<int> treeLoop(const CappedSegment& c, const Tree& t, int a, int b) {
  const auto up = [&](int v) {
    const CappedSegment::Edge& e = c.edges[size_t(t.parentEdge[size_t(v)])];
    return e.a == v ? e.b : e.a;
  };
  std::vector<int> fromA{a}, fromB{b};
  while (a != b) {
    if (t.depth[size_t(a)] >= t.depth[size_t(b)])
      fromA.push_back(a = up(a));
    else
      fromB.push_back(b = up(b));
  }
  fromB.pop_back();  // the meeting point is fromA's last
  fromA.insert(fromA.end(), fromB.rbegin(), fromB.rend());
  return fromA;
}

// Whether the segment's triangles stay connected across its inside edges but those of `cut` (cut-mesh vertex pairs,
// lower first): loops round handles and cuts round a ring leave it whole; a loop round a few triangles, or two round
// the same handle, cut a piece off.
bool staysWhole(const Segmentation& sg, const Segment& s, const std::set<std::pair<int, int>>& cut) {
  std::set<std::pair<int, int>> seamEdges;
  for (const BoundaryLoop& loop : s.loops)
    for (size_t i = 0; i < loop.vertices.size(); ++i)
      seamEdges.insert(std::minmax(loop.vertices[i], loop.vertices[(i + 1) % loop.vertices.size()]));
  UnionFind parts(int(s.triangles.size()));
  std::map<std::pair<int, int>, int> firstAlong;
  for (int i = 0; i < int(s.triangles.size()); ++i)
    for (int k = 0; k < 3; ++k) {
      const int t = s.triangles[size_t(i)];
      const std::pair<int, int> e = std::minmax(sg.mesh.F(t, k), sg.mesh.F(t, (k + 1) % 3));
      if (cut.count(e) || seamEdges.count(e)) continue;
      if (const auto [it, added] = firstAlong.emplace(e, i); !added) parts.unite(i, it->second);
    }
  for (int i = 1; i < int(s.triangles.size()); ++i)
    if (parts.find(i) != parts.find(0)) return false;
  return true;
}

// The edges of a path of cut-mesh vertices, lower vertex first; closing it when `closed`.
void addEdges(const std::vector<int>& path, bool closed, std::set<std::pair<int, int>>& edges) {
  for (size_t i = 0; i + (closed ? 0 : 1) < path.size(); ++i)
    edges.insert(std::minmax(path[i], path[(i + 1) % path.size()]));
}

}  // namespace

std::vector<std::vector<int>> cutsJoiningLoops(const Segmentation& sg, int segment) {
  if (segment < 0 || segment >= int(sg.segments.size())) return {};
  const Segment& s = sg.segments[size_t(segment)];
  const TriMesh& m = sg.mesh;
  const auto length = [&](int a, int b) { return (m.V.row(a) - m.V.row(b)).norm(); };
  std::unordered_map<int, char> onLoop;
  for (const BoundaryLoop& loop : s.loops)
    for (int v : loop.vertices) onLoop[v] = 1;
  // The segment's inside: its vertices off the loops, and the edges between them.
  std::unordered_map<int, std::vector<int>> around;
  std::map<std::pair<int, int>, int> leftOf;  // a loop's directed edge -> the third corner of the triangle on its left
  for (int t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(t, k), b = m.F(t, (k + 1) % 3), c = m.F(t, (k + 2) % 3);
      leftOf[{a, b}] = c;
      if (!onLoop.count(a) && !onLoop.count(b)) around[a].push_back(b);
    }
  // Every inside vertex's nearest loop through the inside (Dijkstra from all loops at once), each loop reached from
  // the side the segment lies on: a seam's two sides are two loops of one segment where it goes round a handle.
  struct Reach {
    double distance = INFINITY;
    int loop = -1, parent = -1;  // parent: the previous vertex, a loop vertex for the first inside one
  };
  std::unordered_map<int, Reach> reach;
  std::map<std::pair<int, int>, std::pair<double, int>> seed;  // (inside vertex, loop) -> nearest
  for (size_t l = 0; l < s.loops.size(); ++l) {
    const std::vector<int>& v = s.loops[l].vertices;
    for (size_t i = 0; i < v.size(); ++i) {
      const auto third = leftOf.find({v[i], v[(i + 1) % v.size()]});
      if (third == leftOf.end() || onLoop.count(third->second)) continue;
      for (int a : {v[i], v[(i + 1) % v.size()]}) {
        auto [it, added] = seed.emplace(std::pair{third->second, int(l)}, std::pair{length(a, third->second), a});
        if (!added && length(a, third->second) < it->second.first) it->second = {length(a, third->second), a};
      }
    }
  }
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (const auto& [key, nearest] : seed) {
    Reach& r = reach[key.first];
    if (nearest.first < r.distance)
      r = {nearest.first, key.second, nearest.second}, queue.push({nearest.first, key.first});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    const Reach here = reach.at(v);
    if (d > here.distance) continue;
    for (int w : around[v]) {
      Reach& there = reach[w];
      if (const double dw = d + length(v, w); dw < there.distance) {
        there = {dw, here.loop, v};
        queue.push({dw, w});
      }
    }
  }
  // The shortest path between two loops passes an inside edge between their regions, or an inside vertex next to both.
  struct Joint {
    double length = INFINITY;
    int a = -1, b = -1;  // inside vertices (a == b: one vertex next to both loops)
    int viaB = -1;       // for a single vertex: the second loop's vertex
  };
  std::map<std::pair<int, int>, Joint> joints;  // (loop, loop) -> the shortest path's middle
  for (const auto& [a, next] : around)
    for (int b : next) {
      const Reach &ra = reach.at(a), &rb = reach.at(b);
      if (ra.loop < 0 || rb.loop < 0 || ra.loop >= rb.loop) continue;
      Joint& j = joints[{ra.loop, rb.loop}];
      if (const double total = ra.distance + length(a, b) + rb.distance; total < j.length) j = {total, a, b};
    }
  for (const auto& [key, nearest] : seed) {
    const Reach& r = reach.at(key.first);
    if (key.second == r.loop) continue;
    Joint& j = joints[std::minmax(key.second, r.loop)];
    if (const double total = nearest.first + r.distance; total < j.length)
      j = {total, key.first, key.first, nearest.second};
  }
  std::vector<std::pair<std::pair<int, int>, Joint>> order(joints.begin(), joints.end());
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.second.length < y.second.length; });
  UnionFind joined(int(s.loops.size()));
  std::vector<std::vector<int>> cuts;
  const auto back = [&](int v, std::vector<int>& path) {  // v, its parents, and the loop vertex it came from
    for (; v >= 0 && !onLoop.count(v); v = reach.at(v).parent) path.push_back(v);
    if (v >= 0) path.push_back(v);
  };
  for (const auto& [loops, j] : order) {
    if (joined.find(loops.first) == joined.find(loops.second)) continue;
    std::vector<int> path;
    back(j.a, path);
    std::reverse(path.begin(), path.end());
    if (j.a != j.b)
      back(j.b, path);
    else
      path.push_back(j.viaB);
    // A path back to the vertex it left goes round a ring, or round a few triangles where two loops touch.
    std::set<std::pair<int, int>> cut;
    addEdges(path, false, cut);
    if (path.front() == path.back() && !staysWhole(sg, s, cut)) continue;
    joined.unite(loops.first, loops.second);
    cuts.push_back(std::move(path));
  }
  return cuts;
}

std::vector<std::vector<int>> loopsAroundHandles(const Segmentation& sg, int segment, double minLength, int roots) {
  if (segment < 0 || segment >= int(sg.segments.size()) || sg.segments[size_t(segment)].genus <= 0) return {};
  const CappedSegment c = capSegment(sg, segment);
  const int n = int(c.cutVertex.size());
  std::vector<double> nearestRoot(size_t(n), INFINITY);
  int root = -1;
  for (int v = 0; v < n && root < 0; ++v)
    if (!c.onSeam[size_t(v)]) root = v;
  std::vector<std::pair<double, std::vector<int>>> found;  // (length, loop)
  for (int r = 0; r < roots && root >= 0; ++r) {
    const Tree t = shortestPaths(c, root);
    std::vector<char> inTree(c.edges.size(), 0);
    for (int v = 0; v < n; ++v)
      if (t.parentEdge[size_t(v)] >= 0) inTree[size_t(t.parentEdge[size_t(v)])] = 1;
    // The cotree: of the edges off the tree, the longest loops first join the faces on their two sides; the 2g
    // left over close the greedy system's loops.
    std::vector<int> off;
    for (int e = 0; e < int(c.edges.size()); ++e)
      if (!inTree[size_t(e)]) off.push_back(e);
    const auto loopLength = [&](int e) {
      return t.distance[size_t(c.edges[size_t(e)].a)] + c.edges[size_t(e)].weight +
             t.distance[size_t(c.edges[size_t(e)].b)];
    };
    std::sort(off.begin(), off.end(), [&](int x, int y) { return loopLength(x) > loopLength(y); });
    UnionFind dual(c.faces);
    for (int e : off) {
      const CappedSegment::Edge& edge = c.edges[size_t(e)];
      if (edge.faceA >= 0 && edge.faceB >= 0 && dual.find(edge.faceA) != dual.find(edge.faceB)) {
        dual.unite(edge.faceA, edge.faceB);
        continue;
      }
      if (loopLength(e) >= c.far) continue;  // along or across a seam
      std::vector<int> loop = treeLoop(c, t, edge.a, edge.b);
      double length = 0;
      for (size_t i = 0; i < loop.size(); ++i) {
        const int a = c.cutVertex[size_t(loop[i])], b = c.cutVertex[size_t(loop[(i + 1) % loop.size()])];
        length += (sg.mesh.V.row(a) - sg.mesh.V.row(b)).norm();
      }
      if (length >= minLength) found.push_back({length, std::move(loop)});
    }
    // The next root: the inside vertex farthest from the roots so far.
    for (int v = 0; v < n; ++v) nearestRoot[size_t(v)] = std::min(nearestRoot[size_t(v)], t.distance[size_t(v)]);
    root = -1;
    double farthest = 0;
    for (int v = 0; v < n; ++v)
      if (!c.onSeam[size_t(v)] && nearestRoot[size_t(v)] < c.far && nearestRoot[size_t(v)] > farthest)
        farthest = nearestRoot[size_t(v)], root = v;
  }
  // The shortest first, each apart from those taken, while all of them together leave the segment whole: one around
  // each handle.
  std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  const Segment& s = sg.segments[size_t(segment)];
  std::vector<std::vector<int>> taken;
  std::set<std::pair<int, int>> cut;  // the taken loops' edges
  std::vector<char> onTaken(size_t(n), 0);
  for (const auto& [length, loop] : found) {
    if (int(taken.size()) == s.genus) break;
    if (loop.size() < 3 || std::any_of(loop.begin(), loop.end(), [&](int v) { return onTaken[size_t(v)]; })) continue;
    std::vector<int> path;
    for (int v : loop) path.push_back(c.cutVertex[size_t(v)]);
    std::set<std::pair<int, int>> with = cut;
    addEdges(path, true, with);
    if (!staysWhole(sg, s, with)) continue;
    cut = std::move(with);
    for (int v : loop) onTaken[size_t(v)] = 1;
    taken.push_back(std::move(path));
  }
  return taken;
}

std::vector<int> cutAcross(const Segmentation& sg, int segment, const Eigen::Vector3d& near) {
  if (segment < 0 || segment >= int(sg.segments.size())) return {};
  const Segment& s = sg.segments[size_t(segment)];
  const TriMesh& m = sg.mesh;
  const auto length = [&](int a, int b) { return (m.V.row(a) - m.V.row(b)).norm(); };
  // Each loop vertex's places: its loop and arc length from that loop's first vertex, twice where the segment lies on
  // both sides of its seam (a slit); the start nearest `near`.
  struct Place {
    int loop = -1;
    double arc = 0;
  };
  std::unordered_map<int, std::vector<Place>> places;
  std::set<std::pair<int, int>> loopEdges;
  std::vector<double> loopLength(s.loops.size(), 0.0);
  int start = -1;
  for (size_t l = 0; l < s.loops.size(); ++l) {
    const std::vector<int>& v = s.loops[l].vertices;
    for (size_t i = 0; i < v.size(); ++i) {
      places[v[i]].push_back({int(l), loopLength[l]});
      loopEdges.insert(std::minmax(v[i], v[(i + 1) % v.size()]));
      loopLength[l] += length(v[i], v[(i + 1) % v.size()]);
      if (start < 0 || (m.V.row(v[i]).transpose() - near).norm() < (m.V.row(start).transpose() - near).norm())
        start = v[i];
    }
  }
  if (start < 0) return {};
  const auto apart = [&](int v) {  // along the loop, the shorter way, from the nearest places; across loops: far
    double nearest = INFINITY;
    for (const Place& from : places.at(start))
      for (const Place& to : places.at(v))
        if (to.loop == from.loop) {
          const double d = std::abs(to.arc - from.arc);
          nearest = std::min({nearest, d, loopLength[size_t(from.loop)] - d});
        }
    return nearest;
  };
  std::unordered_map<int, std::vector<int>> around;
  for (int t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(t, k), b = m.F(t, (k + 1) % 3);
      if (!loopEdges.count(std::minmax(a, b))) around[a].push_back(b), around[b].push_back(a);
    }
  // Dijkstra from the start through inside vertices; a loop vertex ends a path and is not gone on from.
  std::unordered_map<int, std::pair<double, int>> reach;  // vertex -> (distance, previous)
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  reach[start] = {0, -1};
  queue.push({0, start});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > reach.at(v).first) continue;
    if (v != start && places.count(v)) {
      if (apart(v) < 2 * d) continue;
      std::vector<int> path;
      for (int w = v; w >= 0; w = reach.at(w).second) path.push_back(w);
      std::reverse(path.begin(), path.end());
      return path;
    }
    for (int w : around[v]) {
      const double dw = d + length(v, w);
      const auto it = reach.find(w);
      if (it == reach.end() || dw < it->second.first) reach[w] = {dw, v}, queue.push({dw, w});
    }
  }
  return {};
}

SegmentSpread segmentSpread(const Segmentation& sg, int segment) {
  const TriMesh& m = sg.mesh;
  SegmentSpread out;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int t : sg.segments[size_t(segment)].triangles) {
    const Eigen::Vector3d a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
    const double at = 0.5 * (b - a).cross(c - a).norm();
    const Eigen::Vector3d mid = (a + b + c) / 3;
    out.center += at * mid, second += at * mid * mid.transpose(), out.area += at;
  }
  if (!(out.area > 0)) return out;
  out.center /= out.area;
  out.axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(second / out.area - out.center * out.center.transpose())
                 .eigenvectors();
  return out;
}

std::vector<int> cutAlong(const Segmentation& sg, int segment, double minFlatShare) {
  if (segment < 0 || segment >= int(sg.segments.size())) return {};
  const Segment& s = sg.segments[size_t(segment)];
  if (s.loops.size() != 1) return {};
  const TriMesh& m = sg.mesh;
  const auto length = [&](int a, int b) { return (m.V.row(a) - m.V.row(b)).norm(); };
  const std::vector<int>& loop = s.loops[0].vertices;
  std::unordered_map<int, double> arc;  // loop vertex -> arc length from the loop's first vertex
  std::set<std::pair<int, int>> loopEdges;
  double loopLength = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    // A vertex twice on the loop (the segment on both sides of a seam) keeps its first place.
    arc.emplace(loop[i], loopLength);
    loopEdges.insert(std::minmax(loop[i], loop[(i + 1) % loop.size()]));
    loopLength += length(loop[i], loop[(i + 1) % loop.size()]);
  }
  // The segment's flattest direction (a curled tail's plane's normal) and each vertex's normal: the cut runs where the
  // surface is seen edge-on from that direction, along the inner and the outer side of the curl, as two mirror pieces
  // of a curled tube are sewn.
  const SegmentSpread spread = segmentSpread(sg, segment);
  if (!(spread.area > 0)) return {};
  const Eigen::Vector3d flattest = spread.axes.col(0);
  std::unordered_map<int, std::vector<int>> around;
  std::unordered_map<int, Eigen::Vector3d> normal;
  for (int t : s.triangles) {
    const Eigen::Vector3d a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) {
      const int u = m.F(t, k), v = m.F(t, (k + 1) % 3);
      if (!loopEdges.count(std::minmax(u, v))) around[u].push_back(v), around[v].push_back(u);
      normal.try_emplace(u, Eigen::Vector3d::Zero()).first->second += n;
    }
  }
  const auto facing = [&](int v) { return std::abs(normal.at(v).normalized().dot(flattest)); };
  // Dijkstra from `sources` through inside vertices (a loop vertex is reached, not gone on from), an edge weighing its
  // length, times 1 + kFacing x its ends' mean facing when `edgeOn`: vertex -> (distance, previous).
  constexpr double kFacing = 10;
  using Reach = std::unordered_map<int, std::pair<double, int>>;
  const auto paths = [&](const std::vector<int>& sources, bool edgeOn) {
    Reach reach;
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (int v : sources) reach[v] = {0, -1}, queue.push({0, v});
    while (!queue.empty()) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > reach.at(v).first) continue;
      if (reach.at(v).second >= 0 && arc.count(v)) continue;
      for (int w : around[v]) {
        const double weight = edgeOn ? 1 + 0.5 * kFacing * (facing(v) + facing(w)) : 1;
        const double dw = d + weight * length(v, w);
        const auto it = reach.find(w);
        if (it == reach.end() || dw < it->second.first) reach[w] = {dw, v}, queue.push({dw, w});
      }
    }
    return reach;
  };
  const Reach fromLoop = paths(loop, false);
  int tip = -1;
  for (const auto& [v, r] : fromLoop)
    if (!arc.count(v) &&
        (tip < 0 || r.first > fromLoop.at(tip).first || (r.first == fromLoop.at(tip).first && v < tip)))
      tip = v;
  if (tip < 0) return {};
  const Reach fromTip = paths({tip}, true);
  // Down to the nearest loop vertex, and to the nearest of those a third of the loop or more along from it: the other
  // side's.
  int a = -1, b = -1;
  for (int v : loop)
    if (fromTip.count(v) && (a < 0 || fromTip.at(v).first < fromTip.at(a).first)) a = v;
  if (a < 0) return {};
  for (int v : loop) {
    const double d = std::abs(arc.at(v) - arc.at(a));
    if (fromTip.count(v) && std::min(d, loopLength - d) >= loopLength / 3 &&
        (b < 0 || fromTip.at(v).first < fromTip.at(b).first))
      b = v;
  }
  if (b < 0) return {};
  const auto down = [&](int v) {
    std::vector<int> path;
    for (int w = v; w >= 0; w = fromTip.at(w).second) path.push_back(w);
    std::reverse(path.begin(), path.end());  // from the tip
    return path;
  };
  const std::vector<int> toA = down(a), toB = down(b);
  size_t shared = 1;  // both begin at the tip
  while (shared < toA.size() && shared < toB.size() && toA[shared] == toB[shared]) ++shared;
  std::vector<int> path(toA.rbegin(), toA.rend() - long(shared) + 1);  // a up to where the ways part
  path.insert(path.end(), toB.begin() + long(shared), toB.end());
  // The two pieces: the segment's triangles joined across its inside edges but the cut's, each with its area and the
  // length of its outline (its part of the loop and the cut).
  std::set<std::pair<int, int>> cutEdges;
  for (size_t i = 0; i + 1 < path.size(); ++i) cutEdges.insert(std::minmax(path[i], path[i + 1]));
  const int triangles = int(s.triangles.size());
  UnionFind pieces(triangles);
  std::map<std::pair<int, int>, int> firstBeside;
  for (int i = 0; i < triangles; ++i)
    for (int k = 0; k < 3; ++k) {
      const int t = s.triangles[size_t(i)];
      const auto edge = std::minmax(m.F(t, k), m.F(t, (k + 1) % 3));
      if (cutEdges.count(edge) || loopEdges.count(edge)) continue;
      const auto [it, added] = firstBeside.emplace(edge, i);
      if (!added) pieces.unite(i, it->second);
    }
  std::map<int, std::pair<double, double>> pieceSize;  // piece -> (area, outline length)
  for (int i = 0; i < triangles; ++i) {
    const int t = s.triangles[size_t(i)];
    const Eigen::Vector3d p0 = m.V.row(m.F(t, 0)), p1 = m.V.row(m.F(t, 1)), p2 = m.V.row(m.F(t, 2));
    auto& [pieceArea, outline] = pieceSize[pieces.find(i)];
    pieceArea += 0.5 * (p1 - p0).cross(p2 - p0).norm();
    for (int k = 0; k < 3; ++k) {
      const int u = m.F(t, k), v = m.F(t, (k + 1) % 3);
      if (cutEdges.count(std::minmax(u, v)) || loopEdges.count(std::minmax(u, v))) outline += length(u, v);
    }
  }
  if (pieceSize.size() != 2) return {};
  for (const auto& [piece, size] : pieceSize)
    if (size.second * size.second / (4 * M_PI * size.first) < minFlatShare) return {};
  return path;
}

}  // namespace billow
