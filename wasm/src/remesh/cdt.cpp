// Constrained Delaunay triangulation: incremental Lawson insertion, Sloan's segment recovery by flips.
// Triangle t has vertices v[0..2] counter-clockwise; edge i is (v[i+1], v[i+2]), opposite v[i].
#include "remesh/cdt.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numeric>
#include <string>

#include "remesh/predicates.hpp"
#include "util/error.hpp"

namespace billow {

namespace {

inline int nx(int i) { return i == 2 ? 0 : i + 1; }
inline int pv(int i) { return i == 0 ? 2 : i - 1; }

int localIndex(const Cdt::Tri& t, int v) {
  for (int k = 0; k < 3; ++k)
    if (t.v[k] == v) return k;
  return -1;
}

// Position along a Hilbert curve on a 2^16 grid: nearby points get nearby keys, so walks stay short.
std::uint64_t hilbertKey(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0;
    const std::uint32_t ry = (y & s) ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant so the curve stays continuous
      if (rx == 1) {
        x = 65535u - x;
        y = 65535u - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

}  // namespace

Cdt::Cdt(const Pslg& pslg) {
  const int n = static_cast<int>(pslg.points.rows());
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(pslg.points(i, 0)) || !std::isfinite(pslg.points(i, 1)))
      throw Error("cdt.bad-point", "Point " + std::to_string(i) + " of the outline is not a finite number.");
  for (int s = 0; s < pslg.segments.rows(); ++s)
    for (int k = 0; k < 2; ++k)
      if (pslg.segments(s, k) < 0 || pslg.segments(s, k) >= n)
        throw Error("cdt.bad-segment", "Segment " + std::to_string(s) + " refers to a point that does not exist.");

  Eigen::Vector2d lo(0, 0), hi(0, 0);
  if (n > 0) {
    lo = pslg.points.colwise().minCoeff().transpose();
    hi = pslg.points.colwise().maxCoeff().transpose();
  }
  const Eigen::Vector2d mid = 0.5 * (lo + hi);
  double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  if (!(extent > 0)) extent = std::max(1.0, mid.norm());
  // A bounding triangle far enough that its vertices barely shape the triangles near the input.
  const double r = 64.0 * extent;
  pts_ = {mid + Eigen::Vector2d(-2 * r, -r), mid + Eigen::Vector2d(2 * r, -r), mid + Eigen::Vector2d(0, 2 * r)};
  vertTri_ = {0, 0, 0};
  Tri root;
  root.v = {0, 1, 2};
  root.n = {-1, -1, -1};
  root.c = {false, false, false};
  tris_.push_back(root);

  // Insert in Hilbert order so that each walk starts next to its target.
  std::vector<std::pair<std::uint64_t, int>> order(n);
  for (int i = 0; i < n; ++i) {
    const double fx = (pslg.points(i, 0) - lo.x()) / extent, fy = (pslg.points(i, 1) - lo.y()) / extent;
    const auto gx = static_cast<std::uint32_t>(std::clamp(fx, 0.0, 1.0) * 65535.0);
    const auto gy = static_cast<std::uint32_t>(std::clamp(fy, 0.0, 1.0) * 65535.0);
    order[i] = {hilbertKey(gx, gy), i};
  }
  std::sort(order.begin(), order.end());
  inputToVertex_.assign(n, -1);
  for (const auto& [key, i] : order) inputToVertex_[i] = insertPoint(pslg.points.row(i).transpose(), lastTri_);

  if (pslg.segments.rows() > 0) {
    for (int s = 0; s < pslg.segments.rows(); ++s)
      insertSegment(inputToVertex_[pslg.segments(s, 0)], inputToVertex_[pslg.segments(s, 1)]);
  } else if (numVertices() > 3) {
    // No segments: mesh the convex hull (monotone chain; collinear hull points are split into by the walk).
    std::vector<int> ids(numVertices() - 3);
    std::iota(ids.begin(), ids.end(), 3);
    std::sort(ids.begin(), ids.end(), [&](int a, int b) {
      return pts_[a].x() < pts_[b].x() || (pts_[a].x() == pts_[b].x() && pts_[a].y() < pts_[b].y());
    });
    std::vector<int> hull;
    for (int pass = 0; pass < 2; ++pass) {
      const std::size_t base = hull.size();
      for (int id : ids) {
        while (hull.size() >= base + 2 && orient2d(pts_[hull[hull.size() - 2]], pts_[hull.back()], pts_[id]) <= 0)
          hull.pop_back();
        hull.push_back(id);
      }
      hull.pop_back();
      std::reverse(ids.begin(), ids.end());
    }
    for (std::size_t k = 0; k < hull.size() && hull.size() >= 2; ++k)
      insertSegment(hull[k], hull[(k + 1) % hull.size()]);
  }
  classify(pslg.holes);
}

int Cdt::addVertex(const Eigen::Vector2d& p) {
  pts_.push_back(p);
  vertTri_.push_back(-1);
  return numVertices() - 1;
}

void Cdt::setTri(int t, int a, int b, int c, int na, int nb, int nc, bool ca, bool cb, bool cc, bool inside) {
  if (t == numTriangles()) tris_.emplace_back();
  Tri& T = tris_[t];
  T.v = {a, b, c};
  T.n = {na, nb, nc};
  T.c = {ca, cb, cc};
  T.inside = inside;
  vertTri_[a] = vertTri_[b] = vertTri_[c] = t;
}

void Cdt::relink(int t, int edge) {
  const int nb = tris_[t].n[edge];
  if (nb < 0) return;
  const int x = tris_[t].v[nx(edge)], y = tris_[t].v[pv(edge)];
  Tri& N = tris_[nb];
  for (int k = 0; k < 3; ++k)
    if (N.v[nx(k)] == y && N.v[pv(k)] == x) {
      N.n[k] = t;
      N.c[k] = tris_[t].c[edge];
      return;
    }
}

Cdt::Location Cdt::locate(const Eigen::Vector2d& p, int hint) const {
  int t = (hint >= 0 && hint < numTriangles()) ? hint : std::min(lastTri_, numTriangles() - 1);
  for (long step = 0;; ++step) {
    const Tri& T = tris_[t];
    rng_ = rng_ * 1664525u + 1013904223u;  // random first edge: no cycling in non-Delaunay regions
    const int start = static_cast<int>((rng_ >> 16) % 3);
    bool moved = false;
    for (int k = 0; k < 3 && !moved; ++k) {
      const int i = (start + k) % 3;
      if (orient2d(pts_[T.v[nx(i)]], pts_[T.v[pv(i)]], p) < 0) {
        if (T.n[i] < 0) throw Error("cdt.outside", "A point lies outside the triangulated area.");
        t = T.n[i];
        moved = true;
      }
    }
    if (moved) continue;
    Location loc;
    loc.tri = t;
    int zeros[3], nz = 0;
    for (int i = 0; i < 3; ++i)
      if (orient2d(pts_[T.v[nx(i)]], pts_[T.v[pv(i)]], p) == 0) zeros[nz++] = i;
    if (nz >= 2) loc.vertex = 3 - zeros[0] - zeros[1];
    if (nz == 1) loc.edge = zeros[0];
    return loc;
  }
}

int Cdt::insertPoint(const Eigen::Vector2d& p, int hint) {
  const Location loc = locate(p, hint);
  if (loc.vertex >= 0) return tris_[loc.tri].v[loc.vertex];
  if (loc.edge >= 0) return splitEdge(loc.tri, loc.edge, p);
  return insertInTriangle(loc.tri, p);
}

int Cdt::insertInTriangle(int t, const Eigen::Vector2d& p) {
  const Tri T = tris_[t];
  const int v = addVertex(p);
  const int t1 = numTriangles(), t2 = t1 + 1;
  const int a = T.v[0], b = T.v[1], c = T.v[2];
  setTri(t, a, b, v, t1, t2, T.n[2], false, false, T.c[2], T.inside);
  setTri(t1, b, c, v, t2, t, T.n[0], false, false, T.c[0], T.inside);
  setTri(t2, c, a, v, t, t1, T.n[1], false, false, T.c[1], T.inside);
  relink(t, 2);
  relink(t1, 2);
  relink(t2, 2);
  std::vector<std::pair<int, int>> stack = {{t, 2}, {t1, 2}, {t2, 2}};
  legalizeAround(v, stack);
  lastTri_ = vertTri_[v];
  return v;
}

int Cdt::splitEdge(int t, int edge, const Eigen::Vector2d& p) {
  const Tri T = tris_[t];
  const int c = T.v[edge], a = T.v[nx(edge)], b = T.v[pv(edge)];
  const bool ce = T.c[edge];
  const int u = T.n[edge];
  const int v = addVertex(p);
  const int t1 = numTriangles();
  const int u1 = u >= 0 ? t1 + 1 : -1;
  std::vector<std::pair<int, int>> stack;
  if (u >= 0) {
    const Tri U = tris_[u];
    int j = 0;
    while (U.n[j] != t) ++j;
    const int d = U.v[j];  // U = (d, b, a)
    setTri(t, c, a, v, u1, t1, T.n[pv(edge)], ce, false, T.c[pv(edge)], T.inside);
    setTri(t1, c, v, b, u, T.n[nx(edge)], t, ce, T.c[nx(edge)], false, T.inside);
    setTri(u, d, b, v, t1, u1, U.n[pv(j)], ce, false, U.c[pv(j)], U.inside);
    setTri(u1, d, v, a, t, U.n[nx(j)], u, ce, U.c[nx(j)], false, U.inside);
    relink(u, 2);
    relink(u1, 1);
    stack = {{t, 2}, {t1, 1}, {u, 2}, {u1, 1}};
  } else {
    setTri(t, c, a, v, -1, t1, T.n[pv(edge)], ce, false, T.c[pv(edge)], T.inside);
    setTri(t1, c, v, b, -1, T.n[nx(edge)], t, ce, T.c[nx(edge)], false, T.inside);
    stack = {{t, 2}, {t1, 1}};
  }
  relink(t, 2);
  relink(t1, 1);
  legalizeAround(v, stack);
  lastTri_ = vertTri_[v];
  return v;
}

// Flips edge `edge` of t: (p, a, b) + (q, b, a) -> (p, a, q) + (p, q, b).
void Cdt::flip(int t, int edge) {
  const Tri T = tris_[t];
  const int u = T.n[edge];
  const Tri U = tris_[u];
  int j = 0;
  while (U.n[j] != t) ++j;
  const int p = T.v[edge], a = T.v[nx(edge)], b = T.v[pv(edge)], q = U.v[j];
  setTri(t, p, a, q, U.n[nx(j)], u, T.n[pv(edge)], U.c[nx(j)], false, T.c[pv(edge)], T.inside);
  setTri(u, p, q, b, U.n[pv(j)], T.n[nx(edge)], t, U.c[pv(j)], T.c[nx(edge)], false, T.inside);
  relink(t, 0);
  relink(t, 2);
  relink(u, 0);
  relink(u, 1);
}

// Lawson's flips after inserting v: test the edges opposite v until all are locally Delaunay.
void Cdt::legalizeAround(int v, std::vector<std::pair<int, int>>& stack) {
  while (!stack.empty()) {
    const int t = stack.back().first;
    stack.pop_back();
    const int k = localIndex(tris_[t], v);
    if (k < 0) continue;
    const Tri& T = tris_[t];
    const int u = T.n[k];
    if (u < 0 || T.c[k]) continue;
    const Tri& U = tris_[u];
    int j = 0;
    while (U.n[j] != t) ++j;
    if (incircle(pts_[T.v[0]], pts_[T.v[1]], pts_[T.v[2]], pts_[U.v[j]]) > 0) {
      flip(t, k);
      stack.push_back({t, 0});
      stack.push_back({u, 0});
    }
  }
}

// Lawson's flips from a list of suspicious edges (after segment recovery).
void Cdt::legalizeEdges(std::vector<std::pair<int, int>> edges) {
  while (!edges.empty()) {
    const auto [x, y] = edges.back();
    edges.pop_back();
    const auto [t, e] = findEdge(x, y);
    if (t < 0) continue;
    const Tri& T = tris_[t];
    const int u = T.n[e];
    if (u < 0 || T.c[e]) continue;
    const Tri& U = tris_[u];
    int j = 0;
    while (U.n[j] != t) ++j;
    const int p = T.v[e], q = U.v[j];
    if (incircle(pts_[T.v[0]], pts_[T.v[1]], pts_[T.v[2]], pts_[q]) > 0) {
      flip(t, e);
      edges.insert(edges.end(), {{y, p}, {p, x}, {x, q}, {q, y}});
    }
  }
}

std::pair<int, int> Cdt::findEdge(int a, int b) const {
  const int t0 = vertTri_[a];
  if (t0 < 0) return {-1, -1};
  // Counter-clockwise around a, then clockwise if a border stopped us.
  int t = t0;
  do {
    const Tri& T = tris_[t];
    const int k = localIndex(T, a);
    if (T.v[nx(k)] == b) return {t, pv(k)};
    if (T.v[pv(k)] == b) {
      const int u = T.n[nx(k)];
      if (u < 0) return {-1, -1};
      const Tri& U = tris_[u];
      return {u, pv(localIndex(U, a))};
    }
    t = T.n[nx(k)];
  } while (t >= 0 && t != t0);
  if (t == t0) return {-1, -1};
  t = t0;
  while (t >= 0) {
    const Tri& T = tris_[t];
    const int k = localIndex(T, a);
    if (T.v[nx(k)] == b) return {t, pv(k)};
    t = T.n[pv(k)];
    if (t == t0) break;
  }
  return {-1, -1};
}

void Cdt::trianglesAround(int v, std::vector<int>& out) const {
  out.clear();
  const int t0 = vertTri_[v];
  int t = t0;
  do {
    out.push_back(t);
    const Tri& T = tris_[t];
    t = T.n[nx(localIndex(T, v))];
  } while (t >= 0 && t != t0);
}

void Cdt::markConstrained(int a, int b) {
  const auto [t, e] = findEdge(a, b);
  if (t < 0) return;
  tris_[t].c[e] = true;
  relink(t, e);
}

void Cdt::insertSegment(int a, int b) {
  std::vector<int> ring;
  while (a != b) {
    if (findEdge(a, b).first >= 0) {
      markConstrained(a, b);
      return;
    }
    const Eigen::Vector2d& A = pts_[a];
    const Eigen::Vector2d& B = pts_[b];
    // The triangle around a whose wedge the segment leaves through.
    trianglesAround(a, ring);
    int cur = -1, pr = -1, ql = -1, onSegment = -1;
    for (int t : ring) {
      const Tri& T = tris_[t];
      const int k = localIndex(T, a);
      const int p = T.v[nx(k)], q = T.v[pv(k)];
      const int op = orient2d(A, pts_[p], B);
      if (op == 0 && (pts_[p] - A).dot(B - A) > 0) {
        onSegment = p;  // the segment runs through vertex p
        break;
      }
      if (op > 0 && orient2d(A, pts_[q], B) < 0) {
        cur = t;
        pr = p;
        ql = q;
        break;
      }
    }
    if (onSegment >= 0) {
      markConstrained(a, onSegment);
      a = onSegment;
      continue;
    }
    if (cur < 0) throw Error("cdt.internal", "Could not start a segment walk in the triangulation.");
    // Walk along a -> b collecting the crossed edges (pr right of the segment, ql left of it).
    std::vector<std::pair<int, int>> crossed;
    int c = -1;
    while (c < 0) {
      const Tri& T = tris_[cur];
      int e = 0;
      while (!(T.v[nx(e)] == pr && T.v[pv(e)] == ql)) ++e;
      if (T.c[e]) {
        // Two segments cross. Insert the (rounded) crossing point as an ordinary vertex w (it may coincide with
        // an existing vertex or land beside the edge), re-route the crossed segment through w, go on from w.
        const double dp = orient2dFast(A, B, pts_[pr]), dq = orient2dFast(A, B, pts_[ql]);
        const double s = std::clamp(dp / (dp - dq), 0.0, 1.0);
        const int x0 = pr, x1 = ql;
        const int w = insertPoint(pts_[x0] + s * (pts_[x1] - pts_[x0]), cur);
        if (w != x0 && w != x1) {
          const auto [t2, e2] = findEdge(x0, x1);
          if (t2 >= 0 && tris_[t2].c[e2]) {
            tris_[t2].c[e2] = false;
            relink(t2, e2);
            insertSegment(x0, w);
            insertSegment(w, x1);
            legalizeEdges({{x0, x1}});
          }
        }
        insertSegment(a, w);
        c = w;
        crossed.clear();
        break;
      }
      crossed.push_back({pr, ql});
      const int nb = T.n[e];
      const Tri& N = tris_[nb];
      int f = 0;
      while (N.n[f] != cur) ++f;
      const int r = N.v[f];
      cur = nb;
      if (r == b) {
        c = b;
      } else {
        const int o = orient2d(A, B, pts_[r]);
        if (o == 0)
          c = r;
        else if (o > 0)
          ql = r;
        else
          pr = r;
      }
    }
    if (!crossed.empty()) recoverSegmentFlips(a, c, crossed);
    a = c;
  }
}

// Sloan's recovery: flip edges crossing (a, c) until none is left, then restore Delaunay around them.
void Cdt::recoverSegmentFlips(int a, int c, const std::vector<std::pair<int, int>>& crossed) {
  std::deque<std::pair<int, int>> queue(crossed.begin(), crossed.end());
  std::vector<std::pair<int, int>> fresh;
  const Eigen::Vector2d& A = pts_[a];
  const Eigen::Vector2d& C = pts_[c];
  std::size_t stall = 0;
  while (!queue.empty()) {
    const auto [x, y] = queue.front();
    queue.pop_front();
    const auto [t, e] = findEdge(x, y);
    if (t < 0) continue;
    const Tri& T = tris_[t];
    const int u = T.n[e];
    const Tri& U = tris_[u];
    int j = 0;
    while (U.n[j] != t) ++j;
    const int p = T.v[e], q = U.v[j];
    if (orient2d(pts_[p], pts_[q], pts_[x]) * orient2d(pts_[p], pts_[q], pts_[y]) < 0) {
      flip(t, e);
      stall = 0;
      const bool touches = p == a || p == c || q == a || q == c;
      if (!touches && orient2d(A, C, pts_[p]) * orient2d(A, C, pts_[q]) < 0)
        queue.push_back({p, q});
      else
        fresh.push_back({p, q});
    } else {
      queue.push_back({x, y});
      if (++stall > 2 * queue.size() + 8) throw Error("cdt.internal", "Segment recovery did not converge.");
    }
  }
  markConstrained(a, c);
  legalizeEdges(std::move(fresh));
}

// Region by parity: 0-1 breadth-first search from the outside, crossing a constraint costs 1.
void Cdt::classify(const Points2& holes) {
  const int nt = numTriangles();
  std::vector<int> depth(nt, std::numeric_limits<int>::max());
  std::deque<int> queue;
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i)
      if (tris_[t].n[i] < 0 && depth[t] != 0) {
        depth[t] = 0;
        queue.push_back(t);
      }
  while (!queue.empty()) {
    const int t = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      const int u = tris_[t].n[i];
      if (u < 0) continue;
      const int d = depth[t] + (tris_[t].c[i] ? 1 : 0);
      if (d < depth[u]) {
        depth[u] = d;
        if (tris_[t].c[i])
          queue.push_back(u);
        else
          queue.push_front(u);
      }
    }
  }
  for (int t = 0; t < nt; ++t) {
    Tri& T = tris_[t];
    T.inside = depth[t] % 2 == 1 && !isBounding(T.v[0]) && !isBounding(T.v[1]) && !isBounding(T.v[2]);
  }
  for (int h = 0; h < holes.rows(); ++h) {
    const Location loc = locate(holes.row(h).transpose());
    std::vector<int> stack = {loc.tri};
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      if (!tris_[t].inside) continue;
      tris_[t].inside = false;
      for (int i = 0; i < 3; ++i)
        if (!tris_[t].c[i] && tris_[t].n[i] >= 0) stack.push_back(tris_[t].n[i]);
    }
  }
}

