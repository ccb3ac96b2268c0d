// billow inflate PATTERN.json [--out RESULT.json] [--obj INFLATED.obj] [--pressure PA] [--tolerance T]
//                 [--max-iterations N] [--max-memory MB] [--quiet]
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "io/mesh_file.hpp"
#include "io/obj_writer.hpp"
#include "io/pattern_json.hpp"
#include "simulate/coarse_start.hpp"
#include "simulate/inflate.hpp"
#include "util/error.hpp"
#include "util/memory_budget.hpp"

namespace billow::cli {
namespace {

double number(const Args& args, const std::string& name, double fallback) {
  const std::string v = args.get(name);
  if (v.empty()) return fallback;
  try {
    return std::stod(v);
  } catch (const std::exception&) {
    throw Error("cli.usage", "the option " + name + " needs a number, not '" + v + "'");
  }
}

// Stitched vertices merged (one OBJ vertex per simulation vertex), outer triangles only, facing outwards.
std::string toObj(const SewnMesh& mesh, const Vertices& x) {
  return writeObj(x, outerTriangles(mesh), "billow inflated shape (outer surface)");
}

nlohmann::json resultJson(const Pattern& p, const SewnMesh& mesh, const InflateResult& r) {
  using nlohmann::json;
  json panels = json::array();
  for (size_t i = 0; i < p.panels.size(); ++i) {
    json inflated = json::array();
    for (int v = 0; v < p.panels[i].vertices.rows(); ++v) {
      const int s = mesh.simVertex(int(i), v);
      inflated.push_back({r.positions(s, 0), r.positions(s, 1), r.positions(s, 2)});
    }
    panels.push_back({{"name", p.panels[i].name}, {"internal", p.panels[i].internal}, {"inflated", inflated}});
  }
  json compression = json::array(), regime = json::array(), stress = json::array();
  for (int f = 0; f < mesh.numTriangles(); ++f) {
    compression.push_back(r.fields.compression[f]);
    regime.push_back(r.fields.regime[f]);
    stress.push_back(r.fields.stress[f]);
  }
  return {{"format", "billow-inflated"},
          {"version", 1},
          {"state", toString(r.state)},
          {"converged", r.converged},
          {"message", r.message},
          {"iterations", r.iterations},
          {"residual", r.residual},
          {"volume", r.volume},
          {"pressure", p.pressure},
          {"max_compression", r.fields.compression.size() ? r.fields.compression.maxCoeff() : 0.0},
          {"max_stress", r.fields.stress.size() ? r.fields.stress.maxCoeff() : 0.0},
          {"timings_ms",
           {{"setup", r.timings.setupMs},
            {"assemble", r.timings.assembleMs},
            {"factor", r.timings.factorMs},
            {"line_search", r.timings.lineSearchMs},
            {"total", r.timings.totalMs + r.timings.setupMs},
            {"factorizations", r.timings.factorizations}}},
          {"panels", panels},
          // Per triangle of the pattern, panel by panel in file order.
          {"triangles", {{"regime", regime}, {"compression", compression}, {"stress", stress}}}};
}

}  // namespace

int inflateCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(
      argv, {"--out", "--obj", "--pressure", "--material", "--tolerance", "--max-iterations", "--max-memory"});
  if (args.has("--help") || args.positional.size() != 1) {
    std::fprintf(args.has("--help") ? stdout : stderr,
                 "usage: billow inflate PATTERN.json [--out RESULT.json] [--obj INFLATED.obj] [--pressure PA]\n"
                 "                      [--material foil|pvc|ripstop|tpu] [--tolerance T] [--max-iterations N]\n"
                 "                      [--max-memory MB] [--quiet]\n\n"
                 "Inflates a sewn pattern (tension-field membrane, Skouras et al. 2014) and writes the\n"
                 "inflated shape. Exit code 0 when it settles, 1 when the pattern is rejected or the\n"
                 "simulation does not settle (the last shape is still written). A pattern whose predicted\n"
                 "memory need exceeds --max-memory (default: this computer's memory) is refused before work.\n");
    return args.has("--help") ? 0 : 2;
  }
  const std::string path = args.positional[0];
  std::vector<PatternWarning> warnings;
  Pattern p = readPatternJson(readFileBytes(path), &warnings);
  for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.message.c_str());
  p.pressure = number(args, "--pressure", p.pressure);
  p.material = materialOption(args, p.material);
  if (!(p.pressure > 0)) throw Error("cli.usage", "the pressure must be positive");
  InflateOptions o;
  o.tolerance = number(args, "--tolerance", o.tolerance);
  o.maxIterations = static_cast<int>(number(args, "--max-iterations", o.maxIterations));
  const long long patternTriangles = numTriangles(p);
  const double neededBytes = inflationBytes(patternTriangles);
  requireMemory(neededBytes, memoryBudgetOption(args),
                "Inflating this pattern (" + std::to_string(patternTriangles) + " triangles)",
                "Use a pattern with fewer triangles.");
  SewnMesh mesh = sewPattern(p);
  const bool quiet = args.has("--quiet");
  if (!quiet)
    std::fprintf(stderr, "%s: %d triangles, %d simulation vertices\n", path.c_str(), mesh.numTriangles(),
                 mesh.numVertices);
  StartReport startReport;
  const Vertices start = startPositions(p, mesh, o, &startReport);
  if (!quiet && startReport.levels > 0)
    std::fprintf(
        stderr, "  coarse start: %d coarser pattern%s inflated first (coarsest %d triangles), %d iterations, %.0f ms\n",
        startReport.levels, startReport.levels > 1 ? "s" : "", startReport.coarseTriangles,
        startReport.coarseIterations, startReport.coarseMs);
  InflationSolver solver(mesh, p.material, p.pressure, o, start);
  while (solver.step(5, 500) == InflateState::Running)
    if (!quiet)
      std::fprintf(stderr, "  iteration %3d  residual %.3e  volume %.6g m^3\n", solver.iterations(), solver.residual(),
                   solver.volume());
  const InflateResult r = solver.result();
  if (args.has("--out")) {
    nlohmann::json out = resultJson(p, mesh, r);
    out["memory"] = {{"predicted_bytes", neededBytes}, {"peak_resident_bytes", peakResidentBytes()}};
    writeFile(args.get("--out"), out.dump() + "\n");
  }
  if (args.has("--obj")) writeFile(args.get("--obj"), toObj(mesh, r.positions));
  std::fprintf(stderr, "%s after %d iterations (residual %.2e), volume %.6g m^3, %.0f ms\n",
               r.converged ? "settled" : "did not settle", r.iterations, r.residual, r.volume,
               r.timings.totalMs + r.timings.setupMs);
  if (!r.converged) {
    std::fprintf(stderr, "billow inflate: %s\n", r.message.c_str());
    return 1;
  }
  return 0;
}

}  // namespace billow::cli
