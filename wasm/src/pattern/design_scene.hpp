// A design made concrete: the target scaled to meters, its seams traced and the target segmented. What the
// CLI commands and the tests start from (the web worker keeps the same pieces in its sessions).
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "io/design_json.hpp"
#include "pattern/build_pattern.hpp"
#include "seams/geodesic.hpp"
#include "segment/segmentation.hpp"

namespace billow {

class OptimizationTarget;

struct DesignScene {
  Design design;
  TriMesh target;    // in meters
  double scale = 1;  // meters per target unit
  // The target file's own faces, checked: the faces after them are the ones added as it was loaded (caps over its
  // holes, the ends of cut handles), which a later version may add otherwise.
  int facesRead = 0;
  MeshTopology topology;
  std::unique_ptr<SurfaceProjector> projector;
  std::unique_ptr<GeodesicSolver> geodesic;
  std::vector<SeamCurve> curves;
  Segmentation segmentation;
  // The target as the pattern optimizer measures it (optimize/optimization_target.hpp), made by the first suggested
  // layout optimized on this scene and kept for the next.
  std::shared_ptr<const OptimizationTarget> optimizationTarget;
  double loadMs = 0, seamsMs = 0, segmentMs = 0;
};

// Loads the target (designPath for relative files, exampleDirs for examples), scales it, checks that it is a
// closed surface (billow::Error "design.bad-target" with the validator's words), traces and segments.
std::unique_ptr<DesignScene> makeDesignScene(const Design& design, const std::string& designPath,
                                             const std::vector<std::string>& exampleDirs);

// makeDesignScene's phases. The target: loaded, checked and scaled, with its topology, projector and geodesic
// solver (no curves, no segmentation yet). guessUp: a mesh file opened anew, whose design names no up axis yet: the
// scene's design takes the one the check guesses (mesh/up_axis.hpp guessUp) and is scaled along it.
std::unique_ptr<DesignScene> loadDesignTargetScene(const Design& design, const std::string& designPath,
                                                   const std::vector<std::string>& exampleDirs, bool guessUp = false);
// The same for a target already loaded and checked, in its own units (the app's worker holds it): scaled by the
// design's size.
std::unique_ptr<DesignScene> makeTargetScene(const Design& design, const TriMesh& targetOwnUnits);
// Seam points on faces added as the target was loaded (DesignScene::facesRead) made 3D points in its own units, as
// a design file beside the mesh keeps them: read again, they are projected onto whatever that version added.
void addedFacePointsAsPositions(const DesignScene& scene, std::vector<DesignSeam>& seams);
// The seams placed on it (designSeamSpecs: triangles it has, 3D points near it) and traced.
void traceDesignSeams(DesignScene& scene);
// A target as seams are laid on it: a scene's, or one its holder keeps in its own units (the app's target session).
struct SeamSurface {
  const TriMesh& target;
  double scale;  // a design's 3D points (the target's own units) times this are in `target`'s coordinates
  const MeshTopology& topology;
  const SurfaceProjector& projector;
  const GeodesicSolver& geodesic;
  SeamSurface(const DesignScene& s)  // implicit: a scene is one
      : target(s.target), scale(s.scale), topology(s.topology), projector(*s.projector), geodesic(*s.geodesic) {}
  SeamSurface(const TriMesh& t, double sc, const MeshTopology& to, const SurfaceProjector& p, const GeodesicSolver& g)
      : target(t), scale(sc), topology(to), projector(p), geodesic(g) {}
};
// For each of `seams` from `from` on that is open, the seams whose traced lines on `surface` its first and its last
// control point lie on (a hair from them), -1 where none: a cut that opens a tube from one loop to another or ends on
// a limb's loop, a meridian at the pole where the others meet. The app keeps such an end on its host as the host is
// edited (a point's "on"); only the traced lines tell, since a loop's few control points can lie far from the line
// between them (a seam around a boot's handle). Closed seams and those before `from`: {-1, -1}.
std::vector<std::array<int, 2>> openSeamEndHosts(const std::vector<DesignSeam>& seams, const SeamSurface& surface,
                                                 size_t from = 0);
// `seams` laid on `from` as they lie on `to`, a mesh of the same surface (a simplified copy of a fine target, or the
// target it copies), each control point projected onto `to`; an open seam's end that lies on another seam's line on
// `from` (a cut ending on a limb's loop) is put on that seam's line as traced on `to`, so that the two still meet.
// The first onTo.size() seams are given as they lie on `to` already (the designer's own), taken as they are.
std::vector<DesignSeam> carriedSeams(const std::vector<DesignSeam>& seams, const SeamSurface& from,
                                     const SeamSurface& to, const std::vector<DesignSeam>& onTo = {});
// The target cut along them.
void segmentDesignScene(DesignScene& scene);

// A design file read strictly (readDesignJson) and made into its scene: where the CLI and the design bench start.
std::unique_ptr<DesignScene> loadDesignScene(const std::string& designPath,
                                             const std::vector<std::string>& exampleDirs);

// The options the design's panels are built with at a resolution of `triangles`: its material, pressure,
// internal connections and seam names (for problems and panel names).
PatternBuildOptions designBuildOptions(const Design& design, int triangles);

// The design's flattened panels (buildPattern with designBuildOptions), what the optimizer starts from.
BuiltPattern buildDesignPattern(const DesignScene& scene, int triangles);

// sigma_s of each seam (Eq. 10), as PatternOptimizer takes them.
std::vector<double> designSeamWeights(const Design& design);

}  // namespace billow
