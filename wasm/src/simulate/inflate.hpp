// Inflation: the equilibrium f(x) = 0 of a sewn pattern under pressure, as a stationary point of
// Pi(x) = sum_e h A_e psi~(C_e) - p V(x) (Skouras et al. 2014, Sec. 4; DESIGN.md "Simulation").
// Newton with a backtracking (Armijo) line search on Pi; the Hessian is the projected (PSD) membrane part
// minus p times the exact volume Hessian, which is indefinite. Without a shift the factorization is a
// modified Cholesky (small or negative pivots raised, InflateOptions::minPivot); a Levenberg-Marquardt shift
// mu * p * l is raised whenever that step is no descent, too long, or the line search fails (or, with
// minPivot = 0 or the simplicial solver, the factorization shows a non-positive pivot), and lowered after
// full steps. Rigid motions are pinned without bias: all of vertex a, two coordinates of b and one of c
// (the reactions vanish at equilibrium because pressure and membrane forces on a closed surface have zero
// resultant and moment). The sparsity pattern is analysed once (AMD ordering, symbolic
// factorization) and reused for every iteration and every later solve on the same mesh.
#pragma once
#include <Eigen/Sparse>
#include <memory>
#include <string>
#include <vector>

#include "simulate/seam_rods.hpp"
#include "simulate/sewn_pattern.hpp"

namespace billow {

// The Newton systems are solved by our multifrontal Cholesky on 3x3 vertex blocks (block_cholesky.hpp), nested
// dissection ordered, the same in native and wasm builds.
struct InflateOptions {
  // When a solve ends (InflationSolver::step).
  // Converged when max |f_i| / (p * l^2) < tolerance: the largest net force on a vertex relative to the pressure
  // load on a patch of mean rest edge length l (the paper stops at 1e-5 too).
  double tolerance = 1e-5;
  // Also converged once an unshifted Newton step would move no vertex by settledStep radii of the sphere with the
  // pattern's area yet raises Pi beyond its round-off: the relaxed membrane is so stiff along its tension that a
  // residual of 1e-4 p l^2 is a move of 1e-8 radii, below what Pi resolves (0: off). The optimizer's line-search
  // trials sat there at 2-400 times the tolerance, halving steps of 1e-9 radii to their Newton budget.
  double settledStep = 1e-6;
  int maxIterations = 1000;
  double maxShift = 1e12;  // fails when the LM shift (in units of p * mean edge length) exceeds this

  // The energy Pi (Eqs. 1-7).
  double band = 1e-4;  // soft-max band of the relaxed energy (MembraneMaterial::band)
  // Seam stiffness (seam_rods.hpp): each seam line resists bending like a rod of stiffness k = seamStiffness p R^4
  // (R: the radius of the sphere with the outer panels' area), so the seams do not crimp at the scale of the mesh
  // and the Mylar balloon converges to Paulsen's shape under refinement (0: off).
  double seamStiffness = 5e-4;
  // When set, these rods instead of the ones seamStiffness gives this mesh: the pattern optimizer fixes them per
  // phase, so its equilibria depend on the panels only through the membrane.
  std::shared_ptr<const SeamRods> seamRods;

  // The Newton step and its line search.
  double armijo = 1e-4;  // sufficient decrease constant
  int maxHalvings = 30;
  // Modified Cholesky while the LM shift is zero: pivots below minPivot (in units of the pressure stiffness p l,
  // like the shift) are raised to it instead of refusing the factorization (0: off), since a free panel edge keeps
  // small positive pivots to the end and a floppy one tiny ones. Once the residual is below smallPivotResidual
  // only non-positive and tiny pivots (< minPivot / 1000) are, and only to minPivot / 1000, so the last steps
  // are nearly exact Newton steps.
  double minPivot = 1;
  double smallPivotResidual = 1;
  // A step moving a vertex by more than maxMoveRadii x the radius of the sphere with the pattern's area is
  // refused (the shift goes up): the energy of an over-inflated sheet is unbounded.
  double maxMoveRadii = 2;

