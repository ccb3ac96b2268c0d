// Small 2D polygon helpers shared by the fabrication outputs (outlines, allowance, nesting, writers).
// A polygon is a closed loop of points (the last point is not repeated); counterclockwise = positive area.
#pragma once
#include <vector>

#include "util/vec2.hpp"

namespace billow {

using Polygon2 = std::vector<Vec2>;  // #n points, closed implicitly (edge n-1 -> 0)

double signedArea(const Polygon2& p);  // > 0 for counterclockwise
double perimeter(const Polygon2& p);
Vec2 polygonCentroid(const Polygon2& p);

struct Box2 {
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  void add(const Vec2& v) { lo = lo.cwiseMin(v), hi = hi.cwiseMax(v); }
  bool empty() const { return lo.x() > hi.x(); }
  Vec2 size() const { return empty() ? Vec2(0, 0) : Vec2(hi - lo); }
  bool overlaps(const Box2& o) const {
    return !(hi.x() < o.lo.x() || o.hi.x() < lo.x() || hi.y() < o.lo.y() || o.hi.y() < lo.y());
  }
};
Box2 boundingBox(const Polygon2& p);

// Proper or touching intersection of segments ab and cd; on success t (along ab) and u (along cd) in [0, 1].
bool segmentIntersection(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double& t, double& u);

// The parameter t in [0, 1] of the point a + t (b - a) of segment ab closest to q, and the distance from q to ab.
double closestSegmentParameter(const Vec2& q, const Vec2& a, const Vec2& b);
double pointSegmentDistance(const Vec2& q, const Vec2& a, const Vec2& b);
// Distance from q to the polygon's boundary.
double distanceToBoundary(const Vec2& q, const Polygon2& p);
// Even-odd point-in-polygon test.
bool insidePolygon(const Vec2& q, const Polygon2& p);
// True when the two polygons' interiors or boundaries meet (edge crossing or one inside the other).
bool polygonsIntersect(const Polygon2& a, const Polygon2& b);
// True when two non-adjacent edges of p cross or touch.
bool selfIntersects(const Polygon2& p);

// Rotation by `angle` (radians, counterclockwise) then translation.
struct Placement2 {
  double angle = 0;
  Vec2 offset{0, 0};
  Vec2 apply(const Vec2& v) const;
  Vec2 rotate(const Vec2& v) const;  // directions
};
Polygon2 transformed(const Polygon2& p, const Placement2& t);

}  // namespace billow
