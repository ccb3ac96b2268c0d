// Embind for inflation (simulate/) and the example patterns.
#include <emscripten/bind.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "guarded.hpp"

namespace {
using billow::bindings::guarded;
using nlohmann::json;
}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Inflation (simulate/): a stepped session so the worker can post progress and cancel between steps.
//
//   const s = new Module.InflationSession();          // never throws
//   s.load(patternJson, optionsJson)                  // -> {"status":"ok","result":{vertices, triangles, panels,
//                                                     //     panelVertices, warnings:[{code,message,mismatch}]}}
//     optionsJson (all optional): {"tolerance":1e-5, "maxIterations":400, "pressure":PA, "band":1e-4,
//                                  "memoryBudget":BYTES (default: the heap's room; a pattern needing more
//                                  is refused with "memory.budget" before any work)}
//   s.setStart(ptr, numVertices)                       // #V x 3 doubles: restart from these positions (target)
//   s.step(maxIterations, maxMillis)                   // -> result {state:"running"|"converged"|"failed",
//                                                     //     iteration, residual, volume, energy, message}
//   s.updateFields()                                   // recomputes the per-triangle fields below
//   pointers into the wasm heap (copy at once: views detach when memory grows):
//     positionsPtr()   #V x 3 float64 (simulation vertices)       numVertices()
//     trianglesPtr()   #F x 3 int32 (sewn mesh, outward)          numTriangles()
//     outerPtr()       #F int32 (1: outer surface, 0: internal panel)
//     compressionPtr() #F x 4 float64 (magnitude, direction x, y, z)   after updateFields()
//     stressPtr()      #F x 2 float64 (max principal stress [Pa], tension [N/m])   after updateFields()
//     regimePtr()      #F int32 (0 slack, 1 wrinkled, 2 taut)      after updateFields()
//     panelVertexMapPtr() #panel vertices int32: simulation vertex of each panel vertex, panels in file order
//     panelVertexStartPtr() #panels+1 int32 offsets into that map
//   s.result()                                         // -> scalars: state, converged, iterations, residual,
//                                                     //    volume, energy, message, pressure, timings
//   s.timeFactorization() -> {ms};  s.measureMylar() -> {rimRadius, thickness, poleThickness}   (benchmarks)
//   Module.examplePattern(name, '{"triangles":3000,"size":0.3,"pressure":1000,"aspect":1}') -> pattern JSON as result
//   s.delete()
// ---------------------------------------------------------------------------------------------------------
#include <memory>

#include "io/pattern_json.hpp"
#include "simulate/coarse_start.hpp"
#include "simulate/example_patterns.hpp"
#include "simulate/inflate.hpp"
#include "util/memory_budget.hpp"

namespace {

class InflationSession {
 public:
  InflationSession() = default;  // must not throw (embind constructors cannot report errors)

  std::string load(const std::string& patternJson, const std::string& optionsJson) {
    return guarded([&] {
      solver_.reset();
      std::vector<billow::PatternWarning> warnings;
      pattern_ = billow::readPatternJson(patternJson, &warnings);
      billow::InflateOptions o;
      double budget = billow::availableBytes();  // "memoryBudget" (bytes) replaces it, for tests
      if (!optionsJson.empty()) {
        json j = json::parse(optionsJson, nullptr, false);
        if (j.is_discarded() || !j.is_object())
          throw billow::Error("inflate.options", "The simulation options are not valid JSON.");
        o.tolerance = j.value("tolerance", o.tolerance);
        o.maxIterations = j.value("maxIterations", o.maxIterations);
        o.band = j.value("band", o.band);
        pattern_.pressure = j.value("pressure", pattern_.pressure);
        if (!(pattern_.pressure > 0) || !(o.tolerance > 0) || o.maxIterations < 1 || !(o.band > 0))
          throw billow::Error("inflate.options", "Pressure, tolerance, band and iteration limit must be positive.");
        if (j.contains("memoryBudget") && j["memoryBudget"].is_number()) budget = j["memoryBudget"].get<double>();
      }
      const long long triangles = billow::numTriangles(pattern_);
      billow::requireMemory(billow::inflationBytes(triangles), budget,
                            "Inflating this pattern (" + std::to_string(triangles) + " triangles)",
                            "Use a pattern with fewer triangles, or inflate it with the billow command-line tool "
                            "on a computer with more memory.");
      billow::SewnMesh mesh = billow::sewPattern(pattern_);
      // A bare pattern starts from its coarser versions inflated first (coarse_start.hpp).
      billow::StartReport report;
      const billow::Vertices start = billow::startPositions(pattern_, mesh, o, &report);
      solver_ =
          std::make_unique<billow::InflationSolver>(std::move(mesh), pattern_.material, pattern_.pressure, o, start);
      const billow::SewnMesh& m = solver_->mesh();
      triangles_ = m.triangles;
      outer_.assign(m.outer.begin(), m.outer.end());
      json w = json::array();
      for (const auto& x : warnings) w.push_back({{"code", x.code}, {"message", x.message}, {"mismatch", x.mismatch}});
      return json({{"vertices", m.numVertices},
                   {"triangles", m.numTriangles()},
                   {"panels", pattern_.panels.size()},
                   {"panelVertices", m.simVertexOf.size()},
                   {"coarseStart",
                    {{"levels", report.levels},
                     {"triangles", report.coarseTriangles},
                     {"iterations", report.coarseIterations},
                     {"ms", report.coarseMs},
                     {"gaussSeidelMs", report.gaussSeidelMs}}},
                   {"warnings", w}})
          .dump();
    });
  }

