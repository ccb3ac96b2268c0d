#include "io/distance_json.hpp"

namespace billow {

nlohmann::json uncoveredJson(const std::vector<UncoveredRegion>& regions) {
  nlohmann::json list = nlohmann::json::array();
  for (const UncoveredRegion& r : regions)
    list.push_back({{"area", r.areaFraction},
                    {"max", r.maxDistance},
                    {"position", {r.farthest.x(), r.farthest.y(), r.farthest.z()}},
                    {"radius", r.radius},
                    {"where", r.where},
                    {"message", uncoveredMessage(r)},
                    {"helps", uncoveredRemedy(r)}});
  return list;
}

nlohmann::json distanceReportJson(const TwoWayDistance& d) {
  const auto summary = [](const DistanceSummary& s) { return nlohmann::json{{"rms", s.rms}, {"max", s.max}}; };
  nlohmann::json j = summary(d.worse());
  j["inflated_to_target"] = summary(d.inflatedToTarget);
  j["target_to_inflated"] = summary(d.targetToInflated.summary);
  j["uncovered"] = uncoveredJson(d.uncovered);
  j["relative_to"] = "bounding-box diagonal";
  return j;
}

}  // namespace billow
