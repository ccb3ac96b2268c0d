// The sheet: outlines, seam allowance, notches, nesting and labels put together in sheet millimetres.
#pragma once
#include <vector>

#include "export/drawing.hpp"
#include "export/export_options.hpp"
#include "export/nesting.hpp"
#include "export/notches.hpp"
#include "export/outline.hpp"

namespace billow {

struct PanelLayout {
  Polygon2 sew;                // sewing line (the panel outline) [mm], panel frame
  Polygon2 cut;                // cut line (with the allowance) [mm], panel frame
  std::vector<double> widths;  // allowance per outline edge [mm]
  Placement2 placement;        // panel frame -> sheet
  Vec2 labelPoint{0, 0};       // inside the panel, far from its outline [mm], panel frame
  double labelHeight = 5;      // [mm]
};

// A fill valve's gap on one piece: the stretch of sewing line left open and the mark drawn over it (the
// sewing line there and back along the outside of the allowance or seal band), panel frame [mm].
struct ValveGap {
  int valve = -1;  // index in ExportOptions::valves
  int panel = -1;
  Polygon2 mark;
};

struct SheetLayout {
  Outlines outlines;
  std::vector<Notch> notches;
  std::vector<ValveGap> valveGaps;  // two per valve on a seam of the pattern (one per side), none otherwise
  std::vector<PanelLayout> panels;
  NestResult nest;
  Drawing drawing;
};

// Throws billow::Error: export.empty, export.bad-value, export.panel-shape, export.sheet-too-narrow.
SheetLayout layoutSheet(const Pattern& pattern, const ExportOptions& options);

// A registration notch as a short tick across the cut line, mostly inside the allowance so a snip does not
// cut the seam: its two ends in the panel's frame [mm].
Polygon2 notchTick(const Notch& notch, const PanelLayout& panel, const ExportOptions& options);
// Per panel, its notches' ticks one after another (a0, b0, a1, b1, ...) in its frame [mm].
std::vector<Polygon2> notchTicks(const SheetLayout& sheet, const ExportOptions& options);

// Allowance [mm] of a seam (its override, else the default) or of a free edge (seam < 0).
double allowanceOf(int seam, const ExportOptions& options);

}  // namespace billow
