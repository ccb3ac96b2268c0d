#include "suggest/creases.hpp"

#include <algorithm>
#include <cmath>

#include "util/union_find.hpp"

namespace billow {

namespace {

// A set of creases that meet is kept when its length is at least this share of the target's diagonal: a facet's few
// sharp edges are not a fold a designer would sew along.
constexpr double kLeastCreaseShare = 0.5;
// A crease shorter than this share of the diagonal (a seam point spacing) would be a sliver's side: left out.
constexpr double kShortestCrease = 0.02;
// A crease is smooth on either side: the other edges of its two faces turn by less than this share of its own turn
// (the generated box, drum and star cushions: under 0.08; the shared meshes' edges that turn 40 degrees or more: a
// median of 0.11-0.43 of theirs, bench/README.md "Suggested seam layouts").
constexpr double kSmoothBeside = 0.15;

// The creases along the `sharp` edges: peeled from their loose ends (a crease that fades out), walked from junction to
// junction and round the loops left; a chain shorter than kShortestCrease left out and the rest walked again (a
// sliver's side); the sets that meet kept when long enough.
Creases creasesAlong(const TriMesh& target, const MeshTopology& topo, std::vector<char> sharp) {
  const int nv = int(target.V.rows()), ne = topo.numEdges();
  const double diagonal = (target.V.colwise().maxCoeff() - target.V.colwise().minCoeff()).norm();
  std::vector<Crease> creases;
  std::vector<int> degree;
  for (bool again = true; again;) {
    degree.assign(size_t(nv), 0);
    for (int e = 0; e < ne; ++e)
      if (sharp[size_t(e)]) ++degree[size_t(topo.E(e, 0))], ++degree[size_t(topo.E(e, 1))];
    std::vector<int> loose;
    for (int v = 0; v < nv; ++v)
      if (degree[size_t(v)] == 1) loose.push_back(v);
    while (!loose.empty()) {
      const int v = loose.back();
      loose.pop_back();
      if (degree[size_t(v)] != 1) continue;
      for (const auto& [u, e] : topo.neighbors[size_t(v)])
        if (sharp[size_t(e)]) {
          sharp[size_t(e)] = 0, --degree[size_t(v)];
          if (--degree[size_t(u)] == 1) loose.push_back(u);
          break;
        }
    }
    std::vector<char> walked(size_t(ne), 0);
    creases.clear();
    // Walks from `from` along edge e until a junction, or back to `from` round a loop; the crease and its edges.
    const auto walk = [&](int from, int e, std::vector<int>& edges) {
      Crease c;
      c.vertices.push_back(from);
      for (int v = from;;) {
        walked[size_t(e)] = 1, edges.push_back(e);
        const int u = topo.E(e, 0) == v ? topo.E(e, 1) : topo.E(e, 0);
        c.length += (target.V.row(u) - target.V.row(v)).norm();
        if (u == from && degree[size_t(u)] == 2) {
          c.closed = true;
          break;
        }
        c.vertices.push_back(u);
        if (degree[size_t(u)] != 2) break;
        int next = -1;
        for (const auto& [w, f] : topo.neighbors[size_t(u)])
          if (sharp[size_t(f)] && !walked[size_t(f)]) next = f;
        if (next < 0) break;
        v = u, e = next;
      }
      return c;
    };
    again = false;
    const auto add = [&](int from, int e) {
      std::vector<int> edges;
      Crease c = walk(from, e, edges);
      if (c.length < kShortestCrease * diagonal) {
        for (int k : edges) sharp[size_t(k)] = 0;
        again = true;
      }
      creases.push_back(std::move(c));
    };
    for (int v = 0; v < nv; ++v)
      if (degree[size_t(v)] >= 3)
        for (const auto& [u, e] : topo.neighbors[size_t(v)])
          if (sharp[size_t(e)] && !walked[size_t(e)]) add(v, e);
    for (int e = 0; e < ne; ++e)
      if (sharp[size_t(e)] && !walked[size_t(e)]) add(topo.E(e, 0), e);
  }
  // Each set of creases that meet bounds E - V + 1 more regions (Euler on the sphere; a loop is one edge and one
  // vertex).
  Creases out;
  UnionFind sets(nv);
  for (const Crease& c : creases)
    for (int v : c.vertices) sets.unite(c.vertices.front(), v);
  std::vector<double> setLength(size_t(nv), 0);
  for (const Crease& c : creases) setLength[size_t(sets.find(c.vertices.front()))] += c.length;
  const auto kept = [&](int v) { return setLength[size_t(sets.find(v))] >= kLeastCreaseShare * diagonal; };
  std::vector<int> vertices(size_t(nv), 0), edges(size_t(nv), 0);
  for (const Crease& c : creases) {
    if (!kept(c.vertices.front())) continue;
    ++edges[size_t(sets.find(c.vertices.front()))];
    if (c.closed) ++vertices[size_t(sets.find(c.vertices.front()))];
    out.creases.push_back(c);
  }
  for (int v = 0; v < nv; ++v)
    if (degree[size_t(v)] >= 3 && kept(v)) ++vertices[size_t(sets.find(v))];
  for (int v = 0; v < nv; ++v)
    if (edges[size_t(v)] > 0) out.panels += edges[size_t(v)] - vertices[size_t(v)] + 1;
  std::sort(out.creases.begin(), out.creases.end(),
            [](const Crease& a, const Crease& b) { return a.length > b.length; });
  return out;
}

}  // namespace

std::vector<Creases> findCreases(const TriMesh& target, int axis, double mid) {
  std::vector<Creases> out;
  if (target.F.rows() == 0) return out;
  const MeshTopology topo = buildTopology(target);
  const int ne = topo.numEdges();
  Eigen::MatrixX3d normal(target.F.rows(), 3);
  for (int f = 0; f < target.F.rows(); ++f) {
    const Eigen::Vector3d a = target.V.row(target.F(f, 0)), b = target.V.row(target.F(f, 1)),
                          c = target.V.row(target.F(f, 2));
    normal.row(f) = (b - a).cross(c - a).normalized().transpose();
  }
  std::vector<double> bend(static_cast<size_t>(ne));  // per edge, the turn across it [rad]
  for (int e = 0; e < ne; ++e)
    bend[size_t(e)] =
        std::acos(std::clamp(normal.row(topo.edgeFaces(e, 0)).dot(normal.row(topo.edgeFaces(e, 1))), -1.0, 1.0));
  std::vector<char> sharp(size_t(ne), 0);
  for (int e = 0; e < ne; ++e) {
    if (!(bend[size_t(e)] >= kCreaseTurn)) continue;
    bool smooth = true;
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k < 3; ++k) {
        const double t = bend[size_t(topo.faceEdges(topo.edgeFaces(e, side), k))];
        smooth = smooth && (t >= kCreaseTurn || t < kSmoothBeside * bend[size_t(e)]);
      }
    sharp[size_t(e)] = smooth;
  }
  // All of them, then fewer: the shortest left out, one at a time.
  for (Creases c = creasesAlong(target, topo, sharp); !c.creases.empty();) {
    if (out.empty() || c.panels < out.back().panels) out.push_back(c);
    size_t drop = c.creases.size() - 1;
    if (axis >= 0 && axis < 3) {
      double farthest = -1;
      for (size_t i = 0; i < c.creases.size(); ++i) {
        if (c.creases[i].length > c.creases.back().length * (1 + 1e-6)) continue;
        double at = 0;
        for (int v : c.creases[i].vertices) at += target.V(v, axis);
        if (const double d = std::abs(at / double(c.creases[i].vertices.size()) - mid); d > farthest)
          farthest = d, drop = i;
      }
    }
    for (int e : creaseEdges(topo, c.creases[drop])) sharp[size_t(e)] = 0;
    c = creasesAlong(target, topo, sharp);
  }
  return out;
}

