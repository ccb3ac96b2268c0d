// Newton equilibrium solver for the inflated shape; see inflate.hpp for the method.
#include "simulate/inflate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simulate/block_cholesky.hpp"
#include "simulate/coarse_start.hpp"
#include "simulate/enclosed_volume.hpp"
#include "simulate/initial_shape.hpp"
#include "util/clock.hpp"
#include "util/error.hpp"

namespace billow {
MembraneMaterial membraneMaterial(const Material& material, const InflateOptions& options) {
  MembraneMaterial m;
  m.youngsModulus = material.youngsModulus;
  m.thickness = material.thickness;
  m.band = options.band;
  return m;
}

std::shared_ptr<const SeamRods> seamRodsFor(const SewnMesh& mesh, double pressure, const InflateOptions& options) {
  if (options.seamRods) return options.seamRods;
  return std::make_shared<const SeamRods>(
      makeSeamRods(mesh, seamRodCoefficient(mesh, pressure, options.seamStiffness)));
}

const char* toString(InflateState s) {
  switch (s) {
    case InflateState::Running:
      return "running";
    case InflateState::Converged:
      return "converged";
    default:
      return "failed";
  }
}

// Lower triangle of the 3n x 3n Hessian (the part SimplicialLDLT reads) with a fixed pattern, and for every
// element the 81 value slots it adds into (-1 for the upper triangle).
struct InflationSolver::Sparse {
  Eigen::SparseMatrix<double> H;
  Eigen::VectorXd values;  // unshifted Hessian values
  std::vector<int> slot;
  std::vector<int> diag;
  std::vector<int> pinnedEntries;
  BlockCholesky chol;

  // Factorizes H; false when it is not positive definite.
  // raisedPivot > 0: modified Cholesky, see BlockCholesky::factorize.
  bool factorize(double tinyPivot = 0, double raisedPivot = 0) { return chol.factorize(H, tinyPivot, raisedPivot); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) {
    Eigen::VectorXd x = b;
    chol.solve(x);
    return x;
  }
};

InflationSolver::InflationSolver(SewnMesh mesh, const Material& material, double pressure,
                                 const InflateOptions& options, const Vertices& x0)
    : mesh_(std::move(mesh)), pressure_(pressure), options_(options), sparse_(std::make_unique<Sparse>()) {
  const auto start = Clock::now();
  material_ = membraneMaterial(material, options);
  if (x0.rows() != 0 && (x0.rows() != mesh_.numVertices || !x0.allFinite()))
    throw Error("inflate.bad-start", "The start shape does not fit the pattern (" + std::to_string(x0.rows()) +
                                         " positions for " + std::to_string(mesh_.numVertices) + " vertices).");
  x_ = x0.rows() == mesh_.numVertices ? x0 : sphericalStart(mesh_);
  const int n = 3 * mesh_.numVertices, F = mesh_.numTriangles();
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(size_t(F) * 45 + n);
  // Visits the lower-triangle Hessian entries (r >= c) of each element, with their slot in the 9x9 block.
  auto forEachLowerEntry = [&](auto visit) {
    for (int f = 0; f < F; ++f)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
              const int r = 3 * mesh_.triangles(f, a) + i, c = 3 * mesh_.triangles(f, b) + j;
              if (r >= c) visit(f, (3 * a + i) * 9 + 3 * b + j, r, c);
            }
  };
  for (int i = 0; i < n; ++i) trip.emplace_back(i, i, 0.0);
  forEachLowerEntry([&](int, int, int r, int c) { trip.emplace_back(r, c, 0.0); });
  rods_ = seamRodsFor(mesh_, pressure, options_);
  rods_->forEachHessianEntry([&](int r, int c, double) {
    if (r >= c) trip.emplace_back(r, c, 0.0);
  });
  Sparse& s = *sparse_;
  s.H.resize(n, n);
  s.H.setFromTriplets(trip.begin(), trip.end());
  s.H.makeCompressed();
  auto find = [&](int r, int c) {
    const int* begin = s.H.innerIndexPtr() + s.H.outerIndexPtr()[c];
    const int* end = s.H.innerIndexPtr() + s.H.outerIndexPtr()[c + 1];
    return int(std::lower_bound(begin, end, r) - s.H.innerIndexPtr());
  };
  s.slot.assign(size_t(F) * 81, -1);
  forEachLowerEntry([&](int f, int k, int r, int c) { s.slot[size_t(f) * 81 + k] = find(r, c); });
  s.diag.resize(n);
  for (int i = 0; i < n; ++i) s.diag[i] = find(i, i);
  rodSlot_.clear();
  rods_->forEachHessianEntry([&](int r, int c, double) { rodSlot_.push_back(r >= c ? find(r, c) : -1); });
  choosePins();
  // Symbolic factorization, once per mesh.
  s.chol.analyze(s.H, x_, BlockCholesky::Ordering::FewerFlops);
  timings_.factorNonZeros = s.chol.factorNonZeros(), timings_.factorFlops = s.chol.factorFlops();
  forceScale_ = std::max(pressure_ * mesh_.meanEdgeLength * mesh_.meanEdgeLength, 1e-300);
  sizeScale_ = std::sqrt(mesh_.outerArea / (4 * M_PI));
  energy_ = totalEnergy(x_);
  if (!std::isfinite(energy_)) fail("The start shape is invalid (a triangle is collapsed). Try another start.");
  timings_.setupMs = msSince(start);
}

