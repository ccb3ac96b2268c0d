#include "export/polygon.hpp"

#include <algorithm>
#include <cmath>

namespace billow {

double signedArea(const Polygon2& p) {
  double a = 0;
  for (size_t i = 0, n = p.size(); i < n; ++i) a += cross2(p[i], p[(i + 1) % n]);
  return 0.5 * a;
}

double perimeter(const Polygon2& p) {
  double l = 0;
  for (size_t i = 0, n = p.size(); i < n; ++i) l += (p[(i + 1) % n] - p[i]).norm();
  return l;
}

Vec2 polygonCentroid(const Polygon2& p) {
  // Area-weighted centroid relative to the first point (keeps precision far from the origin).
  Vec2 c(0, 0);
  double a = 0;
  for (size_t i = 1; i + 1 < p.size(); ++i) {
    const double w = cross2(p[i] - p[0], p[i + 1] - p[0]);
    c += w * (p[i] + p[i + 1] - 2 * p[0]) / 3;
    a += w;
  }
  return a == 0 ? p.empty() ? Vec2(0, 0) : p[0] : Vec2(p[0] + c / a);
}

Box2 boundingBox(const Polygon2& p) {
  Box2 b;
  for (const Vec2& v : p) b.add(v);
  return b;
}

bool segmentIntersection(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double& t, double& u) {
  const Vec2 r = b - a, s = d - c;
  const double den = cross2(r, s);
  if (den == 0) return false;  // parallel (collinear overlaps are not reported)
  t = cross2(c - a, s) / den;
  u = cross2(c - a, r) / den;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

double closestSegmentParameter(const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  return l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
}

double pointSegmentDistance(const Vec2& q, const Vec2& a, const Vec2& b) {
  return (a + closestSegmentParameter(q, a, b) * (b - a) - q).norm();
}

double distanceToBoundary(const Vec2& q, const Polygon2& p) {
  double d = 1e300;
  for (size_t i = 0, n = p.size(); i < n; ++i) d = std::min(d, pointSegmentDistance(q, p[i], p[(i + 1) % n]));
  return d;
}

bool insidePolygon(const Vec2& q, const Polygon2& p) {
  bool in = false;
  for (size_t i = 0, n = p.size(), j = n - 1; i < n; j = i++) {
    if ((p[i].y() > q.y()) != (p[j].y() > q.y()) &&
        q.x() < (p[j].x() - p[i].x()) * (q.y() - p[i].y()) / (p[j].y() - p[i].y()) + p[i].x())
      in = !in;
  }
  return in;
}

bool polygonsIntersect(const Polygon2& a, const Polygon2& b) {
  if (a.empty() || b.empty() || !boundingBox(a).overlaps(boundingBox(b))) return false;
  double t, u;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j)
      if (segmentIntersection(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()], t, u)) return true;
  return insidePolygon(a[0], b) || insidePolygon(b[0], a);
}

bool selfIntersects(const Polygon2& p) {
  const size_t n = p.size();
  double t, u;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (segmentIntersection(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n], t, u)) return true;
    }
  return false;
}

Vec2 Placement2::rotate(const Vec2& v) const {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

Vec2 Placement2::apply(const Vec2& v) const { return rotate(v) + offset; }

Polygon2 transformed(const Polygon2& p, const Placement2& t) {
  Polygon2 out;
  out.reserve(p.size());
  for (const Vec2& v : p) out.push_back(t.apply(v));
  return out;
}

}  // namespace billow
