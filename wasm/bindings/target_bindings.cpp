// Embind for the target and its seams: a TargetSession holds the target with its topology, projector
// and geodesic solver (built once per target), traces seams and segments the target.
//
//   const t = new Module.TargetSession();                 // never throws
//   t.setTarget(positionsPtr, numVertices, indicesPtr, numTriangles)   -> {}
// Seams, internal connections, material and pressure are read by the design document's rules
// (io/design_json.hpp, as the CLI reads a design file): a bad one is refused with "design.bad-value" and a message
// naming the seam ("seam 3 \"belly\"") and the field ("seams[2].points[1]"), and so is a 3D point farther from the
// target than its size.
//
//   t.traceSeam(seamJson)  seam: { points: [{face, bary} | [x,y,z]], closed, smooth, name }
//     -> { positions: [x,y,z,...], faces: [...], barys: [...], controls: [x,y,z,...], controlIndices, length }
//        (faces/barys: a surface point per curve point; curve points of closed seams end at the start)
//   t.segment(seamsJson, optionsJson)   seams: [{ points, closed, weight, smooth }]; options: { up } (the target's
//     up axis, "+y" when absent: problems are placed as the target stands)
//     -> { vertices, triangles, segments: [{ area, isDisk, eulerCharacteristic, genus, loops, triangles, label
//          (Segment::labelPoint) }],
//          junctions: [{ position, segments }], problems: [{ code, severity, message, segment, seam, location }] }
//        and fills the cut mesh: cutPositionsPtr() #V*3 f64, cutTrianglesPtr() #F*3 i32, faceSegmentPtr() #F i32
//   t.buildPattern(seamsJson, optionsJson)
//     options: { scale (meters per target unit), triangles, pressure [Pa], up,
//                material: { name (a preset: foil, pvc, ripstop, tpu), thickness [m], youngs_modulus [Pa],
//                density [kg/m^3] },
//                connections: [[i, j], ...] or [{ seams: [i, j] }, ...] (internal connections: an internal
//                panel between seams i and j, indices into seamsJson; a seam's "name" is used in messages) }
//     -> { ok, pattern (billow-pattern JSON, "inflated" = the target shape; internal panels last, with
//          "internal": true), figures (internalPanels among them), problems ({ code, severity, message,
//          segment, seam, location (target units) }; a connection that cannot be built is one: code
//          "pattern.connection", severity "error", seam) }
//   t.startOptimization(seamsJson, optionsJson)  the same, and keeps a PatternOptimizer for:
//   t.optimizeStep(maxIterations, maxMillis) -> { state, iteration, message, remeshings, slidingSeams (some seam's
//                                                 weight lets it slide: OptimizeSliding::seamWeight),
//                                                 distanceRms, distanceMax, targetDistanceRms,
//                                                 targetDistanceMax (the target's to the shape),
//                                                 flattenedDistanceRms (of the flattened panels' equilibrium),
//                                                 seamMismatch, objective, ownMesh ({ distanceRms,
//                                                 targetDistanceRms } of the run's own mesh once it ended on its
//                                                 cut panels: OptimizeRemeshing::cutPanels) }
//   t.optimizedPattern() -> billow-pattern JSON of the current panels, "inflated" = their inflated shape
//   optimizedPositionsPtr() #V*3 f64 / optimizedVertices(): the current inflated shape (simulation vertices)
//   optimizedTrianglesPtr() #F*3 i32 / optimizedTriangles(), optimizedOuterPtr() #F i32: the optimizer's sewn mesh
//   t.optimizedDistance(scale, up): distanceToTarget of the optimizer's current shape on its outer surface (the
//     target's side of a fine target, which the run samples, measured whole at most a tenth of the time)
//   t.distanceToTarget(positionsPtr, numVertices, scale, surfacePtr, numSurfaceTriangles, up)
//     -> { rms, max, diagonal }
//     (rms and max of |d| over the diagonal of the target's box, over the corners of the #S x 3 int32 surface
//     triangles, e.g. the outer surface; over all points when there are none) and distancesPtr() #V f64: per
//     point [m], the signed distance to the target scaled by `scale` (positive outside); with surface triangles
//     also the other way (targetCoverage): targetRms, targetMax, uncovered: [{ area (fraction of the target's),
//     max, position (target units), radius, where, message, helps }] (uncoveredRegions, io/distance_json.hpp),
//     uncoveredDistance (the threshold, over the diagonal) and uncoveredTrianglesPtr() #U x 3 i32 (the regions'
//     target triangles as vertex indices, U = uncoveredTriangles(): what the inflated pane draws as left out)
//   Suggested seam layouts (suggest/seam_layouts.hpp), a layout a call so the worker reports progress and can stop:
//   t.mirrorSymmetry() -> { axis: "x" | "y" | "z" | null }: the target's own axis across whose box mid-plane it is
//     its own mirror image (mirrorSymmetryAxis)
//   t.suggestPrepare(optionsJson) -> { onCopy }: the scene suggestStart at the options' scale lays its layouts on,
//     made ahead (a fine target's simplified copy, suggestionScene, else the target's own)
//   t.suggestStart(keptSeamsJson, optionsJson)  kept: the designer's seams the layouts add to; options: buildPattern's
//     and { panels (2-40), symmetry ("x" | "y" | "z" | null: layouts that are their own mirror image across it),
//     maxIterations (the optimized layouts', default 40) } -> { proposals: [name, ...], optimize, ofOneFamily (how many
//     of the looks to optimize, at most how many of one family: looksToOptimize's rule) }
//   t.suggestLook(index) -> { ok, problem (also where it makes more panels than asked for), name,
//     description (the seams added or left out to make every part a panel, or ""),
//     panels, seamLength [m], sheetUse (optimized only: the share of the sheet its nested cut pieces cover, nested as
//     the options' fabrication settings give: the design's "fabrication"), sheetNeeded (optimized only: the sheet
//     width [mm] its widest piece needs where it is wider than that sheet, else 0),
//     distance (the worse way),
//     inflatedToTarget, targetToInflated (over the target's diagonal), rank (layoutRank: how the app orders the
//     layouts, lower first, entry by entry), lookRank (lookRank: the looks worth optimizing are the lowest, its first
//     entry what the look promises), family (layoutFamily; looks only), iterations, ms, seams (the kept ones first,
//     then the layout's, as the design document writes them), connections (its internal connections: [i, j] pairs
//     of indices into seams, as the app writes them), balloon (its inflated outer surface for the card's
//     picture, LayoutBalloon, null when not ok: { positions #V*3 [m] (about 5 significant digits; the frame the
//     inflated pane draws in), triangles #F*3 (outward), distance #V (signed, over the target's diagonal, positive
//     outside), panel #F }) }: a first look (the flattened panels inflated)
//   t.suggestOptimize(index, seamsJson, connectionsJson) -> the same for the layout with the seams and connections
//     its look ended with (from any session: several workers share a suggestion), optimized at the options'
//     resolution
//   t.openIntoPanels(seamsJson, optionsJson)  options: buildPattern's and fixed (how many of the seams, first, stay as
//     they are; all where not given) -> { ok, problem, description (what was added or left out, suggestLook's words),
//     seams (the fixed ones first, as they were, then the others as mended and those that make every part a panel) }
#include <emscripten/bind.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "guarded.hpp"
#include "heap_mesh.hpp"
#include "io/design_json.hpp"
#include "io/distance_json.hpp"
#include "io/export_options_json.hpp"
#include "io/pattern_json.hpp"
#include "optimize/optimized_pattern.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "optimize/stopping_rule.hpp"
#include "pattern/build_pattern.hpp"
#include "pattern/design_scene.hpp"
#include "seams/geodesic.hpp"
#include "seams/mesh_topology.hpp"
#include "seams/seam_curve.hpp"
#include "seams/surface_distance.hpp"
#include "seams/surface_point.hpp"
#include "segment/segmentation.hpp"
#include "suggest/seam_layouts.hpp"
#include "util/clock.hpp"
#include "util/memory_budget.hpp"

