#include "optimize/pattern_optimizer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "flatten/flatten_boundary.hpp"
#include "optimize/adjoint.hpp"
#include "optimize/rest_derivatives.hpp"
#include "optimize/rigid_align.hpp"
#include "optimize/seam_projection.hpp"
#include "optimize/stopping_rule.hpp"
#include "pattern/remesh_pattern.hpp"
#include "remesh/panel_mesher.hpp"
#include "seams/surface_distance.hpp"
#include "simulate/gauss_seidel.hpp"
#include "simulate/initial_shape.hpp"
#include "util/error.hpp"

namespace billow {

namespace {
double nowMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A line-search trial needs only E, which settles long before the alignment's step does; the accepted trial is
// aligned to the default tolerance before its gradient.
constexpr double kTrialAlignment = 1e-6, kTrialAlignDecrease = 1e-9;
// A refused trial whose equilibrium lies this far (x the model size) from the predicted one, and further than 1.5
// times the predicted move, snapped into another equilibrium.
constexpr double kSnapDistance = 1e-2;
constexpr int kResettleNewton = 100;
// A trial solve may take this many times the median Newton iterations of the recent accepted solves (at least
// kTrialNewtonFloor) before it counts as one that does not settle: in wasm a fb-blub trial took 1,000 (10 s)
// where accepted ones take 5-30.
constexpr int kTrialNewtonFactor = 5, kTrialNewtonFloor = 50;
// Trials in a row that run out of that budget unsettled: the balloon's equilibrium chatters near this pattern
// (wrinkled fabric changing regime, the residual alternating between 0.02 and 0.2 for the whole budget), and shorter
// steps do not settle either, each costing the whole budget. It is taken as a snap: the shape the balloon moves to
// (resettle), else the line search ends (bench/README.md "Trials that do not settle").
constexpr int kUnsettledTrials = 5;
// The largest move of the predicted equilibrium, in multiples of the panels' largest move, that is trusted.
constexpr double kPredictionReach = 1000;
// A Gauss-Newton step that lowered E by less than this (relative) is followed by an L-BFGS step.
constexpr double kGaussNewtonStall = 1e-4;
// OptimizeRemeshing::stallIterations: a mesh on which E fell by less than this (relative) over them is stalled.
constexpr double kStallDecrease = 1e-3;
// A cut whose objective on its new mesh exceeds its own mesh's by this factor snapped (settleCutPanels: fb-spot's
// snapped cuts 1.34-1.70, those that keep their shape 0.99-1.17 on the bench's designs), unless it settled within
// kCutSnapMove (x the model size) of the shape it was cut from: a new mesh's own offset, not another shape (the
// elephant's cuts 1.26-1.34 and 1.9-2.2 %, the snapped ones 6.7-25 %); then the iterates this many back are tried,
// the last 33 kept.
constexpr double kCutSnapRatio = 1.25, kCutSnapMove = 0.03;
// A cut's settle that moves a vertex further than this (x the model size) from the shape it was cut from has snapped
// (beyond every cut that kept its shape, 0.2-6.8 %), and its walk into the other shape is not finished: fb-spot's
// snapped cuts pass 7 % at Newton iteration 34-53 of 75-145.
constexpr double kCutSnapAbandon = 0.07;
constexpr int kCutBack[] = {4, 8, 16, 32};
constexpr int kCheckpoints = 33;
}  // namespace

const char* toString(OptimizeState s) {
  switch (s) {
    case OptimizeState::Running:
      return "running";
    case OptimizeState::Converged:
      return "converged";
    case OptimizeState::Stopped:
      return "stopped";
    case OptimizeState::Failed:
      return "failed";
  }
  return "?";
}

bool hasSlidingSeams(const OptimizeOptions& options, const std::vector<double>& seamWeights) {
  for (double sigma : seamWeights)
    if (sigma * options.weights.seam < options.sliding.seamWeight) return true;
  return false;
}

OptimizeOptions slidingOptions(const OptimizeOptions& options, const std::vector<double>& seamWeights, double h,
                               double D) {
  OptimizeOptions o = options;
  if (!hasSlidingSeams(options, seamWeights)) return o;
  o.search.gaussNewton = true;
  o.search.alignment = {10, true};
  o.remeshing.stallIterations = o.sliding.stallIterations;
  if (o.sliding.iterationFactor > 1)
    o.stopping.maxIterations = int(std::lround(o.stopping.maxIterations * o.sliding.iterationFactor));
  o.stopping.windowDecrease = 0;
  o.stopping.distanceWindow = o.sliding.distanceWindow;
  if (o.sliding.remeshEvery > 0) {
    o.remeshing.every =
        o.remeshing.every > 0 ? std::min(o.remeshing.every, o.sliding.remeshEvery) : o.sliding.remeshEvery;
    o.remeshing.maxRemeshings = std::max(o.remeshing.maxRemeshings, o.stopping.maxIterations / o.remeshing.every + 1);
  }
  const double k = h > 0 && D > 0 ? std::max(1.0, o.sliding.regularizerEdgeLength * D / h) : 1.0;
  o.search.sobolevLength *= k;
  o.search.maxMoveEdges *= k;
  o.weights.slidingSmooth *= k * k;  // only along sliding seams: held ones keep their outlines as they were
  o.weights.slidingBelow = o.sliding.seamWeight;
  return o;
}

namespace {
// remeshPattern at edge length h, and again at the edge length that gives about `triangles` (> 0) when h gave
// more than 10 % off: the remesher's triangles at an edge length are 0.7-1.45 x the pattern builder's.
RemeshedPattern remeshNear(const BuiltPattern& built, const std::vector<Vertices>& inflated, double h,
                           double triangles) {
  RemeshedPattern out = remeshPattern(built, inflated, h);
  const double ratio = triangles > 0 ? out.built.figures.triangles / triangles : 1;
  if (std::abs(ratio - 1) > 0.1) out = remeshPattern(built, inflated, h * std::sqrt(ratio));
  return out;
}

}  // namespace

PatternOptimizer::PatternOptimizer(const TriMesh& target, const BuiltPattern& built,
                                   const std::vector<double>& seamWeights, const OptimizeOptions& options)
    : PatternOptimizer(nullptr, built, seamWeights, options, target) {}

PatternOptimizer::PatternOptimizer(std::shared_ptr<const OptimizationTarget> target, const BuiltPattern& built,
                                   const std::vector<double>& seamWeights, const OptimizeOptions& options)
    : PatternOptimizer(target, built, seamWeights, options, target->whole()) {}

PatternOptimizer::PatternOptimizer(std::shared_ptr<const OptimizationTarget> shared, const BuiltPattern& built,
                                   const std::vector<double>& seamWeights, const OptimizeOptions& options,
                                   const TriMesh& target)
    : options_(slidingOptions(options, seamWeights, built.figures.edgeLength, boundingDiagonal(target))),
      sliding_(hasSlidingSeams(options, seamWeights)),
      seamWeights_(seamWeights),
      target_(shared ? std::move(shared) : std::make_shared<const OptimizationTarget>(target, options.imls)),
      start_(nowMs()) {
  material_ = membraneMaterial(built.pattern.material, options.inflate);
  fineEdgeLength_ = built.figures.edgeLength, designTriangles_ = built.figures.triangles;
  const OptimizeRemeshing& remeshing = options_.remeshing;
  if (!sliding_ && remeshing.coarseFactor > 1 && built.pattern.inflated.size() == built.pattern.panels.size() &&
      int(built.figures.triangles) >= remeshing.coarseMinTriangles) {
    try {
      const double f = remeshing.coarseFactor;
      setUp(remeshNear(built, built.pattern.inflated, f * fineEdgeLength_, built.figures.triangles / (f * f)).built,
            true);
      coarsePhase_ = true, flattened_ = built;
    } catch (const Error&) {  // an outline the coarse edge length cannot mesh: no coarse phase
    }
  }
  if (!coarsePhase_) setUp(built);
  timings_.setupMs = elapsedMs();
}

void PatternOptimizer::setUp(const BuiltPattern& built, bool coarse) {
  built_ = built;
  pattern_ = built.pattern;
  // Which seam vertices carry a rod is fixed for the phase (a corner is judged by its rest angle, a jump), so E(X)
  // stays smooth; their coefficient follows the panels (rodsAt), as the cut panels' own rods do. The pattern marks
  // its corners, so the cut panels keep these rods wherever the optimizer turned an outline across 45 degrees
  // (fb-penguin's cut shape snapped from 1.62 to 2.42 % over six such vertices, bench/README.md).
  mesh_ = sewPattern(pattern_);
  for (size_t p = 0; p < pattern_.panels.size(); ++p)
    if (!pattern_.panels[p].seamCorners) pattern_.panels[p].seamCorners = seamCorners(mesh_, int(p));
  solver_.reset();
  stiffness_.reset();
  rods_ = std::make_shared<const SeamRods>(
      makeSeamRods(mesh_, seamRodCoefficient(mesh_, pattern_.pressure, options_.inflate.seamStiffness)));
  OptimizeWeights weights = options_.weights;
  if (coarse) {
    weights = weightsAtEdgeLength(weights, built.figures.edgeLength / fineEdgeLength_);
    weights.coverReachAtSeams = options_.remeshing.coarseCoverReachAtSeams;
  }
  objective_ = std::make_unique<PatternObjective>(target_->distance(), built, mesh_, seamWeights_, weights);
  X_ = packPattern(pattern_);
  boundaryVertices_.clear();
  for (const BuiltPanel& bp : built.panels) boundaryVertices_.push_back(bp.boundaryVertices);
  sobolevReady_ = false;
  if (options_.search.sobolevLength > 0) {
    const double b = options_.search.sobolevLength * options_.search.sobolevLength;
    std::vector<Eigen::Triplet<double>> trip;
    for (int r = 0; r < X_.size(); ++r) trip.emplace_back(r, r, 1.0);
    for (size_t p = 0; p < built.panels.size(); ++p) {
      const int nb = built.panels[p].boundaryVertices, first = mesh_.panelVertexStart[p];
      for (int j = 0; j < nb && nb > 2; ++j) {
        const int u = first + j, v = first + (j + 1) % nb;
        for (int c = 0; c < 2; ++c) {
          trip.emplace_back(2 * u + c, 2 * u + c, b), trip.emplace_back(2 * v + c, 2 * v + c, b);
          trip.emplace_back(2 * u + c, 2 * v + c, -b), trip.emplace_back(2 * v + c, 2 * u + c, -b);
        }
      }
    }
    Eigen::SparseMatrix<double> S(X_.size(), X_.size());
    S.setFromTriplets(trip.begin(), trip.end());
    sobolevMatrix_ = S;
    sobolev_.compute(S);
    sobolevReady_ = sobolev_.info() == Eigen::Success;
  }
  interior_.reset();
  if (started_) startInterior();
  x_ = startFromInflated(pattern_, mesh_);
  if (x_.rows() != mesh_.numVertices) x_ = sphericalStart(mesh_);
  S_.clear(), Y_.clear();
  dampingScale_ = 0, gaussNewtonStalled_ = false;
  stalled_ = 0;
  best_ = {};
  checkpoints_.clear();
}

void PatternOptimizer::startInterior() {
  interior_ = std::make_unique<HarmonicInterior>(pattern_, mesh_.panelVertexStart, boundaryVertices_, X_);
  if (!interior_->ok()) interior_.reset();
}

bool PatternOptimizer::projectStart() {
  Eigen::VectorXd X = X_;
  projectSeamLengths(objective_->edgePairs(), X, 10, 1e-12);
  followBoundary(X);
  SewnMesh mesh = mesh_;
  if (!rebuildRest(X, mesh)) return false;
  X_ = X, unpackPattern(X_, pattern_);
  return true;
}

std::vector<Vertices> PatternOptimizer::panelInflated() const { return panelPositions(mesh_, x_); }

bool PatternOptimizer::remesh(bool recordIt, double snapLimit, bool* snapped) {
  const double t0 = nowMs();
  BuiltPattern current = built_;
  current.pattern = pattern_;
  const std::vector<Vertices> inflated = panelInflated();
  RemeshedPattern remeshed;
  try {
    remeshed = remeshNear(current, inflated, fineEdgeLength_, designTriangles_);
  } catch (const Error&) {
    return false;  // an outline that no longer bounds a simple polygon: go on with the old mesh
  }
  const Eigen::VectorXd oldX = X_;
  const Vertices oldx = x_;
  const bool wasSimple = outlinesSimple(X_);
  // The new panels must still sew. Their sewn mesh may not close where a pinch is beyond flipPinchingEdges' mending
  // (sewn_pattern.hpp): the old mesh is kept. An outline that zig-zags below the edge length resamples into
  // chords that differ across a seam; when projecting them back onto equal lengths fails, the old mesh is kept. So it
  // is where the projection makes an outline cross itself (a tight bend's chords pulled across each other), since
  // such a panel cannot be cut.
  bool sewn = true;
  try {
    setUp(remeshed.built);
  } catch (const Error&) {
    sewn = false;
  }
  const bool sewable = sewn && (!projectTrials_ || (projectStart() && objective_->maxEdgeMismatch(X_) < 1e-6 &&
                                                    (!wasSimple || outlinesSimple(X_))));
  Vertices x;
  int newton = 0;
  const Vertices carried = x_;
  EquilibriumLimits limits;
  limits.snapLimit = snapLimit;
  if (snapped) *snapped = false;
  if (!sewable || !solveEquilibrium(X_, x_, x, &newton, false, limits, snapped)) {  // back to the old mesh
    current.pattern.inflated = inflated;
    setUp(current, coarsePhase_);
    X_ = oldX, x_ = oldx;
    E_ = settledEnergy(X_, x_);
    variableGradient(X_, x_, g_);
    timings_.remeshMs += nowMs() - t0;
    return false;
  }
  remeshMove_ = (x - carried).rowwise().norm().maxCoeff() / objective_->modelSize();
  takeNewMesh(std::move(x), newton, t0, recordIt);
  return true;
}

void PatternOptimizer::takeNewMesh(Vertices x, int newton, double t0, bool recordIt) {
  x_ = std::move(x);
  E_ = settledEnergy(X_, x_);
  variableGradient(X_, x_, g_);
  ++timings_.remeshings;
  timings_.remeshMs += nowMs() - t0;
  if (!recordIt) return;
  record(0, newton, false);
  history_.back().remeshed = true;
}

void PatternOptimizer::setUpFlattened() {
  coarsePhase_ = false;
  const BuiltPattern flattened = std::move(flattened_);
  flattened_ = {};
  setUp(flattened);
  if (options_.search.projectEveryStep) projectTrials_ = projectStart();
}

bool PatternOptimizer::leaveCoarsePhase() {
  remeshedAt_ = iteration_, stalled_ = 0;
  if (remesh()) {
    coarsePhase_ = false, flattened_ = {};
    return true;
  }
  // The optimized outlines do not mesh or settle at the design's edge length: the flattened panels again.
  const double t0 = nowMs();
  setUpFlattened();
  Vertices x;
  int newton = 0;
  if (!solveEquilibrium(X_, x_, x, &newton)) {
    finish(OptimizeState::Failed, unsettledReason());
    return false;
  }
  takeNewMesh(std::move(x), newton, t0);
  return true;
}

PatternOptimizer::~PatternOptimizer() = default;

CutPanelsCheck PatternOptimizer::checkCutPanels(double h) const {
  const double t0 = nowMs();
  CutPanelsCheck out;
  BuiltPattern current = built_;
  current.pattern = pattern_;
  try {
    const RemeshedPattern remeshed = h > 0 ? remeshPattern(current, panelInflated(), h)
                                           : remeshNear(current, panelInflated(), fineEdgeLength_, designTriangles_);
    // Settled on the cut mesh itself: a coarse first phase would mesh the outlines at twice the edge length and
    // back, losing their detail (the bench's cut figure did: bench/README.md "The cut panels").
    OptimizeOptions settle = options_;
    settle.stopping.maxIterations = 0, settle.stopping.maxMillis = 0, settle.keepShapes = false;
    settle.remeshing.coarseFactor = 1, settle.remeshing.every = 0;
    const std::unique_ptr<PatternOptimizer> cut(
        new PatternOptimizer(target_, remeshed.built, seamWeights_, settle, {}));
    while (cut->step(1) == OptimizeState::Running) {
    }
    out.elements = cut->mesh().numTriangles();
    if (cut->state() == OptimizeState::Failed || cut->history().empty()) {
      out.message = cut->message().empty() ? "the cut panels do not settle under pressure" : cut->message();
    } else {
      const OptimizeRecord& r = cut->history().back();
      out.ok = true;
      out.distanceRms = r.distanceRms, out.distanceMax = r.distanceMax;
      out.targetDistanceRms = r.targetDistanceRms, out.targetDistanceMax = r.targetDistanceMax;
      out.pattern = cut->pattern();
    }
  } catch (const Error& e) {
    out.message = e.what();
  }
  out.ms = nowMs() - t0;
  return out;
}

double PatternOptimizer::elapsedMs() const { return nowMs() - start_; }

bool PatternOptimizer::rebuildRest(const Eigen::VectorXd& X, SewnMesh& mesh) const {
  const std::vector<int> start = panelTriangleStart(pattern_);
  for (size_t p = 0; p < pattern_.panels.size(); ++p) {
    const Triangles& F = pattern_.panels[p].triangles;
    for (int k = 0; k < F.rows(); ++k) {
      const auto corner = [&](int c) {
        return Eigen::Vector2d(X.segment<2>(2 * (mesh.panelVertexStart[p] + F(k, c))));
      };
      const Eigen::Vector2d a = corner(0), b = corner(1), c = corner(2);
      const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      if (!(cross > 1e-6 * mesh.meanEdgeLength * mesh.meanEdgeLength)) return false;  // flipped or degenerate
      mesh.rest[start[p] + k] = makeElementRest(a, b, c);
    }
  }
  return true;
}

std::string PatternOptimizer::unsettledReason() const {
  SewnMesh mesh = mesh_;
  if (!rebuildRest(X_, mesh))
    return "a panel flattens with a sliver too thin to inflate, where seams end a hair apart: bring their ends "
           "together or apart";
  return "the flattened pattern does not settle under pressure";
}

bool PatternOptimizer::outlinesSimple(const Eigen::VectorXd& X) const {
  for (size_t p = 0; p < boundaryVertices_.size(); ++p) {
    const int nb = boundaryVertices_[p], first = mesh_.panelVertexStart[p];
    Points2 Q(nb, 2);
    for (int j = 0; j < nb; ++j) Q.row(j) = X.segment<2>(2 * (first + j)).transpose();
    if (signedArea(Q) < 0) Q = Points2(Q.colwise().reverse());
    if (!isSimpleCcwPolygon(Q)) return false;
  }
  return true;
}

bool PatternOptimizer::solveEquilibrium(const Eigen::VectorXd& X, const Vertices& start, Vertices& x, int* newton,
                                        bool asCut, const EquilibriumLimits& limits, bool* snapped) {
  if (!X.allFinite()) return false;
  SewnMesh mesh = mesh_;
  if (!rebuildRest(X, mesh)) return false;
  const double t0 = nowMs();
  InflateOptions io = options_.inflate;
  io.seamRods = asCut ? nullptr : rodsAt(X);
  if (limits.maxNewton > 0) io.maxIterations = std::min(io.maxIterations, limits.maxNewton);
  if (asCut) {
    // As the cut panels inflate on their own (billow inflate, the app's stored results): their own seam rods, at
    // the corners the pattern marks (the rods the optimizer had).
    Pattern cut = pattern_;
    unpackPattern(X, cut);
    try {
      mesh = sewPattern(cut);
    } catch (const Error&) {
      return false;
    }
  }
  Vertices from = start;
  if (options_.search.gaussSeidelSweeps > 0)
    gaussSeidelSweeps(mesh, pattern_.material, pattern_.pressure, io, from, options_.search.gaussSeidelSweeps,
                      options_.search.gaussSeidelThreshold, false);
  // The cut panels have their own mesh: a solver of their own. Otherwise the phase's solver, new rest shapes.
  std::unique_ptr<InflationSolver> own;
  if (asCut)
    own = std::make_unique<InflationSolver>(std::move(mesh), pattern_.material, pattern_.pressure, io, from);
  else if (solver_)
    solver_->setSeamRodCoefficient(io.seamRods->coefficient), solver_->restartWithRest(mesh.rest, from);
  else
    solver_ = std::make_unique<InflationSolver>(std::move(mesh), pattern_.material, pattern_.pressure, io, from);
  InflationSolver& solver = own ? *own : *solver_;
  if (snapped) *snapped = false;
  const double snapLimit = limits.snapLimit;
  while (solver.step(snapLimit > 0 ? 1 : io.maxIterations) == InflateState::Running &&
         solver.iterations() < io.maxIterations) {
    if (snapLimit > 0 && (solver.positions() - start).rowwise().norm().maxCoeff() > snapLimit) {
      if (snapped) *snapped = true;
      x = solver.positions();
      break;
    }
  }
  ++timings_.equilibriumSolves;
  timings_.newtonIterations += solver.iterations();
  timings_.equilibriumMs += nowMs() - t0;
  if (newton) *newton = solver.iterations();
  if (snapped && *snapped) return false;
  x = solver.positions();  // where it stopped when it did not settle: a resettling may start there
  if (solver.state() != InflateState::Converged || !x.allFinite()) return false;
  align(X, x, limits.alignTolerance, limits.alignDecrease);
  return x.allFinite();
}

std::shared_ptr<const SeamRods> PatternOptimizer::rodsAt(const Eigen::VectorXd& X, Eigen::VectorXd* dcdX) const {
  auto rods = std::make_shared<SeamRods>(*rods_);
  rods->coefficient = seamRodCoefficientAt(mesh_, pattern_, X, pattern_.pressure, options_.inflate.seamStiffness, dcdX);
  return rods;
}

void PatternOptimizer::align(const Eigen::VectorXd& X, Vertices& x, double tolerance, double relativeDecrease) {
  const double t0 = nowMs();
  alignRigid(*objective_, X, x, 300, tolerance, relativeDecrease, options_.search.alignment);
  timings_.alignMs += nowMs() - t0;
}

double PatternOptimizer::energy(const Eigen::VectorXd& X, const Vertices& x, ObjectiveTerms* terms) const {
  return objective_->shapeEnergy(x, X, nullptr, nullptr, terms) + objective_->patternEnergy(X, nullptr, terms);
}

double PatternOptimizer::settledEnergy(const Eigen::VectorXd& X, const Vertices& x) const {
  objective_->trackCover(x);
  return energy(X, x, nullptr);
}

void PatternOptimizer::reducedGradient(const Eigen::VectorXd& X, const Vertices& x, Eigen::VectorXd& grad) {
  const double t0 = nowMs();
  SewnMesh mesh = mesh_;
  rebuildRest(X, mesh);
  Eigen::VectorXd dEdx, dEdX, lambda, dcdX, product = Eigen::VectorXd::Zero(X.size());
  objective_->shapeEnergy(x, X, &dEdx, &dEdX);
  removeRigidPart(x, dEdx);
  const std::shared_ptr<const SeamRods> rods = rodsAt(X, &dcdX);
  const Eigen::SparseMatrix<double> K = assembleStiffness(mesh, x, material_, pattern_.pressure, rods.get());
  if (!stiffness_) stiffness_ = std::make_unique<PinnedStiffness>();
  stiffness_->solve(K, dEdx, rigidPins(x), lambda);
  adjointPattern_ = X, adjointShape_ = x;
  addRestGradientProduct(mesh, pattern_, X, x, lambda, material_, product);
  addRodGradientProduct(*rods, x, dcdX, lambda, product);
  objective_->patternEnergy(X, &grad);
  grad += dEdX - product;  // dE/dX = dE/dX|_x - lambda^T dg/dX
  timings_.adjointMs += nowMs() - t0;
}

Vertices PatternOptimizer::predictEquilibrium(const Eigen::VectorXd& X) const {
  if (!options_.search.predictEquilibrium || !stiffness_ || adjointPattern_.size() != X_.size() ||
      adjointPattern_ != X_ || adjointShape_.rows() != x_.rows() || adjointShape_ != x_ || X.size() != X_.size())
    return x_;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * x_.rows()), dx, dcdX;
  addRestJacobianProduct(mesh_, pattern_, X_, x_, X - X_, material_, b);
  addRodJacobianProduct(*rodsAt(X_, &dcdX), x_, dcdX, X - X_, b);
  if (!stiffness_->solveAgain(b, dx)) return x_;
  // A K near singular (a floppy internal panel about to snap) makes the first-order response explode: the fish's
  // moved 3e5-3e8 times as far as its panels, and those trials did not settle in 100 Newton iterations where the
  // same steps from x settle in 9; where it holds, the response is 1-25 times the panels' move.
  double panelMove = 0, shapeMove = 0;
  for (int v = 0; v < X.size() / 2; ++v)
    panelMove = std::max(panelMove, (X.segment<2>(2 * v) - X_.segment<2>(2 * v)).norm());
  for (int v = 0; v < x_.rows(); ++v) shapeMove = std::max(shapeMove, dx.segment<3>(3 * v).norm());
  if (!(shapeMove <= kPredictionReach * panelMove)) return x_;
  Vertices x = x_;
  for (int v = 0; v < x.rows(); ++v) x.row(v) -= dx.segment<3>(3 * v).transpose();
  return x;
}

