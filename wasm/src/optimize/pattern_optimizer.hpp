// Pattern optimization (Skouras et al. 2014, Sec. 5; DESIGN.md "Pattern optimization"): flat panels X whose
// inflated shape x(X) is as close as possible to the target, min_X E(x(X), X) with f(x, X) = 0 (Eq. 8).
//
// Reduced-space method: x(X) by the simulator (InflationSolver, warm-started from the last accepted x),
// placed rigidly where E is least (rigid_align.hpp); the gradient by the adjoint (adjoint.hpp); L-BFGS on X
// with a backtracking Armijo line search that re-solves equilibrium for every trial (so the objective of
// every accepted step is the true E(x(X), X) and decreases monotonically). Trial patterns with a flipped or
// degenerate rest triangle, a failed equilibrium, or a non-finite value are rejected; the last good state
// is never lost. The variables are the panel outlines, as a cut panel is only its outline: the interior
// follows them (harmonic_interior.hpp).
// Null spaces: each panel's 2D rigid motion leaves E unchanged (its gradient has no component there, so
// L-BFGS never moves along it); where a panel's interior cannot follow its outline (no harmonic interior),
// interior sliding is held by E_laplace (Eq. 13) and E_quality, and E_target weighs by current areas so sliding does
// not pay (objectives.hpp). Equal seam lengths: E_length as a penalty while iterating, then an exact projection
// (seam_projection.hpp) and one more equilibrium solve when the optimizer stops.
#pragma once
#include <Eigen/SparseCholesky>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "optimize/adjoint.hpp"
#include "optimize/harmonic_interior.hpp"
#include "optimize/objectives.hpp"
#include "optimize/optimization_target.hpp"
#include "optimize/rigid_align.hpp"
#include "optimize/seam_projection.hpp"
#include "simulate/inflate.hpp"

