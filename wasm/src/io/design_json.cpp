#include "io/design_json.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "io/mesh_file.hpp"
#include "simulate/materials.hpp"
#include "util/error.hpp"

namespace billow {

namespace {

using nlohmann::json;

constexpr long long kMaxVertices = 5'000'000, kMaxSeams = 10'000, kMaxPoints = 100'000;

// A value as JSON for a message, cut short: a document may hold a long list where one number was expected.
std::string shortDump(const json& v) {
  std::string text = v.dump();
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

// Reads fields with validation: a bad field throws (strict) or warns and keeps the default.
class FieldReader {
 public:
  FieldReader(const DesignReadOptions& o, std::vector<DesignWarning>* w) : strict_(o.strict), warnings_(w) {}

  // Returns false after reporting when the field is bad.
  bool bad(const std::string& field, const std::string& message) {
    if (strict_) throw Error("design.bad-value", message);
    if (warnings_) warnings_->push_back({field, message + " The default is used."});
    return false;
  }

  // A number from lo to hi; `range` says so in the designer's units ("between 1 Pa and 10 MPa").
  double number(const json& v, double fallback, double lo, double hi, const std::string& field, const std::string& what,
                const std::string& range = "") {
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo || v.get<double>() > hi) {
      bad(field, what + " (" + field + ") must be " +
                     (range.empty() ? "a number from " + fmt(lo) + " to " + fmt(hi) : range) + ", not " + shortDump(v) +
                     ".");
      return fallback;
    }
    return v.get<double>();
  }

  double number(const json& obj, const char* key, double fallback, double lo, double hi, const std::string& field,
                const std::string& what, const std::string& range = "") {
    return obj.contains(key) ? number(obj[key], fallback, lo, hi, field, what, range) : fallback;
  }

  bool boolean(const json& obj, const char* key, bool fallback, const std::string& field, const std::string& what) {
    if (!obj.contains(key)) return fallback;
    if (!obj[key].is_boolean()) {
      bad(field, what + " (" + field + ") must be true or false, not " + shortDump(obj[key]) + ".");
      return fallback;
    }
    return obj[key].get<bool>();
  }

  static std::string fmt(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", x);
    return b;
  }

 private:
  bool strict_;
  std::vector<DesignWarning>* warnings_;
};

std::string capitalized(std::string s) {
  if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

bool finiteTriple(const json& p) {
  if (!p.is_array() || p.size() != 3) return false;
  for (const auto& x : p)
    if (!x.is_number() || !std::isfinite(x.get<double>())) return false;
  return true;
}

// what: "point 2 of seam 1", for messages.
bool readPoint(FieldReader& r, const json& p, const std::string& field, const std::string& what, DesignPoint& out) {
  const std::string at = capitalized(what) + " (" + field + ")";
  if (finiteTriple(p)) {
    out.onSurface = false;
    out.position = Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    return true;
  }
  if (!p.is_object() || !p.contains("face") || !p.contains("bary"))
    return r.bad(field, at + " must be a surface point {face, bary} or a 3D point [x, y, z].");
  const json& face = p["face"];
  if (!face.is_number_integer() || face.get<double>() < 0 || face.get<double>() > 2147483647.0)
    return r.bad(field, at + " names no triangle of the target: " + shortDump(face) + ".");
  if (!finiteTriple(p["bary"])) return r.bad(field, at + " needs three barycentric coordinates.");
  Eigen::Vector3d b(p["bary"][0].get<double>(), p["bary"][1].get<double>(), p["bary"][2].get<double>());
  if (b.minCoeff() < -1e-6 || std::abs(b.sum() - 1) > 1e-3)
    return r.bad(field,
                 at + " lies outside its triangle: its barycentric coordinates must be at least 0 and sum to 1, not " +
                     shortDump(p["bary"]) + ".");
  b = b.cwiseMax(0.0);
  out.onSurface = true;
  out.surface.face = static_cast<int>(face.get<long long>());
  out.surface.bary = b / b.sum();
  return true;
}

bool readSeam(FieldReader& r, const json& s, int index, DesignSeam& out) {
  const std::string field = index >= 0 ? "seams[" + std::to_string(index) + "]" : "seam";
  if (!s.is_object())
    return r.bad(field,
                 capitalized(seamLabel(index, "")) + " (" + field + ") must be an object with a list of points.");
  if (s.contains("name")) {
    if (s["name"].is_string())
      out.name = s["name"].get<std::string>();
    else
      r.bad(field + ".name", "The name of " + seamLabel(index, "") + " (" + field + ".name) must be text, not " +
                                 shortDump(s["name"]) + ".");
  }
  const std::string label = seamLabel(index, out.name);
  out.closed = r.boolean(s, "closed", false, field + ".closed", "Whether " + label + " is closed");
  out.smooth = r.boolean(s, "smooth", false, field + ".smooth", "Whether " + label + " is smooth");
  out.band = s.contains("band") && s["band"].is_object();
  out.weight =
      r.number(s, "weight", 1.0, 0.0, 1e6, field + ".weight", "The weight of " + label, "a number from 0 to 1000000");
  if (!s.contains("points") || !s["points"].is_array())
    return r.bad(field + ".points", capitalized(label) + " (" + field + ") has no list of points.");
  if (static_cast<long long>(s["points"].size()) > kMaxPoints)
    throw Error("design.too-large", capitalized(label) + " (" + field + ") has more than 100,000 points.");
  for (size_t i = 0; i < s["points"].size(); ++i) {
    DesignPoint p;
    if (!readPoint(r, s["points"][i], field + ".points[" + std::to_string(i) + "]",
                   "point " + std::to_string(i + 1) + " of " + label, p))
      return false;
    out.points.push_back(p);
  }
  const size_t least = out.closed ? 3 : 2;
  if (out.points.size() < least)
    return r.bad(field + ".points", capitalized(label) + " (" + field + ") is " + (out.closed ? "closed" : "open") +
                                        " and needs at least " + std::to_string(least) + " points, not " +
                                        std::to_string(out.points.size()) + ".");
  return true;
}

bool readConnection(FieldReader& r, const json& c, size_t i, size_t seamCount, DesignConnection& out) {
  const std::string field = "connections[" + std::to_string(i) + "]";
  const std::string at = "Internal connection " + std::to_string(i + 1) + " (" + field + ")";
  const json& pair = c.is_object() && c.contains("seams") ? c["seams"] : c;
  if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number_integer() || !pair[1].is_number_integer())
    return r.bad(field,
                 at + " must join two of the design's seams: {\"seams\": [i, j]} or [i, j], not " + shortDump(c) + ".");
  for (const json& s : pair)
    if (s.get<double>() < 0 || s.get<double>() >= static_cast<double>(seamCount))
      return r.bad(field, at + " joins seam " + s.dump() + " (counted from 0), but the design has " +
                              (seamCount ? "only " + std::to_string(seamCount) + " seam" + (seamCount > 1 ? "s" : "")
                                         : std::string("no seams")) +
                              ".");
  out.seams = {pair[0].get<int>(), pair[1].get<int>()};
  return true;
}

bool readInlineMesh(FieldReader& r, const json& t, TriMesh& mesh) {
  const json &v = t["vertices"], &f = t.contains("triangles") ? t["triangles"] : json();
  if (!v.is_array() || !f.is_array() || v.size() < 4 || f.size() < 4)
    return r.bad("target", "An inline target needs \"vertices\" and \"triangles\" lists (a closed surface).");
  if (static_cast<long long>(v.size()) > kMaxVertices || static_cast<long long>(f.size()) > 2 * kMaxVertices)
    throw Error("design.too-large", "The inline target has more than 5 million vertices.");
  mesh.V.resize(static_cast<Eigen::Index>(v.size()), 3);
  mesh.F.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (size_t i = 0; i < v.size(); ++i) {
    if (!finiteTriple(v[i]))
      return r.bad("target.vertices", "Target vertex " + std::to_string(i) + " is not three numbers.");
    for (int k = 0; k < 3; ++k) mesh.V(static_cast<Eigen::Index>(i), k) = v[i][k].get<double>();
  }
  for (size_t i = 0; i < f.size(); ++i) {
    const json& tri = f[i];
    bool good = tri.is_array() && tri.size() == 3;
    for (int k = 0; good && k < 3; ++k)
      good = tri[k].is_number_integer() && tri[k].get<long long>() >= 0 &&
             tri[k].get<long long>() < static_cast<long long>(v.size());
    if (!good)
      return r.bad("target.triangles", "Target triangle " + std::to_string(i) +
                                           " is not three vertex numbers of the target's vertex list.");
    for (int k = 0; k < 3; ++k) mesh.F(static_cast<Eigen::Index>(i), k) = tri[k].get<int>();
  }
  return true;
}

UpAxis readUp(FieldReader& r, const json& value) {
  UpAxis up;
  if (value.is_string() && parseUpAxis(value.get<std::string>(), up)) return up;
  r.bad("target.up",
        "The target's up axis (target.up) must be one of \"+y\", \"-y\", \"+z\", \"-z\", \"+x\", \"-x\", not " +
            shortDump(value) + ".");
  return UpAxis{};
}

bool readTarget(FieldReader& r, const json& t, DesignTarget& out) {
  if (!t.is_object()) return r.bad("target", "The target must be an object such as {\"example\": \"spot\"}.");
  if (t.contains("up")) out.up = readUp(r, t["up"]);
  out.cutThinHandles =
      r.boolean(t, "cutThinHandles", false, "target.cutThinHandles", "Whether its thin handles are cut");
  out.closeHoles = r.boolean(t, "closeHoles", false, "target.closeHoles", "Whether its holes are closed");
  const int kinds =
      int(t.contains("example")) + int(t.contains("obj")) + int(t.contains("file")) + int(t.contains("vertices"));
  if (kinds != 1)
    return r.bad("target",
                 "The target needs exactly one of \"example\", \"obj\", \"file\" or inline "
                 "\"vertices\" and \"triangles\".");
  if (t.contains("vertices")) {
    out.kind = DesignTarget::Inline;
    out.name.clear();
    return readInlineMesh(r, t, out.mesh);
  }
  const char* key = t.contains("example") ? "example" : t.contains("obj") ? "obj" : "file";
  if (!t[key].is_string() || t[key].get<std::string>().empty())
    return r.bad(std::string("target.") + key, std::string("The target's \"") + key + "\" must be a name.");
  const std::string name = t[key].get<std::string>();
  if (t.contains("example") && name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos)
    return r.bad("target.example", "There is no example called \"" + name + "\".");
  out.kind = t.contains("example") ? DesignTarget::Example : t.contains("obj") ? DesignTarget::Obj : DesignTarget::File;
  out.name = name;
  return true;
}

void readMaterial(FieldReader& r, const json& m, Material& out) {
  if (!m.is_object()) {
    r.bad("material", "The material (material) must be an object with a thickness and a Young's modulus, not " +
                          shortDump(m) + ".");
    return;
  }
  if (m.contains("name")) {
    if (m["name"].is_string())
      out = namedMaterial(m["name"].get<std::string>(), out);
    else
      r.bad("material.name", "The material's name (material.name) must be text, not " + shortDump(m["name"]) + ".");
  }
  out.thickness = r.number(m, "thickness", out.thickness, kMinThickness, kMaxThickness, "material.thickness",
                           "The sheet thickness", "between 0.1 µm and 1 cm");
  out.youngsModulus = r.number(m, "youngs_modulus", out.youngsModulus, kMinYoungsModulus, kMaxYoungsModulus,
                               "material.youngs_modulus", "The material's Young's modulus", "between 1 kPa and 10 TPa");
  out.density =
      r.number(m, "density", out.density, 0, 1e5, "material.density", "The density", "between 0 and 100000 kg/m³");
}

void readSize(FieldReader& r, const json& s, Design& d) {
  if (!s.is_object()) {
    r.bad("size", "The size must be an object such as {\"height\": 0.6}.");
    return;
  }
  if (s.contains("height") && s.contains("scale")) {
    r.bad("size", "Give the size as a height or as a scale, not both.");
    return;
  }
  d.height = r.number(s, "height", d.height, 0.01, 100, "size.height", "The height [m]");
  d.scale = r.number(s, "scale", 0.0, 1e-9, 1e9, "size.scale", "The scale [m per target unit]");
}

}  // namespace

Design readDesignJson(std::string_view text, const DesignReadOptions& options, std::vector<DesignWarning>* warnings) {
  json doc = json::parse(text.begin(), text.end(), nullptr, false);
  if (doc.is_discarded() || !doc.is_object())
    throw Error("design.json", "This is not a design file: it is not a JSON object.");
  if (!doc.contains("format") || doc["format"] != "billow-design")
    throw Error("design.unknown-format", "This is not a Billow design (its \"format\" is not \"billow-design\").");
  FieldReader r(options, warnings);
  Design d;
  if (!doc.contains("version") || !doc["version"].is_number_integer() || doc["version"].get<long long>() < 1)
    r.bad("version", "The design has no valid version number.");
  else if (doc["version"].get<long long>() > 1)
    throw Error("design.version", "This design was saved by a newer Billow (version " + doc["version"].dump() +
                                      "); this one reads version 1. Please update Billow.");
  if (doc.contains("target") && !readTarget(r, doc["target"], d.target)) d.target = DesignTarget{};
  if (doc.contains("size")) readSize(r, doc["size"], d);
  if (doc.contains("seams")) d.seams = readDesignSeams(doc["seams"], options, warnings);
  if (doc.contains("connections"))
    d.connections = readDesignConnections(doc["connections"], d.seams.size(), options, warnings);
  if (doc.contains("material")) readMaterial(r, doc["material"], d.material);
  if (doc.contains("pressure")) d.pressure = readDesignPressure(doc["pressure"], d.pressure, options, warnings);
  d.extra = std::move(doc);
  return d;
}

bool readDesignSeam(const json& value, int index, DesignSeam& out, const DesignReadOptions& options,
                    std::vector<DesignWarning>* warnings) {
  FieldReader r(options, warnings);
  out = DesignSeam{};
  return readSeam(r, value, index, out);
}

std::vector<DesignSeam> readDesignSeams(const json& list, const DesignReadOptions& options,
                                        std::vector<DesignWarning>* warnings) {
  FieldReader r(options, warnings);
  std::vector<DesignSeam> seams;
  if (!list.is_array()) {
    r.bad("seams", "The seams (seams) must be a list.");
    return seams;
  }
  if (static_cast<long long>(list.size()) > kMaxSeams)
    throw Error("design.too-large", "The design has more than 10,000 seams.");
  for (size_t i = 0; i < list.size(); ++i) {
    DesignSeam s;
    if (readSeam(r, list[i], static_cast<int>(i), s)) seams.push_back(std::move(s));
  }
  return seams;
}

std::vector<DesignConnection> readDesignConnections(const json& list, size_t seamCount,
                                                    const DesignReadOptions& options,
                                                    std::vector<DesignWarning>* warnings) {
  FieldReader r(options, warnings);
  std::vector<DesignConnection> out;
  if (!list.is_array()) {
    r.bad("connections",
          "The internal connections (connections) must be a list of seam pairs, not " + shortDump(list) + ".");
    return out;
  }
  if (static_cast<long long>(list.size()) > kMaxSeams)
    throw Error("design.too-large", "The design has more than 10,000 internal connections.");
  for (size_t i = 0; i < list.size(); ++i) {
    DesignConnection c;
    if (readConnection(r, list[i], i, seamCount, c)) out.push_back(c);
  }
  return out;
}

Material readDesignMaterial(const json& value, const Material& base, const DesignReadOptions& options,
                            std::vector<DesignWarning>* warnings) {
  FieldReader r(options, warnings);
  Material m = base;
  readMaterial(r, value, m);
  return m;
}

double readDesignPressure(const json& value, double fallback, const DesignReadOptions& options,
                          std::vector<DesignWarning>* warnings) {
  FieldReader r(options, warnings);
  return r.number(value, fallback, 1.0, 1e7, "pressure", "The pressure", "between 1 Pa and 10 MPa");
}

UpAxis readDesignUp(const json& value, const DesignReadOptions& options, std::vector<DesignWarning>* warnings) {
  FieldReader r(options, warnings);
  return readUp(r, value);
}

json designSeamJson(const DesignSeam& s, const json& base) {
  json js = base.is_object() ? base : json::object();
  if (!s.name.empty()) js["name"] = s.name;
  js["closed"] = s.closed, js["weight"] = s.weight, js["smooth"] = s.smooth;
  json pts = json::array();
  for (const DesignPoint& p : s.points)
    pts.push_back(p.onSurface ? json{{"face", p.surface.face},
                                     {"bary", {p.surface.bary[0], p.surface.bary[1], p.surface.bary[2]}}}
                              : json{p.position[0], p.position[1], p.position[2]});
  js["points"] = pts;
  return js;
}

std::string writeDesignJson(const Design& d, int indent) {
  json doc = d.extra.is_object() ? d.extra : json::object();
  const auto base = [&](const char* key) {
    return doc.contains(key) && doc[key].is_object() ? doc[key] : json::object();
  };
  doc["format"] = "billow-design";
  doc["version"] = 1;
  json target = json::object();
  if (d.target.kind == DesignTarget::Inline) {
    json v = json::array(), f = json::array();
    for (int i = 0; i < d.target.mesh.numVertices(); ++i)
      v.push_back({d.target.mesh.V(i, 0), d.target.mesh.V(i, 1), d.target.mesh.V(i, 2)});
    for (int i = 0; i < d.target.mesh.numTriangles(); ++i)
      f.push_back({d.target.mesh.F(i, 0), d.target.mesh.F(i, 1), d.target.mesh.F(i, 2)});
    target["vertices"] = v, target["triangles"] = f;
  } else {
    const char* key = d.target.kind == DesignTarget::Example ? "example"
                      : d.target.kind == DesignTarget::Obj   ? "obj"
                                                             : "file";
    target[key] = d.target.name;
  }
  if (d.target.up != UpAxis{}) target["up"] = toString(d.target.up);
  if (d.target.cutThinHandles) target["cutThinHandles"] = true;
  if (d.target.closeHoles) target["closeHoles"] = true;
  doc["target"] = target;
  json size = base("size");
  size.erase("height"), size.erase("scale");
  if (d.scale > 0)
    size["scale"] = d.scale;
  else
    size["height"] = d.height;
  doc["size"] = size;
  json seams = json::array();
  const json* oldSeams = doc.contains("seams") && doc["seams"].is_array() ? &doc["seams"] : nullptr;
  for (size_t i = 0; i < d.seams.size(); ++i) {
    const DesignSeam& s = d.seams[i];
    seams.push_back(
        designSeamJson(s, oldSeams && i < oldSeams->size() && (*oldSeams)[i].is_object() ? (*oldSeams)[i] : json()));
  }
  doc["seams"] = seams;
  json conns = json::array();
  for (const DesignConnection& c : d.connections) conns.push_back({{"seams", c.seams}});
  doc["connections"] = conns;
  json m = base("material");
  m["name"] = d.material.name, m["thickness"] = d.material.thickness, m["youngs_modulus"] = d.material.youngsModulus;
  if (d.material.density >= 0) m["density"] = d.material.density;
  doc["material"] = m;
  doc["pressure"] = d.pressure;
  return doc.dump(indent) + "\n";
}

std::vector<std::string> exampleSearchPath(const std::string& exeDir) {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("BILLOW_EXAMPLES")) {
    std::string s = env;
    for (size_t a = 0; a <= s.size();) {
      const size_t b = std::min(s.find(':', a), s.size());
      if (b > a) dirs.push_back(s.substr(a, b - a));
      a = b + 1;
    }
  }
  if (!exeDir.empty()) dirs.push_back(exeDir + "/../../web/public/examples");
  return dirs;
}

