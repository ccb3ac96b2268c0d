// billow check MESH [--json]: the same validation as the app's, with a non-zero exit on errors.
// billow check DESIGN.json [--json]: the design read by the rules the app's worker reads it with
// (io/design_json.hpp), its target loaded and checked, and its seams placed on it; --json prints the reply a
// binding gives ({"status":"ok","result":...} or {"status":"error","code","message"}), so tests compare the two.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "io/design_json.hpp"
#include "io/mesh_file.hpp"
#include "mesh/validate.hpp"
#include "util/error.hpp"

namespace billow::cli {

namespace {

bool isDesignPath(const std::string& path) { return path.size() > 5 && path.compare(path.size() - 5, 5, ".json") == 0; }

int checkMesh(const std::string& path, bool asJson) {
  TriMesh mesh = readMeshBytes(readFileBytes(path), path);
  const ValidationReport report = validateTarget(mesh);
  if (asJson) {
    std::printf("%s\n", toJson(report).c_str());
  } else {
    const auto& st = report.stats;
    std::printf("%s: %d vertices, %d triangles, %d edges", path.c_str(), st.vertices, st.triangles, st.edges);
    if (st.genus >= 0) std::printf(", genus %d", st.genus);
    const Eigen::Vector3d size = st.bboxMax - st.bboxMin;
    std::printf("\n  size %.4g x %.4g x %.4g (file units), area %.4g, volume %.4g\n", size.x(), size.y(), size.z(),
                st.area, st.volume);
    if (report.ok && st.standing.up.axis == 2)
      std::printf("  it stands on its Z bottom and would tip over on its Y bottom: made Z up, as CAD files are\n");
    for (const auto& issue : report.issues) {
      std::fprintf(issue.severity == "error" ? stderr : stdout, "  %s: %s\n", issue.severity.c_str(),
                   issue.message.c_str());
      // The validation's words serve the app too, whose message offers a button for it: here, the option.
      if (issue.code == "mesh.open")
        std::fprintf(stderr,
                     "  Or let Billow close them: billow suggest %s --close-holes, as the app's \"Close the holes\" "
                     "button does.\n",
                     path.c_str());
    }
    std::printf("%s\n", report.ok ? "OK: Billow can use this target." : "NOT USABLE: fix the errors above.");
  }
  return report.ok ? 0 : 1;
}

int checkDesign(const std::string& path, bool asJson) {
  using nlohmann::json;
  try {
    const Design design = readDesignJson(readFileBytes(path));
    const auto scene = loadDesignTargetScene(design, path, exampleSearchPath(executableDir()));
    const std::vector<SeamSpec> specs = designSeamSpecs(design.seams, scene->target, *scene->projector, scene->scale);
    size_t points = 0;
    for (const SeamSpec& s : specs) points += s.controls.size();
    if (asJson) {
      const json result = {{"seams", specs.size()},
                           {"points", points},
                           {"connections", design.connections.size()},
                           {"triangles", scene->target.numTriangles()},
                           {"scale", scene->scale},
                           {"material", design.material.name},
                           {"pressure", design.pressure}};
      std::printf("%s\n", json({{"status", "ok"}, {"result", result}}).dump().c_str());
    } else {
      std::printf(
          "%s: %zu seams (%zu points) and %zu internal connections on a target of %d triangles scaled by %.4g to "
          "meters; %s at %g Pa\nOK: Billow can read this design.\n",
          path.c_str(), specs.size(), points, design.connections.size(), scene->target.numTriangles(), scene->scale,
          design.material.name.c_str(), design.pressure);
    }
    return 0;
  } catch (const Error& e) {
    if (!asJson) throw;  // main says it
    std::printf("%s\n", json({{"status", "error"}, {"code", e.code}, {"message", e.what()}}).dump().c_str());
    return 1;
  }
}

}  // namespace

int checkCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(argv, {});
  if (args.has("--help") || args.positional.size() != 1) {
    std::fprintf(args.has("--help") ? stdout : stderr,
                 "usage: billow check MESH [--json]\n"
                 "       billow check DESIGN.json [--json]\n\n"
                 "Checks that MESH (.obj, .stl, .ply, .off) is a closed, manifold, consistently oriented single shape.\n"
                 "A design (a .json file) is read as the app reads it: every field checked, its target loaded and\n"
                 "checked, its seams placed on the target.\n"
                 "Exit code 0 when Billow can use it, 1 when not.\n");
    return args.has("--help") ? 0 : 2;
  }
  const std::string& path = args.positional[0];
  return isDesignPath(path) ? checkDesign(path, args.has("--json")) : checkMesh(path, args.has("--json"));
}

}  // namespace billow::cli