  // The coarse-to-fine start (coarse_start.hpp) for patterns of at least coarseStartTriangles triangles without
  // start positions (0: always the spherical or folded start): each coarser level has coarseStartRatio times
  // fewer triangles and is solved to coarseTolerance within coarseMaxIterations; each prolongated shape gets
  // gaussSeidelSweeps nonlinear Gauss-Seidel sweeps (gauss_seidel.hpp) before Newton takes it up.
  int coarseStartTriangles = 600;
  double coarseStartRatio = 6;
  double coarseTolerance = 1e-3;
  int coarseMaxIterations = 200;
  int gaussSeidelSweeps = 10;
};

// The terms of Pi for these options, shared by InflationSolver, the Gauss-Seidel sweeps (gauss_seidel.hpp) and the
// pattern optimizer: the pattern's material with the options' soft-max band, and options.seamRods when given, else the
// rods of options.seamStiffness on this mesh.
MembraneMaterial membraneMaterial(const Material& material, const InflateOptions& options);
std::shared_ptr<const SeamRods> seamRodsFor(const SewnMesh& mesh, double pressure, const InflateOptions& options);

enum class InflateState { Running, Converged, Failed };
const char* toString(InflateState s);

struct InflateTimings {
  double setupMs = 0, assembleMs = 0, factorMs = 0, lineSearchMs = 0, totalMs = 0;
  int factorizations = 0;
  int raisedPivots = 0;                        // modified Cholesky: pivots raised (InflateOptions::minPivot)
  double factorNonZeros = 0, factorFlops = 0;  // size and multiply-adds of one factorization (supernodal)
};

// Per-triangle fields for display (the compression field predicts wrinkles).
struct TriangleFields {
  std::vector<int> regime;      // #F: 0 slack, 1 wrinkled, 2 taut
  Eigen::VectorXd compression;  // #F, see ElementState
  Vertices direction;           // #F by 3, unit (zero when taut)
  Eigen::VectorXd stress;       // #F max principal stress [Pa]
  Eigen::VectorXd tension;      // #F max principal membrane tension [N/m]
};

struct InflateResult {
  InflateState state = InflateState::Running;
  std::string message;  // designer words; empty when converged
  Vertices positions;   // #V by 3 simulation vertices [m]
  double volume = 0;    // [m^3]
  double energy = 0;    // Pi [J]
  double residual = 0;  // relative force residual (see InflateOptions::tolerance)
  int iterations = 0;
  bool converged = false;
  InflateTimings timings;
  TriangleFields fields;
};

class InflationSolver {
 public:
  // x0: start positions (#V by 3), e.g. the target shape; empty = sphericalStart(mesh) (callers that have the
  // pattern use startPositions, coarse_start.hpp, which inflates a coarser version first). Throws
  // billow::Error("inflate.bad-start") when x0 has another size or invalid coordinates.
  InflationSolver(SewnMesh mesh, const Material& material, double pressure, const InflateOptions& options = {},
                  const Vertices& x0 = {});
  ~InflationSolver();

  // Up to maxIterations Newton iterations or maxMillis of work (<= 0: no limit), whichever first.
  InflateState step(int maxIterations, double maxMillis = 0);

  // Restarts from new positions or pressure, keeping the symbolic factorization.
  void restart(const Vertices& x0, double pressure);
  // Restarts from x0 with new rest shapes of the same triangles (the pattern optimizer's trial panels),
  // keeping the symbolic factorization. Throws billow::Error("inflate.bad-start") on another count.
  void restartWithRest(const std::vector<ElementRest>& rest, const Vertices& x0);
  // The same rods with another coefficient (the pattern optimizer's rods follow its panels: seamRodCoefficientAt),
  // for the next restart.
  void setSeamRodCoefficient(double coefficient);

  InflateState state() const { return state_; }
  const std::string& message() const { return message_; }
  const Vertices& positions() const { return x_; }
  const SewnMesh& mesh() const { return mesh_; }
  int iterations() const { return iterations_; }
  double residual() const { return residual_; }
  const Eigen::VectorXd& gradient() const { return grad_; }  // dPi/dx at the last assembly, pins zeroed
  double energy() const { return energy_; }
  double volume() const;
  const InflateTimings& timings() const { return timings_; }
  double lastStepLength() const { return lastAlpha_; }  // line-search alpha of the last step
  double shift() const { return shift_; }               // current LM shift (relative)
  // Energy before and after every accepted step (tests: it never increases).
  const std::vector<double>& energyHistory() const { return energyHistory_; }
  TriangleFields fields() const;
  InflateResult result() const;

  // Times one numeric factorization of the current Hessian (benchmark floor), in ms.
  double timeFactorization();

 private:
  struct Sparse;
  double totalEnergy(const Vertices& x) const;
  bool assemble();  // gradient + Hessian at x_; false when not finite
  void choosePins();
  void fail(const std::string& message);

  SewnMesh mesh_;
  MembraneMaterial material_;
  double pressure_;
  InflateOptions options_;
  Vertices x_;
  Eigen::VectorXd grad_;
  std::unique_ptr<Sparse> sparse_;
  std::shared_ptr<const SeamRods> rods_;
  std::vector<int> rodSlot_;  // lower Hessian slot of each SeamRods::forEachHessianEntry visit (-1 above)
  std::vector<int> pinned_;   // DOF indices
  double shift_ = 0;          // LM shift, relative to the mean diagonal
  double lastAlpha_ = 0;
  double energy_ = 0, residual_ = 0, forceScale_ = 1;
  double sizeScale_ = 1;  // radius of the sphere with the outer panels' area [m]
  int iterations_ = 0;
  InflateState state_ = InflateState::Running;
  std::string message_;
  InflateTimings timings_;
  std::vector<double> energyHistory_;
};

// One-shot: sew, start (pattern.inflated, else x0, else sphere), solve to convergence.
InflateResult inflate(const Pattern& pattern, const InflateOptions& options = {}, const Vertices& x0 = {});

}  // namespace billow