CdtResult Cdt::result() const {
  CdtResult out;
  const int nv = numVertices();
  std::vector<int> row(nv, -1);
  std::vector<int> order;
  order.reserve(nv);
  for (int v : inputToVertex_)
    if (row[v] < 0) {
      row[v] = static_cast<int>(order.size());
      order.push_back(v);
    }
  for (int v = 3; v < nv; ++v)
    if (row[v] < 0) {
      row[v] = static_cast<int>(order.size());
      order.push_back(v);
    }
  out.points.resize(static_cast<Eigen::Index>(order.size()), 2);
  for (std::size_t k = 0; k < order.size(); ++k) out.points.row(static_cast<Eigen::Index>(k)) = pts_[order[k]];
  out.inputToPoint.resize(inputToVertex_.size());
  for (std::size_t i = 0; i < inputToVertex_.size(); ++i) out.inputToPoint[i] = row[inputToVertex_[i]];

  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<int, 2>> segs;
  for (int t = 0; t < numTriangles(); ++t) {
    const Tri& T = tris_[t];
    if (T.inside) faces.push_back({row[T.v[0]], row[T.v[1]], row[T.v[2]]});
    for (int i = 0; i < 3; ++i) {
      if (!T.c[i]) continue;
      const int u = T.n[i];
      const bool uin = u >= 0 && tris_[u].inside;
      if ((T.inside && (!uin || t < u)) || (!T.inside && !uin && (u < 0 || t < u)))
        if (!isBounding(T.v[nx(i)]) && !isBounding(T.v[pv(i)])) segs.push_back({row[T.v[nx(i)]], row[T.v[pv(i)]]});
    }
  }
  out.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) out.triangles(static_cast<Eigen::Index>(f), k) = faces[f][k];
  out.segments.resize(static_cast<Eigen::Index>(segs.size()), 2);
  for (std::size_t s = 0; s < segs.size(); ++s)
    for (int k = 0; k < 2; ++k) out.segments(static_cast<Eigen::Index>(s), k) = segs[s][k];
  return out;
}

CdtResult triangulate(const Pslg& pslg) { return Cdt(pslg).result(); }

}  // namespace billow
