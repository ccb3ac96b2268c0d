#include "export/nesting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "util/error.hpp"

namespace billow {
namespace {

// Skyline: the top of the placed boxes as x-sorted steps [x, x + width) at height y.
struct Step {
  double x, width, y;
};

struct Fit {
  double x = 0, y = 0;
  bool ok = false;
};

// Lowest y at which a box of width w rests with its left side at x (the tallest step under it).
double restingHeight(const std::vector<Step>& sky, double x, double w) {
  double y = 0;
  for (const Step& s : sky)
    if (s.x < x + w && s.x + s.width > x) y = std::max(y, s.y);
  return y;
}

void addBox(std::vector<Step>& sky, double x, double w, double top) {
  std::vector<Step> out;
  for (const Step& s : sky) {
    if (s.x < x) out.push_back({s.x, std::min(s.width, x - s.x), s.y});
    if (s.x + s.width > x + w) {
      const double from = std::max(s.x, x + w);
      out.push_back({from, s.x + s.width - from, s.y});
    }
  }
  out.push_back({x, w, top});
  std::sort(out.begin(), out.end(), [](const Step& a, const Step& b) { return a.x < b.x; });
  sky.clear();
  for (const Step& s : out) {  // merge equal neighbours so the candidate list stays short
    if (s.width <= 0) continue;
    if (!sky.empty() && sky.back().y == s.y)
      sky.back().width += s.width;
    else
      sky.push_back(s);
  }
}

}  // namespace

double principalAxisAngle(const Polygon2& p) {
  // Second moments of the area about its centroid, from the triangle fan (Green's theorem).
  const Vec2 c = polygonCentroid(p);
  double sxx = 0, syy = 0, sxy = 0;
  for (size_t i = 0, n = p.size(); i < n; ++i) {
    const Vec2 a = p[i] - c, b = p[(i + 1) % n] - c;
    const double w = cross2(a, b);
    sxx += w * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x());
    syy += w * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y());
    sxy += w * (2 * a.x() * a.y() + a.x() * b.y() + b.x() * a.y() + 2 * b.x() * b.y());
  }
  return 0.5 * std::atan2(sxy, sxx - syy);  // (the common 1/12 and 1/24 factors cancel in the ratio)
}

namespace {

// The turns a piece may be laid at: as drawn and upside down with the grain locked, else also its principal
// axis along the sheet and the quarter turns of both.
std::vector<double> turns(const Polygon2& piece, const NestOptions& o) {
  std::vector<double> angles = {0};
  if (o.grainLock) {
    angles.push_back(M_PI);
  } else if (o.allowRotation) {
    const double axis = principalAxisAngle(piece);
    for (int k = 1; k < 4; ++k) angles.push_back(k * M_PI / 2);
    for (int k = 0; k < 4; ++k) angles.push_back(-axis + k * M_PI / 2);
  }
  return angles;
}

}  // namespace

NestResult nestPieces(const std::vector<Polygon2>& pieces, const NestOptions& o,
                      const std::vector<std::string>& names) {
  if (!(o.sheetWidth > 2 * o.gap && std::isfinite(o.sheetWidth)))
    throw Error("export.bad-value", "The sheet width must be positive.");
  NestResult result;
  result.placements.resize(pieces.size());
  std::vector<size_t> order(pieces.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> areas(pieces.size());
  for (size_t i = 0; i < pieces.size(); ++i) areas[i] = std::abs(signedArea(pieces[i]));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return areas[a] > areas[b]; });

  const double usable = o.sheetWidth - 2 * o.gap;
  std::vector<Step> sky = {{0, o.sheetWidth, 0}};
  double total = 0;
  for (size_t i : order) {
    const Polygon2& piece = pieces[i];
    const std::vector<double> angles = turns(piece, o);
    double bestTop = 1e300, bestX = 0;
    Placement2 best;
    bool found = false;
    double narrowest = 1e300;
    for (double angle : angles) {
      Placement2 t{angle, Vec2(0, 0)};
      const Box2 box = boundingBox(transformed(piece, t));
      const Vec2 size = box.size();
      narrowest = std::min(narrowest, size.x());
      if (size.x() > usable) continue;
      // Candidate left sides: each skyline step's start (and the far-right wall for the last step).
      std::vector<double> xs = {o.gap, o.sheetWidth - o.gap - size.x()};
      for (const Step& s : sky) xs.push_back(std::max(o.gap, s.x)), xs.push_back(s.x + s.width - size.x());
      for (double x : xs) {
        if (x < o.gap - 1e-9 || x + size.x() > o.sheetWidth - o.gap + 1e-9) continue;
        const double y = std::max(o.gap, restingHeight(sky, x, size.x()));
        const double top = y + size.y();
        if (top < bestTop - 1e-9 || (top < bestTop + 1e-9 && x < bestX)) {
          bestTop = top, bestX = x, found = true;
          best = {angle, Vec2(x, y) - box.lo};
        }
      }
    }
    if (!found) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "is %.0f mm wide at its narrowest; the sheet leaves %.0f mm.", narrowest, usable);
      const std::string name = i < names.size() ? "'" + names[i] + "'" : "a piece";
      // The width every piece fits in, turned its narrowest way, rounded up to 10 mm: what the app offers.
      double widest = 0;
      for (const Polygon2& p : pieces) {
        double narrow = 1e300;
        for (double angle : turns(p, o))
          narrow = std::min(narrow, boundingBox(transformed(p, {angle, Vec2(0, 0)})).size().x());
        widest = std::max(widest, narrow);
      }
      Error e("export.sheet-too-narrow",
              "The panel " + name + " (with its seam allowance) " + buf + " Choose a wider sheet.");
      e.sheetWidth = 10 * std::ceil((widest + 2 * o.gap) / 10);
      throw e;
    }
    result.placements[i] = best;
    const Box2 placed = boundingBox(transformed(piece, best));
    // The footprint keeps `gap` free on the sides and above (pieces resting on it start higher).
    addBox(sky, placed.lo.x() - o.gap, placed.size().x() + 2 * o.gap, placed.hi.y() + o.gap);
    result.length = std::max(result.length, placed.hi.y() + o.gap);
    total += areas[i];
  }
  result.utilisation = result.length > 0 ? total / (o.sheetWidth * result.length) : 0;
  return result;
}

}  // namespace billow
