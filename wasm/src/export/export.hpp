// The fabrication outputs in one call (what the CLI and the worker use): SVG and DXF cut files of the
// nested sheet, a tiled printable PDF, and statistics as JSON text. All at true scale, in millimetres.
#pragma once
#include <string>
#include <vector>

#include "export/export_options.hpp"
#include "export/outline.hpp"
#include "export/polygon.hpp"
#include "pattern/pattern.hpp"

namespace billow {

struct ExportBundle {
  std::string svg, dxf, pdf;
  std::string statistics;          // JSON (statistics.hpp)
  std::vector<Polygon2> cutLines;  // per panel, the cut line (with the allowance) in its own frame [mm]
  Outlines outlines;               // the seams, and per panel its sewing line's loop and each edge's seam id
  // The nested sheet, for a view of it: per panel its placement (panel frame -> sheet, both [mm]), the
  // sheet's width and the length used [mm], and per panel its registration notches as tick segments
  // (a0, b0, a1, b1, ...) in its own frame [mm].
  std::vector<Placement2> placements;
  double sheetWidth = 0, sheetLength = 0, utilisation = 0;
  std::vector<Polygon2> notchTicks;
  std::vector<std::vector<Polygon2>> valveMarks;  // per panel, the marks of its fill valves' gaps, its frame [mm]
};

// Throws billow::Error: export.empty, export.bad-value, export.panel-shape, export.sheet-too-narrow.
ExportBundle exportPattern(const Pattern& pattern, const ExportOptions& options = {});

}  // namespace billow