InflationSolver::~InflationSolver() = default;

// Pins 6 DOFs against rigid motion: a fully, b across the direction a-b, c across the plane (a, b, c).
void InflationSolver::choosePins() {
  const int n = mesh_.numVertices;
  int a = 0, b = 0, c = 0;
  for (int v = 0; v < n; ++v)
    if ((x_.row(v) - x_.row(a)).squaredNorm() > (x_.row(b) - x_.row(a)).squaredNorm()) b = v;
  const Eigen::Vector3d d = x_.row(b) - x_.row(a);
  double best = -1;
  for (int v = 0; v < n; ++v) {
    const double dist = d.cross(Eigen::Vector3d(x_.row(v) - x_.row(a))).squaredNorm();
    if (dist > best) best = dist, c = v;
  }
  int major = 0;
  d.cwiseAbs().maxCoeff(&major);
  const Eigen::Vector3d normal = d.cross(Eigen::Vector3d(x_.row(c) - x_.row(a)));
  int across = 0;
  normal.cwiseAbs().maxCoeff(&across);
  pinned_ = {3 * a, 3 * a + 1, 3 * a + 2};
  for (int k = 0; k < 3; ++k)
    if (k != major) pinned_.push_back(3 * b + k);
  pinned_.push_back(3 * c + across);
  std::vector<char> isPinned(3 * n, 0);
  for (int p : pinned_) isPinned[p] = 1;
  Sparse& s = *sparse_;
  s.pinnedEntries.clear();
  for (int col = 0; col < 3 * n; ++col)
    for (int k = s.H.outerIndexPtr()[col]; k < s.H.outerIndexPtr()[col + 1]; ++k)
      if ((isPinned[col] || isPinned[s.H.innerIndexPtr()[k]]) && s.H.innerIndexPtr()[k] != col)
        s.pinnedEntries.push_back(k);
}

double InflationSolver::totalEnergy(const Vertices& x) const {
  double e = 0, v = 0;
  for (int f = 0; f < mesh_.numTriangles(); ++f) {
    const Eigen::Vector3d a = x.row(mesh_.triangles(f, 0)), b = x.row(mesh_.triangles(f, 1)),
                          c = x.row(mesh_.triangles(f, 2));
    e += membraneElementEnergy(mesh_.rest[f], a, b, c, material_);
    if (mesh_.outer[f]) v += triangleVolume(a, b, c);
  }
  if (!rods_->empty()) e += rods_->energy(x);
  return e - pressure_ * v;  // Pi = sum h A psi~ + E_seams - p V
}

