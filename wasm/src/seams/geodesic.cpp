// Approximate geodesics: Dijkstra corridor, funnel, vertex flip-outs (see geodesic.hpp).
#include "seams/geodesic.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>

#include "seams/funnel.hpp"

namespace billow {

namespace {

// Faces around v from `from` to `to` (both included) turning in direction dir; empty if not reached.
std::vector<int> fan(const TriMesh& m, const MeshTopology& topo, int v, int from, int to, int dir) {
  std::vector<int> out{from};
  for (int f = from, guard = 0; f != to; ++guard) {
    f = topo.rotate(m, f, v, dir);
    if (f < 0 || guard > 256 || f == from) return {};
    out.push_back(f);
  }
  return out;
}

std::vector<int> shorterFan(const TriMesh& m, const MeshTopology& topo, int v, int from, int to) {
  std::vector<int> a = fan(m, topo, v, from, to, +1), b = fan(m, topo, v, from, to, -1);
  if (a.empty() || (!b.empty() && b.size() < a.size())) return b;
  return a;
}

void append(std::vector<int>& strip, const std::vector<int>& faces) {
  for (int f : faces)
    if (strip.empty() || strip.back() != f) strip.push_back(f);
}

// A strip that visits a face twice is shortened to visit it once (the path in between can only be longer).
void removeLoops(std::vector<int>& strip) {
  std::unordered_map<int, int> seen;
  std::vector<int> out;
  for (int f : strip) {
    auto it = seen.find(f);
    if (it != seen.end()) {
      while (static_cast<int>(out.size()) > it->second + 1) seen.erase(out.back()), out.pop_back();
      continue;
    }
    seen[f] = static_cast<int>(out.size());
    out.push_back(f);
  }
  strip.swap(out);
}

// Drops strip ends that the end points do not need (an end on a vertex or edge shared with the next face).
void trimEnds(const TriMesh& m, const MeshTopology& topo, std::vector<int>& strip, SurfacePoint& a, SurfacePoint& b) {
  SurfacePoint moved;
  size_t first = 0;
  while (first + 1 < strip.size() && expressInFace(m, topo, a, strip[first + 1], moved)) a = moved, ++first;
  strip.erase(strip.begin(), strip.begin() + first);
  while (strip.size() > 1 && expressInFace(m, topo, b, strip[strip.size() - 2], moved)) b = moved, strip.pop_back();
}

bool hasVertex(const TriMesh& m, int f, int v) { return m.F(f, 0) == v || m.F(f, 1) == v || m.F(f, 2) == v; }

// Moves the corridor to the other side of every vertex the path wraps needlessly; false if none.
bool flipOut(const TriMesh& m, const MeshTopology& topo, const StripPath& sp, std::vector<int>& strip) {
  bool changed = false;
  int barrier = static_cast<int>(strip.size());  // wraps are handled back to front, runs never overlap
  for (auto w = sp.wraps.rbegin(); w != sp.wraps.rend(); ++w) {
    const double other = topo.angleSum[w->vertex] - (M_PI + w->turn);
    if (other >= M_PI - 1e-9) continue;
    int i = w->portal - 1, j = w->portal;
    if (i < 0 || j >= barrier || !hasVertex(m, strip[i], w->vertex) || !hasVertex(m, strip[j], w->vertex)) continue;
    while (i > 0 && hasVertex(m, strip[i - 1], w->vertex)) --i;
    while (j + 1 < barrier && hasVertex(m, strip[j + 1], w->vertex)) ++j;
    const int dir = topo.rotate(m, strip[i], w->vertex, +1) == strip[i + 1] ? +1 : -1;
    const std::vector<int> side = fan(m, topo, w->vertex, strip[i], strip[j], -dir);
    if (side.empty()) continue;
    strip.erase(strip.begin() + i, strip.begin() + j + 1);
    strip.insert(strip.begin() + i, side.begin(), side.end());
    barrier = i;
    changed = true;
  }
  return changed;
}

}  // namespace

GeodesicSolver::GeodesicSolver(const TriMesh& mesh, const MeshTopology& topology) : mesh_(mesh), topo_(topology) {}

std::vector<int> GeodesicSolver::vertexPath(const SurfacePoint& a, const SurfacePoint& b, int onlyVertex) const {
  const int nv = mesh_.numVertices();
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::vector<int> prev(nv, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  const Eigen::Vector3d pa = position(mesh_, a), pb = position(mesh_, b);
  for (int k = 0; k < 3; ++k) {
    const int v = mesh_.F(a.face, k);
    dist[v] = (mesh_.V.row(v).transpose() - pa).norm();
    queue.push({dist[v], v});
  }
  double best = std::numeric_limits<double>::infinity();
  int bestV = -1;
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    if (d >= best) break;
    if (onlyVertex >= 0 ? v == onlyVertex : hasVertex(mesh_, b.face, v)) {
      const double total = d + (mesh_.V.row(v).transpose() - pb).norm();
      if (total < best) best = total, bestV = v;
    }
    for (const auto& [u, e] : topo_.neighbors[v]) {
      const double du = d + (mesh_.V.row(u) - mesh_.V.row(v)).norm();
      if (du < dist[u]) dist[u] = du, prev[u] = v, queue.push({du, u});
    }
  }
  std::vector<int> path;
  for (int v = bestV; v >= 0; v = prev[v]) path.insert(path.begin(), v);
  return path;
}

// Triangles left of the Dijkstra path (plus fans to the end faces): they contain the edge path.
std::vector<int> GeodesicSolver::corridor(const SurfacePoint& a, const SurfacePoint& b) const {
  if (a.face == b.face) return {a.face};
  const std::vector<int> vs = vertexPath(a, b);
  if (vs.empty()) return {};
  const int k = static_cast<int>(vs.size()) - 1;
  std::vector<int> left(k);  // left[i]: the face holding the half-edge vs[i] -> vs[i+1]
  for (int i = 0; i < k; ++i) {
    const int e = topo_.edgeBetween(vs[i], vs[i + 1]);
    const int f = topo_.edgeFaces(e, 0), c = topo_.cornerOf(mesh_, f, vs[i]);
    left[i] = mesh_.F(f, (c + 1) % 3) == vs[i + 1] ? f : topo_.edgeFaces(e, 1);
  }
  std::vector<int> strip;
  if (k == 0) return shorterFan(mesh_, topo_, vs[0], a.face, b.face);
  append(strip, shorterFan(mesh_, topo_, vs[0], a.face, left[0]));
  for (int i = 1; i < k; ++i) append(strip, fan(mesh_, topo_, vs[i], left[i - 1], left[i], +1));
  append(strip, shorterFan(mesh_, topo_, vs[k], left[k - 1], b.face));
  return strip;
}

GeodesicPath GeodesicSolver::path(const SurfacePoint& a0, const SurfacePoint& b0,
                                  const GeodesicOptions& options) const {
  std::vector<int> strip = corridor(a0, b0);
  SurfacePoint a = a0, b = b0;
  removeLoops(strip);

  if (strip.empty() || strip.front() != a.face || strip.back() != b.face) strip = {a.face}, b.face = -1;
  if (b.face < 0) {  // no corridor (cannot happen on a connected target): a straight piece in a's face
    GeodesicPath g;
    g.points.resize(2);
    g.points[0].point = a0, g.points[1].point = b0;
    g.points[0].position = position(mesh_, a0), g.points[1].position = position(mesh_, b0);
    g.faces = {a0.face};
    g.length = (g.points[1].position - g.points[0].position).norm();
    return g;
  }
  trimEnds(mesh_, topo_, strip, a, b);
  StripPath best = straightenInStrip(mesh_, topo_, strip, a, b);
  int it = 1;
  for (; it < options.maxIterations; ++it) {
    if (!flipOut(mesh_, topo_, best, strip)) break;
    removeLoops(strip);  // keeps the end faces, so a and b stay expressed in them
    trimEnds(mesh_, topo_, strip, a, b);
    StripPath next = straightenInStrip(mesh_, topo_, strip, a, b);
    if (!(next.path.length < best.path.length * (1 - 1e-12))) break;
    best = std::move(next);
  }
  best.path.iterations = it;
  // keep the caller's own end points (exactly as given)
  best.path.points.front().point = a0;
  best.path.points.back().point = b0;
  return best.path;
}

double GeodesicSolver::edgeGraphDistance(int v0, int v1) const {
  const std::vector<int> vs = vertexPath(vertexPoint(mesh_, topo_, v0), vertexPoint(mesh_, topo_, v1), v1);
  if (vs.empty()) return 0;
  double length = (mesh_.V.row(v0) - mesh_.V.row(vs[0])).norm();  // corners of a face are edge neighbours
  for (size_t i = 0; i + 1 < vs.size(); ++i) length += (mesh_.V.row(vs[i]) - mesh_.V.row(vs[i + 1])).norm();
  return length;
}

}  // namespace billow
