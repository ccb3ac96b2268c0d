#include "optimize/adjoint.hpp"

#include <cmath>

namespace billow {

std::vector<int> rigidPins(const Vertices& x) {
  const int n = static_cast<int>(x.rows());
  if (n < 3) return {};
  const Eigen::Vector3d a = x.row(0);
  int b = 0, c = 0;
  double best = -1;
  for (int v = 0; v < n; ++v)
    if (const double d = (x.row(v).transpose() - a).squaredNorm(); d > best) best = d, b = v;
  const Eigen::Vector3d ab = (x.row(b).transpose() - a).normalized();
  best = -1;
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector3d r = x.row(v).transpose() - a;
    if (const double d = (r - r.dot(ab) * ab).squaredNorm(); d > best) best = d, c = v;
  }
  const Eigen::Vector3d normal = ab.cross(x.row(c).transpose() - a);
  int ia = 0, in = 0;
  ab.cwiseAbs().maxCoeff(&ia);      // b slides along its dominant axis
  normal.cwiseAbs().maxCoeff(&in);  // c keeps its coordinate along the plane normal
  std::vector<int> pins = {0, 1, 2};
  for (int k = 0; k < 3; ++k)
    if (k != ia) pins.push_back(3 * b + k);
  pins.push_back(3 * c + in);
  return pins;
}

void removeRigidPart(const Vertices& x, Eigen::VectorXd& b) {
  const int n = static_cast<int>(x.rows());
  if (n < 3 || b.size() != 3 * n) return;
  const Eigen::Vector3d center = x.colwise().mean().transpose();
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d r = x.row(i).transpose() - center, f = b.segment<3>(3 * i);
    force += f, torque += r.cross(f);
    inertia += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
  }
  // b_i -= t + omega x r_i, the rigid motion (t, omega) nearest b: translations and rotations about the centroid
  // are orthogonal, so t is the mean and omega solves the inertia tensor against the torque.
  const Eigen::Vector3d t = force / n, omega = inertia.ldlt().solve(torque);
  if (!omega.allFinite()) return;
  for (int i = 0; i < n; ++i) b.segment<3>(3 * i) -= t + omega.cross(x.row(i).transpose() - center);
}

double solveAdjoint(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& b, const std::vector<int>& pins,
                    Eigen::VectorXd& lambda) {
  PinnedStiffness s;
  return s.solve(K, b, pins, lambda);
}

bool PinnedStiffness::solveAgain(const Eigen::VectorXd& b, Eigen::VectorXd& y) const {
  if (kind_ == Kind::None || b.size() != static_cast<long>(pinned_.size())) return false;
  Eigen::VectorXd rhs = b;
  for (long i = 0; i < rhs.size(); ++i)
    if (pinned_[i]) rhs[i] = 0;
  if (kind_ == Kind::Cholesky)
    cholesky_.solve(y = rhs);
  else
    y = kind_ == Kind::Lu ? Eigen::VectorXd(lu_.solve(rhs)) : Eigen::VectorXd(ldlt_.solve(rhs));
  for (long i = 0; i < y.size(); ++i)
    if (pinned_[i]) y[i] = 0;
  return y.allFinite();
}