namespace {

using billow::bindings::guarded;
using nlohmann::json;

// x to `decimals` decimal places (negative: to tens, hundreds, ...), divided back by the power of ten so that it
// prints as the short decimal it is.
double roundedTo(double x, int decimals) {
  decimals = std::clamp(decimals, -20, 20);
  const double p = std::pow(10.0, std::abs(decimals));
  return decimals >= 0 ? std::round(x * p) / p : std::round(x / p) * p;
}

// A layout's balloon for its card (billow::LayoutBalloon) as flat arrays: positions to about five significant digits
// of its size and distances to 1e-5 of the target's diagonal, all a thumbnail shows, so that a layout's message stays
// small.
json balloonJson(const billow::LayoutBalloon& b) {
  const Eigen::Vector3d extent =
      b.positions.rows() ? Eigen::Vector3d(b.positions.colwise().maxCoeff() - b.positions.colwise().minCoeff())
                         : Eigen::Vector3d::Zero();
  const int decimals = extent.norm() > 0 ? 4 - int(std::floor(std::log10(extent.norm()))) : 5;
  json positions = json::array(), triangles = json::array(), distance = json::array();
  for (Eigen::Index i = 0; i < b.positions.size(); ++i) positions.push_back(roundedTo(b.positions.data()[i], decimals));
  for (Eigen::Index i = 0; i < b.triangles.size(); ++i) triangles.push_back(b.triangles.data()[i]);
  for (Eigen::Index i = 0; i < b.distance.size(); ++i) distance.push_back(roundedTo(b.distance[i], 5));
  return {{"positions", positions}, {"triangles", triangles}, {"distance", distance}, {"panel", b.panel}};
}

class TargetSession {
  struct Suggestion;  // a seam suggestion under way (below)

 public:
  TargetSession() = default;

  std::string setTarget(uintptr_t positions, int numVertices, uintptr_t indices, int numTriangles) {
    return guarded([&] {
      geodesic_.reset();
      projector_.reset();
      scaledGeodesic_.reset();
      optimizer_.reset();
      optimizationTarget_.reset();
      suggest_.reset();
      mesh_ = billow::bindings::meshFromHeap(positions, numVertices, indices, numTriangles);
      topology_ = billow::buildTopology(mesh_);
      projector_ = std::make_unique<billow::SurfaceProjector>(mesh_);
      geodesic_ = std::make_unique<billow::GeodesicSolver>(mesh_, topology_);
      return std::string("{}");
    });
  }

