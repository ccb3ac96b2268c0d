#include "suggest/creases.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

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

// A crease spread over a bevel (a modeller's rounded edge: a foil letter's or a cushion's rim, a CAD part's fillet):
// rows of edges along it, each turning a little, that turn kCreaseTurn or more together within kWidestBevel of the
// diagonal. Convex bevels only: a concave fillet is as rare on a designer's shape as a smooth valley is common.
constexpr double kLeastRowTurn = 0.035;  // a row turns 2 degrees or more
constexpr double kWidestBevel = 0.06;    // of the diagonal (a 2 cm radius at 0.6 m: 4 %)
// A band that turns more is round a tube or a thin fin's rim, not along a fold (a star's tip turns 144 degrees).
constexpr double kMostBandTurn = 2.62;  // 150 degrees
// A bevel's crease runs on: its rows that join up shorter than this share of the diagonal are an organic mesh's chance
// (a coarse fish's fin), left out; so are their loose ends' gaps.
constexpr double kLongChain = 0.1;

struct EdgeFrame {
  Eigen::Vector3d middle, along;  // unit along
  bool convex = true;
};

// Edge e's band: the plane through its middle across it meets the other rows (edges along e turning the same way by
// kLeastRowTurn or more); those next to each other (no gap wider than two of the local edge lengths) make the band.
// e carries its crease if it is the band's middle row: where the turn, summed from the band's negative end, passes half
// of it (of two middle rows, the one on the negative side; offsets count positive along the first of z, y, x the band
// runs across, so that every edge of a bevel picks the same, where a fixed direction would flip round a rim). Also the
// band is narrower than kWidestBevel, turns at most kMostBandTurn, and the surface just beyond it turns by less than
// kSmoothBeside of the band's turn. Returns the band's turn [rad] and width (0 where e is not a bevel's middle row).
struct Band {
  double turn = 0, width = 0;
};

// What bevelBand marks as walked, cleared where it walked after each edge (every edge's walk is a few faces).
struct BandScratch {
  std::vector<char> seenFace, seenEdge;
  std::vector<int> faces, edges;
};

