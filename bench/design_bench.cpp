// Native benchmark of pattern optimization, the paper's Table 1 as the anchor (bench/README.md): per design
// of bench/designs/manifest.json, the elements, panels (internal ones), Newton iterations, L-BFGS
// iterations, the time to preview quality (the first iterate whose inflated shape is within 5 % of the
// model size of the final one, DESIGN.md) and to the end, the final distance to the target, the largest
// seam mismatch and the peak RSS.
//   billow_design_bench [--json] [--designs sphere3,teddy] [--max-seconds S] [--manifest FILE] [--triangles N]
//                       [--trace] [--app-rule] [--set NAME=VALUE ...] [--no-remesh-check] [--cut-scale F]
//                       [--out-dir DIR] [--perturb SEED] [--json-out FILE]
// --triangles overrides every design's element count (quick runs); --trace prints every iterate to stderr;
// --set changes an optimizer option (sobolevLength, quality, laplace, smooth, fair, seam, cover,
// gap, coverReach, maxIterations, stallIterations, tolerance and band: the equilibrium's) to compare variants;
// --app-rule stops where the app stops (optimize/stopping_rule.hpp), before any --set. After
// each run the final outlines are meshed anew and inflated (the cut panels' RMS, "remeshedOutlines"; --no-remesh-check
// skips it; --cut-scale F meshes them at F x the design's edge length). --perturb SEED moves every flattened panel
// vertex by up to 1e-12 of the edge length (seeded): a start that differs at the rounding level, to see the
// spread of a design's runs, which one run does not show (bench/README.md "How much one run tells"). --json-out FILE
// writes the rows --json prints besides the table (bench/table1.mjs reads them).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/design_json.hpp"
#include "io/mesh_file.hpp"
#include "io/pattern_json.hpp"
#include "optimize/optimized_pattern.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "optimize/stopping_rule.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/design_scene.hpp"
#include "seams/surface_point.hpp"

namespace {

using namespace billow;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

double peakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // Linux: kilobytes
}

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

struct BenchOptions {
  double maxSeconds = 600;
  int triangles = 0;  // > 0: overrides the manifest's
  bool trace = false;
  bool appRule = false;  // --app-rule: the app's stopping rule
  std::vector<std::pair<std::string, double>> set;
  bool remeshCheck = true;  // --no-remesh-check: skip the cut-panel figure (remeshedOutlines)
  double cutScale = 1;      // --cut-scale F: the cut panels are meshed at F x the design's edge length
  std::string outDir;  // non-empty: the optimized pattern of each design, with its inflated shape, is written there
                       // (NAME.pattern.json)
  int perturb = 0;     // > 0: the seed of a rounding-level move of the flattened panels
};

// The largest distance from a vertex of p to the surface `to` (its projector). Two shapes on different meshes
// are compared both ways, vertex to surface: vertex to vertex would count a coarse-phase iterate's spacing as a
// difference of shape (half a coarse edge, 1-3 % of the model size at 3,000 elements).
double farthestFrom(const Vertices& p, const SurfaceProjector& to) {
  double worst = 0;
  for (int i = 0; i < p.rows(); ++i) {
    double d = 0;
    to.project(p.row(i).transpose(), &d);
    worst = std::max(worst, d);
  }
  return worst;
}

// Total |turning| of each panel's outline [degrees] (its first boundaryVertices rows, in order): about 360 for
// a smooth convex outline plus its corners; a zig-zag outline turns far more.
std::vector<double> outlineTurning(const Pattern& pattern, const BuiltPattern& built) {
  std::vector<double> out;
  for (size_t p = 0; p < pattern.panels.size(); ++p) {
    const PanelVertices& V = pattern.panels[p].vertices;
    const int nb = built.panels[p].boundaryVertices;
    double total = 0;
    for (int j = 0; j < nb; ++j) {
      const Eigen::Vector2d a = V.row((j + nb - 1) % nb), b = V.row(j), c = V.row((j + 1) % nb);
      const Eigen::Vector2d u = b - a, v = c - b;
      total += std::abs(std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v)));
    }
    out.push_back(total * 180 / M_PI);
  }
  return out;
}