  std::string traceSeam(const std::string& seamJson) {
    return guarded([&] {
      requireTarget();
      billow::DesignSeam seam;
      billow::readDesignSeam(parse(seamJson), -1, seam);
      const billow::SeamSpec spec = billow::designSeamSpec(seam, -1, mesh_, *projector_);
      return curveJson(billow::buildSeamCurve(*geodesic_, *projector_, spec)).dump();
    });
  }

  std::string segment(const std::string& seamsJson, const std::string& optionsJson) {
    return guarded([&] {
      requireTarget();
      std::vector<billow::SeamCurve> curves;
      for (const billow::SeamSpec& spec : seamSpecs(billow::readDesignSeams(parse(seamsJson))))
        curves.push_back(billow::buildSeamCurve(*geodesic_, *projector_, spec));
      billow::SegmentationOptions options;
      options.up = readUp(parse(optionsJson));
      billow::Segmentation seg = billow::segmentTarget(mesh_, topology_, curves, options);
      cut_ = std::move(seg.mesh);
      faceSegment_ = seg.faceSegment;
      return segmentationJson(seg).dump();
    });
  }

  std::string buildPattern(const std::string& seamsJson, const std::string& optionsJson) {
    return guarded([&] { return patternJson(makePattern(readPatternRequest(seamsJson, optionsJson))).dump(); });
  }

  std::string startOptimization(const std::string& seamsJson, const std::string& optionsJson) {
    return guarded([&] {
      optimizer_.reset();
      streamTarget_.reset();
      requireOptimizationMemory(optionsJson);
      const PatternRequest request = readPatternRequest(seamsJson, optionsJson);
      const billow::BuiltPattern built = makePattern(request);
      // The app stops once the shape no longer changes visibly (the CLI goes on to full convergence).
      if (built.ok()) {
        if (!optimizationTarget_) optimizationTarget_ = std::make_shared<const billow::OptimizationTarget>(scaled_);
        optimizer_ = std::make_unique<billow::PatternOptimizer>(
            optimizationTarget_, built, billow::designSeamWeights(request.design), billow::appStoppingRule());
      }
      return patternJson(built).dump();
    });
  }

  std::string optimizeStep(int maxIterations, double maxMillis) {
    return guarded([&] {
      if (!optimizer_) throw billow::Error("optimize.not-started", "There are no panels to optimize yet.");
      const billow::OptimizeState state = optimizer_->step(maxIterations, maxMillis);
      json out = {{"state", billow::toString(state)},
                  {"iteration", optimizer_->iterations()},
                  {"message", optimizer_->message()},
                  {"remeshings", optimizer_->timings().remeshings},
                  {"slidingSeams", optimizer_->slidingSeams()}};
      if (!optimizer_->history().empty()) {
        const auto& r = optimizer_->history().back();
        out["distanceRms"] = r.distanceRms;
        out["distanceMax"] = r.distanceMax;
        out["targetDistanceRms"] = r.targetDistanceRms;
        out["targetDistanceMax"] = r.targetDistanceMax;
        out["seamMismatch"] = r.seamMismatch;
        out["objective"] = r.objective;
        out["flattenedDistanceRms"] = optimizer_->history().front().distanceRms;  // the flattened panels'
        const auto& h = optimizer_->history();
        const auto cut =
            std::find_if(h.rbegin(), h.rend(), [](const billow::OptimizeRecord& q) { return q.cutPanels; });
        if (cut != h.rend() && std::next(cut) != h.rend())  // the run's own mesh's last figures, before its cut panels
          out["ownMesh"] = {{"distanceRms", std::next(cut)->distanceRms},
                            {"targetDistanceRms", std::next(cut)->targetDistanceRms}};
      }
      return out.dump();
    });
  }

  std::string optimizedPattern() const {
    return guarded([&] {
      if (!optimizer_) throw billow::Error("optimize.not-started", "There are no panels to optimize yet.");
      return billow::writePatternJson(billow::optimizedPattern(*optimizer_));
    });
  }

  int optimizedVertices() const { return optimizer_ ? static_cast<int>(optimizer_->inflated().rows()) : 0; }
  // The optimizer's sewn mesh, to draw its streamed shapes: #F x 3 int32 (outward) and #F int32 (1: outer).
  int optimizedTriangles() const { return optimizer_ ? optimizer_->mesh().numTriangles() : 0; }
  uintptr_t optimizedTrianglesPtr() const {
    return optimizer_ ? reinterpret_cast<uintptr_t>(optimizer_->mesh().triangles.data()) : 0;
  }
  uintptr_t optimizedOuterPtr() {
    outer_.clear();
    if (optimizer_) outer_.assign(optimizer_->mesh().outer.begin(), optimizer_->mesh().outer.end());
    return reinterpret_cast<uintptr_t>(outer_.data());
  }
  uintptr_t optimizedPositionsPtr() const {
    return optimizer_ ? reinterpret_cast<uintptr_t>(optimizer_->inflated().data()) : 0;
  }

  // Refuses, before any work, a resolution whose optimization would not fit in memory ("memoryBudget" in
  // the options, in bytes, replaces the heap's room for tests).
  void requireOptimizationMemory(const std::string& optionsJson) const {
    const json o = parse(optionsJson);
    const double triangles = o.is_object() ? o.value("triangles", 3000.0) : 3000.0;
    const double budget = o.is_object() && o.contains("memoryBudget") && o["memoryBudget"].is_number()
                              ? o["memoryBudget"].get<double>()
                              : billow::availableBytes();
    billow::requireMemory(billow::optimizationBytes(static_cast<long long>(triangles), mesh_.F.rows()), budget,
                          "Optimizing panels of " + std::to_string(static_cast<long long>(triangles)) + " triangles",
                          "Choose a coarser panel resolution.");
  }