double PinnedStiffness::solve(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& b,
                              const std::vector<int>& pins, Eigen::VectorXd& lambda) {
  kind_ = Kind::None;
  const int n = static_cast<int>(K.rows());
  std::vector<char>& pinned = pinned_;
  pinned.assign(n, 0);
  for (int p : pins) pinned[p] = 1;
  const double scale = K.diagonal().cwiseAbs().mean();
  // A DOF without any stiffness (a vertex whose triangles are all slack and carry no pressure: the inside of
  // a slack internal panel) is free at equilibrium: nothing there moves the shape, so lambda = 0 there, like
  // a pin. Left in, its zero row makes K singular and no factorization would succeed.
  Eigen::VectorXd rowMax = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
      rowMax[it.row()] = std::max(rowMax[it.row()], std::abs(it.value()));
  for (int i = 0; i < n; ++i)
    if (!(rowMax[i] > 1e-14 * scale)) pinned[i] = 1;
  Eigen::VectorXd rhs = b;
  for (int i = 0; i < n; ++i)
    if (pinned[i]) rhs[i] = 0;
  const double bn = std::max(rhs.norm(), 1e-300);
  if (n % 3 == 0) {
    // The supernodal Cholesky on K's own lower pattern (pinned rows and columns zeroed, their diagonal the
    // mean), analyzed once per pattern: the same for every iterate on one mesh.
    Eigen::SparseMatrix<double> lower = K.triangularView<Eigen::Lower>();
    lower.makeCompressed();
    for (int j = 0; j < n; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
        if (pinned[it.row()] || pinned[j]) it.valueRef() = it.row() == j ? (scale > 0 ? scale : 1.0) : 0.0;
    const std::vector<int> outer(lower.outerIndexPtr(), lower.outerIndexPtr() + n + 1),
        inner(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros());
    bool diagonal = true;  // the pinned diagonal must be stored
    for (int i = 0; i < n && diagonal; ++i) diagonal = !pinned[i] || lower.coeff(i, i) != 0;
    if (diagonal && (outer != analyzedOuter_ || inner != analyzedInner_)) {
      cholesky_.analyze(lower, Eigen::MatrixXd(), BlockCholesky::Ordering::Amd);
      analyzedOuter_ = outer, analyzedInner_ = inner;
    }
    if (diagonal && cholesky_.factorize(lower)) {
      lambda = rhs;
      cholesky_.solve(lambda);
      for (int i = 0; i < n; ++i)
        if (pinned[i]) lambda[i] = 0;
      Eigen::VectorXd r = K * lambda - rhs;
      for (int i = 0; i < n; ++i)
        if (pinned[i]) r[i] = 0;
      const double relative = lambda.allFinite() ? r.norm() / bn : INFINITY;
      if (relative < 1e-8) {
        kind_ = Kind::Cholesky;
        return relative;
      }
    }
  }
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(K.nonZeros() + n);
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
      if (!pinned[it.row()] && !pinned[it.col()]) trip.emplace_back(it.row(), it.col(), it.value());
  for (int i = 0; i < n; ++i)
    if (pinned[i]) trip.emplace_back(i, i, scale > 0 ? scale : 1.0);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  const auto residual = [&]() { return lambda.allFinite() ? (A * lambda - rhs).norm() / bn : INFINITY; };
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& ldlt = ldlt_;
  ldlt.analyzePattern(A);
  ldlt.factorize(A);
  if (ldlt.info() == Eigen::Success) {
    lambda = ldlt.solve(rhs);
    const double r = residual();
    if (r < 1e-8) {
      kind_ = Kind::Ldlt;
      return r;
    }
  }
  {
    lu_.compute(A);
    if (lu_.info() == Eigen::Success) {
      lambda = lu_.solve(rhs);
      const double r = residual();
      if (r < 1e-6) {
        kind_ = Kind::Lu;
        return r;
      }
    }
  }
  // Nearly singular (soft slack or wrinkled regions, whose shape is not unique): the smallest shift that
  // factorizes, i.e. those soft directions held by a weak spring, as if the sheet had a little stiffness there.
  Eigen::SparseMatrix<double> I(n, n);
  I.setIdentity();
  for (double eps = 1e-10; eps <= 1e-2; eps *= 10) {
    const Eigen::SparseMatrix<double> shifted = A + (eps * (scale > 0 ? scale : 1.0)) * I;
    ldlt.factorize(shifted);
    if (ldlt.info() != Eigen::Success) continue;
    Eigen::VectorXd l = ldlt.solve(rhs);
    if (!l.allFinite() || (shifted * l - rhs).norm() / bn > 1e-6) continue;
    lambda = l;
    kind_ = Kind::Shifted;
    return residual();
  }
  lambda = Eigen::VectorXd::Zero(n);
  return INFINITY;
}

}  // namespace billow
