// Pattern optimization (Skouras et al. 2014, Sec. 5; DESIGN.md "Pattern optimization"): flat panels X whose
// inflated shape x(X) is as close as possible to the target, min_X E(x(X), X) with f(x, X) = 0 (Eq. 8).
//
// Reduced-space method: x(X) by the simulator (InflationSolver, warm-started from the last accepted x),
// placed rigidly where E is least (rigid_align.hpp); the gradient by the adjoint (adjoint.hpp); L-BFGS on X
// with a backtracking Armijo line search that re-solves equilibrium for every trial (so the objective of
// every accepted step is the true E(x(X), X) and decreases monotonically). Trial patterns with a flipped or
// degenerate rest triangle, a failed equilibrium, or a non-finite value are rejected; the last good state
// is never lost. The variables are the panel outlines, the interior follows them (interiorFollowsBoundary).
// Null spaces: each panel's 2D rigid motion leaves E unchanged (its gradient has no component there, so
// L-BFGS never moves along it); with free interior vertices, interior sliding is held by E_laplace (Eq. 13)
// and E_quality, and E_target weighs by current areas so sliding does not pay (objectives.hpp).
// Equal seam lengths: E_length as a penalty while iterating, then an exact projection (seam_projection.hpp)
// and one more equilibrium solve when the optimizer stops.
#pragma once
#include <Eigen/SparseCholesky>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "optimize/adjoint.hpp"
#include "optimize/harmonic_interior.hpp"
#include "optimize/objectives.hpp"
#include "optimize/seam_projection.hpp"
#include "simulate/inflate.hpp"