  // gusseted: the design has a gusset band (UncoveredRegion::gusseted).
  std::string distanceToTarget(uintptr_t positions, int numVertices, double scale, uintptr_t surface,
                               int numSurfaceTriangles, const std::string& up, bool gusseted) {
    return guarded([&] {
      requireTarget();
      if (!(scale > 0) || !std::isfinite(scale))
        throw billow::Error("pattern.bad-scale", "The target's size is not valid.");
      if (numVertices < 0 || numSurfaceTriangles < 0)
        throw billow::Error("seams.bad-input", "The shape has no points.");
      // In target units, on the target's own projector (a running optimization's scaled target stays).
      const billow::Vertices x =
          Eigen::Map<const billow::Vertices>(reinterpret_cast<const double*>(positions), numVertices, 3) / scale;
      if (!x.allFinite()) throw billow::Error("seams.bad-input", "The shape has invalid coordinates.");
      const billow::Triangles F =
          Eigen::Map<const billow::Triangles>(reinterpret_cast<const int*>(surface), numSurfaceTriangles, 3);
      if (F.size() && (F.minCoeff() < 0 || F.maxCoeff() >= numVertices))
        throw billow::Error("seams.bad-input", "The shape's surface refers to points it does not have.");
      return distanceJson(
          billow::measureDistance(mesh_, *projector_, x, F, readUp(json{{"up", up}}), nullptr, gusseted), scale);
    });
  }

  // distanceToTarget of the optimizer's current shape on its outer surface, the other way as its last record
  // measured it when the shape has not changed since (one closest-point search per target vertex less per
  // iterate streamed). Where the record sampled a fine target (PatternOptimizer::measureTarget), measuring every
  // target vertex again took a fifth of each iterate's time on a 47k-vertex scan in wasm (bench/README.md "What
  // the app streams"): the target's side is then measured whole at most a tenth of the time, and the iterates in
  // between show the last whole measurement's (at most a second old) beside their own side.
  std::string optimizedDistance(double scale, const std::string& up, bool gusseted) {
    return guarded([&] {
      requireTarget();
      if (!optimizer_) throw billow::Error("optimize.not-started", "There are no panels to optimize yet.");
      if (!(scale > 0) || !std::isfinite(scale))
        throw billow::Error("pattern.bad-scale", "The target's size is not valid.");
      const billow::Vertices x = optimizer_->inflated() / scale;
      const billow::Triangles outer = billow::outerTriangles(optimizer_->mesh());
      const billow::UpAxis upAxis = readUp(json{{"up", up}});
      if (const Eigen::VectorXd* measured = optimizer_->targetDistances()) {
        const Eigen::VectorXd targetDistances = *measured / scale;
        return distanceJson(billow::measureDistance(mesh_, *projector_, x, outer, upAxis, &targetDistances, gusseted),
                            scale);
      }
      if (!streamTarget_ || billow::msSince(streamTargetAt_) >= 9 * streamTargetMs_) {
        const billow::Clock::time_point start = billow::Clock::now();
        streamTarget_ = billow::measureDistance(mesh_, *projector_, x, outer, upAxis, nullptr, gusseted);
        streamTargetMs_ = billow::msSince(start), streamTargetAt_ = billow::Clock::now();
      } else {  // this shape's own side beside the last whole measurement's target side
        streamTarget_->signedDistances = billow::signedDistances(mesh_, *projector_, x);
        streamTarget_->inflatedToTarget =
            billow::summarizeDistances(streamTarget_->signedDistances, outer, streamTarget_->diagonal);
      }
      return distanceJson(*streamTarget_, scale);
    });
  }

  // distanceToTarget's figures; keeps the per-point distances [m] and the uncovered triangles for their pointers.
  std::string distanceJson(const billow::TwoWayDistance& d, double scale) {
    distances_ = scale * d.signedDistances;
    uncoveredTriangles_.clear();
    for (const billow::UncoveredRegion& r : d.uncovered)
      for (int f : r.triangles)
        for (int k = 0; k < 3; ++k) uncoveredTriangles_.push_back(mesh_.F(f, k));
    const double diagonal = scale * d.diagonal;
    json out = {{"rms", d.inflatedToTarget.rms}, {"max", d.inflatedToTarget.max}, {"diagonal", diagonal}};
    if (d.targetToInflated.distances.size()) {  // measured on a surface
      out["targetRms"] = d.targetToInflated.summary.rms;
      out["targetMax"] = d.targetToInflated.summary.max;
      out["uncoveredDistance"] = billow::kUncoveredDistance;
      out["uncovered"] = billow::uncoveredJson(d.uncovered);
    }
    return out.dump();
  }
  uintptr_t distancesPtr() const { return reinterpret_cast<uintptr_t>(distances_.data()); }
  uintptr_t uncoveredTrianglesPtr() const { return reinterpret_cast<uintptr_t>(uncoveredTriangles_.data()); }
  int uncoveredTriangles() const { return static_cast<int>(uncoveredTriangles_.size() / 3); }

