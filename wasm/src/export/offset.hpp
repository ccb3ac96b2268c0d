// Seam allowance: the cut line as an outward offset of a panel outline (the sewing line).
// Each edge i of the counterclockwise polygon is pushed out by its own width w_i (seam allowances may differ
// per seam; 0 = heat sealing, cut on the sewing line). Convex corners are mitered up to `miterLimit` x w
// and beyond that squared off at distance w (a bevel that never eats into the allowance); where the width
// changes at a gentle corner (two seams meeting on a curve) the cut line steps out along the end of the wider
// edge's strip instead, so each seam keeps its own allowance up to the corner. Concave corners
// join through the original vertex; the raw offset then has small backward loops wherever the allowance is
// wider than a concave curve's radius, and only its outer boundary is kept (the cut line of the union of
// all edge strips, which is at distance w from the sewing line and has no self-intersections).
#pragma once
#include <vector>

#include "export/polygon.hpp"

namespace billow {

struct OffsetOptions {
  double miterLimit = 2.0;  // a mitered corner reaches at most this many widths from the vertex
};

// polygon: counterclockwise, no repeated points. widths: one per edge (edge i = polygon[i] -> polygon[i+1]),
// >= 0, in the polygon's units. Returns the counterclockwise cut line.
Polygon2 offsetPolygon(const Polygon2& polygon, const std::vector<double>& widths, const OffsetOptions& options = {});
Polygon2 offsetPolygon(const Polygon2& polygon, double width, const OffsetOptions& options = {});

// The outer boundary of a closed, possibly self-intersecting loop (counterclockwise overall): walks the
// arrangement of its segments from the leftmost point, always taking the rightmost turn.
Polygon2 outerBoundary(const Polygon2& raw);

}  // namespace billow