namespace billow {

// When a run ends; PatternOptimizer::stopReason checks these in this order.
struct OptimizeStopping {
  // Converged when the scaled reduced gradient ||dE/dX||_inf n D / 2 (about the largest residual moved per meter,
  // relative to the model size D) is below this.
  double gradientTolerance = 1e-6;
  // Converged when E decreased by less than relativeDecrease (relative) in each of the last stallIterations.
  double relativeDecrease = 1e-6;
  int stallIterations = 5;
  // Converged when no inflated vertex moved by more than windowMove x D over the last windowIterations
  // iterations (0: off): the long tail where the shape no longer changes visibly.
  int windowIterations = 0;
  double windowMove = 1e-3;
  // Converged when the best objective fell by less than windowDecrease (relative) over the window (0: off): the
  // line search's tail against unstable equilibria, where the RMS moves in its third digit.
  double windowDecrease = 0;
  // Converged when the best distance to the target (both ways, OptimizeRecord::bothWaysDistance) fell by less than
  // distanceDecrease (relative) over the last distanceWindow iterations (0: off). Unlike E it is comparable across
  // remeshings, so it can judge a run that remeshes every few iterations (sliding seams).
  int distanceWindow = 0;
  double distanceDecrease = 0.05;
  int maxIterations = 300;
  double maxMillis = 0;  // total budget over all steps (<= 0: none)
  // Stopped once the equilibrium solves (refused trials included) took this many Newton iterations in all (0: no
  // limit): a bound on the work, where maxMillis would depend on the machine.
  int maxNewtonIterations = 0;
  // Converged once the run's work reached this (0: no limit): Newton iterations of every solve plus kIterationWork
  // per iteration (its adjoint solve, alignment and closest points). The app's 1,600, about 9 s natively at 3,000
  // elements, left the cut panels as close as runs without it; the iterations past it refined the optimizer's own
  // mesh (bench/README.md "Stopping rules").
  int maxWork = 0;
  static constexpr int kIterationWork = 7;
};

// One L-BFGS iteration: its direction, its line search and the equilibrium solve of every trial.
struct OptimizeSearch {
  int memory = 8;  // L-BFGS pairs
  // H0 = gamma (I + b K)^-1, K the graph Laplacian along every panel outline and b = sobolevLength^2 (in mean
  // edge lengths): a Sobolev preconditioner, so the long, smooth changes of an outline, which move the inflated
  // shape most, are not left behind the short, stiff ones (0: H0 = gamma I).
  double sobolevLength = 4;
  double maxMoveEdges = 0.5;  // largest panel-vertex move of one step, in mean rest edge lengths
  int maxHalvings = 12;
  // A line search's first trial whose equilibrium is predicted (first order) to move some vertex more than this
  // many times as far as the largest prediction of the last three accepted steps is shortened to that (0:
  // never). Full steps predicted to move the balloon far settle higher about half the time, after 20-30 Newton
  // iterations (bench/README.md "The line search").
  double shapeStepGrowth = 5;
  // Every trial projected onto equal seam lengths, so the panels never drift far from sewable (one large
  // projection at the end can fold triangles). L-BFGS then searches along the tangent of that set (the recorded
  // gradient is the Lagrangian's): full steps left the projection a part across it to undo, which it did by the
  // shortest move, at the outlines' kinks, and the outlines grew teeth (bench/README.md "Tangent steps").
  bool projectEveryStep = true;
  // Each trial's equilibrium solve starts from the first-order prediction x + dx, dx = -K^-1 dg/dX dX, with the
  // adjoint's factorization of K (one more back-substitution), instead of from x.
  bool predictEquilibrium = true;
  // Before each solve, nonlinear Gauss-Seidel sweeps (gauss_seidel.hpp) down to a relative vertex force of
  // gaussSeidelThreshold: a step of the panels leaves parts of the sheet slack, which the pressure pushes out
  // vertex by vertex for less than Newton iterations cost (0 sweeps: off).
  int gaussSeidelSweeps = 10;
  double gaussSeidelThreshold = 0.1;
  // An unstable equilibrium (E(X) jumps: PatternOptimizer::resettle) is left for the one the balloon snaps into
  // at most this many times (0: the run stops there instead).
  int maxResettlings = 10;
  // Gauss-Newton directions instead of L-BFGS (on for sliding seams: slidingOptions): the shape terms' Gauss-Newton
  // matrix in X, J^T H J with J = dx/dX by the adjoint's factorization and the rigid placement eliminated, plus the
  // pattern terms' Hessian, damped by mu (I + b K) (Levenberg-Marquardt) and solved by preconditioned CG to a
  // relative residual gaussNewtonCgTolerance in at most gaussNewtonCg iterations (bench/README.md "Sliding seams").
  bool gaussNewton = false;
  int gaussNewtonCg = 30;
  double gaussNewtonCgTolerance = 0.1;
  // The rigid alignment's steps (rigid_align.hpp): plain Gauss-Newton, but for sliding seams (slidingOptions).
  RigidAlignOptions alignment;
};

// Remeshing (Sec. 5.3, pattern/remesh_pattern.hpp): every `every` iterations (0: never) the panels are meshed
// again from their outlines and the optimization goes on there (L-BFGS restarted), so it cannot fit its own
// mesh's discretization for long; at most maxRemeshings times.
struct OptimizeRemeshing {
  int every = 0;
  int maxRemeshings = 10;
  // Also meshed anew where the objective fell by less than a thousandth over the last stallIterations iterations on
  // this mesh (0: never; sliding seams: OptimizeSliding::stallIterations).
  int stallIterations = 0;
  // Held seams, at least coarseMinTriangles: a first phase on the panels meshed at coarseFactor x the design's
  // edge length (<= 1: none), until a stopping rule of that mesh ends it (the objective window over coarseWindow
  // iterations, not the fine mesh's 20) or coarseIterations (at most half the iterations) are spent; then the outlines
  // are meshed at the design's triangle count and the run goes on there. A coarse iterate costs a sixth, so the shapes
  // near the final one come sooner, and the fine phase starts off the folds the flattened panels' first steps meet
  // (bench/README.md "The coarse first phase").
  double coarseFactor = 2;
  int coarseMinTriangles = 1500;
  int coarseIterations = 30;
  int coarseWindow = 10;
  // E_cover's reach near the seams in the coarse phase (OptimizeWeights::coverReachAtSeams, of the target's
  // diagonal): a limb's tip past a front/back balloon's rim (the cow's hooves) is reached by growing the outline,
  // which the fine phase alone took some 20 iterations to do, the preview coming with it (bench/README.md "The
  // coarse first phase"); inside the panels the reach stays coverReach. The fine phase keeps coverReach everywhere.
  double coarseCoverReachAtSeams = 0.15;
  // Held seams: where the run stops, its outlines are meshed anew at the design's triangle count, as a maker's cut
  // panels are, and settled there, so the shape and distance the designer gets are the cut panels' (the optimizer's
  // own mesh can hold an equilibrium they do not have: a gusseted penguin's flippers stood out once cut). Where the
  // last iterate's cut panels snap into another shape, an earlier iterate's are tried (settleCutPanels).
  bool cutPanels = true;
};

// Sliding seams (Sec. 6, "Seam Placement": a seam of small weight moves to where the shape fits best). When some
// seam's sigma x weights.seam is below seamWeight (<= 0: never), only E_smooth holds its outline and
// slidingOptions changes the run: Gauss-Newton directions (they leave the symmetric first plateau sooner); the panels
// meshed anew every remeshEvery iterations, or where a mesh stalls; the outline regularizers and the step held at a
// physical length (tuned at an edge length of regularizerEdgeLength x the model size: at an edge length h that many
// times finer, sobolevLength and maxMoveEdges grow with 1/h and E_smooth along sliding seams with 1/h^2, else the
// outlines zig-zag below the edge length); maxIterations x iterationFactor and no objective window, which cannot tell
// the first plateau, before the seams move, from the end, but a distance window over distanceWindow iterations (two
// remeshings, longer than the first plateau under Gauss-Newton steps; bench/README.md "Sliding seams").
struct OptimizeSliding {
  double seamWeight = 0.1;
  double iterationFactor = 2;
  int distanceWindow = 40;
  int remeshEvery = 20;
  // A plateau that is this mesh's own (the gores' symmetric first layout) is left by a fresh mesh, not by waiting
  // for the schedule's next one (OptimizeRemeshing::stallIterations).
  int stallIterations = 5;
  double regularizerEdgeLength = 0.055;
};

struct OptimizeOptions {
  OptimizeWeights weights;
  ImlsOptions imls;
  InflateOptions inflate;  // equilibrium solves (tolerance: forces < 1e-5 relative, as the paper)
  OptimizeStopping stopping;
  OptimizeSearch search;
  OptimizeRemeshing remeshing;
  OptimizeSliding sliding;
  bool keepShapes = false;  // keep x of every accepted iterate (benchmarks: preview quality)
};

// Whether some seam slides (OptimizeSliding::seamWeight); seamWeights as PatternOptimizer's.
bool hasSlidingSeams(const OptimizeOptions& options, const std::vector<double>& seamWeights);
// The options a design with sliding seams is optimized with, at edge length h and model size D [m]: options
// unchanged when no seam slides.
OptimizeOptions slidingOptions(const OptimizeOptions& options, const std::vector<double>& seamWeights, double h,
                               double D);

// Stopped: at the iteration or time limit, before the optimizer settled.
enum class OptimizeState { Running, Converged, Stopped, Failed };
const char* toString(OptimizeState s);

// What the cut panels give (PatternOptimizer::checkCutPanels): a maker cuts the panels' outlines, and the sheet
// knows nothing of the solver's interior vertices.
struct CutPanelsCheck {
  bool ok = false;
  std::string message;                      // why not, when !ok
  double distanceRms = 0, distanceMax = 0;  // as OptimizeRecord's, of the outlines meshed anew and inflated
  double targetDistanceRms = 0, targetDistanceMax = 0;
  int elements = 0;
  double ms = 0;
  Pattern pattern;  // the cut panels, as settled (equal seam lengths)
};

struct OptimizeRecord {
  int iteration = 0;
  ObjectiveTerms terms;
  double objective = 0;
  double distanceRms = 0, distanceMax = 0;  // closest-point distance of outer vertices / bbox diagonal
  // The other way: of the target's vertices to the outer surface (targetCoverage), which sees what is left out.
  double targetDistanceRms = 0, targetDistanceMax = 0;
  // Those two over E_cover's sample of a fine target's vertices (during a run; the run's last records measure every
  // vertex).
  bool targetSampled = false;
  double seamMismatch = 0;   // max relative stitched-edge length difference
  double gradient = 0;       // scaled ||dE/dX||_inf (see gradientTolerance); its part tangent to equal seam lengths
                             // (the Lagrangian's) while every trial is projected onto them
  double stepLength = 0;     // line-search alpha
  double predictedMove = 0;  // the accepted trial's largest vertex move, predicted to first order [m] (0: none)
  int equilibriumIterations = 0;  // Newton iterations of the accepted solve
  double ms = 0;                  // since the optimizer was made
  bool projected = false;         // the final seam-length projection (not an L-BFGS step)
  bool remeshed = false;          // the panels were meshed again (not an L-BFGS step)
  // The inflated shape snapped to another equilibrium of the same panels (not an L-BFGS step; the objective
  // may rise): the one it was in proved unstable (see PatternOptimizer::resettle).
  bool resettled = false;
  // The line search came to this step after a trial snapped into another equilibrium: the balloon is at the
  // edge of a shape it can hold (a fold of its equilibria), which longer steps cross.
  bool snapLimited = false;
  // The step taken is a tenth or less of the search direction's own (shortened by the hold on its growth or by
  // the line search): like a snap-limited one, a step that cannot grow (the fish's last iterations alternate
  // between the two).
  bool cutShort = false;
  // The optimizer went back to its best iterate of this mesh at the end (not an L-BFGS step): resettlings had
  // left it at a worse equilibrium; or, before a second cut, to the earlier iterate whose cut panels did not snap.
  bool restored = false;
  // The run's end: its outlines meshed anew as they are cut and settled (OptimizeRemeshing::cutPanels); the record
  // before is the run's own mesh's last (of the iterate cut). A run has two where the first cut snapped and an
  // earlier iterate cut closer.
  bool cutPanels = false;
  // The distance to the target both ways as one figure: the RMS of the two ways' RMS.
  double bothWaysDistance() const {
    return std::sqrt(0.5 * (distanceRms * distanceRms + targetDistanceRms * targetDistanceRms));
  }
};

struct OptimizeTimings {
  double setupMs = 0, equilibriumMs = 0, alignMs = 0, adjointMs = 0, totalMs = 0;
  double directionMs = 0;  // the search directions: L-BFGS's two loops, or Gauss-Newton's CG with its solves
  int equilibriumSolves = 0, rejectedTrials = 0;
  int newtonIterations = 0;  // of every equilibrium solve, trials refused and snapped included
  int snappedTrials = 0;     // line-search trials abandoned on their way into another equilibrium
  int unsettledTrials = 0;   // line-search trials that ran out of their Newton budget without settling
  int resettlings = 0;       // see OptimizeRecord::resettled
  int remeshings = 0;        // remeshing steps taken
  double remeshMs = 0;       // their time, their equilibrium solves included
};

// How PatternOptimizer solves one equilibrium (line-search trials, resettling).
struct EquilibriumLimits {
  double alignTolerance = 1e-12;  // of the rigid alignment, x the model size (rigid_align.hpp)
  double alignDecrease = 0;       // the alignment's relativeDecrease (rigid_align.hpp)
  // > 0: a solve whose Newton iterate moves further than that from its start is abandoned (false, *snapped set,
  // x where it was)
  double snapLimit = 0;
  int maxNewton = 0;  // > 0: fewer Newton iterations than options.inflate's
};

class PatternOptimizer {
 public:
  // built: the flattened pattern (its `inflated` = the target positions, the first equilibrium's start).
  // seamWeights[s]: sigma_s of seam s (Eq. 10). Throws billow::Error when the pattern does not sew.
  PatternOptimizer(const TriMesh& target, const BuiltPattern& built, const std::vector<double>& seamWeights,
                   const OptimizeOptions& options = {});
  // The same on the target as another run measures it (made once per target: a suggestion's layouts share one, and
  // so do the app's runs on one target).
  PatternOptimizer(std::shared_ptr<const OptimizationTarget> target, const BuiltPattern& built,
                   const std::vector<double>& seamWeights, const OptimizeOptions& options = {});
  ~PatternOptimizer();

