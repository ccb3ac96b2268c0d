// Ruppert/Chew Delaunay refinement on the CDT. Segments first: an encroached segment (a vertex strictly inside
// its diametral circle, seen from the meshed side) is split. Then each bad triangle gets its circumcenter,
// unless that point would encroach a segment (split the segment instead, Ruppert's rule) or is hidden behind
// one. Termination with small input angles: concentric-shell splits and Shewchuk's rule of not refining a
// skinny triangle whose short edge joins two segments that meet at a small input angle; plus a point cap.
#include "remesh/refine.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "remesh/predicates.hpp"
#include "util/vec2.hpp"

namespace billow {

namespace {

enum class Badness { None, Shape, Size };

class Refiner {
 public:
  Refiner(Cdt& cdt, const RefineOptions& opt) : cdt_(cdt), opt_(opt) {
    sinMin_ = std::sin(std::clamp(opt.minAngleDeg, 0.0, 60.0) * M_PI / 180.0);
    isInput_.assign(cdt.numVertices(), 1);
    root_.assign(cdt.numVertices(), {-1, -1});
  }

  RefineStats run() {
    for (int t = 0; t < cdt_.numTriangles(); ++t) {
      const Cdt::Tri& T = cdt_.tri(t);
      if (!T.inside) continue;
      triQ_.push_back(T.v);
      if (opt_.allowBoundarySplits)
        for (int i = 0; i < 3; ++i)
          if (T.c[i]) segQ_.push_back({T.v[(i + 1) % 3], T.v[(i + 2) % 3]});
    }
    while (!capped()) {
      while (!segQ_.empty() && !capped()) {
        const auto [x, y] = segQ_.front();
        segQ_.pop_front();
        if (encroached(x, y)) splitSegment(x, y);
      }
      if (triQ_.empty() || capped()) break;
      const auto tv = triQ_.front();
      triQ_.pop_front();
      refineTriangle(tv);
    }
    return stats_;
  }

 private:
  bool capped() {
    if (stats_.steinerPoints < opt_.maxSteinerPoints) return false;
    stats_.hitSteinerCap = true;
    return true;
  }

  const Eigen::Vector2d& P(int v) const { return cdt_.point(v); }

  // A segment (x, y) still in the mesh with a meshed-side apex inside its diametral circle.
  bool encroached(int x, int y) const {
    const auto [t, e] = cdt_.findEdge(x, y);
    if (t < 0 || !cdt_.tri(t).c[e]) return false;
    const int sides[2] = {t, cdt_.tri(t).n[e]};
    for (int s : sides) {
      if (s < 0 || !cdt_.tri(s).inside) continue;
      for (int z : cdt_.tri(s).v)
        if (z != x && z != y && (P(x) - P(z)).dot(P(y) - P(z)) < 0) return true;
    }
    return false;
  }

  std::array<int, 2> rootOf(int x, int y) const {
    if (!isInput_[x]) return root_[x];
    if (!isInput_[y]) return root_[y];
    return {x, y};
  }

  // Split point: the midpoint, or next to an input vertex a power-of-two distance from it (concentric shells,
  // so that splits on two segments meeting at a small angle stay at equal distances from the corner).
  Eigen::Vector2d splitPoint(int x, int y) const {
    const double len = (P(y) - P(x)).norm();
    int from = -1, to = -1;
    if (isInput_[x] && !isInput_[y]) from = x, to = y;
    if (isInput_[y] && !isInput_[x]) from = y, to = x;
    if (from < 0 || !(len > 0)) return 0.5 * (P(x) + P(y));
    const double d = std::exp2(std::ceil(std::log2(len / 3.0)));  // in [len/3, 2 len/3)
    return P(from) + (d / len) * (P(to) - P(from));
  }

  void splitSegment(int x, int y) {
    const auto [t, e] = cdt_.findEdge(x, y);
    if (t < 0 || !opt_.allowBoundarySplits) return;
    const auto r = rootOf(x, y);
    const int before = cdt_.numVertices();
    const int v = cdt_.splitEdge(t, e, splitPoint(x, y));
    if (v < before) return;
    isInput_.push_back(0);
    root_.push_back(r);
    ++stats_.steinerPoints;
    ++stats_.segmentSplits;
    segQ_.push_back({x, v});
    segQ_.push_back({v, y});
    afterInsert(v);
  }

  void afterInsert(int v) {
    cdt_.trianglesAround(v, ring_);
    for (int t : ring_) {
      const Cdt::Tri& T = cdt_.tri(t);
      if (!T.inside) continue;
      triQ_.push_back(T.v);
      if (!opt_.allowBoundarySplits) continue;
      for (int i = 0; i < 3; ++i)
        if (T.c[i] && T.v[i] == v) segQ_.push_back({T.v[(i + 1) % 3], T.v[(i + 2) % 3]});
    }
  }

  Badness badness(const Cdt::Tri& T, int& shortEdge) const {
    const Eigen::Vector2d &a = P(T.v[0]), &b = P(T.v[1]), &c = P(T.v[2]);
    const double l[3] = {(b - c).squaredNorm(), (c - a).squaredNorm(), (a - b).squaredNorm()};
    const double area2 = std::abs(cross2(b - a, c - a));
    shortEdge = static_cast<int>(std::min_element(l, l + 3) - l);
    if (area2 > 2.0 * opt_.maxArea) return Badness::Size;
    if (std::max({l[0], l[1], l[2]}) > opt_.maxEdgeLength * opt_.maxEdgeLength) return Badness::Size;
    const double other = std::sqrt(l[(shortEdge + 1) % 3] * l[(shortEdge + 2) % 3]);
    if (area2 < sinMin_ * other) return Badness::Shape;  // sine of the smallest angle below the bound
    return Badness::None;
  }