  std::string setStart(uintptr_t positions, int numVertices) {
    return guarded([&] {
      requireLoaded();
      if (numVertices != solver_->mesh().numVertices)
        throw billow::Error("inflate.bad-start", "The start shape has " + std::to_string(numVertices) +
                                                     " vertices; the pattern has " +
                                                     std::to_string(solver_->mesh().numVertices) + ".");
      const billow::Vertices x0 =
          Eigen::Map<const billow::Vertices>(reinterpret_cast<const double*>(positions), numVertices, 3);
      if (!x0.allFinite()) throw billow::Error("inflate.bad-start", "The start shape has invalid coordinates.");
      solver_->restart(x0, pattern_.pressure);
      return std::string("{}");
    });
  }

  std::string step(int maxIterations, double maxMillis) {
    return guarded([&] {
      requireLoaded();
      solver_->step(maxIterations, maxMillis);
      return json({{"state", billow::toString(solver_->state())},
                   {"iteration", solver_->iterations()},
                   {"residual", solver_->residual()},
                   {"volume", solver_->volume()},
                   {"energy", solver_->energy()},
                   {"message", solver_->message()}})
          .dump();
    });
  }

  std::string updateFields() {
    return guarded([&] {
      requireLoaded();
      const billow::TriangleFields f = solver_->fields();
      const int F = static_cast<int>(f.regime.size());
      compression_.resize(size_t(F) * 4);
      stress_.resize(size_t(F) * 2);
      regime_ = f.regime;
      for (int t = 0; t < F; ++t) {
        compression_[4 * t] = f.compression[t];
        for (int k = 0; k < 3; ++k) compression_[4 * t + 1 + k] = f.direction(t, k);
        stress_[2 * t] = f.stress[t];
        stress_[2 * t + 1] = f.tension[t];
      }
      return json(
                 {{"maxCompression", F ? f.compression.maxCoeff() : 0.0}, {"maxStress", F ? f.stress.maxCoeff() : 0.0}})
          .dump();
    });
  }

  std::string result() const {
    return guarded([&] {
      requireLoaded();
      const billow::InflateTimings& t = solver_->timings();
      return json({{"state", billow::toString(solver_->state())},
                   {"converged", solver_->state() == billow::InflateState::Converged},
                   {"iterations", solver_->iterations()},
                   {"residual", solver_->residual()},
                   {"volume", solver_->volume()},
                   {"energy", solver_->energy()},
                   {"message", solver_->message()},
                   {"pressure", pattern_.pressure},
                   {"timings",
                    {{"setupMs", t.setupMs},
                     {"assembleMs", t.assembleMs},
                     {"factorMs", t.factorMs},
                     {"lineSearchMs", t.lineSearchMs},
                     {"totalMs", t.totalMs},
                     {"factorizations", t.factorizations}}}})
          .dump();
    });
  }

