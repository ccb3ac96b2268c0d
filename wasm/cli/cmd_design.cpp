// billow design DESIGN.json --out-dir DIR [--resolution N] [--no-optimize] [--max-memory MB] [--quiet]: the design's
// sewn pattern (DIR/pattern.json, with the target shape as "inflated" start; an internal panel per internal
// connection), its inflated shape from the target
// (DIR/inflated.obj) and a report (DIR/report.json: distance to the target, seam length mismatch, solver
// figures, timings). Unless --no-optimize, the panels are optimized first (optimize/pattern_optimizer.hpp)
// and report.json gets the per-iteration error and time.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "export/export.hpp"
#include "io/distance_json.hpp"
#include "io/obj_writer.hpp"
#include "io/pattern_json.hpp"
#include "optimize/optimized_pattern.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/design_scene.hpp"
#include "seams/surface_distance.hpp"
#include "simulate/inflate.hpp"
#include "simulate/initial_shape.hpp"
#include "util/error.hpp"
#include "util/memory_budget.hpp"

namespace billow::cli {

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// Outer surface, one OBJ vertex per simulation vertex.
std::string objText(const SewnMesh& mesh, const Vertices& x) {
  return writeObj(x, outerTriangles(mesh), "billow inflated shape (outer surface, meters)");
}

// The outer surface against the target both ways (the inside of internal panels is not meant to lie on it),
// relative to the target's bounding-box diagonal.
TwoWayDistance distanceToTarget(const DesignScene& scene, const SewnMesh& mesh, const Vertices& x) {
  const bool gusseted =
      std::any_of(scene.design.seams.begin(), scene.design.seams.end(), [](const DesignSeam& s) { return s.band; });
  return measureDistance(scene.target, *scene.projector, x, outerTriangles(mesh), scene.design.target.up, nullptr,
                         gusseted);
}

int designUsage(bool help) {
  std::fprintf(help ? stdout : stderr,
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
  return help ? 0 : 2;
}

// What the command was asked for.
struct DesignJob {
  std::string designPath, dir;
  int triangles = PatternBuildOptions{}.triangles;
  bool optimize = true, quiet = false;
  double memoryBudget = 0;
};

// Read: the design made into its scene, refused before the long work when it would not fit in memory or its
// fabrication settings are bad.
struct ReadDesign {
  std::unique_ptr<DesignScene> scene;
  double neededBytes = 0;
  ExportOptions cutOptions;  // the design's "fabrication" settings (io/export_options_json.hpp)
};

ReadDesign readPhase(const DesignJob& job) {
  ReadDesign read;
  read.scene = openDesignScene(job.designPath, job.quiet);
  read.neededBytes =
      job.optimize ? optimizationBytes(job.triangles, read.scene->target.F.rows()) : inflationBytes(job.triangles);
  requireMemory(read.neededBytes, job.memoryBudget,
                std::string(job.optimize ? "Optimizing" : "Inflating") + " panels of " + std::to_string(job.triangles) +
                    " triangles",
                "Choose a coarser --resolution.");
  read.cutOptions = designFabrication(read.scene->design);
  read.cutOptions.title = std::filesystem::path(job.designPath).stem().string();
  return read;
}

// Build: the segments flattened into panels. False (after saying why) when the design cannot be patterned.
bool buildPhase(const DesignJob& job, const DesignScene& scene, BuiltPattern& bp) {
  printProblems(scene.segmentation.problems);
  if (!scene.segmentation.ok()) {
    std::fprintf(stderr, "billow design: this design cannot be made into panels yet (see the errors above)\n");
    return false;
  }
  bp = buildDesignPattern(scene, job.triangles);
  printProblems(bp.problems);
  if (!bp.ok()) {
    std::fprintf(stderr,
                 "billow design: some segments or internal connections could not be made into panels (see the errors "
                 "above)\n");
    return false;
  }
  if (!job.quiet)
    std::fprintf(stderr,
                 "pattern: %d panels (%d internal), %d triangles, %d stitches, h %.4g m, seam length mismatch %.2f %% "
                 "(%.0f ms)\n",
                 bp.figures.panels, bp.figures.internalPanels, bp.figures.triangles, bp.figures.stitches,
                 bp.figures.edgeLength, 100 * bp.figures.maxSeamLengthMismatch, bp.figures.totalMs);
  return true;
}

// How the optimization went, for the report.
struct Optimized {
  std::string state = "skipped";
  double ms = 0, edgeMismatch = 0;
  int remeshings = 0;
  bool slidingSeams = false;
  json history = json::array();
};

json historyJson(const std::vector<OptimizeRecord>& records) {
  json history = json::array();
  for (const OptimizeRecord& h : records)
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
  return history;
}

// Optimize: the panels moved so that the inflated shape comes close to the target; bp.pattern becomes the
// optimizer's, its "inflated" the optimized shape (where the last inflation starts).
Optimized optimizePhase(const DesignJob& job, const Args& args, const DesignScene& scene, BuiltPattern& bp) {
  Optimized out;
  out.edgeMismatch = bp.figures.maxEdgeLengthMismatch;
  if (!job.optimize) return out;
  const auto t1 = Clock::now();
  OptimizeOptions optimizeOptions;
  if (args.has("--max-iterations")) {  // as given, also when seams slide (OptimizeSliding::iterationFactor)
    optimizeOptions.stopping.maxIterations =
        intOption(args, "--max-iterations", optimizeOptions.stopping.maxIterations, 1, 100'000, "an iteration count");
    optimizeOptions.sliding.iterationFactor = 1;
  }
  PatternOptimizer optimizer(scene.target, bp, designSeamWeights(scene.design), optimizeOptions);
  out.slidingSeams = optimizer.slidingSeams();
  if (out.slidingSeams && !job.quiet)
    std::fprintf(stderr, "optimize: some seams have a weight below %g and slide to where the shape fits best\n",
                 optimizer.options().sliding.seamWeight);
  while (optimizer.step(5, 1000) == OptimizeState::Running)
    if (!job.quiet && !optimizer.history().empty()) {
      const OptimizeRecord& h = optimizer.history().back();
      std::fprintf(stderr,
                   "  optimize: iteration %3d  distance rms: target to inflated %.3f %%, inflated to target %.3f %%  "
                   "seam mismatch %.1e\n",
                   h.iteration, 100 * h.targetDistanceRms, 100 * h.distanceRms, h.seamMismatch);
    }
  out.ms = msSince(t1);
  out.state = toString(optimizer.state());
  if (!job.quiet)
    std::fprintf(stderr, "optimize: %s after %d iterations (%.0f ms)%s%s\n", out.state.c_str(), optimizer.iterations(),
                 out.ms, optimizer.message().empty() ? "" : ": ", optimizer.message().c_str());
  out.history = historyJson(optimizer.history());
  if (optimizer.state() != OptimizeState::Failed) {
    out.edgeMismatch = optimizer.history().back().seamMismatch;
    bp.pattern = optimizedPattern(optimizer);
    out.remeshings = optimizer.timings().remeshings;
  }
  return out;
}

// Export: pattern.json and the cut file. Returns why the cut file was not written ("" when it was): when the
// pieces cannot be laid out (a sheet narrower than a piece) the other outputs are still written.
std::string exportPhase(const DesignJob& job, const Pattern& pattern, const ExportOptions& cutOptions) {
  std::filesystem::create_directories(job.dir);
  writeFile(job.dir + "/pattern.json", writePatternJson(pattern) + "\n");
  std::filesystem::remove(job.dir + "/pattern.svg");  // never leave an older cut file beside the new pattern
  try {
    writeFile(job.dir + "/pattern.svg", exportPattern(pattern, cutOptions).svg);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Inflate: from the pattern's "inflated" start (the target shape, or the optimizer's shape), to inflated.obj.
InflateResult inflatePhase(const DesignJob& job, const Pattern& pattern, const SewnMesh& mesh) {
  InflationSolver solver(mesh, pattern.material, pattern.pressure, {}, startFromInflated(pattern, mesh));
  while (solver.step(5, 500) == InflateState::Running)
    if (!job.quiet)
      std::fprintf(stderr, "  inflate: iteration %3d  residual %.3e  volume %.6g m^3\n", solver.iterations(),
                   solver.residual(), solver.volume());
  InflateResult r = solver.result();
  writeFile(job.dir + "/inflated.obj", objText(mesh, r.positions));
  return r;
}

// Report: report.json and the closing lines; the exit code.
int reportPhase(const DesignJob& job, const ReadDesign& read, const BuiltPattern& bp, const Optimized& opt,
                const SewnMesh& mesh, const InflateResult& r, const std::string& cutFileProblem, Clock::time_point t0) {
  const DesignScene& scene = *read.scene;
  const TwoWayDistance d = distanceToTarget(scene, mesh, r.positions);
  const json report = {
      {"format", "billow-design-report"},
      {"version", 1},
      {"optimized", job.optimize && opt.state != "failed"},
      {"optimize",
       {{"state", opt.state},
        {"ms", opt.ms},
        {"remeshing_steps", opt.remeshings},
        {"sliding_seams", opt.slidingSeams},
        {"history", opt.history}}},
      {"panels", bp.figures.panels},
      {"internal_panels", bp.figures.internalPanels},
      {"triangles", bp.figures.triangles},
      {"edge_length", bp.figures.edgeLength},
      {"distance_to_target", distanceReportJson(d)},
      {"seam_length_mismatch", {{"max_piece", bp.figures.maxSeamLengthMismatch}, {"max_edge", opt.edgeMismatch}}},
      {"inflate",
       {{"state", toString(r.state)},
        {"converged", r.converged},
        {"message", r.message},
        {"iterations", r.iterations},
        {"residual", r.residual},
        {"volume", r.volume}}},
      {"timings_ms",
       {{"load", scene.loadMs},
        {"seams", scene.seamsMs},
        {"segment", scene.segmentMs},
        {"flatten", bp.figures.flattenMs},
        {"mesh", bp.figures.meshMs},
        {"pattern", bp.figures.totalMs},
        {"optimize", opt.ms},
        {"inflate", r.timings.totalMs + r.timings.setupMs},
        {"total", msSince(t0)}}},
      {"memory", {{"predicted_bytes", read.neededBytes}, {"peak_resident_bytes", peakResidentBytes()}}},
      {"cut_file", {{"written", cutFileProblem.empty()}, {"message", cutFileProblem}}}};
  writeFile(job.dir + "/report.json", report.dump(2) + "\n");
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

}  // namespace

int designCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(argv, {"--out-dir", "--resolution", "--max-memory", "--max-iterations"});
  if (args.has("--help") || args.positional.size() != 1 || !args.has("--out-dir"))
    return designUsage(args.has("--help"));
  const auto t0 = Clock::now();
  DesignJob job;
  job.designPath = args.positional[0];
  job.dir = args.get("--out-dir");
  job.quiet = args.has("--quiet");
  job.triangles = intOption(args, "--resolution", job.triangles, 8, 2'000'000, "a triangle count");
  job.optimize = !args.has("--no-optimize");
  job.memoryBudget = memoryBudgetOption(args);

  const ReadDesign read = readPhase(job);
  BuiltPattern bp;
  if (!buildPhase(job, *read.scene, bp)) return 1;
  const Optimized optimized = optimizePhase(job, args, *read.scene, bp);
  const std::string cutFileProblem = exportPhase(job, bp.pattern, read.cutOptions);
  const SewnMesh mesh = sewPattern(bp.pattern);
  const InflateResult inflated = inflatePhase(job, bp.pattern, mesh);
  return reportPhase(job, read, bp, optimized, mesh, inflated, cutFileProblem, t0);
}

}  // namespace billow::cli