void applySetting(OptimizeOptions& o, const std::string& name, double v) {
  if (name == "sobolevLength")
    o.search.sobolevLength = v;
  else if (name == "quality")
    o.weights.quality = v;
  else if (name == "laplace")
    o.weights.laplace = v;
  else if (name == "smooth")
    o.weights.smooth = v;
  else if (name == "seam")
    o.weights.seam = v;
  else if (name == "cover")
    o.weights.cover = v;
  else if (name == "gap")
    o.weights.gap = v;
  else if (name == "coverReach")
    o.weights.coverReach = v;
  else if (name == "coarseCoverReachAtSeams")
    o.remeshing.coarseCoverReachAtSeams = v;
  else if (name == "maxIterations")
    o.stopping.maxIterations = int(v);
  else if (name == "maxWork")
    o.stopping.maxWork = int(v);
  else if (name == "windowIterations")
    o.stopping.windowIterations = int(v);
  else if (name == "windowMove")
    o.stopping.windowMove = v;
  else if (name == "windowDecrease")
    o.stopping.windowDecrease = v;
  else if (name == "relativeDecrease")
    o.stopping.relativeDecrease = v;
  else if (name == "stallIterations")
    o.stopping.stallIterations = int(v);
  else if (name == "remeshEvery")
    o.remeshing.every = int(v);
  else if (name == "maxRemeshings")
    o.remeshing.maxRemeshings = int(v);
  else if (name == "cutPanels")
    o.remeshing.cutPanels = v != 0;
  else if (name == "coarseFactor")
    o.remeshing.coarseFactor = v;
  else if (name == "coarseIterations")
    o.remeshing.coarseIterations = int(v);
  else if (name == "coarseWindow")
    o.remeshing.coarseWindow = int(v);
  else if (name == "coarseMinTriangles")
    o.remeshing.coarseMinTriangles = int(v);
  else if (name == "tolerance")
    o.inflate.tolerance = v;
  else if (name == "fair")
    o.weights.fair = v;
  else if (name == "projectEveryStep")
    o.search.projectEveryStep = v != 0;
  else if (name == "maxMoveEdges")
    o.search.maxMoveEdges = v;
  else if (name == "shapeStepGrowth")
    o.search.shapeStepGrowth = v;
  else if (name == "gaussSeidelSweeps")
    o.search.gaussSeidelSweeps = int(v);
  else if (name == "gaussSeidelThreshold")
    o.search.gaussSeidelThreshold = v;
  else if (name == "predictEquilibrium")
    o.search.predictEquilibrium = v != 0;
  else if (name == "gaussNewton")
    o.search.gaussNewton = v != 0;
  else if (name == "gaussNewtonCg")
    o.search.gaussNewtonCg = int(v);
  else if (name == "gaussNewtonCgTolerance")
    o.search.gaussNewtonCgTolerance = v;
  else if (name == "slidingSeamWeight")
    o.sliding.seamWeight = v;
  else if (name == "slidingDistanceWindow")
    o.sliding.distanceWindow = int(v);
  else if (name == "distanceDecrease")
    o.stopping.distanceDecrease = v;
  else if (name == "slidingRemeshEvery")
    o.sliding.remeshEvery = int(v);
  else if (name == "regularizerEdgeLength")
    o.sliding.regularizerEdgeLength = v;
  else if (name == "minPivot")
    o.inflate.minPivot = v;
  else if (name == "band")
    o.inflate.band = v;
  else if (name == "seamStiffness")
    o.inflate.seamStiffness = v;
  else if (name == "settledStep")
    o.inflate.settledStep = v;
  else
    throw std::runtime_error("unknown option " + name);
}