std::vector<int> creaseEdges(const MeshTopology& topology, const Crease& crease) {
  const std::vector<int>& v = crease.vertices;
  std::vector<int> edges;
  for (size_t k = 0; k + 1 < v.size() + (crease.closed ? 1 : 0); ++k)
    edges.push_back(topology.edgeBetween(v[k], v[(k + 1) % v.size()]));
  return edges;
}

bool mirrorSymmetric(const TriMesh& target, const std::vector<Crease>& creases, int axis, double mid,
                     double tolerance) {
  std::vector<Eigen::Vector3d> points;
  for (const Crease& c : creases)
    for (int v : c.vertices) points.push_back(target.V.row(v).transpose());
  for (const Eigen::Vector3d& p : points) {
    Eigen::Vector3d q = p;
    q[axis] = 2 * mid - q[axis];
    if (std::none_of(points.begin(), points.end(),
                     [&](const Eigen::Vector3d& r) { return (r - q).norm() < tolerance; }))
      return false;
  }
  return true;
}

SectionLoop creasePath(const TriMesh& target, const MeshTopology& topo, const Crease& crease) {
  std::vector<int> v = crease.vertices;
  // A chain from a junction round to itself is walked as a loop through it.
  const bool loop = crease.closed || (v.size() > 2 && v.front() == v.back());
  if (loop && !crease.closed) v.pop_back();
  const size_t n = v.size();
  SectionLoop path;
  for (size_t k = 0; k < n; ++k) {
    // The face of the edge from the point before (the first point of a path: to the point after).
    const int a = k == 0 && !loop ? v[1] : v[(k + n - 1) % n];
    const int f = topo.edgeFaces(topo.edgeBetween(a, v[k]), 0);
    SectionPoint p;
    p.at.face = f, p.at.bary = Eigen::Vector3d::Unit(topo.cornerOf(target, f, v[k]));
    p.position = target.V.row(v[k]).transpose();
    path.push_back(p);
  }
  return path;
}

}  // namespace billow