double InflationSolver::volume() const {
  double v = 0;
  for (int f = 0; f < mesh_.numTriangles(); ++f)
    if (mesh_.outer[f])
      v += triangleVolume(x_.row(mesh_.triangles(f, 0)), x_.row(mesh_.triangles(f, 1)), x_.row(mesh_.triangles(f, 2)));
  return v;
}

bool InflationSolver::assemble() {
  Sparse& s = *sparse_;
  const int n = 3 * mesh_.numVertices;
  grad_.setZero(n);
  s.values.setZero(s.H.nonZeros());
  ElementOptions eo;
  Vector9d g, gv;
  Matrix9d h, hv;
  for (int f = 0; f < mesh_.numTriangles(); ++f) {
    const int* t = &mesh_.triangles(f, 0);
    const Eigen::Vector3d a = x_.row(t[0]), b = x_.row(t[1]), c = x_.row(t[2]);
    membraneElement(mesh_.rest[f], a, b, c, material_, eo, &g, &h);
    if (mesh_.outer[f]) {
      triangleVolumeDerivatives(a, b, c, &gv, &hv);
      g -= pressure_ * gv;
      h -= pressure_ * hv;
    }
    for (int k = 0; k < 3; ++k) grad_.segment<3>(3 * t[k]) += g.segment<3>(3 * k);
    const int* slots = &s.slot[size_t(f) * 81];
    for (int r = 0; r < 9; ++r)
      for (int col = 0; col <= r; ++col)
        if (slots[r * 9 + col] >= 0) s.values[slots[r * 9 + col]] += h(r, col);
    // Upper-triangle local entries (r < col) can still land in the global lower triangle.
    for (int r = 0; r < 9; ++r)
      for (int col = r + 1; col < 9; ++col)
        if (slots[r * 9 + col] >= 0) s.values[slots[r * 9 + col]] += h(r, col);
  }
  if (!rods_->empty()) {
    rods_->addGradient(x_, grad_);
    size_t k = 0;
    rods_->forEachHessianEntry([&](int, int, double value) {
      const int slot = rodSlot_[k++];
      if (slot >= 0) s.values[slot] += value;
    });
  }
  double meanDiag = 0;
  for (int i = 0; i < n; ++i) meanDiag += std::abs(s.values[s.diag[i]]) / n;
  for (int k : s.pinnedEntries) s.values[k] = 0;
  for (int p : pinned_) {
    grad_[p] = 0;
    s.values[s.diag[p]] = meanDiag > 0 ? meanDiag : 1;
  }
  return grad_.allFinite() && s.values.allFinite();
}

void InflationSolver::fail(const std::string& message) {
  state_ = InflateState::Failed;
  message_ = message;
}