  // Up to maxIterations L-BFGS iterations or maxMillis (<= 0: none), whichever first; checked between
  // iterations (one iteration may overrun). The first call also solves the initial equilibrium.
  OptimizeState step(int maxIterations, double maxMillis = 0);

  OptimizeState state() const { return state_; }
  const std::string& message() const { return message_; }
  int iterations() const { return iteration_; }
  const Pattern& pattern() const { return pattern_; }  // panels X of the last accepted iterate
  const Vertices& inflated() const { return x_; }      // x(X), #V by 3 [m]
  const SewnMesh& mesh() const { return mesh_; }
  const PatternObjective& objective() const { return *objective_; }
  const OptimizationTarget& target() const { return *target_; }  // what the figures measure: its whole()
  const std::vector<OptimizeRecord>& history() const { return history_; }
  const std::vector<Vertices>& shapes() const { return shapes_; }  // when options.keepShapes
  // Per target vertex, its distance to the inflated outer surface [m], as the last record measured it for
  // targetDistanceRms; null once the shape has changed since, or where that record sampled a fine target. The app
  // streams every iterate's distances both ways, and so need not measure this way again.
  const Eigen::VectorXd* targetDistances() const;
  const OptimizeTimings& timings() const { return timings_; }
  const OptimizeOptions& options() const { return options_; }  // as used (slidingOptions)
  bool slidingSeams() const { return sliding_; }

