#include "io/pattern_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "util/error.hpp"

namespace billow {
namespace {

using nlohmann::json;

[[noreturn]] void badPatternValue(const std::string& what) { throw Error("pattern.bad-value", what); }

double positiveNumber(const json& obj, const char* key, const std::string& where, bool required = true,
                      double fallback = 0) {
  if (!obj.contains(key)) {
    if (required) badPatternValue(where + " has no \"" + key + "\".");
    return fallback;
  }
  const json& v = obj.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() <= 0)
    badPatternValue(where + ": \"" + key + "\" must be a positive number.");
  return v.get<double>();
}

const json& arrayField(const json& obj, const char* key, const std::string& where) {
  if (!obj.contains(key) || !obj.at(key).is_array()) badPatternValue(where + " needs a \"" + key + "\" list.");
  return obj.at(key);
}

double number(const json& v, const std::string& where) {
  if (!v.is_number()) badPatternValue(where + " must contain numbers only.");
  return v.get<double>();
}

int index(const json& v, const std::string& where) {
  if (!v.is_number_integer()) throw Error("pattern.bad-index", where + " must contain whole numbers (indices).");
  const long long i = v.get<long long>();
  if (i < 0 || i > 2'000'000'000LL) throw Error("pattern.bad-index", where + " has an index out of range.");
  return static_cast<int>(i);
}

template <int Cols, class Matrix>
Matrix readRows(const json& list, const std::string& where, double scale) {
  Matrix m(static_cast<Eigen::Index>(list.size()), Cols);
  for (size_t r = 0; r < list.size(); ++r) {
    const json& row = list[r];
    if (!row.is_array() || row.size() != Cols)
      badPatternValue(where + ": every entry must be a list of " + std::to_string(Cols) + " numbers.");
    for (int c = 0; c < Cols; ++c) {
      if constexpr (std::is_same_v<typename Matrix::Scalar, int>)
        m(r, c) = index(row[c], where);
      else
        m(r, c) = scale * number(row[c], where);
    }
  }
  return m;
}

Panel readPanel(const json& j, int i, double scale, long long& triangleBudget) {
  const std::string where = "panel " + std::to_string(i);
  if (!j.is_object()) badPatternValue(where + " must be an object.");
  Panel p;
  if (j.contains("name")) {
    if (!j["name"].is_string()) badPatternValue(where + ": \"name\" must be text.");
    p.name = j["name"].get<std::string>();
  }
  if (j.contains("internal")) {
    if (!j["internal"].is_boolean()) badPatternValue(where + ": \"internal\" must be true or false.");
    p.internal = j["internal"].get<bool>();
  }
  const json& tris = arrayField(j, "triangles", where);
  triangleBudget -= static_cast<long long>(tris.size());
  if (triangleBudget < 0)
    throw Error("pattern.too-large", "The pattern has too many triangles for Billow. Use a coarser resolution.");
  p.vertices = readRows<2, PanelVertices>(arrayField(j, "vertices", where), where + " vertices", scale);
  p.triangles = readRows<3, Triangles>(tris, where + " triangles", 1);
  if (j.contains("seam_corners")) {
    const json& corners = arrayField(j, "seam_corners", where);
    p.seamCorners.emplace();
    for (const json& v : corners) p.seamCorners->push_back(index(v, where + " seam_corners"));
  }
  return p;
}

}  // namespace

Pattern readPatternJson(std::string_view text, std::vector<PatternWarning>* warnings, const PatternLimits& limits) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number such as 1e309
    throw Error("pattern.json", std::string("The pattern file is not valid JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("format") || j["format"] != "billow-pattern")
    throw Error("pattern.unknown-format", "This is not a Billow pattern file (\"format\" must be \"billow-pattern\").");
  if (!j.contains("version") || !j["version"].is_number_integer() || j["version"].get<int>() != 1)
    throw Error("pattern.version",
                "This pattern file was written by a different Billow version (only version 1 "
                "is understood here).");
  double scale = 1;
  if (j.contains("units")) {
    const json& u = j["units"];
    if (u == "m")
      scale = 1;
    else if (u == "cm")
      scale = 0.01;
    else if (u == "mm")
      scale = 0.001;
    else
      badPatternValue("\"units\" must be \"m\", \"cm\" or \"mm\".");
  }
  Pattern p;
  p.pressure = positiveNumber(j, "pressure", "The pattern");
  if (!j.contains("material") || !j["material"].is_object()) badPatternValue("The pattern needs a \"material\".");
  const json& mat = j["material"];
  if (mat.contains("name")) {
    if (!mat["name"].is_string()) badPatternValue("The material's \"name\" must be text.");
    p.material.name = mat["name"].get<std::string>();
  }
  p.material.thickness = positiveNumber(mat, "thickness", "The material");
  p.material.youngsModulus = positiveNumber(mat, "youngs_modulus", "The material");
  p.material.density = positiveNumber(mat, "density", "The material", false, -1);

  const json& panels = arrayField(j, "panels", "The pattern");
  if (static_cast<long long>(panels.size()) > limits.maxPanels)
    throw Error("pattern.too-large", "The pattern has more than " + std::to_string(limits.maxPanels) + " panels.");
  long long budget = limits.maxTriangles;
  for (size_t i = 0; i < panels.size(); ++i) p.panels.push_back(readPanel(panels[i], int(i), scale, budget));
  if (j.contains("stitches")) {
    const Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> s =
        readRows<4, Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>>(arrayField(j, "stitches", "The pattern"),
                                                                            "stitches", 1);
    for (int r = 0; r < s.rows(); ++r) p.stitches.push_back({s(r, 0), s(r, 1), s(r, 2), s(r, 3)});
  }
  if (j.contains("inflated")) {
    const json& inf = arrayField(j, "inflated", "The pattern");
    if (inf.size() != panels.size()) badPatternValue("\"inflated\" needs one list of 3D positions per panel.");
    for (size_t i = 0; i < inf.size(); ++i) {
      if (!inf[i].is_array() || inf[i].size() != size_t(p.panels[i].vertices.rows()))
        badPatternValue("\"inflated\" for panel " + std::to_string(i) + " needs one 3D position per panel vertex.");
      p.inflated.push_back(readRows<3, Vertices>(inf[i], "inflated", scale));
    }
  }
  const SewnMesh sewn = sewPattern(p, limits);  // validation; throws with the designer-facing message
  if (warnings) *warnings = sewn.warnings;
  return p;
}

std::string writePatternJson(const Pattern& p, int indent) {
  json j;
  j["format"] = "billow-pattern";
  j["version"] = 1;
  j["units"] = "m";
  j["pressure"] = p.pressure;
  j["material"] = {
      {"name", p.material.name}, {"thickness", p.material.thickness}, {"youngs_modulus", p.material.youngsModulus}};
  if (p.material.density > 0) j["material"]["density"] = p.material.density;
  j["panels"] = json::array();
  for (const Panel& panel : p.panels) {
    json v = json::array(), t = json::array();
    for (int r = 0; r < panel.vertices.rows(); ++r) v.push_back({panel.vertices(r, 0), panel.vertices(r, 1)});
    for (int r = 0; r < panel.triangles.rows(); ++r)
      t.push_back({panel.triangles(r, 0), panel.triangles(r, 1), panel.triangles(r, 2)});
    json out = {{"name", panel.name}, {"internal", panel.internal}, {"vertices", v}, {"triangles", t}};
    if (panel.seamCorners) out["seam_corners"] = *panel.seamCorners;
    j["panels"].push_back(std::move(out));
  }
  j["stitches"] = json::array();
  for (const Stitch& s : p.stitches) j["stitches"].push_back({s.panelA, s.vertexA, s.panelB, s.vertexB});
  if (!p.inflated.empty()) {
    j["inflated"] = json::array();
    for (const Vertices& v : p.inflated) {
      json list = json::array();
      for (int r = 0; r < v.rows(); ++r) list.push_back({v(r, 0), v(r, 1), v(r, 2)});
      j["inflated"].push_back(list);
    }
  }
  return j.dump(indent);
}

}  // namespace billow