  // What the worker sends to build panels: the design's seams, internal connections, material and pressure,
  // read as the CLI reads them from a design file, and the scale and resolution (see the top of this file).
  struct PatternRequest {
    billow::Design design;  // seams, connections, material, pressure, target.up
    double scale = 0;
    int triangles = 3000;
  };

  PatternRequest readPatternRequest(const std::string& seamsJson, const std::string& optionsJson) const {
    requireTarget();
    const json o = parse(optionsJson);
    if (!o.is_object()) throw billow::Error("pattern.bad-options", "The pattern options must be an object.");
    const auto number = [&](const char* key, double fallback) {
      if (!o.contains(key)) return fallback;
      return o[key].is_number() ? o[key].get<double>() : std::nan("");
    };
    PatternRequest r;
    r.scale = number("scale", std::nan(""));
    if (!(r.scale > 0) || !std::isfinite(r.scale))
      throw billow::Error("pattern.bad-scale", "The target's size is not valid.");
    const double triangles = number("triangles", r.triangles);
    if (!(triangles >= 50 && triangles <= 200000))
      throw billow::Error("pattern.bad-resolution", "The resolution must be between 50 and 200,000 triangles.");
    r.triangles = static_cast<int>(triangles);
    billow::Design& d = r.design;
    if (o.contains("pressure")) d.pressure = billow::readDesignPressure(o["pressure"], d.pressure);
    if (o.contains("material")) d.material = billow::readDesignMaterial(o["material"], d.material);
    d.seams = billow::readDesignSeams(parse(seamsJson));
    if (o.contains("connections")) d.connections = billow::readDesignConnections(o["connections"], d.seams.size());
    d.target.up = readUp(o);
    return r;
  }

  billow::BuiltPattern makePattern(const PatternRequest& request) {
    requireTarget();
    // Seam points are placed on the target as it is (surface points are scale-free), traced on the scaled one.
    const std::vector<billow::SeamSpec> specs = seamSpecs(request.design.seams);
    useScale(request.scale);
    std::vector<billow::SeamCurve> curves;
    for (const billow::SeamSpec& spec : specs)
      curves.push_back(billow::buildSeamCurve(*scaledGeodesic_, *scaledProjector_, spec));
    billow::SegmentationOptions segmentation;
    segmentation.up = request.design.target.up;
    const billow::Segmentation seg = billow::segmentTarget(scaled_, scaledTopology_, curves, segmentation);
    return billow::buildPattern(scaled_, seg, billow::designBuildOptions(request.design, request.triangles));
  }

  // The built pattern of the scaled target (scale_): problems are placed in the target's own units, as the
  // segmentation's are.
  json patternJson(const billow::BuiltPattern& built) const {
    json problems = json::array();
    for (const auto& p : built.problems) {
      const Eigen::Vector3d at = p.location / scale_;
      problems.push_back({{"code", p.code},
                          {"severity", p.severity},
                          {"message", p.message},
                          {"segment", p.segment},
                          {"seam", p.seam},
                          {"location", json::array({at.x(), at.y(), at.z()})}});
    }
    const auto& f = built.figures;
    return json({{"ok", built.ok()},
                 {"pattern", json::parse(billow::writePatternJson(built.pattern))},
                 {"problems", problems},
                 {"figures",
                  {{"panels", f.panels},
                   {"internalPanels", f.internalPanels},
                   {"triangles", f.triangles},
                   {"edgeLength", f.edgeLength},
                   {"maxSeamLengthMismatch", f.maxSeamLengthMismatch},
                   {"totalMs", f.totalMs}}}});
  }

  std::string mirrorSymmetry() const {
    return guarded([&] {
      requireTarget();
      const int axis = billow::mirrorSymmetryAxis(mesh_, *projector_);
      return json({{"axis", axis < 0 ? json(nullptr) : json(std::string(1, "xyz"[axis]))}}).dump();
    });
  }

  // The scene a suggestion at the options' size is laid on, made ahead while the designer picks the panels (a fine
  // target's copy takes a second or two): suggestStart at that size takes it on. { onCopy }.
  std::string suggestPrepare(const std::string& optionsJson) {
    return guarded([&] {
      auto s = std::make_unique<Suggestion>();
      takeScene(*s, readPatternRequest("[]", optionsJson));
      suggest_ = std::move(s);
      return json({{"onCopy", suggest_->onCopy}}).dump();
    });
  }

  std::string suggestStart(const std::string& keptSeamsJson, const std::string& optionsJson) {
    return guarded([&] {
      const PatternRequest request = readPatternRequest(keptSeamsJson, optionsJson);
      const json o = parse(optionsJson);
      auto s = std::make_unique<Suggestion>();
      takeScene(*s, request);
      s->keptOnTarget = request.design.seams;
      s->kept = s->onCopy ? billow::carriedSeams(s->keptOnTarget, ownSurface(), *s->scene) : s->keptOnTarget;
      s->evaluate.triangles = request.triangles;
      if (o.contains("fabrication") && o["fabrication"].is_object())
        s->evaluate.cut = billow::readExportOptionsJson(o["fabrication"]);
      if (o.contains("maxIterations") && o["maxIterations"].is_number_integer())
        s->evaluate.maxIterations = std::clamp(o["maxIterations"].get<int>(), 1, 300);
      billow::LayoutRequest layout;
      layout.up = request.design.target.up;
      layout.panels = o.contains("panels") && o["panels"].is_number_integer() ? o["panels"].get<int>() : 0;
      if (layout.panels < 2 || layout.panels > 40) throw billow::Error("suggest.bad-panels", "Ask for 2 to 40 panels.");
      if (o.contains("symmetry") && o["symmetry"].is_string()) {
        const std::string axis = o["symmetry"].get<std::string>();
        layout.symmetryAxis = axis == "x" ? 0 : axis == "y" ? 1 : axis == "z" ? 2 : -1;
      }
      s->panels = layout.panels;
      s->proposals = billow::proposeLayouts(s->scene->target, layout);
      json names = json::array();
      for (const billow::LayoutProposal& p : s->proposals) names.push_back(p.name);
      suggest_ = std::move(s);
      return json({{"proposals", names},
                   {"optimize", billow::kOptimizedLayouts},
                   {"ofOneFamily", billow::kOptimizedOfOneFamily}})
          .dump();
    });
  }

