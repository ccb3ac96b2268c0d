#include "io/export_options_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "util/error.hpp"

namespace billow {
namespace {

using nlohmann::json;

[[noreturn]] void badExportOption(const std::string& message) { throw Error("export.bad-value", message); }

std::string millimetres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A seam id as written in JSON keys: "0", "12" (no sign, no spaces, no leading zeros beyond "0").
bool parseSeamId(const std::string& key, int& id) {
  if (key.empty() || key.size() > 6 ||
      !std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  if (key.size() > 1 && key[0] == '0') return false;
  id = std::stoi(key);
  return true;
}

}  // namespace

std::vector<std::pair<int, double>> readSeamAllowanceJson(const json& value) {
  if (!value.is_object())
    badExportOption(
        "The export option seam_allowance must be an object of seam ids and widths in mm, like {\"3\": 0}.");
  std::vector<std::pair<int, double>> out;
  for (const auto& [key, width] : value.items()) {
    int id = 0;
    if (!parseSeamId(key, id))
      badExportOption("The seam allowance names the seam \"" + key.substr(0, 40) +
                      "\"; seams are named by their id, a whole "
                      "number from 0 (seam S1 is id 0).");
    if (!width.is_number() || !std::isfinite(width.get<double>()) || width.get<double>() < 0 ||
        width.get<double>() > kMaxSeamAllowance)
      badExportOption("The allowance of seam S" + std::to_string(id + 1) + " must be a width from 0 to " +
                      millimetres(kMaxSeamAllowance) + " mm.");
    out.emplace_back(id, width.get<double>());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<FillValve> readFillValvesJson(const json& value) {
  if (!value.is_array())
    badExportOption("The fill valves must be a list, like [{\"seam\": 0, \"at\": 0.5, \"width\": 20}].");
  std::vector<FillValve> out;
  for (const json& v : value) {
    if (!v.is_object() || !v.contains("seam") || !v["seam"].is_number_integer() || v["seam"].get<long long>() < 0 ||
        v["seam"].get<long long>() > 999999)
      badExportOption(
          "A fill valve names no seam: each valve needs \"seam\", the id of the seam it sits on (seam S1 is id 0).");
    FillValve valve;
    valve.seam = v["seam"].get<int>();
    const std::string name = "The fill valve on seam S" + std::to_string(valve.seam + 1);
    if (v.contains("at")) {
      if (!v["at"].is_number() || !(v["at"].get<double>() >= 0 && v["at"].get<double>() <= 1))
        badExportOption(name + " must sit along the seam: \"at\" from 0 (its start) to 1 (its end).");
      valve.at = v["at"].get<double>();
    }
    if (v.contains("width")) {
      if (!v["width"].is_number() || !(v["width"].get<double>() > 0 && v["width"].get<double>() <= kMaxValveWidth))
        badExportOption(name + " must be wider than 0 and at most " + millimetres(kMaxValveWidth) + " mm.");
      valve.width = v["width"].get<double>();
    }
    out.push_back(valve);
  }
  return out;
}

ExportOptions readExportOptionsJson(const json& j, ExportOptions o) {
  if (!j.is_object()) badExportOption("The export options are not valid.");
  const auto number = [&](const char* key, double fallback) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_number()) badExportOption(std::string("The export option ") + key + " must be a number.");
    return j[key].get<double>();
  };
  const auto flag = [&](const char* key, bool fallback) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_boolean()) badExportOption(std::string("The export option ") + key + " is true or false.");
    return j[key].get<bool>();
  };
  const auto text = [&](const char* key, const std::string& fallback) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_string()) badExportOption(std::string("The export option ") + key + " must be text.");
    return j[key].get<std::string>();
  };
  o.allowance = number("allowance", o.allowance);
  if (j.contains("free_edge_allowance")) {
    o.freeEdgeAllowance = number("free_edge_allowance", o.freeEdgeAllowance);
    if (!(o.freeEdgeAllowance >= 0 && o.freeEdgeAllowance <= kMaxSeamAllowance))
      badExportOption("The allowance of free edges must be a width from 0 to " + millimetres(kMaxSeamAllowance) +
                      " mm.");
  }
  if (j.contains("seam_allowance")) o.seamAllowance = readSeamAllowanceJson(j["seam_allowance"]);
  o.sheetWidth = number("sheet_width", o.sheetWidth);
  o.notchSpacing = number("notch_spacing", o.notchSpacing);
  o.tileOverlap = number("overlap", o.tileOverlap);
  const std::string paper = text("paper", o.paper == PaperSize::A4 ? "a4" : "letter");
  if (paper != "a4" && paper != "letter") badExportOption("The paper is A4 or Letter.");
  o.paper = paper == "a4" ? PaperSize::A4 : PaperSize::Letter;
  const std::string units = text("units", o.units == DisplayUnits::Millimeters ? "mm" : "in");
  if (units != "mm" && units != "in") badExportOption("The units are mm or inches.");
  o.units = units == "mm" ? DisplayUnits::Millimeters : DisplayUnits::Inches;
  const std::string joining = text("joining", o.sealed ? "sealed" : "sewn");
  if (joining != "sewn" && joining != "sealed") badExportOption("The pieces are joined \"sewn\" or \"sealed\".");
  o.sealed = joining == "sealed";
  if (j.contains("valves")) o.valves = readFillValvesJson(j["valves"]);
  o.grainLock = flag("grain_lock", o.grainLock);
  o.allowRotation = flag("rotate", o.allowRotation);
  if (j.contains("title") && j["title"].is_string()) o.title = j["title"].get<std::string>().substr(0, 120);
  return o;
}

}  // namespace billow