void PatternOptimizer::variableGradient(const Eigen::VectorXd& X, const Vertices& x, Eigen::VectorXd& grad) {
  reducedGradient(X, x, grad);
  if (interior_) interior_->reduce(grad);
}

void PatternOptimizer::toVariables(Eigen::VectorXd& v) const {
  if (interior_)
    for (int r = 0; r < v.size() / 2; ++r)
      if (interior_->interior(r)) v.segment<2>(2 * r).setZero();
}

Eigen::VectorXd PatternOptimizer::precondition(const Eigen::VectorXd& v) const {
  if (!sobolevReady_) return v;
  Eigen::VectorXd r = sobolev_.solve(v);
  toVariables(r);
  return r;
}

void PatternOptimizer::followBoundary(Eigen::VectorXd& X) const {
  if (interior_) interior_->extend(X);
}

bool PatternOptimizer::evaluate(const Eigen::VectorXd& X, double* E, Eigen::VectorXd* grad, Vertices* x) {
  Vertices xs;
  if (!solveEquilibrium(X, x_, xs, nullptr)) return false;
  if (E) *E = energy(X, xs, nullptr);
  if (grad) reducedGradient(X, xs, *grad);
  if (x) *x = xs;
  return true;
}

void PatternOptimizer::record(double alpha, int newton, bool projected) {
  OptimizeRecord r;
  r.iteration = iteration_;
  r.objective = energy(X_, x_, &r.terms);
  const double D = objective_->modelSize();
  const Eigen::VectorXd& w = objective_->targetWeights();
  int count = 0;
  if (figureFaces_.size() != size_t(x_.rows())) figureFaces_.assign(size_t(x_.rows()), -1);
  for (int i = 0; i < x_.rows(); ++i) {
    if (w[i] == 0) continue;
    const double d = target_->closestDistance(x_.row(i).transpose(), &figureFaces_[size_t(i)]) / D;
    r.distanceRms += d * d, r.distanceMax = std::max(r.distanceMax, d), ++count;
  }
  r.distanceRms = count ? std::sqrt(r.distanceRms / count) : 0;
  measureTarget(r, x_);
  r.seamMismatch = objective_->maxEdgeMismatch(X_);
  const double norm = double(objective_->numVertices()) * D;
  // With every trial projected onto equal seam lengths the constraint is hard, and stationarity is that of the
  // Lagrangian: the gradient's part tangent to the constraint set (least-squares multipliers).
  const Eigen::VectorXd lagrangian =
      projectTrials_ && g_.size() ? tangentToSeamLengths(objective_->edgePairs(), X_, g_) : g_;
  r.gradient = g_.size() ? lagrangian.lpNorm<Eigen::Infinity>() * norm / 2 : 0;
  r.stepLength = alpha, r.equilibriumIterations = newton, r.ms = elapsedMs(), r.projected = projected;
  history_.push_back(r);
  if (options_.keepShapes) shapes_.push_back(x_);
  if (!projected && r.objective < best_.E) best_ = {r.objective, X_, x_, g_};
  if (!projected && !coarsePhase_ && !sliding_) {
    checkpoints_.push_back({X_, x_, r.objective});
    if (int(checkpoints_.size()) > kCheckpoints) checkpoints_.pop_front();
  }
}