InflateState InflationSolver::step(int maxIterations, double maxMillis) {
  const auto start = Clock::now();
  Sparse& s = *sparse_;
  const int n = 3 * mesh_.numVertices;
  for (int done = 0; state_ == InflateState::Running && done < maxIterations; ++done) {
    if (maxMillis > 0 && done > 0 && msSince(start) > maxMillis) break;
    auto t0 = Clock::now();
    if (!assemble()) {
      fail("The simulation broke down (invalid forces). Check the pattern for tiny or overlapping panels.");
      break;
    }
    timings_.assembleMs += msSince(t0);
    residual_ = grad_.lpNorm<Eigen::Infinity>() / forceScale_;
    if (residual_ < options_.tolerance) {
      state_ = InflateState::Converged;
      break;
    }
    if (iterations_ >= options_.maxIterations) {
      fail("The balloon did not settle within " + std::to_string(options_.maxIterations) +
           " iterations; the shape shown is the last one reached.");
      break;
    }
    // The shift is measured in units of the pressure stiffness p * l: the indefinite part of the Hessian is
    // -p d2V (entries ~ p l), while the membrane diagonal (~ E h) is larger by the stiffness ratio.
    const double shiftUnit = pressure_ * mesh_.meanEdgeLength;
    bool accepted = false;
    while (!accepted) {
      if (shift_ > options_.maxShift) break;
      Eigen::Map<Eigen::VectorXd>(s.H.valuePtr(), s.H.nonZeros()) = s.values;
      for (int i = 0; i < n; ++i) s.H.valuePtr()[s.diag[i]] += shift_ * shiftUnit;
      t0 = Clock::now();
      // A failed Cholesky (non-positive pivot) means H + shift is not positive definite: no descent guarantee.
      // Without a shift, small and negative pivots are raised (modified Cholesky) rather than refused: the
      // correction then stays where H is indefinite or nearly singular (slack and wrinkled regions under
      // the pressure's curvature) instead of a shift that damps every direction. A shift comes in only
      // when the modified step fails (no descent, too long, or no decrease along it).
      const bool modified = shift_ == 0 && options_.minPivot > 0;
      const double raised = modified ? options_.minPivot * shiftUnit : 0;
      // Late (residual below smallPivotResidual), tiny pivots are raised only to the tiny threshold: a
      // floppy free flap of an internal panel has a genuine stiffness far below p * l, and raised to p * l
      // every full step moved it a thousandth of the way (open-tipped panels at 500-1000 triangles crept
      // at residual ~3e-5 for 1000 iterations; now they settle in 175-312).
      const bool late = residual_ <= options_.smallPivotResidual;
      const bool factored = late ? s.factorize(1e-3 * raised, 1e-3 * raised) : s.factorize(raised, raised);
      if (modified) timings_.raisedPivots += s.chol.raisedPivots();
      ++timings_.factorizations;
      timings_.factorMs += msSince(t0);
      if (!factored) {
        shift_ = shift_ == 0 ? 1e-3 : shift_ * 10;
        continue;
      }
      const Eigen::VectorXd d = -s.solve(grad_);
      const double slope = grad_.dot(d);
      // A step longer than maxMoveRadii balloon radii is no Newton step to trust: the energy of a neo-Hookean
      // balloon is unbounded below (past its limit point it blows up), and a wild step could find that.
      double longest = 0;
      for (int v = 0; v < mesh_.numVertices; ++v) longest = std::max(longest, d.segment<3>(3 * v).squaredNorm());
      if (!d.allFinite() || !(slope < 0) || std::sqrt(longest) > options_.maxMoveRadii * sizeScale_) {
        shift_ = shift_ == 0 ? 1e-3 : shift_ * 10;
        continue;
      }
      t0 = Clock::now();
      double alpha = 1;
      const bool settledStep = shift_ == 0 && std::sqrt(longest) < options_.settledStep * sizeScale_;
      for (int k = 0; k <= options_.maxHalvings; ++k, alpha *= 0.5) {
        Vertices trial = x_ + alpha * Eigen::Map<const Vertices>(d.data(), mesh_.numVertices, 3);
        const double e = totalEnergy(trial);
        // Armijo on Pi, with a round-off allowance: Pi is a difference of large terms near convergence.
        const double roundoff = 64 * std::numeric_limits<double>::epsilon() * std::abs(energy_);
        const bool decrease = std::isfinite(e) && e <= energy_ + options_.armijo * alpha * slope + roundoff;
        // An unshifted Newton step this short that raises Pi beyond its round-off: the shape is where Pi can place
        // it, and the residual is above tolerance only through the membrane's stiffness (halving on took steps of
        // 1e-9 radii to the iteration limit).
        if (k == 0 && settledStep && !decrease) {
          state_ = InflateState::Converged;
          accepted = true;
          break;
        }
        if (decrease) {
          energyHistory_.push_back(energy_);
          energyHistory_.push_back(e);
          x_ = std::move(trial);
          energy_ = e;
          accepted = true;
          lastAlpha_ = alpha;
          break;
        }
      }
      timings_.lineSearchMs += msSince(t0);
      // Damping grows only when no step is found: raising it after short steps (classic LM) was tried and
      // cost 40 % more iterations on the Mylar balloon.
      if (!accepted)
        shift_ = shift_ == 0 ? 1e-3 : shift_ * 10;
      else if (alpha == 1)
        shift_ = shift_ < 2e-3 ? 0 : shift_ / 10;
    }
    if (state_ == InflateState::Converged) break;
    if (!accepted) {
      fail(
          "The simulation is stuck (no step lowers the energy). The pattern may not hold pressure; the shape "
          "shown is the last good one.");
      break;
    }
    ++iterations_;
  }
  timings_.totalMs += msSince(start);
  return state_;
}