  // Benchmark helpers: one numeric factorization of the current Hessian ({ms}), and the Mylar balloon's
  // figures for a loaded `mylar` example ({rimRadius, thickness, poleThickness} in m).
  std::string timeFactorization() {
    return guarded([&] {
      requireLoaded();
      return json({{"ms", solver_->timeFactorization()}}).dump();
    });
  }
  std::string measureMylar() const {
    return guarded([&] {
      requireLoaded();
      const billow::MylarShape s = billow::measureMylar(solver_->mesh(), solver_->positions());
      return json({{"rimRadius", s.rimRadius}, {"thickness", s.thickness}, {"poleThickness", s.poleThickness}}).dump();
    });
  }

  int numVertices() const { return solver_ ? solver_->mesh().numVertices : 0; }
  int numTriangles() const { return solver_ ? solver_->mesh().numTriangles() : 0; }
  uintptr_t positionsPtr() const { return solver_ ? reinterpret_cast<uintptr_t>(solver_->positions().data()) : 0; }
  uintptr_t trianglesPtr() const { return reinterpret_cast<uintptr_t>(triangles_.data()); }
  uintptr_t outerPtr() const { return reinterpret_cast<uintptr_t>(outer_.data()); }
  uintptr_t compressionPtr() const { return reinterpret_cast<uintptr_t>(compression_.data()); }
  uintptr_t stressPtr() const { return reinterpret_cast<uintptr_t>(stress_.data()); }
  uintptr_t regimePtr() const { return reinterpret_cast<uintptr_t>(regime_.data()); }
  uintptr_t panelVertexMapPtr() const {
    return solver_ ? reinterpret_cast<uintptr_t>(solver_->mesh().simVertexOf.data()) : 0;
  }
  uintptr_t panelVertexStartPtr() const {
    return solver_ ? reinterpret_cast<uintptr_t>(solver_->mesh().panelVertexStart.data()) : 0;
  }

 private:
  void requireLoaded() const {
    if (!solver_) throw billow::Error("inflate.not-loaded", "No pattern is loaded yet.");
  }

  billow::Pattern pattern_;
  std::unique_ptr<billow::InflationSolver> solver_;
  billow::Triangles triangles_;
  std::vector<int> outer_, regime_;
  std::vector<double> compression_, stress_;
};

// An example pattern as pattern-file JSON. optionsJson: {"triangles":3000, "size":0.3, "pressure":1000, "aspect":1}.
std::string examplePattern(const std::string& name, const std::string& optionsJson) {
  return guarded([&] {
    billow::ExampleOptions o;
    if (!optionsJson.empty()) {
      json j = json::parse(optionsJson, nullptr, false);
      if (j.is_discarded() || !j.is_object())
        throw billow::Error("example.bad-value", "The options are not valid JSON.");
      o.triangles = j.value("triangles", o.triangles);
      o.size = j.value("size", o.size);
      o.pressure = j.value("pressure", o.pressure);
      o.aspect = j.value("aspect", o.aspect);
    }
    return billow::writePatternJson(billow::examplePattern(name, o));
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(billow_inflate) {
  emscripten::function("examplePattern", &examplePattern);
  emscripten::class_<InflationSession>("InflationSession")
      .constructor<>()
      .function("load", &InflationSession::load)
      .function("setStart", &InflationSession::setStart)
      .function("step", &InflationSession::step)
      .function("updateFields", &InflationSession::updateFields)
      .function("result", &InflationSession::result)
      .function("timeFactorization", &InflationSession::timeFactorization)
      .function("measureMylar", &InflationSession::measureMylar)
      .function("numVertices", &InflationSession::numVertices)
      .function("numTriangles", &InflationSession::numTriangles)
      .function("positionsPtr", &InflationSession::positionsPtr)
      .function("trianglesPtr", &InflationSession::trianglesPtr)
      .function("outerPtr", &InflationSession::outerPtr)
      .function("compressionPtr", &InflationSession::compressionPtr)
      .function("stressPtr", &InflationSession::stressPtr)
      .function("regimePtr", &InflationSession::regimePtr)
      .function("panelVertexMapPtr", &InflationSession::panelVertexMapPtr)
      .function("panelVertexStartPtr", &InflationSession::panelVertexStartPtr);
}