  // A first look at layout `index` of the suggestion started last. Looks that end alike are told apart by the page,
  // which sees every worker's (web/src/app/suggest-run.js).
  std::string suggestLook(int index) {
    return guarded([&] {
      Suggestion& s = startedSuggestion(index);
      const billow::LayoutEvaluation e =
          billow::lookAtLayout(*s.scene, s.proposals[index], s.kept, s.panels, {}, s.evaluate);
      json look = layoutJson(e, s.proposals[index].name, s);
      look["family"] = billow::layoutFamily(s.proposals[index]);
      return look.dump();
    });
  }

  // Layout `index` optimized, from the seams its look ended with (any worker's: several share a suggestion), as they
  // lie on the scene the suggestion is laid on (a look's `copySeams` where it has them).
  std::string suggestOptimize(int index, const std::string& seamsJson, const std::string& connectionsJson) {
    return guarded([&] {
      Suggestion& s = startedSuggestion(index);
      const std::vector<billow::DesignSeam> seams = billow::readDesignSeams(parse(seamsJson));
      if (seams.empty()) throw billow::Error("suggest.no-seams", "That layout has no seams to optimize.");
      const std::vector<billow::DesignConnection> connections =
          billow::readDesignConnections(parse(connectionsJson), seams.size());
      const billow::LayoutEvaluation e =
          billow::evaluateLayout(*s.scene, seams, int(seams.size()), s.evaluate, connections);
      return layoutJson(e, s.proposals[index].name, s).dump();
    });
  }

  // The seams with those that make every segment a panel where they leave one that is not (suggest/seam_layouts.hpp
  // openIntoPanels), the first `fixed` (options; all where not given) as they were -> { ok, problem, description,
  // seams }.
  std::string openIntoPanels(const std::string& seamsJson, const std::string& optionsJson) {
    return guarded([&] {
      PatternRequest request = readPatternRequest(seamsJson, optionsJson);
      billow::Design design = std::move(request.design);
      design.scale = request.scale;
      const std::vector<billow::DesignSeam> seams = std::move(design.seams);
      const std::vector<billow::DesignConnection> connections = std::move(design.connections);
      design.seams.clear(), design.connections.clear();
      const json o = parse(optionsJson);
      const int fixed = o.contains("fixed") && o["fixed"].is_number_integer()
                            ? std::clamp(o["fixed"].get<int>(), 0, int(seams.size()))
                            : int(seams.size());
      const std::unique_ptr<billow::DesignScene> scene = billow::makeTargetScene(design, mesh_);
      const billow::LayoutEvaluation e = billow::openIntoPanels(*scene, seams, fixed, connections, request.triangles);
      return json({{"ok", e.ok},
                   {"problem", e.problem},
                   {"description", e.description()},
                   {"seams", laidSeamsJson(e.seams, e.ok ? size_t(fixed) : e.seams.size())}})
          .dump();
    });
  }

  int cutVertices() const { return static_cast<int>(cut_.V.rows()); }
  int cutTriangles() const { return static_cast<int>(cut_.F.rows()); }
  uintptr_t cutPositionsPtr() const { return reinterpret_cast<uintptr_t>(cut_.V.data()); }
  uintptr_t cutTrianglesPtr() const { return reinterpret_cast<uintptr_t>(cut_.F.data()); }
  uintptr_t faceSegmentPtr() const { return reinterpret_cast<uintptr_t>(faceSegment_.data()); }

 private:
  static json parse(const std::string& text) {
    json j = json::parse(text, nullptr, false);
    if (j.is_discarded()) throw billow::Error("seams.bad-input", "The seam description is not valid JSON.");
    return j;
  }

  // The options' "up" (the design's target.up) by the design reader's rule. Left out, null or "" (how embind
  // passes a string the page left out), it is Y up, as for a design without one.
  static billow::UpAxis readUp(const json& options) {
    if (!options.is_object() || !options.contains("up")) return {};
    const json& up = options["up"];
    if (up.is_null() || (up.is_string() && up.get<std::string>().empty())) return {};
    return billow::readDesignUp(up);
  }

  void requireTarget() const {
    if (!geodesic_) throw billow::Error("seams.no-target", "Load a target before drawing seams.");
  }

  // The target in its own units, as seams are laid on it.
  billow::SeamSurface ownSurface() const {
    requireTarget();
    return {mesh_, 1.0, topology_, *projector_, *geodesic_};
  }