void PatternOptimizer::measureTarget(OptimizeRecord& r, const Vertices& x) {
  const TriMesh& sampled = target_->distance().target();  // whose vertices E_cover samples
  const std::vector<int>& sample = objective_->coverVertices();
  const double D = objective_->modelSize();
  coverageShape_ = x;
  // A run of no iterations (a first look, the cut panels' settle) keeps its one record: measured whole at once.
  r.targetSampled = !exactTarget_ && options_.stopping.maxIterations > 0 && !sample.empty() &&
                    (target_->copied() || int(sample.size()) < sampled.numVertices());
  if (!r.targetSampled) {
    TargetCoverage coverage = targetCoverage(target_->whole(), x, outerTriangles(mesh_), D);
    r.targetDistanceRms = coverage.summary.rms, r.targetDistanceMax = coverage.summary.max;
    targetDistances_ = std::move(coverage.distances);
    return;
  }
  // A fine target during the run: its distances at E_cover's sample (of its working copy, where it has one), weighted
  // by their areas as targetCoverage weighs every vertex (every vertex of a 94k-vertex target at every record was a
  // quarter of a 1,000-element run: bench/README.md "The target's resolution").
  const TriMesh shape{x, outerTriangles(mesh_)};
  const SurfaceProjector projector(shape);
  const Eigen::VectorXd& area = objective_->coverAreas();
  double sum = 0, weight = 0, largest = 0;
  for (size_t k = 0; k < sample.size(); ++k) {
    double d = 0;
    projector.project(sampled.V.row(sample[k]).transpose(), &d);
    sum += area[long(k)] * d * d, weight += area[long(k)], largest = std::max(largest, d);
  }
  r.targetDistanceRms = weight > 0 ? std::sqrt(sum / weight) / D : 0, r.targetDistanceMax = largest / D;
  targetDistances_.resize(0);
}