namespace billow {

struct OptimizeOptions {
  OptimizeWeights weights;
  ImlsOptions imls;
  InflateOptions inflate;  // equilibrium solves (tolerance: forces < 1e-5 relative, as the paper)
  int maxIterations = 300;
  double maxMillis = 0;  // total budget over all steps (<= 0: none)
  // Converged when the scaled reduced gradient ||dE/dX||_inf n D / 2 (about the largest residual moved per
  // meter, relative to the model size D) is below this, or when E decreased by less than relativeDecrease
  // (relative) in each of the last `stallIterations` iterations.
  double gradientTolerance = 1e-6;
  double relativeDecrease = 1e-6;
  int stallIterations = 5;
  // Also converged when no inflated vertex moved by more than windowMove x the model size over the last
  // windowIterations iterations: the long, slow tail where the shape no longer changes visibly (0: off; the
  // app's setting is optimize/stopping_rule.hpp).
  int windowIterations = 0;
  double windowMove = 1e-3;
  // Also converged when the objective fell by less than windowDecrease (relative) over the last
  // windowIterations iterations (0: off): the line search's tail, where steps shrink to a few percent of the
  // L-BFGS step against unstable equilibria and the RMS moves in its third digit (elephant 14k: iterations
  // 90-131 took 140 s for 0.365 -> 0.363 %; bench/README.md).
  double windowDecrease = 0;
  // Before each equilibrium solve from the last shape, nonlinear Gauss-Seidel sweeps (smoothing.hpp) down to
  // a relative vertex force of warmSmoothingThreshold. A step of the panels changes rest lengths by up to a
  // few percent, ten times the foil's strain at equilibrium, so parts of the sheet start slack; those are
  // pushed out by the pressure, vertex by vertex, before Newton (teddy 3k: 10-12 Newton iterations and 15
  // factorizations per solve -> 6-7 and as many; elephant 14k: 1.11 -> 0.92 s per solve; bench/README.md).
  // 0 sweeps: off.
  int warmSmoothingSweeps = 10;
  double warmSmoothingThreshold = 0.1;
  // Each trial's equilibrium solve starts from the first-order prediction x + dx, dx = -K^-1 dg/dX dX, with
  // the adjoint's factorization of K at the current iterate (one more back-substitution), instead of from x.
  bool predictEquilibrium = true;
  int memory = 8;                // L-BFGS pairs
  double maxStep = 0.5;          // largest panel-vertex move of one step, in mean rest edge lengths
  int maxHalvings = 12;          // line search
  bool exactSeamLengths = true;  // project onto equal stitched edge lengths at the end
  // Also project the start and every trial step, so the panels never drift far from equal seam lengths
  // (a large final projection can fold triangles, and the last shape would then not be sewable).
  bool projectEveryStep = true;
  // With every trial projected: search along the tangent of the equal-seam-length set (L-BFGS on the
  // gradient's tangential part; the recorded gradient is then that part, the Lagrangian's gradient). Off: on
  // the three-gore sphere at 3k it goes on from 1.9 % to 1.19 % RMS in 150 iterations (cut panels 1.90 % ->
  // 1.49 %, teddy's outlines smoother), but the gores turn lumpy, with kinks no designer would cut
  // (bench/README.md "Tangent steps"); it waits for an outline regularizer that holds them.
  bool tangentSteps = false;
  // The seam-length projections (trials, tangent steps, the end) minimal in the outline smoothing's metric
  // I + b K (outlineSmoothing) instead of the Euclidean one: the correction spreads along the outline instead
  // of edge by edge, which left the outlines zig-zagging under tangent steps. Off: it costs one solve per
  // stitched edge pair and projection, and a dense (#X by #pairs) matrix, so it suits small designs only.
  bool smoothSeamProjection = false;
  bool keepShapes = false;  // keep x of every accepted iterate (benchmarks: preview quality)
  // The variables are the panel outlines and the interior follows them (harmonic_interior.hpp), as a cut panel
  // is only its outline. With free interior vertices (false: the paper's X, held by E_laplace and E_quality)
  // the optimizer's own RMS falls far lower, but the cut panels do not follow: it also fits where interior
  // vertices sit, which the cut sheet does not have (checkCutPanels; sphere3 1k: 0.52 % reported, 2.66 % cut,
  // against 1.97 % / 1.97 % with the interior following; teddy 3k: 0.27 % / 0.70 % against 0.56 % / 0.57 %).
  bool interiorFollowsBoundary = true;
  // L-BFGS initial inverse Hessian H0 = gamma (I + b K)^-1 with K the graph Laplacian along every panel
  // outline and b = outlineSmoothing^2 (in mean edge lengths): a smoothing (Sobolev) preconditioner, so the
  // long, smooth changes of a panel's outline that move the inflated shape most are not left to the last
  // iterations behind the short, stiff ones (0: H0 = gamma I).
  double outlineSmoothing = 4;
  // Remeshing (Sec. 5.3, pattern/remesh_pattern.hpp): when the smallest angle of a rest triangle falls below
  // this [degrees], every panel is meshed again from its current outline and the optimization goes on
  // from there (L-BFGS restarted); at most maxRemeshings times. Off (0) by default: with the interior following
  // the outlines the triangles keep their shape (smallest angle ~37 degrees on the three-gore sphere); with
  // free interior vertices they fall below 5-10 degrees within a few iterations, and the restarts cost more
  // than they give (the gallery sphere at 800 elements: 1.6 % RMS after 120 iterations with remeshing at
  // 5 degrees, 0.44 % without).
  double remeshBelowAngleDeg = 0;
  // Also every remeshEvery iterations (0: off): the optimizer then cannot fit its own mesh's discretization
  // for long (bench/README.md, session 13: three gores with free seams, 0.53 % on the optimizer's mesh against
  // 1.40 % for the same outlines meshed anew).
  int remeshEvery = 0;
  int maxRemeshings = 10;
  // Sliding seams (paper Sec. 6, "Seam Placement": a seam of small weight may move to where the shape fits
  // best; the paper's sphere is designed so). When some seam's sigma x weights.seam is below slidingSeamWeight
  // (<= 0: never), nothing but E_smooth holds its outline, and the optimizer changes how it works
  // (slidingOptions): steps tangent to equal seam lengths, the panels meshed anew every slidingRemeshEvery
  // iterations (as often as needed), and the outline regularizers and the step held at a physical length:
  // designed at an edge length of regularizerEdgeLength x the model size (the three-gore sphere at 800
  // elements), at an edge length h that many times finer outlineSmoothing and maxStep grow with 1/h and
  // E_smooth along the sliding seams (weights.slidingSmooth) with 1/h^2, else the outlines zig-zag below the
  // edge length and the seams take longer to slide (bench/README.md "Sliding seams").
  // Sliding takes longer: the layout first sits near the held-seam optimum for 40-50 iterations, then the
  // seams move and the shape keeps visibly improving for a few hundred (three gores at 3k: 0.46 % after 150,
  // 0.32 % after 300), so maxIterations is multiplied by slidingIterationFactor, and the objective window
  // (windowDecrease) is off: it cannot tell that first plateau from the end (the gallery's sliding sphere at
  // 1000 elements stopped there at 1.97 %, against 0.58 % after 150 iterations).
  double slidingSeamWeight = 0.1;
  double slidingIterationFactor = 2;
  int slidingRemeshEvery = 20;
  double regularizerEdgeLength = 0.055;
  // Coarse to fine (> 1: on): the panels are first meshed again at coarseFactor x the design's edge length
  // (about 1 / coarseFactor^2 of the elements, each iteration that much cheaper) and optimized there until a
  // stopping rule ends that phase or after coarseIterations; then they are meshed at the design's resolution
  // from the coarse panels' outlines (pattern/remesh_pattern.hpp) and the optimization goes on there.
  double coarseFactor = 1;
  int coarseIterations = 100;
  // An unstable equilibrium (E(X) jumps: see PatternOptimizer::resettle) is left for the one the balloon
  // snaps into at most this many times (0: the optimizer stops there instead).
  int maxResettlings = 10;
};

// Whether some seam slides (OptimizeOptions::slidingSeamWeight); seamWeights as PatternOptimizer's.
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
};

