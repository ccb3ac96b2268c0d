// billow segment DESIGN.json --out SEGMENTS.json: the design's target cut into segments along its seams,
// with each segment's area, topology and boundary as seam pieces, the internal connections, and the problems
// in the designer's words.
// Exit code 0 when every segment can be made into a panel, 1 when not (the file is still written).
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "io/mesh_file.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/segment_pieces.hpp"
#include "util/error.hpp"

namespace billow::cli {

// Shared with cmd_design.cpp.
std::unique_ptr<DesignScene> loadDesignScene(const std::string& path, bool quiet);
void writeTextFile(const std::string& path, const std::string& text);
void printProblems(const std::vector<SegmentationProblem>& problems);

namespace {

std::string executableDir() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  const std::string exe(buf, static_cast<size_t>(n));
  return exe.substr(0, exe.find_last_of('/'));
}

nlohmann::json vec3(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

nlohmann::json segmentsJson(const DesignScene& scene) {
  using nlohmann::json;
  const Segmentation& seg = scene.segmentation;
  const SeamGraph graph = analyzeSeams(seg);
  json vertices = json::array(), triangles = json::array(), segments = json::array(), problems = json::array(),
       junctions = json::array();
  for (int v = 0; v < seg.mesh.numVertices(); ++v) vertices.push_back(vec3(seg.mesh.V.row(v).transpose()));
  for (int t = 0; t < seg.mesh.numTriangles(); ++t)
    triangles.push_back({seg.mesh.F(t, 0), seg.mesh.F(t, 1), seg.mesh.F(t, 2)});
  for (const Segment& s : seg.segments) {
    json loops = json::array();
    for (const BoundaryLoop& l : s.loops) {
      json pieces = json::array();
      for (const BoundaryPiece& p : splitLoop(seg, graph, l.vertices))
        pieces.push_back(
            {{"seam", p.seam}, {"neighbor", p.neighborSegment}, {"length", p.length}, {"vertices", p.vertices}});
      loops.push_back(pieces);
    }
    segments.push_back({{"triangles", s.triangles},
                        {"area", s.area},
                        {"isDisk", s.isDisk},
                        {"eulerCharacteristic", s.eulerCharacteristic},
                        {"genus", s.genus},
                        {"boundary", loops}});
  }
  for (const SeamJunction& j : seg.junctions)
    junctions.push_back({{"vertex", j.vertex}, {"position", vec3(j.position)}, {"segments", j.segments}});
  json connections = json::array();  // internal connections: each becomes an internal panel (billow design)
  for (const DesignConnection& c : scene.design.connections) {
    json names = json::array();
    for (int s : c.seams)
      names.push_back(s >= 0 && s < static_cast<int>(scene.design.seams.size()) ? scene.design.seams[s].name : "");
    connections.push_back({{"seams", c.seams}, {"names", names}});
  }
  for (const SegmentationProblem& p : seg.problems)
    problems.push_back({{"code", p.code},
                        {"severity", p.severity},
                        {"message", p.message},
                        {"segment", p.segment},
                        {"seam", p.seam},
                        {"location", vec3(p.location)}});
  return {{"format", "billow-segments"},    {"version", 1},         {"units", "m"},
          {"scale", scene.scale},           {"vertices", vertices}, {"triangles", triangles},
          {"faceSegment", seg.faceSegment}, {"segments", segments}, {"junctions", junctions},
          {"connections", connections},     {"problems", problems}, {"ok", seg.ok()}};
}

}  // namespace

std::unique_ptr<DesignScene> loadDesignScene(const std::string& path, bool quiet) {
  std::vector<DesignWarning> warnings;
  const Design design = readDesignJson(readFileBytes(path), {}, &warnings);
  auto scene = makeDesignScene(design, path, exampleSearchPath(executableDir()));
  if (!quiet)
    std::fprintf(stderr, "%s: target of %d triangles scaled by %.4g to meters, %zu seams -> %zu segments (%.0f ms)\n",
                 path.c_str(), scene->target.numTriangles(), scene->scale, scene->curves.size(),
                 scene->segmentation.segments.size(), scene->loadMs + scene->seamsMs + scene->segmentMs);
  return scene;
}

void writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw Error("io.cannot-write", "cannot write " + path);
}

void printProblems(const std::vector<SegmentationProblem>& problems) {
  for (const SegmentationProblem& p : problems)
    std::fprintf(stderr, "  %s: %s\n", p.severity.c_str(), p.message.c_str());
}

int segmentCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(argv, {"--out"});
  if (args.has("--help") || args.positional.size() != 1 || !args.has("--out")) {
    std::fprintf(args.has("--help") ? stdout : stderr,
                 "usage: billow segment DESIGN.json --out SEGMENTS.json [--quiet]\n\n"
                 "Cuts the design's target along its seams and writes the cut mesh (meters), every segment\n"
                 "(triangles, area in m^2, whether it is a disk, its boundary as seam pieces), the internal\n"
                 "connections and the problems.\n"
                 "Exit code 0 when every segment can be laid flat as a panel, 1 when not.\n");
    return args.has("--help") ? 0 : 2;
  }
  const auto scene = loadDesignScene(args.positional[0], args.has("--quiet"));
  writeTextFile(args.get("--out"), segmentsJson(*scene).dump() + "\n");
  printProblems(scene->segmentation.problems);
  if (!scene->segmentation.ok()) {
    std::fprintf(stderr, "billow segment: this design cannot be made into panels yet (see the errors above)\n");
    return 1;
  }
  return 0;
}

}  // namespace billow::cli
