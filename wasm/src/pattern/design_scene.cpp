#include "pattern/design_scene.hpp"

#include <optional>

#include "io/mesh_file.hpp"
#include "mesh/close_holes.hpp"
#include "mesh/validate.hpp"
#include "suggest/thin_handles.hpp"
#include "util/clock.hpp"
#include "util/error.hpp"

namespace billow {

namespace {

// The scene's target: scaled to meters by its design's size, with its topology, projector and geodesic solver.
void fillTargetScene(DesignScene& scene, const TriMesh& own) {
  scene.scale = designScale(scene.design, own);
  scene.target = own;
  scene.target.V *= scene.scale;
  scene.topology = buildTopology(scene.target);
  scene.projector = std::make_unique<SurfaceProjector>(scene.target);
  scene.geodesic = std::make_unique<GeodesicSolver>(scene.target, scene.topology);
}

}  // namespace

std::unique_ptr<DesignScene> loadDesignTargetScene(const Design& design, const std::string& designPath,
                                                   const std::vector<std::string>& exampleDirs, bool guessUp) {
  auto scene = std::make_unique<DesignScene>();
  const auto t0 = Clock::now();
  scene->design = design;
  TriMesh own = loadDesignTarget(design, designPath, exampleDirs);
  // Seam points name the target's triangles and corners, so the mesh is turned the right way as the app turns it
  // (an inside-out mesh flipped, stray triangles turned) before they are read.
  ValidationOptions vo;
  vo.guessUp = guessUp;
  // Holes are closed as the app closes them: on the mesh turned the right way first (its caps then face out).
  if (design.target.closeHoles) {
    validateTarget(own, vo);
    scene->facesRead = own.numTriangles();
    closeHoles(own);
  }
  const ValidationReport report = validateTarget(own, vo);
  if (!design.target.closeHoles) scene->facesRead = own.numTriangles();
  if (!report.ok) {
    std::string why;
    bool onlyHoles = true;
    for (const MeshIssue& i : report.issues) {
      if (i.severity != "error") continue;
      why += (why.empty() ? "" : " ") + i.message;
      onlyHoles = onlyHoles && i.code == "mesh.open";
    }
    if (onlyHoles && !design.target.closeHoles)
      why += " Or have Billow close them: \"closeHoles\": true in the design's target (billow suggest --close-holes).";
    throw Error("design.bad-target", "The design's target cannot be used: " + why);
  }
  if (guessUp) scene->design.target.up = report.stats.standing.up;
  if (design.target.cutThinHandles) cutThinHandles(own, thinHandles(own));
  fillTargetScene(*scene, own);
  scene->loadMs = msSince(t0);
  return scene;
}

std::unique_ptr<DesignScene> makeTargetScene(const Design& design, const TriMesh& own) {
  auto scene = std::make_unique<DesignScene>();
  scene->design = design;
  scene->facesRead = own.numTriangles();
  fillTargetScene(*scene, own);
  return scene;
}

void addedFacePointsAsPositions(const DesignScene& scene, std::vector<DesignSeam>& seams) {
  for (DesignSeam& seam : seams)
    for (DesignPoint& p : seam.points)
      if (p.onSurface && p.surface.face >= scene.facesRead) {
        p.position = position(scene.target, p.surface) / scene.scale;
        p.onSurface = false;
      }
}

void traceDesignSeams(DesignScene& scene) {
  const auto t1 = Clock::now();
  scene.curves.clear();
  for (const SeamSpec& spec : designSeamSpecs(scene.design.seams, scene.target, *scene.projector, scene.scale))
    scene.curves.push_back(buildSeamCurve(*scene.geodesic, *scene.projector, spec));
  scene.seamsMs = msSince(t1);
}

std::vector<std::array<int, 2>> openSeamEndHosts(const std::vector<DesignSeam>& seams, const SeamSurface& surface,
                                                 size_t from) {
  std::vector<std::array<int, 2>> hosts(seams.size(), {-1, -1});
  std::vector<SeamCurve> curves;  // traced once an open seam asks
  for (size_t i = from; i < seams.size(); ++i) {
    if (seams[i].closed || seams[i].points.size() < 2) continue;
    if (curves.empty())
      for (const SeamSpec& spec : designSeamSpecs(seams, surface.target, surface.projector, surface.scale))
        curves.push_back(buildSeamCurve(surface.geodesic, surface.projector, spec));
    SeamCurve own;  // out of the way while its ends look for another seam's line
    std::swap(own, curves[i]);
    for (int e = 0; e < 2; ++e) {
      const SeamSnap snap = snapToSeams(surface.target, surface.topology,
                                        position(surface.target, (e ? own.points.back() : own.points.front()).point),
                                        curves, 1e-6 * boundingDiagonal(surface.target));
      if (snap.kind != SeamSnap::None) hosts[i][size_t(e)] = snap.curve;
    }
    std::swap(own, curves[i]);
  }
  return hosts;
}

std::vector<DesignSeam> carriedSeams(const std::vector<DesignSeam>& seams, const SeamSurface& from,
                                     const SeamSurface& to, const std::vector<DesignSeam>& onTo) {
  const std::vector<SeamSpec> specs = designSeamSpecs(seams, from.target, from.projector, from.scale);
  std::vector<DesignSeam> out = seams;
  const double toFrom = to.scale / from.scale;
  for (size_t i = onTo.size(); i < out.size(); ++i)
    for (size_t k = 0; k < out[i].points.size(); ++k) {
      DesignPoint& p = out[i].points[k];
      p.onSurface = true;
      p.surface = to.projector.project(toFrom * position(from.target, specs[i].controls[k]));
    }
  std::copy(onTo.begin(), onTo.end(), out.begin());
  // The open seams' ends on another seam's line on `from`, where the layout was traced.
  struct End {
    size_t seam, point;
    int host;
  };
  std::vector<End> ends;
  const std::vector<std::array<int, 2>> hosts = openSeamEndHosts(seams, from, onTo.size());
  for (size_t i = onTo.size(); i < out.size(); ++i)
    for (int e = 0; e < 2; ++e)
      if (hosts[i][size_t(e)] >= 0) ends.push_back({i, e ? out[i].points.size() - 1 : 0, hosts[i][size_t(e)]});
  if (ends.empty()) return out;
  const std::vector<SeamSpec> toSpecs = designSeamSpecs(out, to.target, to.projector, to.scale);
  std::vector<std::optional<SeamCurve>> toCurves(out.size());
  for (const End& e : ends) {
    std::optional<SeamCurve>& host = toCurves[size_t(e.host)];
    if (!host) host = buildSeamCurve(to.geodesic, to.projector, toSpecs[size_t(e.host)]);
    // Within a hundredth of the size: the two meshes of one surface differ by far less.
    const SeamSnap snap = snapToSeams(to.target, to.topology, position(to.target, out[e.seam].points[e.point].surface),
                                      {*host}, 1e-2 * boundingDiagonal(to.target));
    if (snap.kind != SeamSnap::None) out[e.seam].points[e.point].surface = snap.point;
  }
  return out;
}

void segmentDesignScene(DesignScene& scene) {
  const auto t2 = Clock::now();
  SegmentationOptions so;
  so.up = scene.design.target.up;  // the problems' places as the target stands
  scene.segmentation = segmentTarget(scene.target, scene.topology, scene.curves, so);
  scene.segmentMs = msSince(t2);
}

std::unique_ptr<DesignScene> makeDesignScene(const Design& design, const std::string& designPath,
                                             const std::vector<std::string>& exampleDirs) {
  auto scene = loadDesignTargetScene(design, designPath, exampleDirs);
  traceDesignSeams(*scene);
  segmentDesignScene(*scene);
  return scene;
}

std::unique_ptr<DesignScene> loadDesignScene(const std::string& designPath,
                                             const std::vector<std::string>& exampleDirs) {
  return makeDesignScene(readDesignJson(readFileBytes(designPath)), designPath, exampleDirs);
}

PatternBuildOptions designBuildOptions(const Design& design, int triangles) {
  PatternBuildOptions options;
  options.triangles = triangles;
  options.material = design.material;
  options.pressure = design.pressure;
  for (const DesignConnection& c : design.connections)
    if (c.seams.size() == 2) options.connections.push_back({c.seams[0], c.seams[1]});
  for (const DesignSeam& s : design.seams) options.seamNames.push_back(s.name);
  return options;
}

BuiltPattern buildDesignPattern(const DesignScene& scene, int triangles) {
  return buildPattern(scene.target, scene.segmentation, designBuildOptions(scene.design, triangles));
}

std::vector<double> designSeamWeights(const Design& design) {
  std::vector<double> weights;
  for (const DesignSeam& s : design.seams) weights.push_back(s.weight);
  return weights;
}

}  // namespace billow