TriMesh loadDesignTarget(const Design& d, const std::string& designPath, const std::vector<std::string>& exampleDirs) {
  if (d.target.kind == DesignTarget::Inline) return d.target.mesh;
  std::string path;
  if (d.target.kind == DesignTarget::Example) {
    for (const std::string& dir : exampleDirs)
      if (std::ifstream(dir + "/" + d.target.name + ".obj").good()) {
        path = dir + "/" + d.target.name + ".obj";
        break;
      }
    if (path.empty())
      throw Error("design.example-not-found", "The example target \"" + d.target.name +
                                                  "\" was not found (looked in the examples folder; set "
                                                  "BILLOW_EXAMPLES to the folder with the example meshes).");
  } else {
    path = d.target.name;
    const size_t slash = designPath.find_last_of('/');
    if (!path.empty() && path[0] != '/' && slash != std::string::npos) path = designPath.substr(0, slash + 1) + path;
  }
  return readMeshBytes(readFileBytes(path), path);
}

double designScale(const Design& d, const TriMesh& target) {
  if (d.scale > 0) return d.scale;
  const int k = d.target.up.axis;
  const double extent = target.numVertices() ? target.V.col(k).maxCoeff() - target.V.col(k).minCoeff() : 0.0;
  if (!(extent > 0))
    throw Error("design.bad-target", std::string("The target is flat along its up axis (") + char('x' + k) +
                                         "), so its height cannot set its size.");
  return d.height / extent;
}