  // The seams as the app's design holds them: from seam `from` on, an open seam's end that lies on another seam's line
  // names it ("on", design_scene.hpp openSeamEndHosts), so that the app keeps it there as that seam is edited.
  json laidSeamsJson(const std::vector<billow::DesignSeam>& seams, size_t from) const {
    const std::vector<std::array<int, 2>> hosts = billow::openSeamEndHosts(seams, ownSurface(), from);
    json out = json::array();
    for (size_t i = 0; i < seams.size(); ++i) {
      json seam = billow::designSeamJson(seams[i]);
      for (size_t e = 0; e < 2; ++e)
        if (hosts[i][e] >= 0) seam["points"][e ? seam["points"].size() - 1 : 0]["on"] = hosts[i][e];
      out.push_back(std::move(seam));
    }
    return out;
  }

  // The seams' control points on the target (io/design_json.hpp designSeamSpecs: faces it has, 3D points near it).
  std::vector<billow::SeamSpec> seamSpecs(const std::vector<billow::DesignSeam>& seams) const {
    return billow::designSeamSpecs(seams, mesh_, *projector_);
  }

  static json curveJson(const billow::SeamCurve& c) {
    json positions = json::array(), faces = json::array(), barys = json::array(), controls = json::array();
    for (const auto& p : c.points) {
      for (int k = 0; k < 3; ++k) positions.push_back(p.position[k]);
      faces.push_back(p.point.face);
      for (int k = 0; k < 3; ++k) barys.push_back(p.point.bary[k]);
    }
    for (int i : c.controlIndices)
      for (int k = 0; k < 3; ++k) controls.push_back(c.points[i].position[k]);
    return {{"positions", positions},
            {"faces", faces},
            {"barys", barys},
            {"controls", controls},
            {"controlIndices", c.controlIndices},
            {"length", c.length}};
  }

  static json segmentationJson(const billow::Segmentation& seg) {
    auto vec = [](const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); };
    json segments = json::array(), problems = json::array(), junctions = json::array();
    for (const auto& s : seg.segments)
      segments.push_back({{"area", s.area},
                          {"isDisk", s.isDisk},
                          {"eulerCharacteristic", s.eulerCharacteristic},
                          {"genus", s.genus},
                          {"loops", s.loops.size()},
                          {"triangles", s.triangles.size()},
                          {"label", vec(s.labelPoint)}});
    for (const auto& p : seg.problems)
      problems.push_back({{"code", p.code},
                          {"severity", p.severity},
                          {"message", p.message},
                          {"segment", p.segment},
                          {"seam", p.seam},
                          {"location", vec(p.location)}});
    for (const auto& j : seg.junctions) junctions.push_back({{"position", vec(j.position)}, {"segments", j.segments}});
    return {{"vertices", seg.mesh.numVertices()},
            {"triangles", seg.mesh.numTriangles()},
            {"segments", segments},
            {"junctions", junctions},
            {"problems", problems},
            {"ok", seg.ok()}};
  }

  // The target in meters for pattern building (cached per scale; seams are surface points, scale-free).
  void useScale(double scale) {
    if (scaledGeodesic_ && scale == scale_) return;
    optimizer_.reset();  // it refers to the scaled target
    optimizationTarget_.reset();
    scaledGeodesic_.reset();
    scaled_ = mesh_;
    scaled_.V *= scale;
    scaledTopology_ = billow::buildTopology(scaled_);
    scaledProjector_ = std::make_unique<billow::SurfaceProjector>(scaled_);
    scaledGeodesic_ = std::make_unique<billow::GeodesicSolver>(scaled_, scaledTopology_);
    scale_ = scale;
  }

  // A layout as the page takes it: `seams` on the target; laid on a copy of it, also `copySeams` as they lie there,
  // which suggestOptimize takes back. The designer may take a layout only looked at as well as an optimized one, so
  // both name the seams their open seams' ends lie on (a trace of its seams: a few ms beside the look's own work).
  json layoutJson(const billow::LayoutEvaluation& e, const std::string& name, const Suggestion& s) const {
    json copySeams = json::array();
    const std::vector<billow::DesignSeam> onTarget =
        s.onCopy && e.ok ? billow::carriedSeams(e.seams, *s.scene, ownSurface(), s.keptOnTarget) : e.seams;
    const json seams = e.ok ? laidSeamsJson(onTarget, s.keptOnTarget.size()) : json::array();
    if (s.onCopy)
      for (const billow::DesignSeam& seam : e.seams) copySeams.push_back(billow::designSeamJson(seam));
    json connections = json::array();
    for (const billow::DesignConnection& c : e.connections) connections.push_back(c.seams);
    json out({{"ok", e.ok},
              {"problem", e.problem},
              {"name", name},
              {"description", e.description()},
              {"panels", e.panels},
              {"seamLength", e.seamLength},
              {"sheetUse", e.sheetUse},
              {"sheetNeeded", e.sheetNeeded},
              {"distance", e.distance},
              {"inflatedToTarget", e.inflatedToTarget},
              {"targetToInflated", e.targetToInflated},
              {"rank", billow::layoutRank(e)},
              {"lookRank", billow::lookRank(e)},
              {"iterations", e.iterations},
              {"ms", e.ms},
              {"seams", seams},
              {"connections", e.ok ? connections : json::array()},
              {"balloon", e.ok ? balloonJson(e.balloon) : json(nullptr)}});
    if (s.onCopy && e.ok) out["copySeams"] = copySeams;
    return out;
  }

