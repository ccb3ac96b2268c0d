// Export options as JSON: the embind module's options and the design document's "fabrication" object
// (docs/formats.md) use the same keys, all optional, lengths in mm:
//   { "allowance": 10, "free_edge_allowance": 5, "seam_allowance": { "3": 0, "5": 15 },
//     "sheet_width": 1000, "notch_spacing": 100, "overlap": 10, "paper": "a4" | "letter",
//     "units": "mm" | "in", "grain_lock": false, "rotate": true, "title": "...",
//     "joining": "sewn" | "sealed", "valves": [ { "seam": 0, "at": 0.5, "width": 20 } ] }
// joining "sealed" (heat sealed foil): the allowance is the seal band. A valve is a gap in its seam (ids as
// below, "at" a share of the seam's length); valves on seams the pattern does not have are reported, unplaced.
// seam_allowance maps a seam id (the "id" of stats.json, labelled S<id + 1> on the pieces) to its own
// allowance. Ids of seams the pattern does not have are kept and ignored by the exporter.
#pragma once
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "export/export_options.hpp"

namespace billow {

constexpr double kMaxSeamAllowance = 100;  // [mm], per seam and for free edges (as in the app)
constexpr double kMaxValveWidth = 200;     // [mm] (as in the app)

// Reads the keys present in `j` over `defaults`. Throws billow::Error("export.bad-value") naming the
// option when a value has the wrong type or is out of range; unknown keys are ignored.
ExportOptions readExportOptionsJson(const nlohmann::json& j, ExportOptions defaults = {});

// The "seam_allowance" object alone: (seam id, width [mm]) sorted by id. Throws billow::Error
// ("export.bad-value") for an id that is not a whole number from 0 or a width outside 0..100 mm.
std::vector<std::pair<int, double>> readSeamAllowanceJson(const nlohmann::json& value);

// The "valves" list alone. Throws billow::Error("export.bad-value") for a valve without a seam id, "at"
// outside 0..1 or a width outside (0, 200] mm.
std::vector<FillValve> readFillValvesJson(const nlohmann::json& value);

}  // namespace billow
