// Embind for the core entry points (validation, version, memory in use, crash test). The bindings/ folder is the only
// place that knows embind. Bulk data crosses as pointers into the wasm heap that the JS layer
// (web/src/worker/solver-api.js) fills from typed arrays; results return as JSON text plus heap arrays.
// Every entry point catches errors and returns {"status":"error","code","message"}: no exception
// ever escapes to JS as a bare number.
#include <emscripten/bind.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "guarded.hpp"
#include "heap_mesh.hpp"
#include "io/mesh_file.hpp"
#include "mesh/close_holes.hpp"
#include "mesh/validate.hpp"
#include "simulate/materials.hpp"
#include "suggest/seam_layouts.hpp"
#include "suggest/thin_handles.hpp"
#include "util/memory_budget.hpp"

namespace {

using billow::bindings::guarded;
using billow::bindings::meshFromHeap;

// positions: #V*3 doubles, indices: #F*3 int32 (rewritten in place when the orientation is fixed). The report, and
// where a point the surface touched itself at got vertices of its own, "positions": all of them, the new ones last.
std::string validateTarget(uintptr_t positions, int numVertices, uintptr_t indices, int numTriangles) {
  return guarded([&] {
    billow::TriMesh mesh = meshFromHeap(positions, numVertices, indices, numTriangles);
    const billow::ValidationReport report = billow::validateTarget(mesh);
    // Repaired, its triangles go back in place: as many or fewer (a triangle's copy left out: report.stats.triangles).
    if (report.modified)
      Eigen::Map<billow::Triangles>(reinterpret_cast<int*>(indices), mesh.numTriangles(), 3) = mesh.F;
    if (mesh.numVertices() == numVertices) return billow::toJson(report);
    nlohmann::json out = nlohmann::json::parse(billow::toJson(report));
    out["positions"] = std::vector<double>(mesh.V.data(), mesh.V.data() + mesh.V.size());
    return out.dump();
  });
}

// A repaired mesh back to JS, appended to `out` as flat "positions" and "indices" (row-major, as they came).
// A coordinate that is not a number goes as the string JavaScript's Number() reads back ("NaN", "Infinity"): JSON
// has no such number, and a file's damaged vertex must reach validation as it is (SolverApi's Float64Array.from).
void putMesh(const billow::TriMesh& mesh, nlohmann::json& out) {
  nlohmann::json positions = nlohmann::json::array();
  for (Eigen::Index k = 0; k < mesh.V.size(); ++k) {
    const double x = mesh.V.data()[k];
    if (std::isfinite(x))
      positions.push_back(x);
    else
      positions.push_back(std::isnan(x) ? "NaN" : x > 0 ? "Infinity" : "-Infinity");
  }
  out["positions"] = std::move(positions);
  out["indices"] = std::vector<int>(mesh.F.data(), mesh.F.data() + mesh.F.size());
}

// positions: #V*3 doubles, indices: #F*3 int32 of a checked target (validateTarget). { handles: [loop length, ...]
// (its thin handles, thinnest first: suggest/thin_handles.hpp), and with cut { positions, indices } of the target
// cut through them (every face keeping its index) }.
std::string thinHandles(uintptr_t positions, int numVertices, uintptr_t indices, int numTriangles, bool cut) {
  return guarded([&] {
    billow::TriMesh mesh = meshFromHeap(positions, numVertices, indices, numTriangles);
    const std::vector<billow::ThinHandle> handles = billow::thinHandles(mesh);
    nlohmann::json out = {{"handles", nlohmann::json::array()}};
    for (const billow::ThinHandle& h : handles) out["handles"].push_back(h.length);
    if (cut) {
      billow::cutThinHandles(mesh, handles);
      putMesh(mesh, out);
    }
    return out.dump();
  });
}

// positions: #V*3 doubles, indices: #F*3 int32 of an open target turned one way (validateTarget). { closed (how many
// holes), positions, indices } of the target with its holes capped (mesh/close_holes.hpp, every face keeping its
// index).
std::string closeHoles(uintptr_t positions, int numVertices, uintptr_t indices, int numTriangles) {
  return guarded([&] {
    billow::TriMesh mesh = meshFromHeap(positions, numVertices, indices, numTriangles);
    nlohmann::json out = {{"closed", billow::closeHoles(mesh)}};
    putMesh(mesh, out);
    return out.dump();
  });
}

// A mesh file's bytes (length bytes at `bytes`) read by the command line's reader for its extension (io/mesh_file.hpp),
// refused beyond maxTriangles: { positions, indices }, its corners welded, or the reader's error. The app reads every
// mesh file so.
std::string readMeshFile(uintptr_t bytes, int length, const std::string& fileName, int maxTriangles) {
  return guarded([&] {
    billow::MeshReadOptions options;
    options.maxTriangles = maxTriangles;
    const std::string_view file(reinterpret_cast<const char*>(bytes), static_cast<size_t>(length));
    const billow::TriMesh mesh = billow::readMeshBytes(file, fileName, options);
    nlohmann::json out = nlohmann::json::object();
    putMesh(mesh, out);
    return out.dump();
  });
}

// Deliberately traps the module: the worker's crash recovery is tested with it.
void crashForTesting() { std::abort(); }

std::string version() { return "0.1.0"; }

// [{ name, label, thickness [m], youngs_modulus [Pa], density [kg/m^3], strength [Pa] }]
std::string materialPresets() {
  return guarded([&] {
    nlohmann::json out = nlohmann::json::array();
    for (const billow::MaterialPreset& p : billow::materialPresets())
      out.push_back({{"name", p.material.name},
                     {"label", p.label},
                     {"thickness", p.material.thickness},
                     {"youngs_modulus", p.material.youngsModulus},
                     {"density", p.material.density},
                     {"strength", p.strength}});
    return out.dump();
  });
}

// { looks: [{ lookRank, family }], optimize, ofOneFamily } -> [index into looks, ...]: the looks to optimize, as the
// command line chooses them (chooseLooks), for the app's workers, each of which has looked at a share of them.
std::string chooseLooks(const std::string& requestJson) {
  return guarded([&] {
    const nlohmann::json r = nlohmann::json::parse(requestJson, nullptr, false);
    if (r.is_discarded() || !r.contains("looks") || !r["looks"].is_array())
      throw billow::Error("suggest.bad-looks", "The looks to choose from are not valid JSON.");
    std::vector<billow::LookChoice> looks;
    for (const nlohmann::json& look : r["looks"])
      looks.push_back({look.at("lookRank").get<billow::LayoutRank>(), look.at("family").get<std::string>()});
    return nlohmann::json(billow::chooseLooks(looks, r.value("optimize", billow::kOptimizedLayouts),
                                              r.value("ofOneFamily", billow::kOptimizedOfOneFamily)))
        .dump();
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(billow) {
  emscripten::function("validateTarget", &validateTarget);
  emscripten::function("thinHandles", &thinHandles);
  emscripten::function("closeHoles", &closeHoles);
  emscripten::function("readMeshFile", &readMeshFile);
  emscripten::function("crashForTesting", &crashForTesting);
  emscripten::function("version", &version);
  emscripten::function("materialPresets", &materialPresets);
  emscripten::function("chooseLooks", &chooseLooks);
  emscripten::function("bytesInUse", &billow::bytesInUse);
}
