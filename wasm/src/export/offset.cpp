#include "export/offset.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "util/error.hpp"

namespace billow {
namespace {

void push(Polygon2& out, const Vec2& v, double eps) {
  if (out.empty() || (out.back() - v).norm() > eps) out.push_back(v);
}

// Where the offset lines of two edges (point + t * direction) meet; false when (nearly) parallel.
bool lineIntersection(const Vec2& p, const Vec2& d, const Vec2& q, const Vec2& e, Vec2& x) {
  const double den = cross2(d, e);
  if (std::abs(den) < 1e-12) return false;
  x = p + cross2(q - p, e) / den * d;
  return true;
}

}  // namespace

Polygon2 outerBoundary(const Polygon2& raw) {
  const int m = int(raw.size());
  if (m < 3) return raw;
  const Box2 box = boundingBox(raw);
  const double eps = 1e-9 * std::max(1.0, box.size().maxCoeff());

  // Nodes: the loop's points, then every crossing of two non-adjacent segments. Each segment keeps the
  // parameters of the nodes on it.
  std::vector<Vec2> nodes(raw.begin(), raw.end());
  std::vector<std::vector<std::pair<double, int>>> onSegment(m);
  for (int i = 0; i < m; ++i) onSegment[i] = {{0.0, i}, {1.0, (i + 1) % m}};
  std::vector<Box2> boxes(m);
  for (int i = 0; i < m; ++i) boxes[i].add(raw[i]), boxes[i].add(raw[(i + 1) % m]);
  for (int i = 0; i < m; ++i)
    for (int j = i + 2; j < m; ++j) {
      if ((i == 0 && j == m - 1) || !boxes[i].overlaps(boxes[j])) continue;
      double t, u;
      if (!segmentIntersection(raw[i], raw[(i + 1) % m], raw[j], raw[(j + 1) % m], t, u)) continue;
      const int node = int(nodes.size());
      nodes.push_back(raw[i] + t * (raw[(i + 1) % m] - raw[i]));
      onSegment[i].push_back({t, node});
      onSegment[j].push_back({u, node});
    }
  // Merge nodes closer than eps (crossings at shared points, touching corners).
  std::vector<int> rep(nodes.size());
  std::iota(rep.begin(), rep.end(), 0);
  {
    std::vector<int> order(nodes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return nodes[a].x() < nodes[b].x(); });
    for (size_t a = 0; a < order.size(); ++a)
      for (size_t b = a + 1; b < order.size() && nodes[order[b]].x() - nodes[order[a]].x() <= eps; ++b)
        if ((nodes[order[a]] - nodes[order[b]]).norm() <= eps) {
          int ra = order[a], rb = order[b];
          while (rep[ra] != ra) ra = rep[ra];
          while (rep[rb] != rb) rb = rep[rb];
          if (ra != rb) rep[std::max(ra, rb)] = std::min(ra, rb);
        }
    for (size_t k = 0; k < rep.size(); ++k)
      while (rep[k] != rep[rep[k]]) rep[k] = rep[rep[k]];
  }
  // Directed pieces between consecutive nodes along each segment, in the loop's direction.
  std::vector<std::vector<int>> outgoing(nodes.size());
  std::vector<std::pair<int, int>> pieces;
  for (auto& list : onSegment) {
    std::sort(list.begin(), list.end());
    for (size_t k = 0; k + 1 < list.size(); ++k) {
      const int a = rep[list[k].second], b = rep[list[k + 1].second];
      if (a == b) continue;
      outgoing[a].push_back(int(pieces.size()));
      pieces.push_back({a, b});
    }
  }
  int start = 0;
  for (int k = 0; k < int(nodes.size()); ++k)
    if (rep[k] == k && !outgoing[k].empty() &&
        (nodes[k].x() < nodes[start].x() || (nodes[k].x() == nodes[start].x() && nodes[k].y() < nodes[start].y())))
      start = k;
  // At the leftmost point a counterclockwise boundary heads down: pretend we arrived heading down.
  Vec2 heading(0, -1);
  Polygon2 out;
  int node = start, firstPiece = -1;
  std::vector<char> used(pieces.size(), 0);
  for (size_t steps = 0; steps <= pieces.size(); ++steps) {
    int best = -1;
    double bestTurn = 1e9;
    for (int k : outgoing[node]) {
      const Vec2 d = (nodes[pieces[k].second] - nodes[node]).normalized();
      double turn = std::atan2(cross2(heading, d), heading.dot(d));  // < 0: right
      if (turn >= M_PI - 1e-12) turn = -M_PI;                        // a U-turn is the rightmost of all
      if (turn < bestTurn) bestTurn = turn, best = k;
    }
    if (best < 0 || best == firstPiece || used[best]) break;
    if (firstPiece < 0) firstPiece = best;
    used[best] = 1;
    out.push_back(nodes[node]);
    heading = (nodes[pieces[best].second] - nodes[node]).normalized();
    node = pieces[best].second;
  }
  return out;
}

