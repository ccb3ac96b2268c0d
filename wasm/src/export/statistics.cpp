#include "export/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace billow {
namespace {

std::string length(double mm, const ExportOptions& o) {
  char buf[48];
  if (o.units == DisplayUnits::Inches)
    std::snprintf(buf, sizeof buf, "%.1f in", mm / 25.4);
  else
    std::snprintf(buf, sizeof buf, "%.0f mm", mm);
  return buf;
}

std::string area(double m2, const ExportOptions& o) {
  char buf[48];
  if (o.units == DisplayUnits::Inches)
    std::snprintf(buf, sizeof buf, "%.2f sq ft", m2 / 0.09290304);
  else
    std::snprintf(buf, sizeof buf, "%.3f m2", m2);
  return buf;
}

}  // namespace

nlohmann::json exportStatistics(const Pattern& pattern, const SheetLayout& s, const ExportOptions& o) {
  using nlohmann::json;
  json panels = json::array(), seams = json::array();
  double panelArea = 0, cutArea = 0, seamLength = 0, freeLength = 0;
  for (size_t p = 0; p < s.panels.size(); ++p) {
    const PanelLayout& pl = s.panels[p];
    const std::vector<int>& edgeSeam = s.outlines.panels[p].edgeSeam;
    for (size_t e = 0; e < edgeSeam.size() && e < pl.sew.size(); ++e)
      if (edgeSeam[e] < 0) freeLength += (pl.sew[(e + 1) % pl.sew.size()] - pl.sew[e]).norm();
    const Box2 box = boundingBox(transformed(pl.cut, pl.placement));
    const double a = std::abs(signedArea(pl.sew)) * 1e-6, c = std::abs(signedArea(pl.cut)) * 1e-6;
    panelArea += a, cutArea += c;
    panels.push_back({{"number", p + 1},
                      {"name", pattern.panels[p].name},
                      {"internal", pattern.panels[p].internal},
                      {"area_m2", a},
                      {"cut_area_m2", c},
                      {"width_mm", box.size().x()},
                      {"height_mm", box.size().y()},
                      {"perimeter_mm", perimeter(pl.sew)},
                      {"rotation_deg", std::remainder(pl.placement.angle * 180 / M_PI, 360.0)},
                      {"position_mm", {box.lo.x(), box.lo.y()}}});
  }
  for (const Seam& seam : s.outlines.seams) {
    const double la = seam.a.length * 1000, lb = seam.b.length * 1000;
    seamLength += 0.5 * (la + lb);
    seams.push_back({{"id", seam.id},
                     {"label", "S" + std::to_string(seam.id + 1)},
                     {"panels", {seam.a.panel + 1, seam.b.panel + 1}},
                     {"length_a_mm", la},
                     {"length_b_mm", lb},
                     {"mismatch_mm", std::abs(la - lb)},
                     {"closed", seam.closed},
                     {"shared", seam.shared},
                     {"allowance_mm", allowanceOf(seam.id, o)}});
  }
  const double sheetArea = o.sheetWidth * s.nest.length * 1e-6;
  const double minutes =
      seamLength / 1000 / o.sewingMetersPerMinute + o.minutesPerSeam * double(s.outlines.seams.size());
  // Fill valves, each with whether its seam is in this pattern (a valve on a seam that is gone is not drawn).
  json valves = json::array();
  for (int v = 0; v < int(o.valves.size()); ++v) {
    const FillValve& valve = o.valves[v];
    const bool placed =
        std::any_of(s.valveGaps.begin(), s.valveGaps.end(), [&](const ValveGap& g) { return g.valve == v; });
    valves.push_back({{"seam", valve.seam},
                      {"label", "S" + std::to_string(valve.seam + 1)},
                      {"at", valve.at},
                      {"width_mm", valve.width},
                      {"placed", placed}});
  }
  json totals = {{"panels", s.panels.size()},
                 {"seams", s.outlines.seams.size()},
                 {"panel_area_m2", panelArea},
                 {"material_area_m2", cutArea},
                 {"sheet_width_mm", o.sheetWidth},
                 {"sheet_length_mm", s.nest.length},
                 {"sheet_area_m2", sheetArea},
                 {"utilisation", s.nest.utilisation},
                 {"seam_length_mm", seamLength},
                 {"free_edge_mm", freeLength},
                 {"max_seam_mismatch_mm", s.outlines.maxMismatch * 1000},
                 {"notches", s.notches.size()},
                 {"sewing_minutes", minutes},
                 {"sewing_rate_m_per_min", o.sewingMetersPerMinute},
                 {"minutes_per_seam", o.minutesPerSeam}};
  return {{"format", "billow-export-stats"},
          {"version", 1},
          {"units", {{"length", "mm"}, {"area", "m2"}, {"time", "min"}}},
          {"allowance_mm", o.allowance},
          {"free_edge_allowance_mm", allowanceOf(-1, o)},
          {"joining", o.sealed ? "sealed" : "sewn"},
          {"valves", valves},
          {"panels", panels},
          {"seams", seams},
          {"totals", totals}};
}

std::vector<std::string> summaryLines(const nlohmann::json& j, const ExportOptions& o) {
  const auto& t = j["totals"];
  char buf[200];
  std::vector<std::string> lines;
  // The seam allowance, and the seams of this pattern that have their own (up to four named).
  std::string allowance = (o.sealed ? "heat sealed, seal band " : "seam allowance ") + length(o.allowance, o);
  std::vector<std::string> own;
  for (const auto& seam : j["seams"])
    if (seam["allowance_mm"].get<double>() != o.allowance)
      own.push_back(seam["label"].get<std::string>() + " " + length(seam["allowance_mm"].get<double>(), o));
  if (own.size() > 4)
    allowance += " (" + std::to_string(own.size()) + " seams their own)";
  else
    for (const std::string& s : own) allowance += ", " + s;
  if (t["free_edge_mm"].get<double>() > 0 && allowanceOf(-1, o) != o.allowance)
    allowance += ", free edges " + length(allowanceOf(-1, o), o);
  const auto count = [](int n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  lines.push_back(count(t["panels"].get<int>(), "panel") + ", " + count(t["seams"].get<int>(), "seam") + ", " +
                  allowance);
  for (const auto& valve : j["valves"])
    if (valve["placed"].get<bool>())
      lines.push_back("fill valve on " + valve["label"].get<std::string>() + ": leave " +
                      length(valve["width_mm"].get<double>(), o) + " open at the marks on both pieces");
  std::snprintf(buf, sizeof buf, "sheet %s wide x %s long, material used %.0f %%", length(o.sheetWidth, o).c_str(),
                length(t["sheet_length_mm"].get<double>(), o).c_str(), 100 * t["utilisation"].get<double>());
  lines.push_back(buf);
  lines.push_back("panel area " + area(t["panel_area_m2"], o) + ", cut pieces " + area(t["material_area_m2"], o) +
                  ", sheet " + area(t["sheet_area_m2"], o));
  // The sewing time is a sewing machine's: a heat-sealed pattern is not sewn.
  std::snprintf(buf, sizeof buf, "seams %s in total, largest mismatch %s",
                length(t["seam_length_mm"].get<double>(), o).c_str(),
                length(t["max_seam_mismatch_mm"].get<double>(), o).c_str());
  lines.push_back(buf);
  if (!o.sealed) {
    std::snprintf(buf, sizeof buf, "; sewing about %.0f min", t["sewing_minutes"].get<double>());
    lines.back() += buf;
  }
  return lines;
}

}  // namespace billow