Band bevelBand(const TriMesh& target, const MeshTopology& topo, const std::vector<double>& bend,
               const std::vector<EdgeFrame>& frame, int e, double diagonal, BandScratch& scratch) {
  const EdgeFrame& edge = frame[size_t(e)];
  const Eigen::Vector3d m = edge.middle, t = edge.along;
  if (!edge.convex) return {};
  Eigen::Vector3d side = Eigen::Vector3d::Zero();  // across e, towards face 0
  for (int k = 0; k < 3; ++k) side += target.V.row(target.F(topo.edgeFaces(e, 0), k)).transpose();
  side = side / 3 - m, side -= side.dot(t) * t;
  const Eigen::Vector3d across = side.normalized();
  const int axis = std::abs(across.z()) > 0.1 ? 2 : std::abs(across.y()) > 0.1 ? 1 : 0;
  if (across[axis] < 0) side = -side;
  double spacing = 0;
  for (int s = 0; s < 2; ++s)
    for (int k = 0; k < 3; ++k) {
      const int g = topo.faceEdges(topo.edgeFaces(e, s), k);
      spacing = std::max(spacing, (target.V.row(topo.E(g, 0)) - target.V.row(topo.E(g, 1))).norm());
    }
  const double reach = kWidestBevel * diagonal + 2 * spacing;
  // The plane's crossings of edges along e, walked from e's faces across the edges it crosses: (offset, the turn of a
  // row, or minus the turn of another edge).
  std::vector<std::pair<double, double>> crossings;
  std::vector<char>&seenFace = scratch.seenFace, &seenEdge = scratch.seenEdge;
  std::vector<int>&faces = scratch.faces, &edges = scratch.edges;
  seenFace.resize(size_t(target.F.rows()), 0), seenEdge.resize(size_t(topo.numEdges()), 0);
  faces = {topo.edgeFaces(e, 0), topo.edgeFaces(e, 1)}, edges = {e};
  seenFace[size_t(faces[0])] = seenFace[size_t(faces[1])] = 1, seenEdge[size_t(e)] = 1;
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int g = topo.faceEdges(faces[i], k);
      const Eigen::Vector3d a = target.V.row(topo.E(g, 0)), b = target.V.row(topo.E(g, 1));
      const double da = (a - m).dot(t), db = (b - m).dot(t);
      if ((da > 0) == (db > 0) && da != 0 && db != 0) continue;
      const Eigen::Vector3d q = a + da / (da - db) * (b - a);
      if ((q - m).norm() > reach) continue;
      if (!seenEdge[size_t(g)] && std::abs(frame[size_t(g)].along.dot(t)) > 0.9) {
        const double offset = (q - m).dot(side) > 0 ? (q - m).norm() : -(q - m).norm();
        const bool row = bend[size_t(g)] >= kLeastRowTurn && frame[size_t(g)].convex;
        crossings.push_back({offset, row ? bend[size_t(g)] : -bend[size_t(g)]});
      }
      if (!seenEdge[size_t(g)]) seenEdge[size_t(g)] = 1, edges.push_back(g);
      for (int s = 0; s < 2; ++s)
        if (const int h = topo.edgeFaces(g, s); !seenFace[size_t(h)]) seenFace[size_t(h)] = 1, faces.push_back(h);
    }
  for (int f : faces) seenFace[size_t(f)] = 0;
  for (int g : edges) seenEdge[size_t(g)] = 0;
  std::sort(crossings.begin(), crossings.end());
  double turn = bend[size_t(e)], below = 0, lo = 0, hi = 0, beyond = 0;
  for (int dir = -1; dir <= 1; dir += 2) {
    double last = 0;
    bool open = true;
    for (size_t i = 0; i < crossings.size(); ++i) {
      const auto& [offset, r] = crossings[dir > 0 ? i : crossings.size() - 1 - i];
      if (dir * offset <= 0) continue;
      if (open && std::abs(offset - last) > 2 * spacing) open = false;
      if (open && r > 0) {
        turn += r, last = offset;
        if (dir < 0)
          below += r, lo = offset;
        else
          hi = offset;
      } else if (!open && std::abs(offset - last) <= 1.5 * spacing) {
        beyond = std::max(beyond, std::abs(r));
      }
    }
  }
  if (turn < kCreaseTurn || turn > kMostBandTurn || hi - lo > kWidestBevel * diagonal || beyond >= kSmoothBeside * turn)
    return {};
  if (!(below < 0.49 * turn && below + bend[size_t(e)] >= 0.49 * turn)) return {};
  return {turn, hi - lo};
}

// The loose ends of the `sharp` edges' chains, for joining them on (bridgeLooseEnds, closeGaps): each vertex's count of
// sharp edges, and its own chain near an end, not to be joined to.
struct LooseEnds {
  const TriMesh& target;
  const MeshTopology& topo;
  const std::vector<char>& sharp;
  std::vector<int> degree;
  std::vector<double> own;  // along the sharp edges from the end being joined, within ownChain's reach (else infinite)
  std::vector<int> touched;

  LooseEnds(const TriMesh& t, const MeshTopology& g, const std::vector<char>& s)
      : target(t), topo(g), sharp(s), degree(size_t(t.V.rows()), 0), own(size_t(t.V.rows()), INFINITY) {
    for (int e = 0; e < topo.numEdges(); ++e)
      if (sharp[size_t(e)]) add(e);
  }
  double length(int e) const { return (target.V.row(topo.E(e, 0)) - target.V.row(topo.E(e, 1))).norm(); }
  void add(int e) { ++degree[size_t(topo.E(e, 0))], ++degree[size_t(topo.E(e, 1))]; }
  // Whether the chain runs `least` (a length) up to its loose end `end`.
  bool chainRuns(int end, double least) const {
    double chain = 0;
    for (int v = end, from = -1, next = -1; chain < least; from = v, v = next) {
      next = -1;
      for (const auto& [u, e] : topo.neighbors[size_t(v)])
        if (sharp[size_t(e)] && u != from) next = u, chain += length(e);
      if (next < 0 || degree[size_t(next)] != 2) break;
    }
    return chain >= least;
  }
  // `own` set along the sharp edges from `end` within `reach`; forgetOwn() clears it.
  void ownChain(int end, double reach) {
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    own[size_t(end)] = 0, touched.push_back(end), queue.push({0, end});
    while (!queue.empty()) {
      const auto [dv, v] = queue.top();
      queue.pop();
      if (dv > own[size_t(v)]) continue;
      for (const auto& [u, e] : topo.neighbors[size_t(v)])
        if (sharp[size_t(e)] && dv + length(e) < own[size_t(u)] && dv + length(e) <= reach)
          own[size_t(u)] = dv + length(e), touched.push_back(u), queue.push({own[size_t(u)], u});
    }
  }
  void forgetOwn() {
    for (int v : touched) own[size_t(v)] = INFINITY;
    touched.clear();
  }
};