struct OptimizeRecord {
  int iteration = 0;
  ObjectiveTerms terms;
  double objective = 0;
  double distanceRms = 0, distanceMax = 0;  // closest-point distance of outer vertices / bbox diagonal
  // The other way: of the target's vertices to the outer surface (targetCoverage), which sees what is left out.
  double targetDistanceRms = 0, targetDistanceMax = 0;
  double seamMismatch = 0;  // max relative stitched-edge length difference
  double gradient = 0;      // scaled ||dE/dX||_inf (see gradientTolerance); its part tangent to equal seam lengths
                            // (the Lagrangian's) while every trial is projected onto them
  double stepLength = 0;    // line-search alpha
  int equilibriumIterations = 0;  // Newton iterations of the accepted solve
  double ms = 0;                  // since the optimizer was made
  bool projected = false;         // the final seam-length projection (not an L-BFGS step)
  bool remeshed = false;          // the panels were meshed again (not an L-BFGS step)
  bool coarse = false;            // an iterate of the coarse phase (OptimizeOptions::coarseFactor)
  // The inflated shape snapped to another equilibrium of the same panels (not an L-BFGS step; the objective
  // may rise): the one it was in proved unstable (see PatternOptimizer::resettle).
  bool resettled = false;
  // The optimizer went back to its best iterate of this mesh at the end (not an L-BFGS step): resettlings had
  // left it at a worse equilibrium.
  bool restored = false;
};

struct OptimizeTimings {
  double setupMs = 0, equilibriumMs = 0, alignMs = 0, adjointMs = 0, objectiveMs = 0, totalMs = 0;
  int equilibriumSolves = 0, rejectedTrials = 0;
  int snappedTrials = 0;  // line-search trials abandoned on their way into another equilibrium
  int resettlings = 0;    // see OptimizeRecord::resettled
  int remeshings = 0;     // remeshing steps taken
  double remeshMs = 0;    // their time, their equilibrium solves included
};

// How PatternOptimizer solves one equilibrium (line-search trials, resettling).
struct EquilibriumLimits {
  double alignTolerance = 1e-12;  // of the rigid alignment, x the model size (rigid_align.hpp)
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
  const std::vector<OptimizeRecord>& history() const { return history_; }
  const std::vector<Vertices>& shapes() const { return shapes_; }  // when options.keepShapes
  const OptimizeTimings& timings() const { return timings_; }
  const OptimizeOptions& options() const { return options_; }  // as used (slidingOptions)
  bool slidingSeams() const { return sliding_; }

  // Meshes the current panels anew from their outlines at edge length h (<= 0: the design's), inflates them
  // from the current shape, places them as the iterates are placed (after the exact seam-length projection)
  // and measures their distance to the target. With free interior vertices
  // (interiorFollowsBoundary = false) this can be far above the optimizer's own figure: the optimizer then
  // also gains from where it puts interior vertices, which a cut panel does not have (bench/README.md).
  CutPanelsCheck checkCutPanels(double h = 0) const;

  // For tests: E(x(X), X) and its reduced gradient dE/dX (every row of X, interior ones too) at pattern
  // coordinates X, solving equilibrium from the current x. Returns false when the equilibrium fails.
  bool evaluate(const Eigen::VectorXd& X, double* E, Eigen::VectorXd* grad, Vertices* x = nullptr);