  // Meshes the current panels anew from their outlines at edge length h (<= 0: the design's, at about its
  // triangle count), inflates them from the current shape, places them as the iterates are placed (after
  // the exact seam-length projection) and measures their distance to the target.
  CutPanelsCheck checkCutPanels(double h = 0) const;

  // For tests: E(x(X), X) and its reduced gradient dE/dX (every row of X, interior ones too) at pattern
  // coordinates X, solving equilibrium from the current x. Returns false when the equilibrium fails.
  bool evaluate(const Eigen::VectorXd& X, double* E, Eigen::VectorXd* grad, Vertices* x = nullptr);
  // For tests: the Gauss-Newton matrix of the shape terms times v at the current iterate (v's interior rows are
  // ignored; empty before the first step), and the pattern change dX that v makes (the interior following).
  Eigen::VectorXd gaussNewtonShapeProduct(const Eigen::VectorXd& v, Eigen::VectorXd* dX = nullptr) const;

 private:
  // Everything that follows from the (flattened or remeshed) pattern: mesh, objective, variables, the
  // preconditioner, the start x (its `inflated`); the L-BFGS memory is cleared.
  // The objective's weights follow the mesh's edge length where it is not the design's (the coarse phase).
  void setUp(const BuiltPattern& built, bool coarse = false);
  // With shared, the target as another run measures it; else made from target, within this run's time.
  PatternOptimizer(std::shared_ptr<const OptimizationTarget> shared, const BuiltPattern& built,
                   const std::vector<double>& seamWeights, const OptimizeOptions& options, const TriMesh& target);
  struct StopReason {
    OptimizeState state;
    const char* message;
    bool thisMesh = true;  // a rule judging this mesh alone (not the distance window, which spans meshes)
  };
  // Why the run ends before another iteration, by the options' stopping rules in this order: the gradient, the
  // stall, the window's move and decrease, the distance window, the iteration and time limits; nothing while it
  // goes on.
  std::optional<StopReason> stopReason() const;
  // Starts the window (options.stopping.windowIterations) anew once full, or after a remeshing changed the mesh.
  void slideWindow();
  // Whether the objective fell by less than kStallDecrease over the last options.remeshing.stallIterations
  // iterations, all on this mesh.
  bool stalledOnThisMesh() const;
  // The harmonic interior of the current panels (none when it cannot be built: every vertex is then a variable).
  void startInterior();
  // Projects the current panels onto equal stitched edge lengths; false (nothing changed) when that folds a
  // rest triangle.
  bool projectStart();
  // Meshes the panels again from their current outlines at the design's size (its edge length, corrected to about
  // its triangle count, since at one edge length the remesher gives 0.7-1.45 x the pattern builder's triangles)
  // and solves the new equilibrium; false (the old mesh kept) when that fails. recordIt: the new iterate goes into the
  // history (not for a trial cut of settleCutPanels). snapLimit > 0: a settle that moves a vertex further than that
  // from the carried shape is abandoned as snapped (false, *snapped set).
  bool remesh(bool recordIt = true, double snapLimit = 0, bool* snapped = nullptr);
  // The new mesh's equilibrium x (newton iterations, the remeshing started at t0 ms) as the current iterate, recorded
  // as a remeshing.
  void takeNewMesh(Vertices x, int newton, double t0, bool recordIt = true);
  // Leaves the coarse first phase for the flattened panels at the design's edge length (setUp, projected).
  void setUpFlattened();
  // Ends the coarse first phase (OptimizeRemeshing::coarseFactor): the outlines meshed at the design's triangle
  // count, else the flattened panels started again; false (the run failed) when neither settles.
  bool leaveCoarsePhase();
  // OptimizeRemeshing::cutPanels at the run's end (finish): the cut panels settled as the current iterate; where they
  // snap into another equilibrium, those of the earlier iterate (checkpoints_) whose cut comes closest.
  void settleCutPanels();
  // Per panel, the current inflated position x of each panel vertex (what remeshPattern carries over).
  std::vector<Vertices> panelInflated() const;
  // asCut: with the seam rods the panels X give on their own instead of the phase's fixed ones (the final solve).
  // False when it does not settle, x then where it stopped (snapped, or out of Newton iterations).
  bool solveEquilibrium(const Eigen::VectorXd& X, const Vertices& start, Vertices& x, int* newton, bool asCut = false,
                        const EquilibriumLimits& limits = {}, bool* snapped = nullptr);
  // Places x at its best rigid motion (rigid_align.hpp) to tolerance x the model size.
  void align(const Eigen::VectorXd& X, Vertices& x, double tolerance, double relativeDecrease = 0);
  void reducedGradient(const Eigen::VectorXd& X, const Vertices& x, Eigen::VectorXd& grad);
  // Where the equilibrium of panels X should be to first order from the current one (options.search.predictEquilibrium;
  // x_ when there is no factorization at the current iterate).
  Vertices predictEquilibrium(const Eigen::VectorXd& X) const;
  // The gradient in the optimization variables (the boundary rows).
  void variableGradient(const Eigen::VectorXd& X, const Vertices& x, Eigen::VectorXd& grad);
  void followBoundary(Eigen::VectorXd& X) const;  // interior rows from the boundary
  void toVariables(Eigen::VectorXd& v) const;     // zero what is not a variable (interior rows)
  double energy(const Eigen::VectorXd& X, const Vertices& x, ObjectiveTerms* terms) const;
  // E at a shape the optimizer takes as its state, E_cover's closest points searched for anew there first (they
  // walk from there until the next one): each trial is compared with the very E that is recorded, so the
  // recorded objective falls monotonically.
  double settledEnergy(const Eigen::VectorXd& X, const Vertices& x) const;
  bool iterate();
  // After a failed line search whose shortest trial still landed on a clearly worse shape (a jump, not a
  // slope): the current equilibrium is unstable, a tiny change of the panels makes the balloon snap into
  // another one. Takes that one (solved again at the current panels from where the trial ended) as the new
  // current state. False when it is no different.
  bool resettle(const Vertices& from);
  void finish(OptimizeState s, const std::string& message);
  // A run of no iterations (a suggested layout's first look, a cut check) only measures its panels' shape: no
  // gradient is taken, and its alignment needs no more than a trial's.
  bool measuresOnly() const { return options_.stopping.maxIterations == 0; }
  // The final iterate, cut: the panels projected onto equal seam lengths and settled (a note in message_ when
  // they do not settle). Returns the objective of the iterate it cut, as it was before the projection.
  double takeCutShape();
  // The panels X with equal seam lengths exactly, as they are cut, settled from x0 with the cut panels' own rods.
  struct CutShape {
    Eigen::VectorXd X;
    Vertices x;
    double E = INFINITY;
    int newton = 0;
  };
  std::optional<CutShape> cutShape(const Eigen::VectorXd& X0, const Vertices& x0);
  void record(double alpha, int newton, bool projected);
  // r's target figures for shape x (on the current mesh): over E_cover's sample during a run on a fine target, else
  // over every target vertex, whose distances targetDistances() then gives.
  void measureTarget(OptimizeRecord& r, const Vertices& x);
  bool rebuildRest(const Eigen::VectorXd& X, SewnMesh& mesh) const;
  // Why the flattened pattern did not settle, in the designer's words: a rest triangle it cannot take, or Newton.
  std::string unsettledReason() const;
  // Whether every panel's outline at X is a simple polygon (no two of its edges meet but neighbours).
  bool outlinesSimple(const Eigen::VectorXd& X) const;
  double elapsedMs() const;

