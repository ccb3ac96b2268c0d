// billow design DESIGN.json --out-dir DIR [--resolution N] [--no-optimize] [--max-memory MB] [--quiet]: the design's
// sewn pattern (DIR/pattern.json, with the target shape as "inflated" start; an internal panel per internal
// connection), its inflated shape from the target
// (DIR/inflated.obj) and a report (DIR/report.json: distance to the target, seam length mismatch, solver
// figures, timings). Unless --no-optimize, the panels are optimized first (optimize/pattern_optimizer.hpp)
// and report.json gets the per-iteration error and time.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "export/export.hpp"
#include "io/distance_json.hpp"
#include "io/export_options_json.hpp"
#include "io/obj_writer.hpp"
#include "io/pattern_json.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/design_scene.hpp"
#include "seams/surface_distance.hpp"
#include "simulate/inflate.hpp"
#include "simulate/initial_shape.hpp"
#include "util/error.hpp"
#include "util/memory_budget.hpp"

namespace billow::cli {

std::unique_ptr<DesignScene> loadDesignScene(const std::string& path, bool quiet);
void writeTextFile(const std::string& path, const std::string& text);
void printProblems(const std::vector<SegmentationProblem>& problems);

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// Outer surface, one OBJ vertex per simulation vertex.
std::string objText(const SewnMesh& mesh, const Vertices& x) {
  return writeObj(x, outerTriangles(mesh), "billow inflated shape (outer surface, meters)");
}

// The outer surface against the target both ways (the inside of internal panels is not meant to lie on it),
// relative to the target's bounding-box diagonal.
TwoWayDistance distanceToTarget(const DesignScene& scene, const SewnMesh& mesh, const Vertices& x) {
  return measureDistance(scene.target, *scene.projector, x, outerTriangles(mesh), scene.design.target.up);
}

int positiveInt(const Args& args, const std::string& name, int fallback) {
  const std::string v = args.get(name);
  if (v.empty()) return fallback;
  try {
    const long n = std::stol(v);
    if (n >= 8 && n <= 2'000'000) return static_cast<int>(n);
  } catch (const std::exception&) {
  }
  throw Error("cli.usage", "the option " + name + " needs a triangle count from 8 to 2000000, not '" + v + "'");
}

}  // namespace

int designCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(argv, {"--out-dir", "--resolution", "--max-memory", "--max-iterations"});
  if (args.has("--help") || args.positional.size() != 1 || !args.has("--out-dir")) {
    std::fprintf(args.has("--help") ? stdout : stderr,
                 "usage: billow design DESIGN.json --out-dir DIR [--resolution TRIANGLES] [--no-optimize]\n"
                 "                     [--max-iterations N] [--max-memory MB] [--quiet]\n\n"
                 "Makes the sewn pattern of a design (its segments flattened into panels of about TRIANGLES\n"
                 "triangles in all, default 3000, and an internal panel for each internal connection), inflates it "
                 "from the target shape and writes\n"
                 "DIR/pattern.json, DIR/pattern.svg (the cut file, with the design's \"fabrication\" settings:\n"
                 "seam allowances, grain, sheet width), DIR/inflated.obj and DIR/report.json.\n"
                 "The panels are optimized so that the inflated shape comes close to the target, unless\n"
                 "--no-optimize, for at most N iterations (default 300, 600 when seams slide: seams of weight below\n"
                 "0.1 slide to where the shape fits best).\n"
                 "Exit code 0 when the inflated shape settles, 1 when the design cannot be patterned or\n"
                 "the simulation does not settle (the files written so far stay). A resolution whose predicted\n"
                 "memory need exceeds --max-memory (default: this computer's memory) is refused before work.\n");
    return args.has("--help") ? 0 : 2;
  }
  const bool quiet = args.has("--quiet");
  const auto t0 = Clock::now();
  const std::string dir = args.get("--out-dir");
  PatternBuildOptions options;
  options.triangles = positiveInt(args, "--resolution", options.triangles);
  const bool optimizePanels = !args.has("--no-optimize");

  const double budget = memoryBudgetOption(args);
  const auto scene = loadDesignScene(args.positional[0], quiet);
  const double neededBytes =
      optimizePanels ? optimizationBytes(options.triangles, scene->target.F.rows()) : inflationBytes(options.triangles);
  requireMemory(neededBytes, budget,
                std::string(optimizePanels ? "Optimizing" : "Inflating") + " panels of " +
                    std::to_string(options.triangles) + " triangles",
                "Choose a coarser --resolution.");
  const Design& design = scene->design;
  // The cut file uses the design's fabrication settings (seam allowances, grain, sheet width; the keys of
  // io/export_options_json.hpp); read now, so that a bad value stops the command before the long work.
  ExportOptions cutOptions;
  if (design.extra.contains("fabrication")) {
    try {
      cutOptions = readExportOptionsJson(design.extra["fabrication"]);
    } catch (const Error& e) {
      throw Error(e.code, std::string("the design's fabrication settings: ") + e.what());
    }
  }
  cutOptions.title = std::filesystem::path(args.positional[0]).stem().string();
  printProblems(scene->segmentation.problems);
  if (!scene->segmentation.ok()) {
    std::fprintf(stderr, "billow design: this design cannot be made into panels yet (see the errors above)\n");
    return 1;
  }
  options.material = design.material;
  options.pressure = design.pressure;
  useDesignConnections(design, options);
  BuiltPattern bp = buildPattern(scene->target, scene->segmentation, options);
  printProblems(bp.problems);
  if (!bp.ok()) {
    std::fprintf(stderr,
                 "billow design: some segments or internal connections could not be made into panels (see the errors "
                 "above)\n");
    return 1;
  }
  if (!quiet)
    std::fprintf(stderr,
                 "pattern: %d panels (%d internal), %d triangles, %d stitches, h %.4g m, seam length mismatch %.2f %% "
                 "(%.0f ms)\n",
                 bp.figures.panels, bp.figures.internalPanels, bp.figures.triangles, bp.figures.stitches,
                 bp.figures.edgeLength, 100 * bp.figures.maxSeamLengthMismatch, bp.figures.totalMs);
  using nlohmann::json;
  json history = json::array();
  std::string optimizeState = "skipped";
  double optimizeMs = 0, edgeMismatch = bp.figures.maxEdgeLengthMismatch;
  int remeshings = 0;
  bool slidingSeams = false;
  if (optimizePanels) {
    std::vector<double> seamWeights;
    for (const DesignSeam& s : design.seams) seamWeights.push_back(s.weight);
    const auto t1 = Clock::now();
    OptimizeOptions optimizeOptions;
    if (args.has("--max-iterations")) {  // as given, also when seams slide (OptimizeSliding::iterationFactor)
      optimizeOptions.stopping.maxIterations =
          positiveInt(args, "--max-iterations", optimizeOptions.stopping.maxIterations);
      optimizeOptions.sliding.iterationFactor = 1;
    }
    PatternOptimizer optimizer(scene->target, bp, seamWeights, optimizeOptions);
    slidingSeams = optimizer.slidingSeams();
    if (slidingSeams && !quiet)
      std::fprintf(stderr, "optimize: some seams have a weight below %g and slide to where the shape fits best\n",
                   optimizer.options().sliding.seamWeight);
    while (optimizer.step(5, 1000) == OptimizeState::Running)
      if (!quiet && !optimizer.history().empty()) {
        const OptimizeRecord& h = optimizer.history().back();
        std::fprintf(stderr,
                     "  optimize: iteration %3d  distance rms: target to inflated %.3f %%, inflated to target %.3f %%  "
                     "seam mismatch %.1e\n",
                     h.iteration, 100 * h.targetDistanceRms, 100 * h.distanceRms, h.seamMismatch);
      }
    optimizeMs = msSince(t1);
    optimizeState = toString(optimizer.state());
    if (!quiet)
      std::fprintf(stderr, "optimize: %s after %d iterations (%.0f ms)%s%s\n", optimizeState.c_str(),
                   optimizer.iterations(), optimizeMs, optimizer.message().empty() ? "" : ": ",
                   optimizer.message().c_str());
    for (const OptimizeRecord& h : optimizer.history())
      history.push_back({{"iteration", h.iteration},
                         {"objective", h.objective},
                         {"distance_rms", h.distanceRms},
                         {"distance_max", h.distanceMax},
                         {"target_distance_rms", h.targetDistanceRms},
                         {"target_distance_max", h.targetDistanceMax},
                         {"seam_mismatch", h.seamMismatch},
                         {"gradient", h.gradient},
                         {"projected", h.projected},
                         {"remeshed", h.remeshed},
                         {"ms", h.ms}});
    if (optimizer.state() != OptimizeState::Failed) {
      edgeMismatch = optimizer.history().back().seamMismatch;
      // The optimizer's panels and stitches (remeshing may have made new ones), and the final inflation
      // starts from its shape (one row per panel vertex).
      bp.pattern.panels = optimizer.pattern().panels;
      bp.pattern.stitches = optimizer.pattern().stitches;
      const SewnMesh& m = optimizer.mesh();
      bp.pattern.inflated.resize(bp.pattern.panels.size());
      for (size_t p = 0; p < bp.pattern.panels.size(); ++p) {
        bp.pattern.inflated[p].resize(bp.pattern.panels[p].vertices.rows(), 3);
        for (int v = 0; v < bp.pattern.panels[p].vertices.rows(); ++v)
          bp.pattern.inflated[p].row(v) = optimizer.inflated().row(m.simVertex(int(p), v));
      }
      remeshings = optimizer.timings().remeshings;
    }
  }
  std::filesystem::create_directories(dir);
  writeTextFile(dir + "/pattern.json", writePatternJson(bp.pattern) + "\n");
  // The cut file, with the design's fabrication settings when it has them. When the pieces cannot be laid out
  // (a sheet narrower than a piece) the other outputs are still written and the command ends with the reason.
  std::string cutFileProblem;
  std::filesystem::remove(dir + "/pattern.svg");  // never leave an older cut file beside the new pattern
  try {
    writeTextFile(dir + "/pattern.svg", exportPattern(bp.pattern, cutOptions).svg);
  } catch (const Error& e) {
    cutFileProblem = e.what();
  }

  // Inflate from the target shape (the pattern's "inflated" start).
  const SewnMesh mesh = sewPattern(bp.pattern);
  InflationSolver solver(mesh, bp.pattern.material, bp.pattern.pressure, {}, startFromInflated(bp.pattern, mesh));
  while (solver.step(5, 500) == InflateState::Running)
    if (!quiet)
      std::fprintf(stderr, "  inflate: iteration %3d  residual %.3e  volume %.6g m^3\n", solver.iterations(),
                   solver.residual(), solver.volume());
  const InflateResult r = solver.result();
  writeTextFile(dir + "/inflated.obj", objText(mesh, r.positions));
  const TwoWayDistance d = distanceToTarget(*scene, mesh, r.positions);

  const json report = {
      {"format", "billow-design-report"},
      {"version", 1},
      {"optimized", optimizePanels && optimizeState != "failed"},
      {"optimize",
       {{"state", optimizeState},
        {"ms", optimizeMs},
        {"remeshing_steps", remeshings},
        {"sliding_seams", slidingSeams},
        {"history", history}}},
      {"panels", bp.figures.panels},
      {"internal_panels", bp.figures.internalPanels},
      {"triangles", bp.figures.triangles},
      {"edge_length", bp.figures.edgeLength},
      {"distance_to_target", distanceReportJson(d)},
      {"seam_length_mismatch", {{"max_piece", bp.figures.maxSeamLengthMismatch}, {"max_edge", edgeMismatch}}},
      {"inflate",
       {{"state", toString(r.state)},
        {"converged", r.converged},
        {"message", r.message},
        {"iterations", r.iterations},
        {"residual", r.residual},
        {"volume", r.volume}}},
      {"timings_ms",
       {{"load", scene->loadMs},
        {"seams", scene->seamsMs},
        {"segment", scene->segmentMs},
        {"flatten", bp.figures.flattenMs},
        {"mesh", bp.figures.meshMs},
        {"pattern", bp.figures.totalMs},
        {"optimize", optimizeMs},
        {"inflate", r.timings.totalMs + r.timings.setupMs},
        {"total", msSince(t0)}}},
      {"memory", {{"predicted_bytes", neededBytes}, {"peak_resident_bytes", peakResidentBytes()}}},
      {"cut_file", {{"written", cutFileProblem.empty()}, {"message", cutFileProblem}}}};
  writeTextFile(dir + "/report.json", report.dump(2) + "\n");
  // The optimizer hands over its own equilibrium, which is usually settled already.
  const std::string settling = !r.converged ? "did not settle after " + std::to_string(r.iterations) + " iterations"
                               : r.iterations == 0 ? "settled where the optimizer left it"
                                                   : "settled after " + std::to_string(r.iterations) + " iterations";
  std::fprintf(stderr,
               "inflated shape %s; distance to target, rms (max) %% of the diagonal: target to inflated %.2f "
               "(%.2f), inflated to target %.2f (%.2f) (%.0f ms)\n",
               settling.c_str(), 100 * d.targetToInflated.summary.rms, 100 * d.targetToInflated.summary.max,
               100 * d.inflatedToTarget.rms, 100 * d.inflatedToTarget.max, msSince(t0));
  for (const UncoveredRegion& u : d.uncovered) std::fprintf(stderr, "billow design: %s\n", uncoveredMessage(u).c_str());
  if (!r.converged) {
    std::fprintf(stderr, "billow design: %s\n", r.message.c_str());
    return 1;
  }
  if (!cutFileProblem.empty()) {
    std::fprintf(stderr,
                 "billow design: the cut file (pattern.svg) was not written: %s The pattern, the inflated shape "
                 "and the report were.\n",
                 cutFileProblem.c_str());
    return 1;
  }
  return 0;
}

}  // namespace billow::cli