 private:
  // Everything that follows from the (flattened or remeshed) pattern: mesh, objective, variables, the
  // preconditioner, the start x (its `inflated`); the L-BFGS memory is cleared.
  void setUp(const BuiltPattern& built);
  // The harmonic interior (options.interiorFollowsBoundary) of the current panels.
  void startInterior();
  // Projects the current panels onto equal stitched edge lengths; false (nothing changed) when that folds a
  // rest triangle.
  bool projectStart();
  // Meshes the panels again from their current outlines (options.remeshBelowAngleDeg) and solves the new
  // equilibrium; false (the old mesh kept) when that fails.
  bool remesh(double h);
  // Per panel, the current inflated position x of each panel vertex (what remeshPattern carries over).
  std::vector<Vertices> panelInflated() const;
  // Ends the coarse phase (OptimizeOptions::coarseFactor): the panels meshed at the design's resolution.
  // False when there was none (or the fine mesh failed: the coarse one is kept).
  bool refine();
  // asCut: with the seam rods the panels X give on their own instead of the phase's fixed ones (the final solve).
  bool solveEquilibrium(const Eigen::VectorXd& X, const Vertices& start, Vertices& x, int* newton, bool asCut = false,
                        const EquilibriumLimits& limits = {}, bool* snapped = nullptr);
  // Places x at its best rigid motion (rigid_align.hpp) to tolerance x the model size.
  void align(const Eigen::VectorXd& X, Vertices& x, double tolerance);
  void reducedGradient(const Eigen::VectorXd& X, const Vertices& x, Eigen::VectorXd& grad);
  // Where the equilibrium of panels X should be to first order from the current one (options.predictEquilibrium;
  // x_ when there is no factorization at the current iterate).
  Vertices predictEquilibrium(const Eigen::VectorXd& X) const;
  // The gradient in the optimization variables (the boundary rows with options.interiorFollowsBoundary).
  void variableGradient(const Eigen::VectorXd& X, const Vertices& x, Eigen::VectorXd& grad);
  void followBoundary(Eigen::VectorXd& X) const;  // interior rows from the boundary (interiorFollowsBoundary)
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
  void record(double alpha, int newton, bool projected);
  bool rebuildRest(const Eigen::VectorXd& X, SewnMesh& mesh) const;
  // Whether every panel's outline at X is a simple polygon (no two of its edges meet but neighbours).
  bool outlinesSimple(const Eigen::VectorXd& X) const;
  double elapsedMs() const;

  OptimizeOptions options_;
  bool sliding_ = false;  // some seam slides (options_ are slidingOptions)
  std::vector<double> seamWeights_;
  BuiltPattern built_;  // as flattened or last remeshed (its pattern's X is not kept up to date)
  std::unique_ptr<ImlsDistance> imls_;
  std::unique_ptr<PatternObjective> objective_;
  std::unique_ptr<HarmonicInterior> interior_;                   // options.interiorFollowsBoundary
  std::vector<int> boundaryVertices_;                            // per panel
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> smoother_;  // I + b K (options.outlineSmoothing)
  bool smoothing_ = false;
  Eigen::VectorXd precondition(const Eigen::VectorXd& v) const;  // (I + b K)^-1 v in the variables
  // v, or its part tangent to equal seam lengths at X when steps are (OptimizeOptions::tangentSteps).
  Eigen::VectorXd tangential(const Eigen::VectorXd& X, const Eigen::VectorXd& v) const;
  SeamMetric seamMetric() const;  // options.smoothSeamProjection's metric, or none
  Pattern pattern_;
  SewnMesh mesh_;
  MembraneMaterial material_;
  Eigen::VectorXd X_, g_;
  Vertices x_;
  double E_ = 0;
  // The iterate of least objective on this phase's mesh (a resettling may raise the objective): finish() goes
  // back to it.
  struct Best {
    double E = INFINITY;
    Eigen::VectorXd X;
    Vertices x;
    Eigen::VectorXd g;
  } best_;
  std::vector<Eigen::VectorXd> S_, Y_;  // L-BFGS pairs
  std::vector<OptimizeRecord> history_;
  std::vector<Vertices> shapes_;
  OptimizeTimings timings_;
  OptimizeState state_ = OptimizeState::Running;
  std::string message_;
  int iteration_ = 0, stalled_ = 0;
  bool started_ = false;
  Vertices windowX_;                      // x at the start of the current window (options.windowIterations)
  int windowStart_ = -1;                  // its iteration
  bool coarse_ = false;                   // in the coarse phase (OptimizeOptions::coarseFactor)
  int remeshedAt_ = -1;                   // the iteration of the last remeshing (or attempt)
  std::shared_ptr<const SeamRods> rods_;  // the seam rods of this phase (setUp), their coefficient at its start
  // The phase's rods with their coefficient at panels X (seamRodCoefficientAt), and its derivative when given.
  std::shared_ptr<const SeamRods> rodsAt(const Eigen::VectorXd& X, Eigen::VectorXd* dcdX = nullptr) const;
  // The equilibrium solver of this phase's mesh, kept from solve to solve for its symbolic factorization.
  std::unique_ptr<InflationSolver> solver_;
  // The adjoint's factorization of K, and the (X, x) it was made at (predictEquilibrium).
  std::unique_ptr<PinnedStiffness> stiffness_;
  Eigen::VectorXd stiffnessX_;
  Vertices stiffnessx_;
  double fineEdgeLength_ = 0;   // the design's edge length [m]
  bool projectTrials_ = false;  // options.projectEveryStep, unless projecting the flattened panels folds them
  double start_ = 0;            // steady-clock ms at construction
};

}  // namespace billow