Polygon2 offsetPolygon(const Polygon2& poly, const std::vector<double>& widths, const OffsetOptions& options) {
  const int n = int(poly.size());
  if (n < 3) throw Error("export.panel-shape", "A panel outline needs at least three corners.");
  if (int(widths.size()) != n) throw Error("export.bad-value", "One seam allowance per outline edge is needed.");
  for (double w : widths)
    if (!(w >= 0 && std::isfinite(w))) throw Error("export.bad-value", "Seam allowances must be 0 or more.");
  if (*std::max_element(widths.begin(), widths.end()) == 0) return poly;
  const double eps = 1e-9 * std::max(1.0, boundingBox(poly).size().maxCoeff());

  std::vector<Vec2> dir(n), normal(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 d = poly[(i + 1) % n] - poly[i];
    dir[i] = d.norm() > 0 ? Vec2(d.normalized()) : Vec2(1, 0);
    normal[i] = Vec2(dir[i].y(), -dir[i].x());  // outward for a counterclockwise polygon
  }
  Polygon2 raw;
  for (int i = 0; i < n; ++i) {
    // The corner at poly[i] joins edge h = i-1 (ending there) and edge i (starting there).
    const int h = (i + n - 1) % n;
    const Vec2 p = poly[i], endH = p + widths[h] * normal[h], startI = p + widths[i] * normal[i];
    const double turn = cross2(dir[h], dir[i]);  // > 0: convex corner
    Vec2 x;
    if (turn > 1e-12 && lineIntersection(endH, dir[h], startI, dir[i], x)) {
      const double w = std::max(widths[h], widths[i]), reach = options.miterLimit * w;
      if ((x - p).norm() <= reach) {
        push(raw, x, eps);
      } else {
        // Square the corner off at distance w from the vertex, across the bisector.
        const Vec2 bis = (normal[h] + normal[i]).normalized();
        const Vec2 a = endH + (w - widths[h] * normal[h].dot(bis)) / dir[h].dot(bis) * dir[h];
        const Vec2 b = startI - (w - widths[i] * normal[i].dot(bis)) / -dir[i].dot(bis) * dir[i];
        if ((a - p).norm() <= reach && (b - p).norm() <= reach) {
          push(raw, a, eps);
          push(raw, b, eps);
        } else {
          // Where the width changes at a gentle corner (two seams meeting on a curve), those points run off
          // along the narrower edge, as the miter did. Step instead: across the corner at the narrower width,
          // then along the wider edge's end to its width, so the wider seam keeps its allowance to its end.
          push(raw, endH, eps);
          push(raw, p + std::min(widths[h], widths[i]) * (widths[h] < widths[i] ? normal[i] : normal[h]), eps);
          push(raw, startI, eps);
        }
      }
    } else if (turn < -1e-12) {
      // Concave: go through the vertex; the crossing offset edges form a loop that outerBoundary removes.
      push(raw, endH, eps);
      push(raw, p, eps);
      push(raw, startI, eps);
    } else {
      push(raw, endH, eps);  // straight on (a step where the width changes)
      push(raw, startI, eps);
    }
  }
  if (raw.size() > 1 && (raw.front() - raw.back()).norm() <= eps) raw.pop_back();
  return outerBoundary(raw);
}

Polygon2 offsetPolygon(const Polygon2& polygon, double width, const OffsetOptions& options) {
  return offsetPolygon(polygon, std::vector<double>(polygon.size(), width), options);
}

}  // namespace billow