const Eigen::VectorXd* PatternOptimizer::targetDistances() const {
  const bool current = coverageShape_.rows() == x_.rows() && (coverageShape_.array() == x_.array()).all();
  return current && targetDistances_.size() ? &targetDistances_ : nullptr;
}

void PatternOptimizer::finish(OptimizeState s, const std::string& message) {
  message_ = message;
  // From here every record is kept as the run's figures (the last, and the own mesh's last before the cut panels,
  // which the app compares with theirs): each measures the whole target.
  exactTarget_ = true;
  if (!history_.empty() && history_.back().targetSampled) measureTarget(history_.back(), Vertices(coverageShape_));
  // A first look (no iteration, no cut panels) whose panels were projected onto equal seam lengths as it started is
  // its own cut shape: settled again, the same equilibrium in no Newton iteration.
  const bool ownCut = measuresOnly() && !options_.remeshing.cutPanels && projectTrials_;
  if (s != OptimizeState::Failed) {
    settleCutPanels();
    if (!ownCut) takeCutShape();
  }
  state_ = s;
  timings_.totalMs = elapsedMs();
}

double PatternOptimizer::takeCutShape() {
  // A resettling took the optimizer to a worse equilibrium and it did not get back below its best: the best
  // iterate is what it found (a settled equilibrium of those panels), nothing of it is lost. But that iterate
  // may sit where its equilibrium is about to vanish (why the resettling came), and cut it can snap into the
  // other one (fb-spot: the head moved 7 cm across the thickness, E +22 %); the last iterate, settled on the
  // branch the balloon snapped into, then cuts better. The designer gets the better of the two cut shapes.
  std::optional<CutShape> cut;
  bool restore = best_.E < E_ && best_.X.size() == X_.size();
  const double lastE = E_;
  if (restore) {
    cut = cutShape(best_.X, best_.x);
    if (!cut || cut->E > E_) {
      std::optional<CutShape> last = cutShape(X_, x_);
      if (last && (!cut || last->E < cut->E)) cut = std::move(last), restore = false;
    }
    if (restore) {
      X_ = best_.X, x_ = best_.x, g_ = best_.g, E_ = settledEnergy(X_, x_);
      unpackPattern(X_, pattern_);
      record(0, 0, false);
      history_.back().restored = true;
    }
  } else {
    cut = cutShape(X_, x_);
  }
  if (cut) {
    X_ = std::move(cut->X), x_ = std::move(cut->x);
    E_ = settledEnergy(X_, x_);
    unpackPattern(X_, pattern_);
    variableGradient(X_, x_, g_);
    record(0, cut->newton, true);
  } else {
    message_ += (message_.empty() ? "" : "; ") + std::string("the exact seam-length projection did not settle");
  }
  return restore ? best_.E : lastE;
}

