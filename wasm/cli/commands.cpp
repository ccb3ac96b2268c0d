#include "cli/commands.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "io/export_options_json.hpp"
#include "simulate/materials.hpp"
#include "util/error.hpp"
#include "util/memory_budget.hpp"

namespace billow::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> list = {
      {"check", "validate a target mesh (closed, manifold, oriented, one piece) or read a design", checkCommand},
      {"inflate", "simulate a sewn pattern under pressure (the inflated shape and its wrinkles)", inflateCommand},
      {"example", "write an example pattern (mylar, pillow, ring, star, cube, sphere3, ...)", exampleCommand},
      {"export", "write cut files (SVG, DXF), a printable tiled PDF and statistics for a pattern", exportCommand},
      {"segment", "cut a design's target along its seams into segments (areas, disks, problems)", segmentCommand},
      {"design", "make the sewn pattern of a design, inflate it and report the distance to the target", designCommand},
      {"suggest", "suggest seam layouts for a target, each tried and ranked by its distance to the target",
       suggestCommand},
  };
  return list;
}

bool Args::has(const std::string& name) const {
  return std::any_of(options.begin(), options.end(), [&](const auto& o) { return o.first == name; });
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
  for (const auto& o : options)
    if (o.first == name) return o.second;
  return fallback;
}

Material materialOption(const Args& args, const Material& fallback) {
  const std::string name = args.get("--material");
  if (name.empty()) return fallback;
  if (const MaterialPreset* preset = findMaterialPreset(name)) return preset->material;
  std::string names;
  for (const MaterialPreset& p : materialPresets()) names += (names.empty() ? "" : ", ") + p.material.name;
  throw Error("cli.usage", "there is no material called '" + name + "' (known: " + names + ")");
}

double numberOption(const Args& args, const std::string& name, double fallback, const std::string& what) {
  const std::string v = args.get(name);
  if (v.empty()) return fallback;
  try {
    size_t used = 0;
    const double d = std::stod(v, &used);
    if (used != v.size()) throw std::invalid_argument(v);
    return d;
  } catch (const std::exception&) {
    throw Error("cli.usage", "the option " + name + " needs " + what + ", not '" + v + "'");
  }
}

int intOption(const Args& args, const std::string& name, int fallback, int lo, int hi, const std::string& what) {
  const double v = numberOption(args, name, fallback, what);
  if (v != std::floor(v) || v < lo || v > hi)
    throw Error("cli.usage", "the option " + name + " needs " + what + " from " + std::to_string(lo) + " to " +
                                 std::to_string(hi) + ", not '" + args.get(name) + "'");
  return int(v);
}

double memoryBudgetOption(const Args& args) {
  if (!args.has("--max-memory")) return availableBytes();
  const double mb = numberOption(args, "--max-memory", 0, "a size in MB");
  if (!(mb > 0)) throw Error("cli.usage", "the option --max-memory needs a positive size in MB");
  return mb * 1024 * 1024;
}

double peakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux reports kilobytes
}

std::string executableDir() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  const std::string exe(buf, static_cast<size_t>(n));
  return exe.substr(0, exe.find_last_of('/'));
}

std::unique_ptr<DesignScene> openDesignScene(const std::string& path, bool quiet) {
  auto scene = loadDesignScene(path, exampleSearchPath(executableDir()));
  if (!quiet)
    std::fprintf(stderr, "%s: target of %d triangles scaled by %.4g to meters, %zu seams -> %zu segments (%.0f ms)\n",
                 path.c_str(), scene->target.numTriangles(), scene->scale, scene->curves.size(),
                 scene->segmentation.segments.size(), scene->loadMs + scene->seamsMs + scene->segmentMs);
  return scene;
}

ExportOptions designFabrication(const Design& design) {
  if (!design.extra.contains("fabrication")) return {};
  try {
    return readExportOptionsJson(design.extra["fabrication"]);
  } catch (const Error& e) {
    throw Error(e.code, std::string("the design's fabrication settings: ") + e.what());
  }
}

void writeFile(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f << bytes;
  if (!f) throw Error("io.cannot-write", "cannot write " + path);
}

void printProblems(const std::vector<SegmentationProblem>& problems) {
  for (const SegmentationProblem& p : problems)
    std::fprintf(stderr, "  %s: %s\n", p.severity.c_str(), p.message.c_str());
}

Args parseArgs(const std::vector<std::string>& args, const std::vector<std::string>& flagsWithValue) {
  Args out;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
      const bool takesValue = std::find(flagsWithValue.begin(), flagsWithValue.end(), a) != flagsWithValue.end();
      if (takesValue) {
        if (i + 1 >= args.size()) throw Error("cli.usage", "the option " + a + " needs a value");
        out.options.push_back({a, args[++i]});
      } else {
        out.options.push_back({a, ""});
      }
    } else {
      out.positional.push_back(a);
    }
  }
  return out;
}

}  // namespace billow::cli
