// billow check MESH [--json]: the same validation as the app's, with a non-zero exit on errors.
#include <cstdio>

#include "cli/commands.hpp"
#include "io/mesh_file.hpp"
#include "mesh/validate.hpp"

namespace billow::cli {

int checkCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(argv, {});
  if (args.has("--help") || args.positional.size() != 1) {
    std::fprintf(args.has("--help") ? stdout : stderr,
                 "usage: billow check MESH [--json]\n\n"
                 "Checks that MESH (.obj) is a closed, manifold, consistently oriented single shape.\n"
                 "Exit code 0 when Billow can use it, 1 when not.\n");
    return args.has("--help") ? 0 : 2;
  }
  const std::string& path = args.positional[0];
  TriMesh mesh = readMeshBytes(readFileBytes(path), path);
  const ValidationReport report = validateTarget(mesh);
  if (args.has("--json")) {
    std::printf("%s\n", toJson(report).c_str());
  } else {
    const auto& st = report.stats;
    std::printf("%s: %d vertices, %d triangles, %d edges", path.c_str(), st.vertices, st.triangles, st.edges);
    if (st.genus >= 0) std::printf(", genus %d", st.genus);
    const Eigen::Vector3d size = st.bboxMax - st.bboxMin;
    std::printf("\n  size %.4g x %.4g x %.4g (file units), area %.4g, volume %.4g\n", size.x(), size.y(), size.z(),
                st.area, st.volume);
    for (const auto& issue : report.issues)
      std::fprintf(issue.severity == "error" ? stderr : stdout, "  %s: %s\n", issue.severity.c_str(),
                   issue.message.c_str());
    std::printf("%s\n", report.ok ? "OK: Billow can use this target." : "NOT USABLE: fix the errors above.");
  }
  return report.ok ? 0 : 1;
}

}  // namespace billow::cli