json run(const json& entry, const std::filesystem::path& base, const BenchOptions& bo) {
  const std::filesystem::path path = base / entry.at("file").get<std::string>();
  const auto t0 = Clock::now();
  auto scene = loadDesignScene(path.string(), {(base / entry.value("examples", "../../web/public/examples")).string()});
  BuiltPattern built = buildDesignPattern(*scene, bo.triangles > 0 ? bo.triangles : entry.at("triangles").get<int>());
  json row = {{"design", entry.at("name")}, {"class", entry.value("class", "")}};
  if (!built.ok()) {
    row["error"] = built.problems.empty() ? "no panels" : built.problems.front().message;
    return row;
  }
  const double patternSeconds = secondsSince(t0);
  if (bo.perturb > 0) {
    std::mt19937 rng(bo.perturb);
    std::uniform_real_distribution<double> u(-1, 1);
    for (Panel& panel : built.pattern.panels)
      for (int v = 0; v < panel.vertices.rows(); ++v)
        for (int k = 0; k < 2; ++k) panel.vertices(v, k) += 1e-12 * built.figures.edgeLength * u(rng);
  }
  const std::vector<double> weights = designSeamWeights(scene->design);
  OptimizeOptions oo = bo.appRule ? appStoppingRule() : OptimizeOptions{};
  oo.keepShapes = true;
  for (const auto& [name, value] : bo.set) applySetting(oo, name, value);
  const auto t1 = Clock::now();
  PatternOptimizer opt(scene->target, built, weights, oo);
  size_t traced = 0;
  const auto trace = [&] {
    for (; bo.trace && traced < opt.history().size(); ++traced) {
      const OptimizeRecord& h = opt.history()[traced];
      std::fprintf(
          stderr,
          "%s it %3d%s E %.6e (t %.2e c %.2e s %.2e l %.2e b %.2e L %.2e q %.2e g %.2e f %.2e) rms %.3f%% max %.3f%% "
          "mismatch %.1e grad %.2e alpha %.3g newton %d %.0f ms%s%s%s%s%s%s\n",
          entry.at("name").get<std::string>().c_str(), h.iteration, h.projected ? "P" : " ", h.objective,
          h.terms.target, h.terms.cover, h.terms.seam, h.terms.length, h.terms.smooth, h.terms.laplace, h.terms.quality,
          h.terms.gap, h.terms.fair, 100 * h.distanceRms, 100 * h.distanceMax, h.seamMismatch, h.gradient, h.stepLength,
          h.equilibriumIterations, h.ms, h.remeshed ? " remeshed" : "", h.resettled ? " resettled" : "",
          h.snapLimited ? " snap-limited" : "", h.cutShort ? " cut-short" : "", h.restored ? " restored" : "",
          h.cutPanels ? " cut" : "");
    }
  };
  // The mesh of each remeshing (the coarse first phase's, then the design's; sliding seams remesh often), for the
  // preview's distance between shapes on different meshes.
  std::vector<Triangles> meshes{opt.mesh().triangles};
  const auto keepMesh = [&] {
    int remeshings = 0;
    for (const auto& h : opt.history()) remeshings += h.remeshed;
    if (remeshings >= int(meshes.size())) meshes.resize(remeshings + 1, opt.mesh().triangles);
  };
  while (opt.step(1) == OptimizeState::Running) {
    keepMesh();
    trace();
    if (secondsSince(t1) > bo.maxSeconds) break;
  }
  trace();
  if (bo.trace)
    std::fprintf(stderr, "%s: %s %s\n", entry.at("name").get<std::string>().c_str(), toString(opt.state()),
                 opt.message().c_str());
  const double seconds = secondsSince(t1);
  const auto& history = opt.history();
  const double D = opt.objective().modelSize();
  int previewIteration = -1;
  double previewSeconds = 0;
  keepMesh();
  const TriMesh finalSurface{opt.inflated(), meshes.back()};
  const SurfaceProjector toFinal(finalSurface);
  // How far a shape on meshes[m] lies from the final one: the largest vertex move on the same mesh, else the farthest
  // point of either from the other's surface.
  const auto fromFinal = [&](const Vertices& shape, int m) {
    if (m + 1 == int(meshes.size())) return (shape - opt.inflated()).rowwise().norm().maxCoeff();
    const TriMesh surface{shape, meshes[m]};
    return std::max(farthestFrom(shape, toFinal), farthestFrom(opt.inflated(), SurfaceProjector(surface)));
  };
  int meshOfShape = 0;  // the remeshings up to the shape looked at
  for (size_t k = 0; k < opt.shapes().size() && previewIteration < 0; ++k) {
    meshOfShape += history[k].remeshed;
    if (fromFinal(opt.shapes()[k], meshOfShape) < 0.05 * D)
      previewIteration = history[k].iteration, previewSeconds = history[k].ms / 1000;
  }
  // The cut panels' shape against the optimizer's own shape of the iterate they were cut from (bench/README "The cut
  // panels use up most of the preview's 5 %"). An earlier iterate cut after a snap (settleCutPanels) is recorded on
  // the design's mesh again, the one before the first cut.
  double cutOffset = -1;
  int meshOfOwn = -1;
  meshOfShape = 0;
  for (size_t k = 0; k + 1 < opt.shapes().size(); ++k) {
    meshOfShape += history[k].remeshed;
    if (!history[k + 1].cutPanels) continue;
    if (meshOfOwn < 0) meshOfOwn = meshOfShape;
    cutOffset = fromFinal(opt.shapes()[k], history[k].restored ? meshOfOwn : meshOfShape) / D;  // the last cut's
  }
  int newton = 0;
  for (const auto& h : history) newton += h.equilibriumIterations;
  // Each vertex's distance to the target (relative to D), for the RMS figures below.
  const SewnMesh& mesh = opt.mesh();
  const Vertices& x = opt.inflated();
  Eigen::VectorXd distance(mesh.numVertices);
  for (int v = 0; v < mesh.numVertices; ++v) distance[v] = opt.target().closestDistance(x.row(v).transpose()) / D;
  // The RMS distance weighted by the inflated surface's lumped area: unlike the per-vertex RMS it does not
  // improve when vertices crowd where the shape is close to the target.
  double areaRms = 0, area = 0;
  for (int t = 0; t < mesh.numTriangles(); ++t) {
    if (!mesh.outer[t]) continue;
    const Eigen::Vector3d a = x.row(mesh.triangles(t, 0)), b = x.row(mesh.triangles(t, 1)),
                          c = x.row(mesh.triangles(t, 2));
    const double at = 0.5 * (b - a).cross(c - a).norm();
    for (int k = 0; k < 3; ++k) areaRms += at / 3 * distance[mesh.triangles(t, k)] * distance[mesh.triangles(t, k)];
    area += at;
  }
  areaRms = area > 0 ? std::sqrt(areaRms / area) : 0;
  // The RMS distance of the outer vertices at least a given distance (relative to D) from every seam: on a
  // seam the inflated panels meet at a crease the smooth target does not have, so "smooth regions" (the
  // issue's RMS goal) leave a band along the seams out.
  json awayFromSeams = json::array();
  {
    std::vector<int> seamVertices;
    for (int v = 0; v < mesh.numVertices; ++v)
      if (mesh.stitchedCount[v] >= 2) seamVertices.push_back(v);
    const Eigen::VectorXd& w = opt.objective().targetWeights();
    std::vector<std::pair<double, double>> seamAndTarget;  // per outer vertex, relative to D
    for (int v = 0; v < mesh.numVertices; ++v) {
      if (w[v] == 0) continue;
      double nearest = INFINITY;
      for (int s : seamVertices) nearest = std::min(nearest, (x.row(v) - x.row(s)).squaredNorm());
      seamAndTarget.push_back({std::sqrt(nearest) / D, distance[v]});
    }
    for (double band : {0.0, 0.01, 0.02, 0.05}) {
      double sum = 0;
      int count = 0;
      for (const auto& [seam, d] : seamAndTarget)
        if (seam >= band) sum += d * d, ++count;
      awayFromSeams.push_back({{"band", band}, {"rms", count ? std::sqrt(sum / count) : 0}, {"vertices", count}});
    }
  }
  // What the cut panels give (PatternOptimizer::checkCutPanels).
  json remeshed = nullptr;
  if (bo.remeshCheck) {
    const CutPanelsCheck cut = opt.checkCutPanels(bo.cutScale == 1 ? 0 : bo.cutScale * built.figures.edgeLength);
    remeshed = cut.ok ? json{{"distanceRms", cut.distanceRms},
                             {"distanceMax", cut.distanceMax},
                             {"targetDistanceRms", cut.targetDistanceRms},
                             {"elements", cut.elements},
                             {"seconds", cut.ms / 1000}}
                      : json{{"error", cut.message}};
  }
  const std::vector<double> turnFlat = outlineTurning(built.pattern, built),
                            turnOpt = outlineTurning(opt.pattern(), built);
  double turningExcess = 0;
  for (size_t p = 0; p < turnFlat.size(); ++p) turningExcess = std::max(turningExcess, turnOpt[p] - turnFlat[p]);
  if (!bo.outDir.empty()) {
    std::filesystem::create_directories(bo.outDir);
    std::ofstream(bo.outDir + "/" + entry.at("name").get<std::string>() + ".pattern.json")
        << writePatternJson(optimizedPattern(opt));
  }
  row.update({{"elements", built.figures.triangles},
              {"outlineTurningFlattened", turnFlat},
              {"outlineTurning", turnOpt},
              {"outlineTurningExcess", turningExcess},
              {"panels", built.figures.panels},
              {"internalPanels", built.figures.internalPanels},
              {"remeshingSteps", opt.timings().remeshings},
              {"slidingSeams", opt.slidingSeams()},
              {"edgeLengthRelative", built.figures.edgeLength / opt.objective().modelSize()},
              {"sobolevLength", opt.options().search.sobolevLength},
              {"smoothWeight", opt.options().weights.smooth},
              {"iterations", opt.iterations()},
              {"newtonIterations", newton},
              {"newtonIterationsAllSolves", opt.timings().newtonIterations},
              {"equilibriumSolves", opt.timings().equilibriumSolves},
              {"rejectedTrials", opt.timings().rejectedTrials},
              {"snappedTrials", opt.timings().snappedTrials},
              {"unsettledTrials", opt.timings().unsettledTrials},
              {"resettlings", opt.timings().resettlings},
              {"timingsMs",
               {{"setup", opt.timings().setupMs},
                {"equilibrium", opt.timings().equilibriumMs},
                {"adjoint", opt.timings().adjointMs},
                {"align", opt.timings().alignMs},
                {"direction", opt.timings().directionMs},
                {"remesh", opt.timings().remeshMs},
                {"total", opt.timings().totalMs}}},
              {"objectives",
               [&] {
                 json e = json::array();
                 for (const auto& h : history)
                   e.push_back({h.objective, h.stepLength, h.gradient, h.equilibriumIterations});
                 return e;
               }()},
              {"patternSeconds", patternSeconds},
              {"previewIteration", previewIteration},
              {"previewSeconds", previewSeconds},
              {"cutOffset", cutOffset},
              {"seconds", seconds},
              {"state", opt.state() == OptimizeState::Running ? "time limit" : toString(opt.state())},
              {"message", opt.message()},
              {"flattenedDistanceRms", history.front().distanceRms},
              {"distanceRms", history.back().distanceRms},
              {"distanceMax", history.back().distanceMax},
              {"targetDistanceRms", history.back().targetDistanceRms},
              {"targetDistanceMax", history.back().targetDistanceMax},
              {"distanceRmsArea", areaRms},
              {"distanceRmsAwayFromSeams", awayFromSeams},
              {"remeshedOutlines", remeshed},
              {"seamMismatch", history.back().seamMismatch},
              {"flattenedSeamMismatch", built.figures.maxSeamLengthMismatch},
              {"peakRssMb", peakRssMb()}});
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  bool asJson = false;
  std::string jsonOut;  // the rows as --json prints them, written to this file besides the table
  BenchOptions bo;
  std::vector<std::string> only;
  std::string manifestPath = std::string(BILLOW_SOURCE_DIR) + "/bench/designs/manifest.json";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--json")
      asJson = true;
    else if (a == "--designs" && hasValue)
      only = split(argv[++i]);
    else if (a == "--max-seconds" && hasValue)
      bo.maxSeconds = std::stod(argv[++i]);
    else if (a == "--triangles" && hasValue)
      bo.triangles = std::stoi(argv[++i]);
    else if (a == "--trace")
      bo.trace = true;
    else if (a == "--app-rule")
      bo.appRule = true;
    else if (a == "--no-remesh-check")
      bo.remeshCheck = false;
    else if (a == "--cut-scale" && hasValue)
      bo.cutScale = std::stod(argv[++i]);
    else if (a == "--set" && hasValue && std::string(argv[i + 1]).find('=') != std::string::npos) {
      const std::string kv = argv[++i];
      bo.set.emplace_back(kv.substr(0, kv.find('=')), std::stod(kv.substr(kv.find('=') + 1)));
    } else if (a == "--manifest" && hasValue)
      manifestPath = argv[++i];
    else if (a == "--json-out" && hasValue)
      jsonOut = argv[++i];
    else if (a == "--out-dir" && hasValue)
      bo.outDir = argv[++i];
    else if (a == "--perturb" && hasValue)
      bo.perturb = std::stoi(argv[++i]);
    else {
      std::fprintf(stderr,
                   "usage: billow_design_bench [--json] [--designs NAME,..] [--max-seconds S] [--manifest FILE] "
                   "[--triangles N] [--trace] [--app-rule] [--set NAME=VALUE] [--no-remesh-check] [--out-dir DIR] "
                   "[--perturb SEED] [--json-out FILE]\n");
      return 2;
    }
  }
  json manifest;
  try {
    manifest = json::parse(readFileBytes(manifestPath));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "billow_design_bench: %s\n", e.what());
    return 2;
  }
  const std::filesystem::path base = std::filesystem::path(manifestPath).parent_path();
  json rows = json::array();
  if (!asJson)
    std::printf("%-8s %-9s %6s %7s %5s %6s %9s %9s %9s %8s %8s %8s %8s %8s %8s %8s %7s %s\n", "design", "class",
                "elems", "panels", "iters", "newton", "pattern s", "preview s", "full s", "rms %", "rmsA %", "rms2 %",
                "cut %", "max %", "tgt %", "seam", "RSS MB", "state");
  for (const json& entry : manifest.at("designs")) {
    const std::string name = entry.at("name");
    if (!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
    json row;
    try {
      row = run(entry, base, bo);
    } catch (const std::exception& e) {
      row = {{"design", name}, {"error", e.what()}};
    }
    rows.push_back(row);
    if (asJson) continue;
    if (row.contains("error")) {
      std::printf("%-8s %s\n", name.c_str(), row["error"].get<std::string>().c_str());
      continue;
    }
    const std::string panels =
        std::to_string(row["panels"].get<int>()) + " (" + std::to_string(row["internalPanels"].get<int>()) + ")";
    // rms2: away from the seams by 2 % of the model size; cut: the final outlines meshed anew (see run()).
    const json& cut = row["remeshedOutlines"];
    const double cutRms = cut.is_object() && cut.contains("distanceRms") ? 100 * cut["distanceRms"].get<double>() : -1;
    // tgt: the other way, the target's distance to the inflated shape (what the shape leaves out).
    std::printf(
        "%-8s %-9s %6d %7s %5d %6d %9.2f %9.2f %9.2f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.1e %7.0f %s\n",
        name.c_str(), row["class"].get<std::string>().c_str(), row["elements"].get<int>(), panels.c_str(),
        row["iterations"].get<int>(), row["newtonIterations"].get<int>(), row["patternSeconds"].get<double>(),
        row["previewSeconds"].get<double>(), row["seconds"].get<double>(), 100 * row["distanceRms"].get<double>(),
        100 * row["distanceRmsArea"].get<double>(), 100 * row["distanceRmsAwayFromSeams"][2]["rms"].get<double>(),
        cutRms, 100 * row["distanceMax"].get<double>(), 100 * row["targetDistanceRms"].get<double>(),
        row["seamMismatch"].get<double>(), row["peakRssMb"].get<double>(), row["state"].get<std::string>().c_str());
    std::fflush(stdout);
  }
  const json result = {{"runtime", "native"}, {"rows", rows}};
  if (asJson) std::printf("%s\n", result.dump(2).c_str());
  if (!jsonOut.empty()) std::ofstream(jsonOut) << result.dump(2) << "\n";
  return 0;
}
