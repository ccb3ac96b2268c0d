// Native benchmark of pattern optimization, the paper's Table 1 as the anchor (bench/README.md): per design
// of bench/designs/manifest.json, the elements, panels (internal ones), Newton iterations, L-BFGS
// iterations, the time to preview quality (the first iterate whose inflated shape is within 5 % of the
// model size of the final one, DESIGN.md) and to the end, the final distance to the target, the largest
// seam mismatch and the peak RSS.
//   billow_design_bench [--json] [--designs sphere3,teddy] [--max-seconds S] [--manifest FILE]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/design_json.hpp"
#include "io/mesh_file.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/design_scene.hpp"

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

json run(const json& entry, const std::filesystem::path& base, double maxSeconds) {
  const std::filesystem::path path = base / entry.at("file").get<std::string>();
  const auto t0 = Clock::now();
  auto scene = makeDesignScene(readDesignJson(readFileBytes(path.string())), path.string(),
                               {(base / entry.value("examples", "../../web/public/examples")).string()});
  PatternBuildOptions o;
  o.triangles = entry.at("triangles").get<int>();
  o.material = scene->design.material;
  o.pressure = scene->design.pressure;
  useDesignConnections(scene->design, o);
  BuiltPattern built = buildPattern(scene->target, scene->segmentation, o);
  json row = {{"design", entry.at("name")}, {"class", entry.value("class", "")}};
  if (!built.ok()) {
    row["error"] = built.problems.empty() ? "no panels" : built.problems.front().message;
    return row;
  }
  const double patternSeconds = secondsSince(t0);
  std::vector<double> weights;
  for (const auto& s : scene->design.seams) weights.push_back(s.weight);
  OptimizeOptions oo;
  oo.keepShapes = true;
  const auto t1 = Clock::now();
  PatternOptimizer opt(scene->target, built, weights, oo);
  while (opt.step(1) == OptimizeState::Running)
    if (secondsSince(t1) > maxSeconds) break;
  const double seconds = secondsSince(t1);
  const auto& history = opt.history();
  const double D = opt.objective().modelSize();
  int previewIteration = -1;
  double previewSeconds = 0;
  for (size_t k = 0; k < opt.shapes().size() && previewIteration < 0; ++k)
    if ((opt.shapes()[k] - opt.inflated()).rowwise().norm().maxCoeff() < 0.05 * D)
      previewIteration = history[k].iteration, previewSeconds = history[k].ms / 1000;
  int newton = 0;
  for (const auto& h : history) newton += h.equilibriumIterations;
  row.update({{"elements", built.figures.triangles},
              {"panels", built.figures.panels},
              {"internalPanels", built.figures.internalPanels},
              {"remeshingSteps", 0},
              {"iterations", opt.iterations()},
              {"newtonIterations", newton},
              {"equilibriumSolves", opt.timings().equilibriumSolves},
              {"rejectedTrials", opt.timings().rejectedTrials},
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
              {"seconds", seconds},
              {"state", opt.state() == OptimizeState::Running ? "time limit" : toString(opt.state())},
              {"message", opt.message()},
              {"flattenedDistanceRms", history.front().distanceRms},
              {"distanceRms", history.back().distanceRms},
              {"distanceMax", history.back().distanceMax},
              {"seamMismatch", history.back().seamMismatch},
              {"flattenedSeamMismatch", built.figures.maxSeamLengthMismatch},
              {"peakRssMb", peakRssMb()}});
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  bool asJson = false;
  double maxSeconds = 600;
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
      maxSeconds = std::stod(argv[++i]);
    else if (a == "--manifest" && hasValue)
      manifestPath = argv[++i];
    else {
      std::fprintf(stderr,
                   "usage: billow_design_bench [--json] [--designs NAME,..] [--max-seconds S] [--manifest FILE]\n");
      return 2;
    }
  }
  const json manifest = json::parse(readFileBytes(manifestPath));
  const std::filesystem::path base = std::filesystem::path(manifestPath).parent_path();
  json rows = json::array();
  if (!asJson)
    std::printf("%-8s %-9s %6s %7s %5s %6s %9s %9s %9s %8s %8s %8s %7s %s\n", "design", "class", "elems", "panels",
                "iters", "newton", "pattern s", "preview s", "full s", "rms %", "max %", "seam", "RSS MB", "state");
  for (const json& entry : manifest.at("designs")) {
    const std::string name = entry.at("name");
    if (!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
    json row;
    try {
      row = run(entry, base, maxSeconds);
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
    std::printf("%-8s %-9s %6d %7s %5d %6d %9.2f %9.2f %9.2f %8.3f %8.3f %8.1e %7.0f %s\n", name.c_str(),
                row["class"].get<std::string>().c_str(), row["elements"].get<int>(), panels.c_str(),
                row["iterations"].get<int>(), row["newtonIterations"].get<int>(), row["patternSeconds"].get<double>(),
                row["previewSeconds"].get<double>(), row["seconds"].get<double>(),
                100 * row["distanceRms"].get<double>(), 100 * row["distanceMax"].get<double>(),
                row["seamMismatch"].get<double>(), row["peakRssMb"].get<double>(),
                row["state"].get<std::string>().c_str());
    std::fflush(stdout);
  }
  if (asJson) std::printf("%s\n", json({{"runtime", "native"}, {"rows", rows}}).dump(2).c_str());
  return 0;
}
