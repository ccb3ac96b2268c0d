// Suggested seam layouts (issue 27): seams for a target the designer has not patterned yet, each layout tried
// and scored by what matters to them: how close its optimized panels inflate to the target, at a coarse
// resolution, and how much there is to sew.
//
// A layout is made of plane sections (seams/plane_section.hpp), as the project's hand-made layouts are: g gores
// around one of the target's own axes (meridians from pole to pole, each a half of a plane through the axis, as a
// beach ball's; two gores: the plane's whole loop, halves) and k planes across it at equal shares of the surface
// (bands), g (k + 1) panels on a round shape, more where a plane cuts a limb on its own. Or of a front and a back
// sealed along the outline seen along one axis (seams/outline.hpp), as a foil balloon is made, with k bands across
// another: 2 (k + 1) panels, and k more where each band's loop is a front and a back seam joined inside by an internal
// connection (a flat shape's pillow held to its thickness). Or, on a shape with limbs, as a plush toy is patterned: a
// seam around each limb where it joins the body, the limb halved along its length and the body in halves or along its
// outline, and in bands. Or, on a shape with creases, along them (a box cushion's six sides, a letter's front, back and
// gusset strip; on a thin one, also held together inside by bands joined across it). A layout that keeps the target's
// mirror symmetry lays only what is its own mirror image across the symmetry plane.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "export/export_options.hpp"
#include "io/design_json.hpp"
#include "mesh/tri_mesh.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/pattern.hpp"
#include "seams/plane_section.hpp"
#include "suggest/creases.hpp"
#include "suggest/limbs.hpp"
#include "suggest/valleys.hpp"

namespace billow {

struct LayoutProposal {
  std::string name;                                  // the designer's words: "6 gores around the vertical axis"
  int axis = 1;                                      // the target's own axis the gores go around and the bands across
  int gores = 2;                                     // g panels around the axis
  int bands = 0;                                     // k planes across it
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // a point of the axis line
  // Three gores or more: each meridian's direction from the axis (unit, across it); its seam is the half of the
  // section by the plane through the axis and that direction on that side, from pole to pole.
  std::vector<Eigen::Vector3d> meridians;
  std::vector<SectionPlane> planes;  // two gores: the halving plane first; then the bands' planes
  // The bands' planes at the target's valleys across `axis` (a neck, a waist: suggest/valleys.hpp), not at even shares
  // of its surface.
  bool atValleys = false;
  // A front and a back sealed along the outline seen along this axis of the target's own (a foil balloon's two
  // pieces, seams/outline.hpp), in place of gores; -1: none.
  int outlineView = -1;
  // Along an outline: each band's loop laid as two seams, its front and its back piece, joined inside by an internal
  // connection (paper Sec. 3.2), which holds the two pieces as far apart as the target is thick there, where a pillow
  // would bulge. Only along a view the target is thin along (a hand, a cushion seen from the front).
  bool connected = false;
  // A seam around each of these limbs where it joins the body (suggest/limbs.hpp), each limb that a flat panel inside
  // that seam would not cover well halved along its length, and the body halved by planes[0] (with an outlineView, in
  // a front and a back along that outline instead) and in bands by the others (`bands` of them, across `axis`), each
  // laid on the body only; in place of gores.
  std::vector<Limb> limbs;
  // Seams along these creases of the target (suggest/creases.hpp), as a cushion or a gusseted letter is patterned: a
  // flat panel bulges everywhere but along its seams. With `planes`, those too (the halving plane); connected, on a
  // thin shape, each band plane's loop laid only as its piece on the front side and its piece on the back (across the
  // target's thinnest extent), from crease to crease, joined by an internal connection (a box cushion's baffle); in
  // place of gores.
  std::vector<Crease> creases;
};

struct LayoutRequest {
  int panels = 6;  // at most this many: layouts of g (k + 1) = panels - max(4, panels / 2) to panels on a round shape
  int symmetryAxis = -1;  // the target's own axis across whose mid-plane (of its box) the layout is its own mirror
                          // image; -1: any layout
  UpAxis up;              // which axis the names call vertical
};

// The design's mirror symmetry (its "symmetry": { "axis": "x" }, as the app keeps it: web/src/app/symmetry.js): the
// target's own axis whose box mid-plane it names, or -1.
int designSymmetryAxis(const Design& design);

// The target's own axis across whose box mid-plane the target is its own mirror image (its vertices reflected lie
// within `tolerance` x its diagonal of its surface, RMS), the closest of the three; -1 when none is.
int mirrorSymmetryAxis(const TriMesh& target, const SurfaceProjector& projector, double tolerance = 0.01);

// The scene the layouts for `design` on `target` (its own units; design.scale set) are laid on: the target's working
// copy (mesh/simplify.hpp), at the design's scale, without its seams; null where it has none (the layouts are laid on
// the target). They are compared at 1,000 triangles; their seams are carried back to the target (carriedSeams).
std::unique_ptr<DesignScene> suggestionScene(const Design& design, const TriMesh& target);

// The layouts worth trying for `request` on `target` (its own coordinates), each plane set once.
std::vector<LayoutProposal> proposeLayouts(const TriMesh& target, const LayoutRequest& request);

// The proposal's seams on `target`, of weight 1, control points about 2 % of the target's diagonal apart (the
// section tool's spacing): each meridian a seam from pole to pole (where the axis line leaves the surface first and
// last), meeting the others there, and the loops its plane cuts on its side around a limb; every loop of the other
// planes a closed seam, but that a connected proposal's band loop crossing its outline twice is two seams from
// crossing to crossing, whose internal connections go to `connections` (indices into the seams returned). Throws
// billow::Error (suggest.no-poles) where the meridians have no poles to meet at.
std::vector<DesignSeam> proposalSeams(const TriMesh& target, const LayoutProposal& proposal,
                                      std::vector<DesignConnection>* connections = nullptr);

// A layout's balloon as the designer sees it on its card: the outer surface of its evaluated shape (the optimizer's
// mesh and inflated positions, internal panels left out since they are not seen).
struct LayoutBalloon {
  Vertices positions;        // #V by 3 [m], in the target's own axes, placed on it as the optimizer placed the shape
  Triangles triangles;       // #F by 3, outward
  Eigen::VectorXd distance;  // #V signed distance to the target over its diagonal, positive outside (the app's colors)
  std::vector<int> panel;    // #F the panel each triangle belongs to
};

// What was done to a layout's sections so that every segment is a panel (evaluateLayout), for its description.
struct LayoutOpenings {
  int tubeCuts = 0;       // cuts that open a tube or a holed part
  int limbSeams = 0;      // sections across a part too big for its seam, around a limb
  int limbEndCuts = 0;    // cuts along a part too big for its seam, through its tip (a limb's end)
  int handleSeams = 0;    // closed seams around a handle of a part
  int grazingLoops = 0;   // loops of its own left out, that only grazed the shape (a tiny or thin part)
  int crossingLoops = 0;  // loops laid with the designer's left out, that crossed themselves (openIntoPanels)
  int acrossCuts = 0;     // cuts across a part that would overlap itself when laid flat