void InflationSolver::restart(const Vertices& x0, double pressure) {
  if (x0.rows() != mesh_.numVertices)
    throw Error("inflate.bad-start", "The start shape has the wrong number of vertices.");
  x_ = x0;
  pressure_ = pressure;
  forceScale_ = std::max(pressure_ * mesh_.meanEdgeLength * mesh_.meanEdgeLength, 1e-300);
  iterations_ = 0;
  shift_ = 0;
  state_ = InflateState::Running;
  message_.clear();
  energyHistory_.clear();
  energy_ = totalEnergy(x_);
  if (!std::isfinite(energy_)) fail("The start shape is invalid (a triangle is collapsed). Try another start.");
}

void InflationSolver::restartWithRest(const std::vector<ElementRest>& rest, const Vertices& x0) {
  if (rest.size() != mesh_.rest.size())
    throw Error("inflate.bad-start", "The panels' rest shapes do not fit the pattern.");
  mesh_.rest = rest;
  restart(x0, pressure_);
}

void InflationSolver::setSeamRodCoefficient(double coefficient) {
  if (rods_->coefficient == coefficient) return;
  auto rods = std::make_shared<SeamRods>(*rods_);
  rods->coefficient = coefficient;
  rods_ = std::move(rods);
}

double InflationSolver::timeFactorization() {
  assemble();
  Sparse& s = *sparse_;
  Eigen::Map<Eigen::VectorXd>(s.H.valuePtr(), s.H.nonZeros()) = s.values;
  const auto t0 = Clock::now();
  s.factorize();
  const double ms = msSince(t0);
  return ms;
}

TriangleFields InflationSolver::fields() const {
  const int F = mesh_.numTriangles();
  TriangleFields out;
  out.regime.resize(F);
  out.compression.resize(F);
  out.direction.resize(F, 3);
  out.stress.resize(F);
  out.tension.resize(F);
  for (int f = 0; f < F; ++f) {
    const ElementState st =
        membraneElementState(mesh_.rest[f], x_.row(mesh_.triangles(f, 0)), x_.row(mesh_.triangles(f, 1)),
                             x_.row(mesh_.triangles(f, 2)), material_);
    out.regime[f] = int(st.regime);
    out.compression[f] = st.compression;
    out.direction.row(f) = st.direction.transpose();
    out.stress[f] = st.stress;
    out.tension[f] = st.tension;
  }
  return out;
}

InflateResult InflationSolver::result() const {
  InflateResult r;
  r.state = state_;
  r.message = message_;
  r.positions = x_;
  r.volume = volume();
  r.energy = energy_;
  r.residual = residual_;
  r.iterations = iterations_;
  r.converged = state_ == InflateState::Converged;
  r.timings = timings_;
  r.fields = fields();
  return r;
}

InflateResult inflate(const Pattern& pattern, const InflateOptions& options, const Vertices& x0) {
  SewnMesh mesh = sewPattern(pattern);
  Vertices start = x0;
  if (start.rows() != mesh.numVertices) start = startPositions(pattern, mesh, options);
  InflationSolver solver(std::move(mesh), pattern.material, pattern.pressure, options, start);
  while (solver.step(50) == InflateState::Running) {
  }
  return solver.result();
}

}  // namespace billow