std::optional<PatternOptimizer::CutShape> PatternOptimizer::cutShape(const Eigen::VectorXd& X0, const Vertices& x0) {
  CutShape c;
  c.X = X0;
  projectSeamLengths(objective_->edgePairs(), c.X, 10, 1e-12);
  followBoundary(c.X);
  if (outlinesSimple(X0) && !outlinesSimple(c.X)) return std::nullopt;  // a panel that could not be cut
  if (!solveEquilibrium(c.X, x0, c.x, &c.newton, true)) return std::nullopt;
  c.E = settledEnergy(c.X, c.x);
  return c;
}

Eigen::VectorXd PatternOptimizer::tangential(const Eigen::VectorXd& X, const Eigen::VectorXd& v) const {
  if (!projectTrials_) return v;
  return tangentToSeamLengths(objective_->edgePairs(), X, v);
}

// The Gauss-Newton model of the shape terms at the current iterate: E_target + E_cover + E_seam as weighted
// residuals (PatternObjective::residualRows), their rigid-motion Jacobians, and the response dx = J dX,
// J = -K^-1 dg/dX, by the adjoint's kept factorization.
struct PatternOptimizer::ShapeModel {
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  std::vector<PatternObjective::ResidualRow> rows;
  std::vector<Vector6d> rigid;  // per row: d r / d(rotation vector about the centroid, translation)
  Eigen::LDLT<Matrix6d> rigidNormal;
  std::shared_ptr<const SeamRods> rods;
  Eigen::VectorXd dcdX;
  std::optional<RestJacobian> restJacobian;
};

std::unique_ptr<PatternOptimizer::ShapeModel> PatternOptimizer::shapeModel() const {
  if (!stiffness_ || adjointPattern_.size() != X_.size() || adjointPattern_ != X_ ||
      adjointShape_.rows() != x_.rows() || adjointShape_ != x_)
    return nullptr;
  auto model = std::make_unique<ShapeModel>();
  objective_->residualRows(x_, X_, model->rows);
  const Eigen::Vector3d center = x_.colwise().mean().transpose();
  ShapeModel::Matrix6d normal = ShapeModel::Matrix6d::Zero();
  model->rigid.resize(model->rows.size());
  for (size_t k = 0; k < model->rows.size(); ++k) {
    const PatternObjective::ResidualRow& row = model->rows[k];
    ShapeModel::Vector6d J = ShapeModel::Vector6d::Zero();
    for (int a = 0; a < row.count; ++a) {
      const Eigen::Vector3d xa = x_.row(row.vertex[a]).transpose();
      J.head<3>() += (xa - center).cross(row.grad[a]), J.tail<3>() += row.grad[a];
    }
    model->rigid[k] = J, normal += row.weight * J * J.transpose();
  }
  model->rigidNormal.compute(normal);
  model->rods = rodsAt(X_, &model->dcdX);
  model->restJacobian.emplace(mesh_, pattern_, X_, x_, material_);
  return model;
}

Eigen::VectorXd PatternOptimizer::patternChange(const Eigen::VectorXd& v) const {
  Eigen::VectorXd dX = X_ + v;  // the interior follows the outline (an affine map: the change is linear in v)
  followBoundary(dX);
  return dX - X_;
}

Eigen::VectorXd PatternOptimizer::shapeProduct(const ShapeModel& model, const Eigen::VectorXd& v) const {
  const Eigen::VectorXd dX = patternChange(v);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * x_.rows()), dx, lambda, out = Eigen::VectorXd::Zero(v.size());
  model.restJacobian->addProduct(dX, b);
  addRodJacobianProduct(*model.rods, x_, model.dcdX, dX, b);
  if (!stiffness_->solveAgain(b, dx)) return out;
  dx = -dx;
  // The shape is placed rigidly where E is least (rigid_align.hpp): to first order that adds the rigid motion
  // theta minimizing the linearized residuals, so the model sees dx less its best rigid fit.
  const std::vector<PatternObjective::ResidualRow>& rows = model.rows;
  std::vector<double> z(rows.size());
  ShapeModel::Vector6d Az = ShapeModel::Vector6d::Zero();
  for (size_t k = 0; k < rows.size(); ++k) {
    for (int a = 0; a < rows[k].count; ++a) z[k] += rows[k].grad[a].dot(dx.segment<3>(3 * rows[k].vertex[a]));
    Az += rows[k].weight * z[k] * model.rigid[k];
  }
  const ShapeModel::Vector6d theta = -model.rigidNormal.solve(Az);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(3 * x_.rows());
  for (size_t k = 0; k < rows.size(); ++k) {
    const double zk = z[k] + model.rigid[k].dot(theta);
    for (int a = 0; a < rows[k].count; ++a)
      w.segment<3>(3 * rows[k].vertex[a]) += 2 * rows[k].weight * zk * rows[k].grad[a];
  }
  if (stiffness_->solveAgain(w, lambda)) {  // J^T w = -(dg/dX)^T K^-1 w
    model.restJacobian->addTransposedProduct(lambda, out);
    addRodGradientProduct(*model.rods, x_, model.dcdX, lambda, out);
    out = -out;
  }
  if (interior_) interior_->reduce(out);
  toVariables(out);
  return out;
}

Eigen::VectorXd PatternOptimizer::patternProduct(const Eigen::VectorXd& v) const {
  const Eigen::VectorXd dX = patternChange(v);
  const double h = 1e-7 * objective_->meanEdgeLength() / std::max(dX.lpNorm<Eigen::Infinity>(), 1e-300);
  Eigen::VectorXd gp, gm, out = Eigen::VectorXd::Zero(v.size());
  objective_->patternEnergy(X_ + h * dX, &gp);
  objective_->patternEnergy(X_ - h * dX, &gm);
  if (gp.allFinite() && gm.allFinite()) out = (gp - gm) / (2 * h);
  if (interior_) interior_->reduce(out);
  toVariables(out);
  return out;
}

Eigen::VectorXd PatternOptimizer::gaussNewtonShapeProduct(const Eigen::VectorXd& v, Eigen::VectorXd* dX) const {
  const std::unique_ptr<ShapeModel> model = shapeModel();
  Eigen::VectorXd w = v;
  toVariables(w);
  if (dX) *dX = patternChange(w);
  return model ? shapeProduct(*model, w) : Eigen::VectorXd();
}