  void add(const LayoutOpenings& o) {
    tubeCuts += o.tubeCuts, limbSeams += o.limbSeams, handleSeams += o.handleSeams, grazingLoops += o.grazingLoops;
    crossingLoops += o.crossingLoops;
    acrossCuts += o.acrossCuts, limbEndCuts += o.limbEndCuts;
  }
};

struct LayoutEvaluation {
  bool ok = false;
  std::string problem;  // why it was not scored, in the designer's words
  // The layout's seams, with those that opened its segments into panels (evaluateLayout), and its internal
  // connections between them.
  std::vector<DesignSeam> seams;
  std::vector<DesignConnection> connections;
  LayoutOpenings opened;
  int panels = 0;         // internal panels included: they are cut too
  double seamLength = 0;  // [m], every seam once
  // After the coarse optimization, relative to the target's diagonal: each way's RMS, and the worse of the two, by
  // which layouts are ranked (one way alone reads close for a shape that leaves a limb out; the app's figure).
  double distance = 0, inflatedToTarget = 0, targetToInflated = 0;
  // The share of the sheet its cut pieces cover, nested as the design's cut file nests them (EvaluateOptions::cut;
  // optimized layouts only): how much material it wastes. Where a piece is wider than the sheet, on a sheet just wide
  // enough, whose width [mm] sheetNeeded gives (0 when every piece fits the design's sheet).
  double sheetUse = 0, sheetNeeded = 0;
  // What was done to its sections so that every segment is a panel (`opened`), and its internal connections, in the
  // designer's words ("2 cuts that open tubes, 1 seam around a limb"), empty when nothing was done.
  std::string description() const;
  int iterations = 0;
  double ms = 0;
  Pattern pattern;  // the optimized panels (coarse)
  // Those panels inflated (a first look: the flattened panels'), for the app's picture of the layout.
  LayoutBalloon balloon;
};

struct EvaluateOptions {
  int triangles = 1000;  // the coarse resolution the layouts are looked at and compared at
  // The design's fabrication settings (its "fabrication", io/export_options_json.hpp): the sheet and seam allowance its
  // pieces are nested with. Layouts whose pieces fit the sheet come first (layoutsRanked).
  ExportOptions cut;
  int maxIterations = 40;  // of the app's stopping rule; 0: the flattened panels' inflation alone, a first look
  // and at most this many Newton iterations per iteration asked for, in all its equilibrium solves together: a layout
  // whose balloon keeps walking (a limb swinging on wrinkled fabric) is compared where it stands rather than holding
  // up the suggestion (1,500 at 40 iterations; most layouts take 250-600, bench/README.md).
  double newtonPerIteration = 37.5;
  // Rounds of seams added where plane sections leave a segment that is not a panel (a tube around a limb, a hole,
  // a limb's end too big for its seam).
  int openingRounds = 3;
};

// Traces and segments `seams` on the scene's target (scene.design's seams and connections become them), adds the
// seams that open its segments into panels (never changing its first `fixedSeams`, the designer's own), and when
// every segment is a disk without a problem, flattens (a segment that would overlap itself when laid flat is cut
// across where its outline crosses itself, and the layout laid again), optimizes at the coarse resolution and
// measures.
LayoutEvaluation evaluateLayout(DesignScene& scene, const std::vector<DesignSeam>& seams, int fixedSeams,
                                const EvaluateOptions& options = {},
                                const std::vector<DesignConnection>& connections = {});

// `seams` with those that make every segment a panel where they leave one that is not: evaluateLayout's opening (cuts
// that open a tube, seams around a handle, ...; a seam that crosses itself mended, a loop that only grazes the shape
// left out; a cut across a panel that would overlap itself laid flat), what the Outline tool adds on a shape with
// handles. The first `fixedSeams` (the designer's) stay as they are. Ok when every segment is then a panel; else the
// first problem.
LayoutEvaluation openIntoPanels(DesignScene& scene, const std::vector<DesignSeam>& seams, int fixedSeams,
                                const std::vector<DesignConnection>& connections, int triangles);

// A first look at a proposal (evaluateLayout without an iteration): its seams laid after the designer's `kept`. Not
// ok, and why, where it cannot be laid (suggest.no-poles), makes more than `panelsAtMost` panels, or ends with the
// same seams as a layout `looked` at before (two proposals can, once the loops that only grazed the shape are gone).
// The layouts to optimize are the most promising looked at (lookPromise), each with the seams its look opened
// (evaluateLayout with all of them fixed).
LayoutEvaluation lookAtLayout(DesignScene& scene, const LayoutProposal& proposal, const std::vector<DesignSeam>& kept,
                              int panelsAtMost, const std::vector<std::vector<DesignSeam>>& looked,
                              EvaluateOptions options = {});

// How layouts rank, lower first, entry by entry, ties going to the one proposed first: an optimized layout by whether
// its pieces need a wider sheet than the design's, then how close it came (the worse way), then its seam length
// (sewing time); a first look by what it promises (lookPromise), then its seam length. The one rule for the command
// line (layoutsRanked, looksToOptimize) and the app, which sorts by the ranks the worker gives (`rank`, `lookRank`:
// web/src/app/suggest-run.js) and asks it which looks to optimize (chooseLooks).
using LayoutRank = std::array<double, 3>;
LayoutRank layoutRank(const LayoutEvaluation& layout);
LayoutRank lookRank(const LayoutEvaluation& look);

// The optimized layouts best first (indices into `layouts`; those not ok are left out).
std::vector<int> layoutsRanked(const std::vector<const LayoutEvaluation*>& layouts);

// What a first look promises, lower first: its target's side (targetToInflated). The optimizer pulls in where the
// balloon bulges past the target (the balloon's side) but cannot reach what the layout leaves out (the target's side),
// so the worse way of a first look ranks layouts the optimizer would bring close too low (bench/README.md "Suggested
// seam layouts": the penguin at 12 panels, 1.93 -> 1.53 %).
double lookPromise(const LayoutEvaluation& look);

// How many of the looks are optimized, most promising first, and at most how many of one family: six missed the
// closest layout on four of ten cases tried with every look optimized, eight on two; eight with at most three of a
// family on one (bench/README.md "Suggested seam layouts"). Many narrow gores look close at first but gain little.
constexpr int kOptimizedLayouts = 8, kOptimizedOfOneFamily = 3;

// The layouts' family: the same kind of layout around and across the same axes (gores, bands in halves or in gores,
// along an outline), whatever its counts and turn; as text, for the app (the look's `family`).
std::string layoutFamily(const LayoutProposal& proposal);

// A look as the choice of looks to optimize sees it.
struct LookChoice {
  LayoutRank rank;  // lookRank
  std::string family;
};

// Which looks to optimize (indices into `looks`): the best ranked first, at most `ofOneFamily` of one family, `count`
// in all.
std::vector<int> chooseLooks(const std::vector<LookChoice>& looks, int count = kOptimizedLayouts,
                             int ofOneFamily = kOptimizedOfOneFamily);
// The same for looked-at layouts (those not ok are skipped), families[i] being looks[i]'s.
std::vector<int> looksToOptimize(const std::vector<const LayoutEvaluation*>& looks,
                                 const std::vector<std::string>& families, int count = kOptimizedLayouts,
                                 int ofOneFamily = kOptimizedOfOneFamily);

}  // namespace billow
