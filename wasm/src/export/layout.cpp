#include "export/layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "export/offset.hpp"
#include "util/error.hpp"

namespace billow {
namespace {

constexpr double kMm = 1000.0;  // pattern meters -> sheet millimetres

// A good spot for the panel's name: the triangle centroid farthest from the outline (a sample of at most
// ~400 triangles keeps this linear in the boundary size).
Vec2 labelSpot(const Panel& panel, const Polygon2& sew) {
  const int nt = int(panel.triangles.rows());
  const int stride = std::max(1, nt / 400);
  Vec2 best = polygonCentroid(sew);
  double bestDistance = -1;
  for (int t = 0; t < nt; t += stride) {
    Vec2 c(0, 0);
    for (int k = 0; k < 3; ++k)
      c += kMm * Vec2(panel.vertices(panel.triangles(t, k), 0), panel.vertices(panel.triangles(t, k), 1));
    c /= 3;
    const double d = distanceToBoundary(c, sew);
    if (d > bestDistance) bestDistance = d, best = c;
  }
  return best;
}

void validate(const Pattern& pattern, const ExportOptions& o) {
  if (pattern.panels.empty()) throw Error("export.empty", "The pattern has no panels to cut.");
  auto bad = [](double v) { return !(v >= 0 && std::isfinite(v)); };
  if (bad(o.allowance) || o.allowance > 200)
    throw Error("export.bad-value", "Choose a seam allowance from 0 to 200 mm.");
  for (const auto& [seam, w] : o.seamAllowance)
    if (bad(w) || w > 200)
      throw Error("export.bad-value",
                  "Choose the allowance of seam S" + std::to_string(seam + 1) + " from 0 to 200 mm.");
  if (o.freeEdgeAllowance >= 0 ? o.freeEdgeAllowance > 200 : !(o.freeEdgeAllowance < 0))
    throw Error("export.bad-value", "Choose the allowance of free edges from 0 to 200 mm.");
  for (const FillValve& v : o.valves)
    if (!(v.width > 0 && v.width <= 200) || !(v.at >= 0 && v.at <= 1) || v.seam < 0)
      throw Error("export.bad-value", "Choose the fill valve on seam S" + std::to_string(v.seam + 1) +
                                          " wider than 0 and at most 200 mm, placed along the seam (0 to 1).");
  if (bad(o.notchSpacing) || bad(o.notchLength) || bad(o.gap) || bad(o.tileOverlap))
    throw Error("export.bad-value", "Notch spacing, notch length, gap and tile overlap must be 0 or more.");
  if (!(o.sheetWidth >= 10 && o.sheetWidth <= 100000))
    throw Error("export.bad-value", "Choose a sheet width from 10 mm to 100 m.");
}

// The mark of a fill valve's gap on one side of its seam, from arc length s0 to s1 [m] along the side: the
// sewing line, then back at the allowance's depth (at least `minDepth` [mm], so a gap in a seam cut on
// its line still shows).
Polygon2 valveMark(const Pattern& pattern, const Outlines& outlines, const SeamSide& side, const PanelLayout& pl,
                   double s0, double s1, double minDepth) {
  std::vector<double> arcs{s0};
  const Polygon2 loop = outlines.panels[side.panel].points(pattern.panels[side.panel]);
  const int n = int(loop.size());
  double along = 0;
  for (int e : side.edges) {
    along += (loop[(e + 1) % n] - loop[e]).norm();
    if (along > s0 && along < s1) arcs.push_back(along);
  }
  arcs.push_back(s1);
  Polygon2 inner, outer;
  for (double s : arcs) {
    const SidePoint sp = pointAlongSide(pattern, outlines, side, s);
    inner.push_back(kMm * sp.point);
    outer.push_back(kMm * sp.point + std::max(pl.widths[sp.edge], minDepth) * sp.normal);
  }
  inner.insert(inner.end(), outer.rbegin(), outer.rend());
  return inner;
}

// A label on a seam side's panel, `inset` text heights inside its sewing line at arc length s [m] along it.
DrawnText besideSide(const Pattern& pattern, const Outlines& outlines, const SeamSide& side, const PanelLayout& pl,
                     double s, double inset, const std::string& text) {
  const double h = std::clamp(0.6 * pl.labelHeight, 3.0, 10.0);
  const SidePoint at = pointAlongSide(pattern, outlines, side, s);
  // Text stays upright on the sheet: centre it vertically after the panel's rotation.
  return {Layer::Label, side.panel, pl.placement.apply(kMm * at.point - inset * h * at.normal) - Vec2(0, 0.35 * h), h,
          text};
}

}  // namespace

double allowanceOf(int seam, const ExportOptions& o) {
  if (seam < 0) return o.freeEdgeAllowance >= 0 ? o.freeEdgeAllowance : o.allowance;
  for (const auto& [id, w] : o.seamAllowance)
    if (id == seam) return w;
  return o.allowance;
}

Polygon2 notchTick(const Notch& n, const PanelLayout& panel, const ExportOptions& o) {
  const double w = panel.widths[n.edge];
  const double inside = w > 0 ? std::min(o.notchLength, 0.5 * w) : o.notchLength;
  const Vec2 p = kMm * n.point;
  return {p + (w - inside) * n.normal, p + (w + o.notchLength) * n.normal};
}

std::vector<Polygon2> notchTicks(const SheetLayout& s, const ExportOptions& o) {
  std::vector<Polygon2> out(s.panels.size());
  for (const Notch& n : s.notches) {
    const Polygon2 tick = notchTick(n, s.panels[n.panel], o);
    out[n.panel].insert(out[n.panel].end(), tick.begin(), tick.end());
  }
  return out;
}

SheetLayout layoutSheet(const Pattern& pattern, const ExportOptions& o) {
  validate(pattern, o);
  SheetLayout s;
  s.outlines = buildOutlines(pattern);
  s.notches = placeNotches(pattern, s.outlines, o.notchSpacing / kMm);
  const int np = int(pattern.panels.size());
  s.panels.resize(np);
  std::vector<Polygon2> cuts;
  std::vector<std::string> names;
  for (int p = 0; p < np; ++p) {
    PanelLayout& pl = s.panels[p];
    const PanelOutline& outline = s.outlines.panels[p];
    pl.sew = outline.points(pattern.panels[p], kMm);
    for (int seam : outline.edgeSeam) pl.widths.push_back(allowanceOf(seam, o));
    pl.cut = offsetPolygon(pl.sew, pl.widths);
    pl.labelPoint = labelSpot(pattern.panels[p], pl.sew);
    const Vec2 size = boundingBox(pl.sew).size();
    pl.labelHeight = std::clamp(0.06 * std::min(size.x(), size.y()), 4.0, 20.0);
    cuts.push_back(pl.cut);
    names.push_back(pattern.panels[p].name);
  }
  s.nest = nestPieces(cuts, {o.sheetWidth, o.gap, o.allowRotation, o.grainLock}, names);

  Drawing& d = s.drawing;
  d.width = o.sheetWidth;
  d.length = s.nest.length;
  for (int p = 0; p < np; ++p) {
    PanelLayout& pl = s.panels[p];
    pl.placement = s.nest.placements[p];
    d.paths.push_back({Layer::Cut, p, true, transformed(pl.cut, pl.placement), {}});
    // Heat sealed: the allowance is the seal band, drawn between the sealing line and the cut line.
    if (o.sealed)
      d.paths.push_back({Layer::Seal, p, true, transformed(pl.sew, pl.placement), transformed(pl.cut, pl.placement)});
    else
      d.paths.push_back({Layer::Sew, p, true, transformed(pl.sew, pl.placement), {}});
    const Panel& panel = pattern.panels[p];
    d.texts.push_back({Layer::Label, p, pl.placement.apply(pl.labelPoint) - Vec2(0, 0.35 * pl.labelHeight),
                       pl.labelHeight,
                       std::to_string(p + 1) + "  " + panel.name + (panel.internal ? " (internal)" : "")});
  }
  // Notches: a short tick across the cut line, mostly inside the allowance so a snip does not cut the seam.
  for (const Notch& n : s.notches) {
    const PanelLayout& pl = s.panels[n.panel];
    d.paths.push_back({Layer::Notch, n.panel, false, transformed(notchTick(n, pl, o), pl.placement), {}});
  }
  // Fill valves: the same stretch of both sides of the seam left open, marked, and named beside the gap.
  for (int v = 0; v < int(o.valves.size()); ++v) {
    const FillValve& valve = o.valves[v];
    const auto seam = std::find_if(s.outlines.seams.begin(), s.outlines.seams.end(),
                                   [&](const Seam& x) { return x.id == valve.seam; });
    if (seam == s.outlines.seams.end()) continue;
    const SeamSide* sides[2] = {&seam->a, &seam->b};
    for (const SeamSide* side : sides) {
      const PanelLayout& pl = s.panels[side->panel];
      const double at = valve.at * side->length, half = 0.5 * valve.width / kMm;
      const double s0 = std::max(0.0, at - half), s1 = std::min(side->length, at + half);
      ValveGap gap{v, side->panel, valveMark(pattern, s.outlines, *side, pl, s0, s1, 2 * o.notchLength)};
      d.paths.push_back({Layer::Valve, gap.panel, true, transformed(gap.mark, pl.placement), {}});
      char text[48];
      std::snprintf(text, sizeof text, "valve %.0f mm", valve.width);
      d.texts.push_back(besideSide(pattern, s.outlines, *side, pl, at, 2.8, text));
      s.valveGaps.push_back(std::move(gap));
    }
  }
  // Seam ids on both panels, inside the sewing line near the seam's middle.
  for (const Seam& seam : s.outlines.seams) {
    const SeamSide* sides[2] = {&seam.a, &seam.b};
    for (const SeamSide* side : sides) {
      // A closed seam starts at a corner of the loop; its middle would be another corner, so use a quarter.
      d.texts.push_back(besideSide(pattern, s.outlines, *side, s.panels[side->panel],
                                   (seam.closed ? 0.25 : 0.5) * side->length,
                                   side == &seam.b && !seam.shared ? 2.6 : 1.3, "S" + std::to_string(seam.id + 1)));
    }
  }
  return s;
}

}  // namespace billow