Eigen::VectorXd PatternOptimizer::gaussNewtonDirection(double* predicted) {
  const std::unique_ptr<ShapeModel> model = shapeModel();
  if (!model || !sobolevReady_) return {};
  // With every trial projected onto equal seam lengths only a step's tangential part is taken: the model lives
  // in the tangent space (T H T, T g), else it counts on a decrease across the set that the projection undoes.
  const SeamTangent tangent(objective_->edgePairs(), X_);
  const auto T = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return projectTrials_ ? tangent(v) : v; };
  const auto H = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    const Eigen::VectorXd t = T(v);
    return T(shapeProduct(*model, t) + patternProduct(t));
  };
  const auto S = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    Eigen::VectorXd r = sobolevMatrix_ * v;
    toVariables(r);
    return T(r);
  };
  const auto Sinv = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return T(precondition(v)); };
  Eigen::VectorXd g = T(g_);
  toVariables(g);
  // Levenberg-Marquardt damping mu S. Its scale, the curvature along the preconditioned gradient, is taken once per
  // phase: taken anew each time, it follows the stiffest direction, which grows without bound near an unstable
  // equilibrium (K nearly singular), and damps every other direction away.
  if (!(dampingScale_ > 0)) {
    const Eigen::VectorXd pg = Sinv(g);
    dampingScale_ = std::max(pg.dot(H(pg)) / std::max(pg.dot(S(pg)), 1e-300), 0.0);
  }
  const double mu = damping_ * dampingScale_;
  // Preconditioned CG on (H + mu S) d = -g, preconditioner S^-1; at negative curvature (the pattern terms'
  // Hessian is not convex) it stops with what it has.
  Eigen::VectorXd d = Eigen::VectorXd::Zero(g.size()), r = -g, z = Sinv(r), p = z;
  double rz = r.dot(z);
  const double r0 = std::sqrt(std::abs(rz));
  for (int it = 0; it < options_.search.gaussNewtonCg; ++it) {
    const Eigen::VectorXd Ap = H(p) + mu * S(p);
    const double pAp = p.dot(Ap);
    if (!(pAp > 0)) {
      if (it == 0) d = p;
      break;
    }
    const double step = rz / pAp;
    d += step * p, r -= step * Ap;
    z = Sinv(r);
    const double rzNext = r.dot(z);
    if (std::sqrt(std::abs(rzNext)) < options_.search.gaussNewtonCgTolerance * r0) break;
    p = z + (rzNext / rz) * p, rz = rzNext;
  }
  if (predicted) *predicted = -(g.dot(d) + 0.5 * d.dot(H(d)));
  return d;
}

// One L-BFGS iteration (two-loop recursion, Armijo backtracking with equilibrium re-solves).
bool PatternOptimizer::iterate() {
  // Gauss-Newton directions (options.search.gaussNewton) carry no pairs: their model is remade at every iterate.
  double modelDecrease = 0;
  // After a Gauss-Newton step that barely lowered E, an L-BFGS step: where the Gauss-Newton model (positive
  // semi-definite, without the equilibrium's second derivatives) sees nothing left to gain, L-BFGS's pairs may.
  const double t0 = nowMs();
  Eigen::VectorXd gn =
      options_.search.gaussNewton && !gaussNewtonStalled_ ? gaussNewtonDirection(&modelDecrease) : Eigen::VectorXd();
  const bool gnStep = gn.size() == X_.size();
  const int m = gnStep ? 0 : static_cast<int>(S_.size());
  // With every trial projected onto equal seam lengths, a step's part across that constraint set is undone by
  // the projection: L-BFGS works with the gradient's tangential part and its steps are made tangential (T, the
  // identity otherwise; one factorization of the seam-length Jacobian at X_ serves them all).
  const std::optional<SeamTangent> tangent =
      projectTrials_ ? std::optional<SeamTangent>(std::in_place, objective_->edgePairs(), X_) : std::nullopt;
  const auto T = [&](const Eigen::VectorXd& v) { return tangent ? (*tangent)(v) : v; };
  const Eigen::VectorXd gt = T(g_);
  Eigen::VectorXd q = -gt;
  std::vector<double> a(m);
  for (int i = m - 1; i >= 0; --i) a[i] = S_[i].dot(q) / Y_[i].dot(S_[i]), q -= a[i] * Y_[i];
  if (gnStep) {
    q = gn;
  } else {
    q = precondition(q);
    if (m > 0) q *= S_[m - 1].dot(Y_[m - 1]) / Y_[m - 1].dot(precondition(Y_[m - 1]));
  }
  for (int i = 0; i < m; ++i) q += (a[i] - Y_[i].dot(q) / Y_[i].dot(S_[i])) * S_[i];
  Eigen::VectorXd d = T(q);
  // A projected trial X_ + alpha d lands at X_ + alpha T d to first order, so the slope the line search meets is
  // g T d; g d overstates it, up to 100-fold once d is mostly across the set.
  const auto slopeAlong = [&](const Eigen::VectorXd& v) { return g_.dot(T(v)); };
  double slope = slopeAlong(d);
  // Else steepest descent within the set: its slope -(T g)^T M^-1 (T g) is negative unless T g = 0.
  if (!(slope < 0)) d = -T(precondition(gt)), slope = slopeAlong(d), S_.clear(), Y_.clear();
  timings_.directionMs += nowMs() - t0;
  if (!(slope < 0)) return false;
  // Cap the largest vertex move (a step without curvature information has no scale of its own).
  double maxMove = 0;
  for (int v = 0; v < d.size() / 2; ++v) maxMove = std::max(maxMove, d.segment<2>(2 * v).norm());
  const double cap = options_.search.maxMoveEdges * objective_->meanEdgeLength();
  double alpha = (S_.empty() || maxMove > cap) ? cap / std::max(maxMove, 1e-300) : 1.0;
  if (!S_.empty() || gnStep) alpha = std::min(alpha, 1.0);
  const double firstAlpha = alpha;
  // A jump: halving the step no longer brings E down towards E_ (the excess E - E_ shrank by less than 10 %
  // over the last `jumps` settled trials), or the refused trial's equilibrium is far from where it was predicted
  // to be (the balloon snapped into another equilibrium); two in a row: E(X) is discontinuous here, see
  // resettle().
  double lastExcess = INFINITY;
  int jumps = 0, unsettled = 0;
  bool snapLimited = false;
  // Backtracking: after a trial with a finite E the next alpha minimizes the quadratic through E_, the slope
  // and E(alpha), kept within [0.1, 0.5] alpha (Nocedal & Wright, Sec. 3.5); after a failed solve, alpha / 2.
  double next = 0.5 * alpha;
  // A panel whose outline crosses itself overlaps itself and cannot be cut, although none of its rest triangles
  // folds: such a trial is refused like a folded one (unless the outlines already cross).
  const bool simple = outlinesSimple(X_);
  std::vector<int> recent;
  for (auto r = history_.rbegin(); r != history_.rend() && recent.size() < 10; ++r)
    if (r->equilibriumIterations > 0) recent.push_back(r->equilibriumIterations);
  std::nth_element(recent.begin(), recent.begin() + recent.size() / 2, recent.end());
  const int trialNewton =
      std::max(kTrialNewtonFloor, recent.empty() ? 0 : kTrialNewtonFactor * recent[recent.size() / 2]);
  // The trial at a step: projected onto equal seam lengths, the interior carried along its outlines.
  const auto trialAt = [&](double step) {
    Eigen::VectorXd X = X_ + step * d;
    if (projectTrials_) projectSeamLengths(objective_->edgePairs(), X, 10, 1e-12);
    followBoundary(X);
    return X;
  };
  for (int h = 0; h <= options_.search.maxHalvings; ++h, alpha = next, next = 0.5 * alpha) {
    Eigen::VectorXd X = trialAt(alpha);
    if (simple && !outlinesSimple(X)) {
      ++timings_.rejectedTrials;
      continue;
    }
    Vertices x;
    int newton = 0;
    Vertices predicted = predictEquilibrium(X);
    double predictedMove = (predicted - x_).rowwise().norm().maxCoeff();
    const double reach =
        options_.search.shapeStepGrowth *
        (predictedMoves_.empty() ? 0 : *std::max_element(predictedMoves_.begin(), predictedMoves_.end()));
    if (h == 0 && reach > 0 && predictedMove > reach) {
      alpha *= reach / predictedMove, next = 0.5 * alpha;
      X = trialAt(alpha);
      if (simple && !outlinesSimple(X)) {
        ++timings_.rejectedTrials;
        continue;
      }
      predicted = predictEquilibrium(X);
      predictedMove = (predicted - x_).rowwise().norm().maxCoeff();
    }
    bool snapped = false;
    const EquilibriumLimits trial{kTrialAlignment, kTrialAlignDecrease,
                                  std::max(3 * predictedMove, 2 * kSnapDistance * objective_->modelSize()),
                                  trialNewton};
    const bool solved = solveEquilibrium(X, predicted, x, &newton, false, trial, &snapped);
    double E = solved ? energy(X, x, nullptr) : NAN;
    if (!(solved && std::isfinite(E) && E <= E_ + 1e-4 * alpha * slope)) {
      ++timings_.rejectedTrials, timings_.snappedTrials += snapped;
      unsettled = !solved && !snapped && newton >= trialNewton ? unsettled + 1 : 0;
      timings_.unsettledTrials += unsettled > 0;
      if (unsettled >= kUnsettledTrials) return x.allFinite() && resettle(x);
      if (!solved) {
        // A trial abandoned on its way into another equilibrium counts as a jump (its E would be far off).
        jumps = snapped ? jumps + 1 : 0, lastExcess = INFINITY;
        if (snapped) next = 0.1 * alpha;
      } else {
        if (std::isfinite(E) && E > E_ + alpha * slope) {
          const double quadratic = -slope * alpha * alpha / (2 * (E - E_ - alpha * slope));
          next = std::clamp(quadratic, 0.1 * alpha, 0.5 * alpha);
        }
        const double excess = E - E_;
        const bool offPrediction = (x - predicted).rowwise().norm().maxCoeff() >
                                   std::max(1.5 * predictedMove, kSnapDistance * objective_->modelSize());
        jumps = std::isfinite(E) && excess > 1e-3 * std::abs(E_) && (excess > 0.9 * lastExcess || offPrediction)
                    ? jumps + 1
                    : 0;
        lastExcess = std::isfinite(E) ? excess : INFINITY;
      }
      snapLimited = snapLimited || jumps > 0;
      if (jumps >= 2) {
        if (resettle(x)) return true;
        // No resettling left: shorter steps jump too (each trial an abandoned solve), the line search ends here.
        if (timings_.resettlings >= options_.search.maxResettlings) return false;
      }
      continue;
    }
    // The adjoint gradient needs the alignment's minimum itself (rigid_align.hpp); aligning further only
    // lowers E, so the accepted trial stays accepted.
    align(X, x, EquilibriumLimits{}.alignTolerance);
    E = settledEnergy(X, x);
    Eigen::VectorXd g;
    variableGradient(X, x, g);
    if (!g.allFinite()) return false;
    const Eigen::VectorXd s = X - X_, y = tangential(X, g) - gt;
    if (s.dot(y) > 1e-12 * s.norm() * y.norm()) {
      S_.push_back(s), Y_.push_back(y);
      if (static_cast<int>(S_.size()) > options_.search.memory) S_.erase(S_.begin()), Y_.erase(Y_.begin());
    }
    gaussNewtonStalled_ = gnStep && (E_ - E) < kGaussNewtonStall * std::abs(E_);
    if (gnStep) {
      // Levenberg-Marquardt: less damping after a full step the model predicted well, more after a short one.
      const double ratio = modelDecrease > 0 ? (E_ - E) / (alpha * modelDecrease) : 1;
      if (alpha == firstAlpha && firstAlpha == 1.0 && ratio > 0.5)
        damping_ = std::max(damping_ / 3, 1e-4);
      else if (alpha < 0.5 * firstAlpha || ratio < 0.25)
        damping_ = std::min(damping_ * 4, 1e2);
    }
    stalled_ = (E_ - E) <= options_.stopping.relativeDecrease * std::abs(E_) ? stalled_ + 1 : 0;
    predictedMoves_.push_back(predictedMove);
    if (predictedMoves_.size() > 3) predictedMoves_.pop_front();
    X_ = X, x_ = std::move(x), g_ = std::move(g), E_ = E, ++iteration_;
    unpackPattern(X_, pattern_);
    record(alpha, newton, false);
    history_.back().snapLimited = snapLimited, history_.back().predictedMove = predictedMove;
    history_.back().cutShort = alpha <= 0.1 * firstAlpha;
    return true;
  }
  return false;
}