  // Shewchuk's terminator: the short edge joins two different segments that meet at a small input angle.
  bool causedBySmallInputAngle(int x, int y) const {
    if (isInput_[x] || isInput_[y]) return false;
    const auto rx = root_[x], ry = root_[y];
    if (rx[0] < 0 || ry[0] < 0) return false;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        if (rx[i] != ry[j] || rx[1 - i] == ry[1 - j]) continue;
        const Eigen::Vector2d u = P(rx[1 - i]) - P(rx[i]), w = P(ry[1 - j]) - P(ry[j]);
        const double cosAngle = u.dot(w) / (u.norm() * w.norm());
        if (cosAngle > 0.5) return true;  // input angle below 60 degrees
      }
    return false;
  }

  void refineTriangle(const std::array<int, 3>& tv) {
    const auto [t, e] = cdt_.findEdge(tv[0], tv[1]);
    if (t < 0 || cdt_.tri(t).v[e] != tv[2] || !cdt_.tri(t).inside) return;  // gone since queued
    const Cdt::Tri T = cdt_.tri(t);
    int shortEdge = 0;
    const Badness bad = badness(T, shortEdge);
    if (bad == Badness::None) return;
    if (bad == Badness::Shape && causedBySmallInputAngle(T.v[(shortEdge + 1) % 3], T.v[(shortEdge + 2) % 3])) {
      ++stats_.skippedTriangles;
      return;
    }
    const Eigen::Vector2d &a = P(T.v[0]), b = P(T.v[1]) - a, c = P(T.v[2]) - a;
    const double d = 2.0 * cross2(b, c);
    const Eigen::Vector2d cc = a + Eigen::Vector2d(c.y() * b.squaredNorm() - b.y() * c.squaredNorm(),
                                                   b.x() * c.squaredNorm() - c.x() * b.squaredNorm()) /
                                       d;
    if (!std::isfinite(cc.x()) || !std::isfinite(cc.y())) {
      ++stats_.skippedTriangles;
      return;
    }
    // Cavity of cc: triangles whose circumcircle contains it, reached without crossing a segment.
    int containing = -1;
    std::vector<std::pair<int, int>> walls;  // segments on the cavity border
    ++stamp_;
    mark_.resize(cdt_.numTriangles(), 0);
    std::vector<int> stack = {t};
    mark_[t] = stamp_;
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      const Cdt::Tri& S = cdt_.tri(s);
      if (containing < 0 && orient2d(P(S.v[1]), P(S.v[2]), cc) >= 0 && orient2d(P(S.v[2]), P(S.v[0]), cc) >= 0 &&
          orient2d(P(S.v[0]), P(S.v[1]), cc) >= 0)
        containing = s;
      for (int i = 0; i < 3; ++i) {
        const int x = S.v[(i + 1) % 3], y = S.v[(i + 2) % 3];
        if (S.c[i]) {
          walls.push_back({x, y});
          continue;
        }
        const int u = S.n[i];
        if (u < 0 || mark_[u] == stamp_ || !cdt_.tri(u).inside) continue;
        const Cdt::Tri& U = cdt_.tri(u);
        if (incircle(P(U.v[0]), P(U.v[1]), P(U.v[2]), cc) > 0) {
          mark_[u] = stamp_;
          stack.push_back(u);
        }
      }
    }
    std::vector<std::pair<int, int>> hit;
    for (const auto& [x, y] : walls)
      if ((P(x) - cc).dot(P(y) - cc) < 0) hit.push_back({x, y});
    if (hit.empty() && containing < 0) {
      // Hidden behind a segment: the segment crossed on the way from the triangle to its circumcenter.
      const Eigen::Vector2d g = (P(T.v[0]) + P(T.v[1]) + P(T.v[2])) / 3.0;
      for (const auto& [x, y] : walls)
        if (orient2d(P(x), P(y), g) * orient2d(P(x), P(y), cc) < 0 && orient2d(g, cc, P(x)) * orient2d(g, cc, P(y)) < 0)
          hit.push_back({x, y});
      if (hit.empty()) {
        ++stats_.skippedTriangles;
        return;
      }
    }
    if (!hit.empty()) {
      if (!opt_.allowBoundarySplits) {
        ++stats_.skippedTriangles;
        return;
      }
      for (const auto& [x, y] : hit)
        if (!capped()) splitSegment(x, y);
      triQ_.push_back(tv);
      return;
    }
    const int before = cdt_.numVertices();
    const int v = cdt_.insertPoint(cc, containing);
    if (v < before) {
      ++stats_.skippedTriangles;
      return;
    }
    isInput_.push_back(0);
    root_.push_back({-1, -1});
    ++stats_.steinerPoints;
    afterInsert(v);
  }

  Cdt& cdt_;
  const RefineOptions& opt_;
  RefineStats stats_;
  double sinMin_ = 0;
  std::vector<char> isInput_;
  std::vector<std::array<int, 2>> root_;
  std::deque<std::pair<int, int>> segQ_;
  std::deque<std::array<int, 3>> triQ_;
  std::vector<unsigned> mark_;
  unsigned stamp_ = 0;
  std::vector<int> ring_;
};

}  // namespace

RefineStats refine(Cdt& cdt, const RefineOptions& options) { return Refiner(cdt, options).run(); }

CdtResult triangulateRefined(const Pslg& pslg, const RefineOptions& options, RefineStats* stats) {
  Cdt cdt(pslg);
  const RefineStats s = refine(cdt, options);
  if (stats) *stats = s;
  return cdt.result();
}

}  // namespace billow
