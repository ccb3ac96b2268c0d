// Statistics of the fabrication outputs, as JSON (all lengths in mm, areas in m^2, time in minutes):
//   { "units": {...}, "allowance_mm", "free_edge_allowance_mm", "joining": "sewn" | "sealed",
//     "valves": [ { "seam", "label", "at", "width_mm", "placed" } ],
//     "panels": [ { "number", "name", "internal", "area_m2", "cut_area_m2", "width_mm", "height_mm",
//     "perimeter_mm", "rotation_deg", "position_mm": [x, y] } ],
//     "seams": [ { "id", "label", "panels": [a, b], "length_a_mm", "length_b_mm", "mismatch_mm", "closed",
//     "shared", "allowance_mm" } ],
//     "totals": { "panel_area_m2", "material_area_m2" (cut pieces), "sheet_width_mm", "sheet_length_mm",
//     "sheet_area_m2", "utilisation", "seam_length_mm", "free_edge_mm" (unsewn outline), "max_seam_mismatch_mm",
//     "notches", "sewing_minutes", "sewing_rate_m_per_min", "minutes_per_seam" } }
// Panel width/height are the bounding size of the cut piece as it lies on the sheet. A seam's "allowance_mm"
// is its own (ExportOptions::seamAllowance) or the default.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "export/layout.hpp"

namespace billow {

nlohmann::json exportStatistics(const Pattern& pattern, const SheetLayout& layout, const ExportOptions& options);

// Lines for people (the PDF overview), in the chosen display units.
std::vector<std::string> summaryLines(const nlohmann::json& statistics, const ExportOptions& options);

}  // namespace billow
