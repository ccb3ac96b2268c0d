// billow segment DESIGN.json --out SEGMENTS.json: the design's target cut into segments along its seams,
// with each segment's area, topology and boundary as seam pieces, the internal connections, and the problems
// in the designer's words.
// Exit code 0 when every segment can be made into a panel, 1 when not (the file is still written).
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/segment_pieces.hpp"

namespace billow::cli {

namespace {

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
  const auto scene = openDesignScene(args.positional[0], args.has("--quiet"));
  writeFile(args.get("--out"), segmentsJson(*scene).dump() + "\n");
  printProblems(scene->segmentation.problems);
  if (!scene->segmentation.ok()) {
    std::fprintf(stderr, "billow segment: this design cannot be made into panels yet (see the errors above)\n");
    return 1;
  }
  return 0;
}

}  // namespace billow::cli
