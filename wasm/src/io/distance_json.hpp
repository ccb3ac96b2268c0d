// A shape's distance to its target (TwoWayDistance) as JSON, for the CLI's report.json and the embind module.
//   uncoveredJson: [{ "area": fraction of the target's area, "max": over the diagonal,
//                     "position": [x, y, z] (the farthest vertex, target units), "radius", "where",
//                     "message" (uncoveredMessage), "helps" (uncoveredRemedy) }]
//   distanceReportJson: { "rms", "max" (the worse way), "inflated_to_target": { "rms", "max" },
//                         "target_to_inflated": { "rms", "max" }, "uncovered", "relative_to" }
#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "seams/surface_distance.hpp"

namespace billow {

nlohmann::json uncoveredJson(const std::vector<UncoveredRegion>& regions);
nlohmann::json distanceReportJson(const TwoWayDistance& d);

}  // namespace billow