// Where a bevel's crease reaches a corner, its middle row ends short of the other creases there (a rounded corner is a
// patch of its own, a mitred one has its own edges). Each loose end of a crease that runs kLongChain of the diagonal up
// to it is joined to the nearest vertex of another crease within the bevel's width and two edges (either crease's
// bevel: a sharp crease meets only a bevel's so), by the shortest path along the edges.
void bridgeLooseEnds(const TriMesh& target, const MeshTopology& topo, std::vector<char>& sharp,
                     const std::vector<double>& bevelWidth, double diagonal) {
  const int nv = int(target.V.rows());
  LooseEnds ends(target, topo, sharp);
  const auto bevelAt = [&](int v) {
    double w = 0;
    for (const auto& [u, e] : topo.neighbors[size_t(v)])
      if (sharp[size_t(e)]) w = std::max(w, bevelWidth[size_t(e)]);
    return w;
  };
  std::vector<double> d(size_t(nv), INFINITY);
  std::vector<int> via(size_t(nv), -1), reached;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int end = 0; end < nv; ++end) {
    if (ends.degree[size_t(end)] != 1 || !ends.chainRuns(end, kLongChain * diagonal)) continue;
    double spacing = 0;
    for (const auto& [u, e] : topo.neighbors[size_t(end)]) spacing = std::max(spacing, 2 * ends.length(e));
    const double ownWidth = bevelAt(end), reach = kWidestBevel * diagonal + spacing;
    ends.ownChain(end, 2 * reach);
    int found = -1;
    d[size_t(end)] = 0, reached.push_back(end), queue.push({0, end});
    while (!queue.empty()) {
      const auto [dv, v] = queue.top();
      queue.pop();
      if (dv > d[size_t(v)]) continue;
      const double width = std::max(ownWidth, bevelAt(v));
      if (v != end && ends.degree[size_t(v)] > 0 && !std::isfinite(ends.own[size_t(v)]) && width > 0 &&
          dv <= width + spacing) {
        found = v;
        break;
      }
      for (const auto& [u, e] : topo.neighbors[size_t(v)])
        if (dv + ends.length(e) < d[size_t(u)] && dv + ends.length(e) <= reach)
          d[size_t(u)] = dv + ends.length(e), via[size_t(u)] = e, reached.push_back(u), queue.push({d[size_t(u)], u});
    }
    queue = {};
    for (int v = found; v >= 0 && v != end;) {
      const int e = via[size_t(v)];
      if (!sharp[size_t(e)]) sharp[size_t(e)] = 1, ends.add(e);
      v = topo.E(e, 0) == v ? topo.E(e, 1) : topo.E(e, 0);
    }
    for (int v : reached) d[size_t(v)] = INFINITY, via[size_t(v)] = -1;
    reached.clear();
    ends.forgetOwn();
  }
}

// A fold's chain of sharp edges breaks where an edge along it turns as much but a short or skewed face beside it turns
// too (a remeshed part's rim: the wing nut of odedstein/meshes had its sharp edges in 30 chains with 62 loose ends, all
// peeled away). Each loose end of a chain that runs kLongChain up to it (an organic mesh's sharp edges come in short
// chains) goes on along convex edges turning kCreaseTurn or more, at most kGapEdges of them, where that reaches another
// crease, or its own one farther along it than a short crease and a few edges (a gap in a loop, not a detour round a
// face). Where the fold rounds off into a fillet the chain still ends: a path across it on to the nearest crease also
// joined the stuffed toy's neck and a goat's horn.
constexpr int kGapEdges = 2;