std::string seamLabel(int index, const std::string& name) {
  const std::string quoted = name.empty() ? "" : " \"" + name + "\"";
  return index >= 0 ? "seam " + std::to_string(index + 1) + quoted : "the seam" + quoted;
}

namespace {

SeamSpec placeSeam(const DesignSeam& s, int index, const TriMesh& target, const SurfaceProjector& projector,
                   double scale, double size) {
  SeamSpec spec;
  spec.closed = s.closed, spec.weight = s.weight, spec.smooth = s.smooth;
  const std::string label = capitalized(seamLabel(index, s.name));
  for (size_t k = 0; k < s.points.size(); ++k) {
    const DesignPoint& p = s.points[k];
    const std::string point = "point " + std::to_string(k + 1);
    if (!p.onSurface) {
      double distance = 0;
      spec.controls.push_back(projector.project(scale * p.position, &distance));
      if (!(distance <= kMaxPointDistance * size)) {
        char where[96];
        std::snprintf(where, sizeof where, "[%g, %g, %g]", p.position.x(), p.position.y(), p.position.z());
        throw Error("design.bad-value", label + ": " + point + " " + where + " lies " +
                                            FieldReader::fmt(std::round(10 * distance / size) / 10) +
                                            " times the target's size away from its surface; it was written for "
                                            "another target or in other units.");
      }
      continue;
    }
    if (p.surface.face >= target.numTriangles())
      throw Error("design.bad-value", label + ": " + point + " lies on triangle " + std::to_string(p.surface.face) +
                                          ", but the target has only " + std::to_string(target.numTriangles()) +
                                          " triangles: the design was made for another target.");
    spec.controls.push_back(p.surface);
  }
  return spec;
}

}  // namespace

SeamSpec designSeamSpec(const DesignSeam& seam, int index, const TriMesh& target, const SurfaceProjector& projector,
                        double scale) {
  return placeSeam(seam, index, target, projector, scale, boundingDiagonal(target));
}

std::vector<SeamSpec> designSeamSpecs(const std::vector<DesignSeam>& seams, const TriMesh& target,
                                      const SurfaceProjector& projector, double scale) {
  const double size = boundingDiagonal(target);
  std::vector<SeamSpec> specs;
  for (size_t i = 0; i < seams.size(); ++i)
    specs.push_back(placeSeam(seams[i], static_cast<int>(i), target, projector, scale, size));
  return specs;
}

}  // namespace billow
