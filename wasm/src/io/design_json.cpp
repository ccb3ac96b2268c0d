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

  double number(const json& obj, const char* key, double fallback, double lo, double hi, const std::string& field,
                const std::string& what) {
    if (!obj.contains(key)) return fallback;
    const json& v = obj[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo || v.get<double>() > hi) {
      bad(field,
          what + " (" + field + ") must be a number from " + fmt(lo) + " to " + fmt(hi) + ", not " + v.dump() + ".");
      return fallback;
    }
    return v.get<double>();
  }

  bool boolean(const json& obj, const char* key, bool fallback, const std::string& field) {
    if (!obj.contains(key)) return fallback;
    if (!obj[key].is_boolean()) {
      bad(field, field + " must be true or false, not " + obj[key].dump() + ".");
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

bool finiteTriple(const json& p) {
  if (!p.is_array() || p.size() != 3) return false;
  for (const auto& x : p)
    if (!x.is_number() || !std::isfinite(x.get<double>())) return false;
  return true;
}

bool readPoint(FieldReader& r, const json& p, const std::string& field, DesignPoint& out) {
  if (finiteTriple(p)) {
    out.onSurface = false;
    out.position = Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    return true;
  }
  if (!p.is_object() || !p.contains("face") || !p.contains("bary"))
    return r.bad(field, "A seam point (" + field + ") must be a surface point {face, bary} or a 3D point [x, y, z].");
  if (!p["face"].is_number_integer() || p["face"].get<long long>() < 0)
    return r.bad(field, "A seam point (" + field + ") names no triangle of the target: " + p["face"].dump() + ".");
  if (!finiteTriple(p["bary"]))
    return r.bad(field, "A seam point (" + field + ") needs three barycentric coordinates.");
  Eigen::Vector3d b(p["bary"][0].get<double>(), p["bary"][1].get<double>(), p["bary"][2].get<double>());
  if (b.minCoeff() < -1e-6 || std::abs(b.sum() - 1) > 1e-3)
    return r.bad(field, "A seam point (" + field +
                            ") lies outside its triangle: its coordinates must be at least 0 "
                            "and sum to 1.");
  b = b.cwiseMax(0.0);
  out.onSurface = true;
  out.surface.face = static_cast<int>(p["face"].get<long long>());
  out.surface.bary = b / b.sum();
  return true;
}

bool readSeam(FieldReader& r, const json& s, const std::string& field, DesignSeam& out) {
  if (!s.is_object()) return r.bad(field, "A seam (" + field + ") must be an object with a list of points.");
  if (s.contains("name")) {
    if (s["name"].is_string())
      out.name = s["name"].get<std::string>();
    else
      r.bad(field + ".name", "A seam's name (" + field + ".name) must be text.");
  }
  out.closed = r.boolean(s, "closed", false, field + ".closed");
  out.smooth = r.boolean(s, "smooth", false, field + ".smooth");
  out.weight = r.number(s, "weight", 1.0, 0.0, 1e6, field + ".weight", "A seam's weight");
  if (!s.contains("points") || !s["points"].is_array())
    return r.bad(field + ".points", "A seam (" + field + ") has no list of points.");
  if (static_cast<long long>(s["points"].size()) > kMaxPoints)
    throw Error("design.too-large", "A seam (" + field + ") has more than 100,000 points.");
  for (size_t i = 0; i < s["points"].size(); ++i) {
    DesignPoint p;
    if (!readPoint(r, s["points"][i], field + ".points[" + std::to_string(i) + "]", p)) return false;
    out.points.push_back(p);
  }
  const size_t least = out.closed ? 3 : 2;
  if (out.points.size() < least)
    return r.bad(field + ".points", "A" + std::string(out.closed ? " closed" : "n open") + " seam (" + field +
                                        ") needs at least " + std::to_string(least) + " points.");
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

bool readTarget(FieldReader& r, const json& t, DesignTarget& out) {
  if (!t.is_object()) return r.bad("target", "The target must be an object such as {\"example\": \"spot\"}.");
  if (t.contains("up") && !(t["up"].is_string() && parseUpAxis(t["up"].get<std::string>(), out.up)))
    r.bad("target.up",
          "The target's up axis (target.up) must be one of \"+y\", \"-y\", \"+z\", \"-z\", \"+x\", \"-x\", not " +
              t["up"].dump() + ".");
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
    r.bad("material", "The material must be an object with a thickness and a Young's modulus.");
    return;
  }
  if (m.contains("name")) {
    if (m["name"].is_string())
      out = namedMaterial(m["name"].get<std::string>(), out);
    else
      r.bad("material.name", "The material's name must be text.");
  }
  out.thickness = r.number(m, "thickness", out.thickness, kMinThickness, kMaxThickness, "material.thickness",
                           "The sheet thickness [m]");
  out.youngsModulus = r.number(m, "youngs_modulus", out.youngsModulus, kMinYoungsModulus, kMaxYoungsModulus,
                               "material.youngs_modulus", "Young's modulus [Pa]");
  out.density = r.number(m, "density", out.density, 0, 1e5, "material.density", "The density [kg/m^3]");
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
  if (doc.contains("seams")) {
    if (!doc["seams"].is_array()) {
      r.bad("seams", "The seams must be a list.");
    } else {
      if (static_cast<long long>(doc["seams"].size()) > kMaxSeams)
        throw Error("design.too-large", "The design has more than 10,000 seams.");
      for (size_t i = 0; i < doc["seams"].size(); ++i) {
        DesignSeam s;
        if (readSeam(r, doc["seams"][i], "seams[" + std::to_string(i) + "]", s)) d.seams.push_back(std::move(s));
      }
    }
  }
  if (doc.contains("connections")) {
    const json& c = doc["connections"];
    for (size_t i = 0; c.is_array() && i < c.size(); ++i) {
      const std::string field = "connections[" + std::to_string(i) + "]";
      DesignConnection conn;
      bool good = c[i].is_object() && c[i].contains("seams") && c[i]["seams"].is_array() && c[i]["seams"].size() == 2;
      for (size_t k = 0; good && k < 2; ++k) {
        const json& s = c[i]["seams"][k];
        good = s.is_number_integer() && s.get<long long>() >= 0 && s.get<long long>() < (long long)d.seams.size();
        if (good) conn.seams.push_back(s.get<int>());
      }
      if (good)
        d.connections.push_back(conn);
      else
        r.bad(field,
              "An internal connection (" + field + ") must join two of the design's seams: {\"seams\": [i, j]}.");
    }
    if (!c.is_array()) r.bad("connections", "The internal connections must be a list.");
  }
  if (doc.contains("material")) readMaterial(r, doc["material"], d.material);
  d.pressure = r.number(doc, "pressure", d.pressure, 1.0, 1e7, "pressure", "The pressure [Pa]");
  d.extra = std::move(doc);
  return d;
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
    json js = oldSeams && i < oldSeams->size() && (*oldSeams)[i].is_object() ? (*oldSeams)[i] : json::object();
    if (!s.name.empty()) js["name"] = s.name;
    js["closed"] = s.closed, js["weight"] = s.weight, js["smooth"] = s.smooth;
    json pts = json::array();
    for (const DesignPoint& p : s.points)
      pts.push_back(p.onSurface ? json{{"face", p.surface.face},
                                       {"bary", {p.surface.bary[0], p.surface.bary[1], p.surface.bary[2]}}}
                                : json{p.position[0], p.position[1], p.position[2]});
    js["points"] = pts;
    seams.push_back(js);
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

std::vector<SeamSpec> designSeamSpecs(const Design& d, const TriMesh& target, const SurfaceProjector& projector,
                                      double scale) {
  std::vector<SeamSpec> specs;
  for (size_t i = 0; i < d.seams.size(); ++i) {
    const DesignSeam& s = d.seams[i];
    SeamSpec spec;
    spec.closed = s.closed, spec.weight = s.weight, spec.smooth = s.smooth;
    for (const DesignPoint& p : s.points) {
      if (!p.onSurface) {
        spec.controls.push_back(projector.project(scale * p.position));
        continue;
      }
      if (p.surface.face >= target.numTriangles())
        throw Error("design.bad-value", "Seam " + std::to_string(i + 1) + (s.name.empty() ? "" : " (" + s.name + ")") +
                                            " has a point on triangle " + std::to_string(p.surface.face) +
                                            ", but the target has only " + std::to_string(target.numTriangles()) +
                                            " triangles: the design was made for another target.");
      spec.controls.push_back(p.surface);
    }
    specs.push_back(std::move(spec));
  }
  return specs;
}

}  // namespace billow
