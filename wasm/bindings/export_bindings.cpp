// Embind for the fabrication outputs (wasm/src/export/export.hpp):
//   Module.exportPattern(patternJson, optionsJson) -> { svg, dxf, pdfBase64, statistics, cutLines, outlines, notches,
//   sheet }
//     options (all optional, lengths in mm; io/export_options_json.hpp): { allowance, free_edge_allowance,
//       seam_allowance: { "<seam id>": mm }, sheet_width, notch_spacing, overlap, paper: "a4"|"letter",
//       units: "mm"|"in", grain_lock, rotate, title, joining: "sewn"|"sealed", valves: [{ seam, at, width }] }
//     cutLines: per panel [x0, y0, x1, y1, ...] in the panel's own frame, in meters (for the pattern pane).
//     outlines: per panel { loop: [vertex index, ...] (its sewing line, counterclockwise), seams: [seam id of
//       loop edge i (loop[i] -> loop[i+1]), -1 for a free edge] }: where each seam of stats.json lies.
//     notches: per panel its registration notches as tick segments [x0, y0, x1, y1, ...] in its frame [m].
//     seamSides: per seam { id, sides: [{ panel, edges: [loop edge, ...] in seam order, forward, length [m] }] x 2 }
//       (export/outline.hpp SeamSide): where a point of a seam lies along it, for placing a fill valve.
//     valves: per panel the marks of its fill valves' gaps, each a closed [x0, y0, ...] in its frame [m].
//     sheet: { width, length [m], utilisation, placements: per panel { angle [rad], x, y [m] } }: the nested
//       sheet (sheet point = rotate(angle) * panel point + (x, y); x across the roll, y along it).
//   The PDF is binary, so it crosses as base64 (embind strings are UTF-8 text).
#include <emscripten/bind.h>

#include <nlohmann/json.hpp>
#include <string>

#include "export/export.hpp"
#include "guarded.hpp"
#include "io/export_options_json.hpp"
#include "io/pattern_json.hpp"
#include "util/error.hpp"

namespace {

using billow::bindings::guarded;
using nlohmann::json;

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 | (unsigned char)bytes[i + 2];
    for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
  }
  if (i < bytes.size()) {
    unsigned v = (unsigned char)bytes[i] << 16;
    if (i + 1 < bytes.size()) v |= (unsigned char)bytes[i + 1] << 8;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

billow::ExportOptions readOptions(const std::string& optionsJson) {
  if (optionsJson.empty()) return {};
  const json j = json::parse(optionsJson, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw billow::Error("export.bad-value", "The export options are not valid.");
  return billow::readExportOptionsJson(j);
}

std::string exportPattern(const std::string& patternJson, const std::string& optionsJson) {
  return guarded([&] {
    const billow::Pattern pattern = billow::readPatternJson(patternJson);
    const billow::ExportBundle bundle = billow::exportPattern(pattern, readOptions(optionsJson));
    const auto meters = [](const billow::Polygon2& points) {
      json flat = json::array();
      for (const billow::Vec2& p : points) flat.push_back(p.x() / 1000), flat.push_back(p.y() / 1000);
      return flat;
    };
    json cut = json::array();
    for (const billow::Polygon2& line : bundle.cutLines) cut.push_back(meters(line));
    json notches = json::array();
    for (const billow::Polygon2& ticks : bundle.notchTicks) notches.push_back(meters(ticks));
    json placements = json::array();
    for (const billow::Placement2& t : bundle.placements)
      placements.push_back({{"angle", t.angle}, {"x", t.offset.x() / 1000}, {"y", t.offset.y() / 1000}});
    const json sheet = {{"width", bundle.sheetWidth / 1000},
                        {"length", bundle.sheetLength / 1000},
                        {"utilisation", bundle.utilisation},
                        {"placements", placements}};
    json outlines = json::array();
    for (const billow::PanelOutline& o : bundle.outlines.panels)
      outlines.push_back({{"loop", o.loop}, {"seams", o.edgeSeam}});
    json seamSides = json::array();
    for (const billow::Seam& seam : bundle.outlines.seams) {
      json sides = json::array();
      for (const billow::SeamSide* side : {&seam.a, &seam.b})
        sides.push_back(
            {{"panel", side->panel}, {"edges", side->edges}, {"forward", side->forward}, {"length", side->length}});
      seamSides.push_back({{"id", seam.id}, {"sides", sides}});
    }
    json valves = json::array();
    for (const auto& marks : bundle.valveMarks) {
      json list = json::array();
      for (const billow::Polygon2& mark : marks) list.push_back(meters(mark));
      valves.push_back(list);
    }
    return json({{"svg", bundle.svg},
                 {"dxf", bundle.dxf},
                 {"pdfBase64", base64(bundle.pdf)},
                 {"statistics", json::parse(bundle.statistics)},
                 {"cutLines", cut},
                 {"outlines", outlines},
                 {"notches", notches},
                 {"seamSides", seamSides},
                 {"valves", valves},
                 {"sheet", sheet}})
        .dump();
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(billow_export) { emscripten::function("exportPattern", &exportPattern); }