  OptimizeOptions options_;
  bool sliding_ = false;  // some seam slides (options_ are slidingOptions)
  std::vector<double> seamWeights_;
  BuiltPattern built_;  // as flattened or last remeshed (its pattern's X is not kept up to date)
  std::shared_ptr<const OptimizationTarget> target_;
  std::vector<int> figureFaces_;  // per vertex, the target face closest to it at the last record (its first guess)
  std::unique_ptr<PatternObjective> objective_;
  std::unique_ptr<HarmonicInterior> interior_;
  std::vector<int> boundaryVertices_;                           // per panel
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> sobolev_;  // I + b K (options.search.sobolevLength)
  bool sobolevReady_ = false;
  Eigen::VectorXd precondition(const Eigen::VectorXd& v) const;  // (I + b K)^-1 v in the variables
  Eigen::SparseMatrix<double> sobolevMatrix_;                    // I + b K
  // Gauss-Newton's damping mu = damping_ x dampingScale_ (its scale set at the phase's first direction). damping_
  // carries over to a new mesh of the same panels: set back to 1 there, it held the next directions short, and the
  // sliding gores' way off their first plateau began only 6-10 iterations after the remeshing that leads to it.
  double damping_ = 1, dampingScale_ = 0;
  bool gaussNewtonStalled_ = false;  // the last Gauss-Newton step barely lowered E: the next is L-BFGS
  struct ShapeModel;
  // The Gauss-Newton model of the shape terms at the current iterate; null without the adjoint's factorization there.
  std::unique_ptr<ShapeModel> shapeModel() const;
  // The change of every pattern row that a change v of the variables makes (the interior following).
  Eigen::VectorXd patternChange(const Eigen::VectorXd& v) const;
  // J^T H J v and the pattern terms' Hessian v (central differences of their gradient), v in the variables.
  Eigen::VectorXd shapeProduct(const ShapeModel& model, const Eigen::VectorXd& v) const;
  Eigen::VectorXd patternProduct(const Eigen::VectorXd& v) const;
  // The damped Gauss-Newton direction at the current iterate and the decrease its model predicts; empty when there
  // is no model.
  Eigen::VectorXd gaussNewtonDirection(double* predicted);
  // v, or its part tangent to equal seam lengths at X when every trial is projected (OptimizeSearch::projectEveryStep).
  Eigen::VectorXd tangential(const Eigen::VectorXd& X, const Eigen::VectorXd& v) const;
  Pattern pattern_;
  SewnMesh mesh_;
  MembraneMaterial material_;
  Eigen::VectorXd X_, g_;
  Vertices x_;
  double E_ = 0;
  std::deque<double> predictedMoves_;  // of the last three accepted steps (OptimizeSearch::shapeStepGrowth)
  // The iterate of least objective on this phase's mesh (a resettling may raise the objective): finish() goes
  // back to it.
  struct Best {
    double E = INFINITY;
    Eigen::VectorXd X;
    Vertices x;
    Eigen::VectorXd g;
  } best_;
  // The last accepted iterates on this mesh (panels, shape, objective), newest last: where the final one's cut
  // panels snap into another equilibrium, an earlier one is cut instead (settleCutPanels).
  struct Checkpoint {
    Eigen::VectorXd X;
    Vertices x;
    double E = INFINITY;
  };
  std::deque<Checkpoint> checkpoints_;
  std::vector<Eigen::VectorXd> S_, Y_;  // L-BFGS pairs
  std::vector<OptimizeRecord> history_;
  std::vector<Vertices> shapes_;
  Eigen::VectorXd targetDistances_;  // targetDistances(), of the shape coverageShape_ (empty where sampled)
  Vertices coverageShape_;           // the last record's shape
  bool exactTarget_ = false;         // records measure the whole target (from finish on)
  OptimizeTimings timings_;
  OptimizeState state_ = OptimizeState::Running;
  std::string message_;
  int iteration_ = 0, stalled_ = 0;
  bool started_ = false;
  Vertices windowX_;       // x at the start of the current window (options.stopping.windowIterations)
  int windowStart_ = -1;   // its iteration
  int remeshedAt_ = -1;    // the iteration of the last remeshing (or attempt)
  double remeshMove_ = 0;  // the last remeshing's settle: its largest vertex move from the carried shape, over D
  std::shared_ptr<const SeamRods> rods_;  // the seam rods of this phase (setUp), their coefficient at its start
  // The phase's rods with their coefficient at panels X (seamRodCoefficientAt), and its derivative when given.
  std::shared_ptr<const SeamRods> rodsAt(const Eigen::VectorXd& X, Eigen::VectorXd* dcdX = nullptr) const;
  // The equilibrium solver of this phase's mesh, kept from solve to solve for its symbolic factorization.
  std::unique_ptr<InflationSolver> solver_;
  // The adjoint's factorization of K, and the (X, x) it was made at (predictEquilibrium).
  std::unique_ptr<PinnedStiffness> stiffness_;
  Eigen::VectorXd adjointPattern_;
  Vertices adjointShape_;
  double fineEdgeLength_ = 0;   // the design's edge length [m]
  int designTriangles_ = 0;     // and its triangle count (the flattened pattern's)
  bool coarsePhase_ = false;    // in the coarse first phase (OptimizeRemeshing::coarseFactor)
  BuiltPattern flattened_;      // the flattened panels at the design's edge length (and count), in the coarse phase
  bool projectTrials_ = false;  // options.search.projectEveryStep, unless projecting the flattened panels folds them
  double start_ = 0;            // steady-clock ms at construction
};

}  // namespace billow