bool PatternOptimizer::resettle(const Vertices& from) {
  if (timings_.resettlings >= options_.search.maxResettlings || from.rows() != x_.rows()) return false;
  Vertices x;
  int newton = 0;
  // From an abandoned trial's shape (not settled): a solve that does not settle soon is no resettling.
  EquilibriumLimits limits;
  limits.maxNewton = kResettleNewton;
  if (!solveEquilibrium(X_, from, x, &newton, false, limits)) return false;
  const double E = settledEnergy(X_, x);
  Eigen::VectorXd g;
  if (std::isfinite(E) && std::abs(E - E_) > 1e-6 * std::abs(E_)) variableGradient(X_, x, g);
  if (!(g.size() && g.allFinite())) {
    objective_->trackCover(x_);  // E_ stays what the line search compares with
    return false;
  }
  x_ = std::move(x), E_ = E, g_ = std::move(g);
  S_.clear(), Y_.clear();
  stalled_ = 0;
  ++timings_.resettlings;
  record(0, newton, false);
  history_.back().resettled = true;
  return true;
}

std::optional<PatternOptimizer::StopReason> PatternOptimizer::stopReason() const {
  if (measuresOnly()) return StopReason{OptimizeState::Stopped, "the iteration limit was reached"};  // no gradient
  if (history_.back().gradient < options_.stopping.gradientTolerance) return StopReason{OptimizeState::Converged, ""};
  if (stalled_ >= options_.stopping.stallIterations)
    return StopReason{OptimizeState::Converged, "the objective stopped decreasing"};
  if (options_.stopping.windowIterations > 0) {
    const bool windowFull = windowStart_ >= 0 && windowX_.rows() == x_.rows() &&
                            iteration_ - windowStart_ >= options_.stopping.windowIterations;
    if (windowFull &&
        (x_ - windowX_).rowwise().norm().maxCoeff() < options_.stopping.windowMove * objective_->modelSize())
      return StopReason{OptimizeState::Converged, "the shape stopped changing"};
    const int window = coarsePhase_ ? std::min(options_.remeshing.coarseWindow, options_.stopping.windowIterations)
                                    : options_.stopping.windowIterations;
    if (options_.stopping.windowDecrease > 0) {
      switch (readObjectiveWindow(history_, iteration_, window, options_.stopping.windowDecrease, E_)) {
        case ObjectiveWindow::NoDecrease:
          return StopReason{OptimizeState::Converged, "the objective no longer decreases noticeably"};
        case ObjectiveWindow::SnapsAway:
          return StopReason{OptimizeState::Converged, "the balloon keeps snapping away from its best shape"};
        case ObjectiveWindow::HeldAtFold:
          return StopReason{OptimizeState::Converged,
                            "the steps that would bring the balloon closer make it snap into another shape"};
        case ObjectiveWindow::GoesOn:
          break;
      }
    }
  }
  if (options_.stopping.distanceWindow > 0 && iteration_ >= options_.stopping.distanceWindow) {
    double before = INFINITY, best = INFINITY;
    for (const OptimizeRecord& r : history_) {
      if (r.projected) continue;
      const double d = r.bothWaysDistance();
      best = std::min(best, d);
      if (r.iteration <= iteration_ - options_.stopping.distanceWindow) before = std::min(before, d);
    }
    if (std::isfinite(before) && before - best < options_.stopping.distanceDecrease * best)
      return StopReason{OptimizeState::Converged, "the distance to the target no longer decreases noticeably", false};
  }
  if (iteration_ >= options_.stopping.maxIterations)
    return StopReason{OptimizeState::Stopped, "the iteration limit was reached"};
  if (options_.stopping.maxMillis > 0 && elapsedMs() > options_.stopping.maxMillis)
    return StopReason{OptimizeState::Stopped, "the time limit was reached"};
  if (options_.stopping.maxNewtonIterations > 0 && timings_.newtonIterations >= options_.stopping.maxNewtonIterations)
    return StopReason{OptimizeState::Stopped, "the work allowed for it was done"};
  if (options_.stopping.maxWork > 0 &&
      timings_.newtonIterations + OptimizeStopping::kIterationWork * iteration_ >= options_.stopping.maxWork)
    return StopReason{OptimizeState::Converged,
                      "its work budget was spent (more steps seldom bring the cut panels closer)"};
  return std::nullopt;
}

bool PatternOptimizer::stalledOnThisMesh() const {
  const int n = options_.remeshing.stallIterations;
  if (n <= 0 || iteration_ - std::max(remeshedAt_, 0) < n) return false;
  for (auto r = history_.rbegin(); r != history_.rend(); ++r)
    if (r->iteration <= iteration_ - n) return r->objective - E_ < kStallDecrease * std::abs(E_);
  return false;
}

void PatternOptimizer::slideWindow() {
  if (options_.stopping.windowIterations <= 0) return;
  if (windowStart_ < 0 || windowX_.rows() != x_.rows() ||
      iteration_ - windowStart_ >= options_.stopping.windowIterations)
    windowX_ = x_, windowStart_ = iteration_;
}