void closeGaps(const TriMesh& target, const MeshTopology& topo, const std::vector<double>& bend,
               const std::vector<EdgeFrame>& frame, std::vector<char>& sharp, double diagonal) {
  LooseEnds ends(target, topo, sharp);
  for (int end = 0; end < int(target.V.rows()); ++end) {
    if (ends.degree[size_t(end)] != 1 || !ends.chainRuns(end, kLongChain * diagonal)) continue;
    // Its own chain within a short crease's length and a few edges: no gap to close there (a detour round a face).
    double spacing = 0;
    for (const auto& [u, e] : topo.neighbors[size_t(end)]) spacing = std::max(spacing, ends.length(e));
    ends.ownChain(end, kShortestCrease * diagonal + (kGapEdges + 2) * spacing);
    // Breadth first along the edges that turn as much, kGapEdges deep.
    std::vector<int> layer = {end}, next;
    std::vector<std::vector<int>> paths = {{}};  // the edges to each vertex of the layer
    std::vector<int> found;
    for (int depth = 0; depth < kGapEdges && found.empty(); ++depth) {
      std::vector<std::vector<int>> longer;
      next.clear();
      for (size_t i = 0; i < layer.size() && found.empty(); ++i) {
        for (const auto& [u, e] : topo.neighbors[size_t(layer[i])]) {
          if (sharp[size_t(e)] || !(bend[size_t(e)] >= kCreaseTurn) || !frame[size_t(e)].convex || u == end) continue;
          std::vector<int> path = paths[i];
          path.push_back(e);
          if (ends.degree[size_t(u)] > 0 && !std::isfinite(ends.own[size_t(u)])) {
            found = std::move(path);
            break;
          }
          if (ends.degree[size_t(u)] == 0) next.push_back(u), longer.push_back(std::move(path));
        }
      }
      layer.swap(next), paths.swap(longer);
    }
    for (int e : found) sharp[size_t(e)] = 1, ends.add(e);
    ends.forgetOwn();
  }
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
  const double diagonal = (target.V.colwise().maxCoeff() - target.V.colwise().minCoeff()).norm();
  std::vector<EdgeFrame> frame(static_cast<size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    const Eigen::Vector3d a = target.V.row(topo.E(e, 0)), b = target.V.row(topo.E(e, 1));
    frame[size_t(e)].middle = (a + b) / 2, frame[size_t(e)].along = (b - a).normalized();
    // Convex where face 1's far corner lies behind face 0's plane.
    Eigen::Vector3d far = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) far += target.V.row(target.F(topo.edgeFaces(e, 1), k)).transpose();
    frame[size_t(e)].convex = (far / 3 - a).dot(normal.row(topo.edgeFaces(e, 0)).transpose()) < 0;
  }
  // Sharp edges (1), and bevels' middle rows (2) with their bevels' widths.
  std::vector<char> sharp(size_t(ne), 0);
  std::vector<double> bevelWidth(size_t(ne), 0);
  BandScratch scratch;
  for (int e = 0; e < ne; ++e) {
    if (!(bend[size_t(e)] >= kLeastRowTurn)) continue;
    bool smooth = bend[size_t(e)] >= kCreaseTurn;
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k < 3; ++k) {
        const double t = bend[size_t(topo.faceEdges(topo.edgeFaces(e, side), k))];
        smooth = smooth && (t >= kCreaseTurn || t < kSmoothBeside * bend[size_t(e)]);
      }
    const Band band = bevelBand(target, topo, bend, frame, e, diagonal, scratch);
    bevelWidth[size_t(e)] = band.width;  // 0 for a sharp edge alone
    sharp[size_t(e)] = smooth ? 1 : band.turn > 0 ? 2 : 0;
  }
  UnionFind rows(int(target.V.rows()));
  for (int e = 0; e < ne; ++e)
    if (bevelWidth[size_t(e)] > 0) rows.unite(topo.E(e, 0), topo.E(e, 1));
  std::vector<double> run(size_t(target.V.rows()), 0);
  for (int e = 0; e < ne; ++e)
    if (bevelWidth[size_t(e)] > 0)
      run[size_t(rows.find(topo.E(e, 0)))] += (target.V.row(topo.E(e, 0)) - target.V.row(topo.E(e, 1))).norm();
  for (int e = 0; e < ne; ++e)
    if (bevelWidth[size_t(e)] > 0 && run[size_t(rows.find(topo.E(e, 0)))] < kLongChain * diagonal) {
      bevelWidth[size_t(e)] = 0;
      if (sharp[size_t(e)] == 2) sharp[size_t(e)] = 0;
    }
  closeGaps(target, topo, bend, frame, sharp, diagonal);
  bridgeLooseEnds(target, topo, sharp, bevelWidth, diagonal);
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