  // A suggestion under way: the target scaled as asked (and its copy), the designer's seams kept, the layouts.
  struct Suggestion {
    // The scene the layouts are laid on: a fine target's simplified copy (suggest/seam_layouts.hpp suggestionScene),
    // else the target's own.
    std::unique_ptr<billow::DesignScene> scene;
    bool onCopy = false;
    std::vector<billow::DesignSeam> keptOnTarget, kept;  // the designer's seams kept, on the target and as laid
    std::vector<billow::LayoutProposal> proposals;
    billow::EvaluateOptions evaluate;
    int panels = 0;  // at most, as asked
  };
  std::unique_ptr<Suggestion> suggest_;
  // The scene of the last suggestion (or preparation) at the request's size serves again (the same target: a new one
  // resets the suggestion), the designer's settings taken anew without their seams, which go to the scene with each
  // layout: another panel count starts at once. Else a fine target's simplified copy, or the target itself.
  void takeScene(Suggestion& s, const PatternRequest& request) {
    std::unique_ptr<Suggestion> last = std::move(suggest_);
    billow::Design design = request.design;
    design.seams.clear(), design.connections.clear();
    design.scale = request.scale;
    if (last && last->scene->scale == design.scale) {
      s.scene = std::move(last->scene), s.onCopy = last->onCopy;
      s.scene->design = design;
      return;
    }
    last.reset();
    s.scene = billow::suggestionScene(design, mesh_);
    s.onCopy = s.scene != nullptr;
    if (!s.onCopy) s.scene = billow::makeTargetScene(design, mesh_);
  }
  Suggestion& startedSuggestion(int index) {
    if (!suggest_ || index < 0 || index >= int(suggest_->proposals.size()))
      throw billow::Error("suggest.not-started", "There are no layouts to try yet.");
    return *suggest_;
  }
  billow::TriMesh mesh_, cut_, scaled_;
  billow::MeshTopology scaledTopology_;
  std::unique_ptr<billow::SurfaceProjector> scaledProjector_;
  std::unique_ptr<billow::GeodesicSolver> scaledGeodesic_;
  double scale_ = 0;
  std::unique_ptr<billow::PatternOptimizer> optimizer_;
  // scaled_ as the optimizer measures it (a fine target's working copy among it), made by the first run at this
  // scale and kept for the next.
  std::shared_ptr<const billow::OptimizationTarget> optimizationTarget_;
  billow::MeshTopology topology_;
  std::unique_ptr<billow::SurfaceProjector> projector_;
  std::unique_ptr<billow::GeodesicSolver> geodesic_;
  std::vector<int> faceSegment_;
  Eigen::VectorXd distances_;            // of the last distanceToTarget
  std::vector<int> uncoveredTriangles_;  // the parts of the target that shape leaves out: #U x 3 vertex indices
  std::vector<int> outer_;               // optimizedOuterPtr's copy
  // optimizedDistance's last whole measurement on a sampled run (its target's side is shown until the next, its own
  // side the latest shape's), when it ended and what it took [ms].
  std::optional<billow::TwoWayDistance> streamTarget_;
  billow::Clock::time_point streamTargetAt_;
  double streamTargetMs_ = 0;
};

}  // namespace

EMSCRIPTEN_BINDINGS(billow_target) {
  emscripten::class_<TargetSession>("TargetSession")
      .constructor<>()
      .function("setTarget", &TargetSession::setTarget)
      .function("traceSeam", &TargetSession::traceSeam)
      .function("segment", &TargetSession::segment)
      .function("buildPattern", &TargetSession::buildPattern)
      .function("startOptimization", &TargetSession::startOptimization)
      .function("optimizeStep", &TargetSession::optimizeStep)
      .function("optimizedPattern", &TargetSession::optimizedPattern)
      .function("optimizedVertices", &TargetSession::optimizedVertices)
      .function("optimizedPositionsPtr", &TargetSession::optimizedPositionsPtr)
      .function("optimizedTriangles", &TargetSession::optimizedTriangles)
      .function("optimizedTrianglesPtr", &TargetSession::optimizedTrianglesPtr)
      .function("optimizedOuterPtr", &TargetSession::optimizedOuterPtr)
      .function("cutVertices", &TargetSession::cutVertices)
      .function("cutTriangles", &TargetSession::cutTriangles)
      .function("cutPositionsPtr", &TargetSession::cutPositionsPtr)
      .function("cutTrianglesPtr", &TargetSession::cutTrianglesPtr)
      .function("faceSegmentPtr", &TargetSession::faceSegmentPtr)
      .function("distanceToTarget", &TargetSession::distanceToTarget)
      .function("optimizedDistance", &TargetSession::optimizedDistance)
      .function("distancesPtr", &TargetSession::distancesPtr)
      .function("uncoveredTrianglesPtr", &TargetSession::uncoveredTrianglesPtr)
      .function("uncoveredTriangles", &TargetSession::uncoveredTriangles)
      .function("mirrorSymmetry", &TargetSession::mirrorSymmetry)
      .function("suggestPrepare", &TargetSession::suggestPrepare)
      .function("suggestStart", &TargetSession::suggestStart)
      .function("suggestLook", &TargetSession::suggestLook)
      .function("suggestOptimize", &TargetSession::suggestOptimize)
      .function("openIntoPanels", &TargetSession::openIntoPanels);
}