void PatternOptimizer::settleCutPanels() {
  if (sliding_ || coarsePhase_ || !options_.remeshing.cutPanels) return;
  // The iterate to cut: the best one, seam lengths exact. Its cut panels are judged against its objective before
  // that projection, as the earlier iterates' below, since where it sits at a fold the projection alone can snap
  // it (a screwdriver's layout: E 7.0e-4 -> 2.0e-3), and against that the snapped cut panels would pass.
  const double ownE = takeCutShape();
  BuiltPattern own = built_;
  own.pattern = pattern_;
  own.pattern.inflated = panelInflated();
  const std::deque<Checkpoint> checkpoints = std::move(checkpoints_);
  const Eigen::VectorXd lastX = X_;
  const Vertices lastx = x_;
  const double snapLimit = kCutSnapAbandon * objective_->modelSize();
  bool snapped = false;
  if (remesh(true, snapLimit, &snapped)) {
    history_.back().cutPanels = true;
    if (E_ <= kCutSnapRatio * ownE || remeshMove_ < kCutSnapMove) return;
  } else if (!snapped) {
    return;  // where the outlines do not mesh or settle anew, the run ends on its own mesh
  }
  // The cut panels snapped into another equilibrium (fb-spot: the head across the thickness, E +35-70 %): the last
  // iterates sit near the fold where the optimizer's mesh keeps its equilibrium and a new mesh does not. An earlier
  // iterate, farther from the fold, may cut without snapping: the designer gets the cut panels of least E.
  struct Cut {
    BuiltPattern built;
    Eigen::VectorXd X;
    Vertices x;
    double E;
    std::optional<CutShape> own;  // the earlier iterate cut on the optimizer's mesh; none: the last iterate's
  };
  auto current = [&](std::optional<CutShape> own) {
    Cut c{built_, X_, x_, E_, std::move(own)};
    c.built.pattern = pattern_;
    return c;
  };
  std::optional<Cut> best;
  if (!snapped) best = current(std::nullopt);
  auto setUpOwn = [&](const Eigen::VectorXd& X) {  // the optimizer's mesh with panels X
    BuiltPattern panels = own;
    unpackPattern(X, panels.pattern);
    setUp(panels);
  };
  // The earlier iterates, of least objective first; the first whose cut keeps its shape ends the search.
  std::vector<const Checkpoint*> earlier;
  for (int back : kCutBack)
    if (back < int(checkpoints.size())) earlier.push_back(&checkpoints[checkpoints.size() - 1 - back]);
  if (earlier.empty() && !snapped) return;
  std::sort(earlier.begin(), earlier.end(), [](const Checkpoint* a, const Checkpoint* b) { return a->E < b->E; });
  bool kept = false;
  for (const Checkpoint* c : earlier) {
    setUpOwn(c->X);
    std::optional<CutShape> cut = cutShape(c->X, c->x);
    if (!cut) continue;
    X_ = cut->X, x_ = cut->x;
    unpackPattern(X_, pattern_);
    if (!remesh(false, snapLimit)) continue;
    if (!best || E_ < best->E) best = current(std::move(cut));
    kept = E_ <= kCutSnapRatio * c->E || remeshMove_ < kCutSnapMove;
    if (kept) break;
  }
  if (!kept && snapped) {  // every cut snapped: the last iterate's, settled into its other shape, is a candidate too
    setUpOwn(lastX);
    X_ = lastX, x_ = lastx;
    unpackPattern(X_, pattern_);
    if (remesh()) {
      history_.back().cutPanels = true;
      if (!best || E_ < best->E) return;
    }
    if (!best) return;  // no cut settled: the run ends on its own mesh, at the last iterate (remesh kept it)
  }
  if (best->own) {  // the chosen iterate, cut, on the optimizer's mesh: what the panes compare the cut panels with
    setUpOwn(best->own->X);
    X_ = std::move(best->own->X), x_ = std::move(best->own->x);
    E_ = settledEnergy(X_, x_);
    record(0, best->own->newton, true);
    history_.back().restored = true;
  }
  setUp(best->built);
  X_ = std::move(best->X), x_ = std::move(best->x);
  E_ = settledEnergy(X_, x_);
  variableGradient(X_, x_, g_);
  ++timings_.remeshings;  // the app fetches the mesh anew by this count
  if (best->own) {
    record(0, 0, false);
    history_.back().remeshed = history_.back().cutPanels = true;
  }
}

OptimizeState PatternOptimizer::step(int maxIterations, double maxMillis) {
  if (state_ != OptimizeState::Running) return state_;
  const double t0 = nowMs();
  if (!started_) {
    started_ = true;
    startInterior();
    // Flattened panels whose seam sides differ a lot (a segment far from developable) may fold when
    // projected at once: then the seam lengths are brought together by E_length alone while iterating,
    // and projected exactly only at the end.
    if (options_.search.projectEveryStep) projectTrials_ = projectStart();
    Vertices x;
    int newton = 0;
    const EquilibriumLimits first{measuresOnly() ? kTrialAlignment : EquilibriumLimits{}.alignTolerance};
    bool settled = solveEquilibrium(X_, x_, x, &newton, false, first);
    if (!settled && coarsePhase_) {  // the coarse mesh alone may not settle: the design's mesh from the start
      setUpFlattened();
      ++timings_.remeshings;  // a new mesh, which the app fetches by this count
      settled = solveEquilibrium(X_, x_, x, &newton, false, first);
    }
    if (!settled) {
      finish(OptimizeState::Failed, unsettledReason());
      return state_;
    }
    x_ = std::move(x);
    E_ = settledEnergy(X_, x_);
    if (!measuresOnly()) variableGradient(X_, x_, g_);
    record(0, newton, false);
  }
  for (int k = 0; k < maxIterations; ++k) {
    std::optional<StopReason> stop = stopReason();
    // Whatever ends the coarse phase, the run ends on the design's mesh: the limits are checked again there.
    if (coarsePhase_ &&
        ((stop && stop->state != OptimizeState::Failed) ||
         iteration_ >= std::min(options_.remeshing.coarseIterations, options_.stopping.maxIterations / 2))) {
      if (leaveCoarsePhase()) continue;
      break;
    }
    if (stop) {
      // Converged on this mesh while the panels are meshed anew as they go (sliding seams): a fresh mesh first,
      // whose discretization may lead off where this one stopped (three sliding gores at 400 elements stall on
      // their symmetric layout, a minimum of that mesh only: bench/README.md "Sliding seams").
      const bool remeshFirst = stop->state == OptimizeState::Converged && stop->thisMesh && sliding_ &&
                               options_.remeshing.every > 0 && timings_.remeshings < options_.remeshing.maxRemeshings &&
                               remeshedAt_ != iteration_;
      if (!remeshFirst) {
        finish(stop->state, stop->message);
        break;
      }
      remeshedAt_ = iteration_, stalled_ = 0;
      if (remesh()) continue;
      finish(stop->state, stop->message);
      break;
    }
    slideWindow();
    if (options_.remeshing.every > 0 && timings_.remeshings < options_.remeshing.maxRemeshings &&
        (iteration_ - std::max(remeshedAt_, 0) >= options_.remeshing.every || stalledOnThisMesh())) {
      remeshedAt_ = iteration_;
      if (remesh()) continue;
    }
    if (!iterate()) {
      if (S_.empty() && projectTrials_ && iteration_ == 0) {
        // Every trial folded or did not settle once projected: go on with the seam-length penalty alone.
        projectTrials_ = false;
        continue;
      }
      if (S_.empty()) {  // not even a short steepest-descent step helps: a (numerical) minimum
        if (coarsePhase_) {
          if (leaveCoarsePhase()) continue;
          break;
        }
        if (iteration_ == 0)
          finish(OptimizeState::Converged, "no change of the panels brings the inflated shape closer to the target");
        else
          finish(OptimizeState::Converged, "no further decrease along the gradient");
        break;
      }
      S_.clear(), Y_.clear();
    }
    if (maxMillis > 0 && nowMs() - t0 > maxMillis) break;
  }
  timings_.totalMs = elapsedMs();
  return state_;
}

}  // namespace billow
