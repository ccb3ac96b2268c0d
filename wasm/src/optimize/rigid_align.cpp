#include "optimize/rigid_align.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "util/skew.hpp"

namespace billow {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// E_target + E_cover + E_seam at x (as PatternObjective::shapeEnergy), and its Gauss-Newton normal equations in
// (rotation vector, translation) about `center`: one pass over the IMLS distances serves both, since each accepted
// trial's energy is the next step's linearization point.
double evaluate(const PatternObjective& obj, const Eigen::VectorXd& w, const Vertices& x, const Eigen::Vector3d& center,
                Matrix6d& H, Vector6d& g) {
  H.setZero(), g.setZero();
  double E = 0;
  Eigen::Vector3d n;
  for (int i = 0; i < x.rows(); ++i) {
    if (w[i] == 0) continue;
    const Eigen::Vector3d xi = x.row(i).transpose();
    const double d = obj.targetDistance(i, xi, &n);
    Vector6d J;
    J << (xi - center).cross(n), n;  // d(d)/d(omega, t)
    E += w[i] * d * d;
    H += w[i] * J * J.transpose(), g += w[i] * d * J;
  }
  std::vector<PatternObjective::CoverPoint> cover;
  obj.coverPoints(x, cover);
  for (const auto& c : cover) {
    // E_cover's residual is the distance |c - t|: moved rigidly, c slides over the shape too, which changes the
    // distance only to second order, so only the motion along u = (c - t) / |c - t| counts (point-to-plane;
    // the point-to-point Jacobian converged linearly, hundreds of steps per alignment).
    const Eigen::Vector3d r = c.closest - c.target;
    const double d = r.norm();
    // The robust kernel by iteratively reweighted least squares: rho(d) enters as irls * d^2, irls = rho'(d)/(2d)
    // at the current d, which gives the kernel's exact gradient (a point far from the shape weighs little).
    double irls = 1;
    E += c.weight * PatternObjective::coverKernel(d * d, c.tau2, &irls);
    if (!(d > 0)) continue;
    const Eigen::Vector3d u = r / d;
    Vector6d J;
    J << (c.closest - center).cross(u), u;
    H += c.weight * irls * J * J.transpose(), g += c.weight * irls * d * J;
  }
  for (const auto& s : obj.seamVertices()) {
    // Same weight as PatternObjective::shapeEnergy's seam term (w_s sigma / (n D^2)).
    const double ws = obj.seamWeight(s);
    const Eigen::Vector3d xi = x.row(s.vertex).transpose();
    Eigen::Matrix<double, 3, 6> J;
    J << -skew(xi - center), Eigen::Matrix3d::Identity();
    E += ws * (xi - s.target).squaredNorm();
    H += ws * J.transpose() * J, g += ws * J.transpose() * (xi - s.target);
  }
  return E;
}

void applyRigid(Vertices& x, const Eigen::Vector3d& center, const Vector6d& step) {
  const double angle = step.head<3>().norm();
  const Eigen::Matrix3d R =
      angle > 0 ? Eigen::AngleAxisd(angle, step.head<3>() / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
  for (int i = 0; i < x.rows(); ++i)
    x.row(i) = (R * (x.row(i).transpose() - center) + center + step.tail<3>()).transpose();
}

// E's own Hessian in (omega, t) at x, halved as H is, by forward differences of g (six evaluations), in the scaled
// variables of the step (S = diag(D, D, D, 1, 1, 1)). Clamped below at 1e-6 of its largest eigenvalue: along a free
// direction (a lens sliding around a sphere) the damping alone would bound the step.
Matrix6d scaledDifferencedHessian(const PatternObjective& obj, const Eigen::VectorXd& w, const Vertices& x,
                                  const Eigen::Vector3d& center, const Vector6d& g, const Vector6d& S, double D) {
  Matrix6d Hd;
  for (int k = 0; k < 6; ++k) {
    const double h = k < 3 ? 1e-6 : 1e-6 * D;  // radians, meters
    Vector6d e = Vector6d::Zero();
    e[k] = h;
    Vertices moved = x;
    applyRigid(moved, center, e);
    Matrix6d Hk;
    Vector6d gk;
    evaluate(obj, w, moved, center, Hk, gk);
    Hd.col(k) = (gk - g) / h;
  }
  const Matrix6d A = S.asDiagonal() * (0.5 * (Hd + Hd.transpose())) * S.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Matrix6d> es(A);
  const double largest = es.eigenvalues().maxCoeff();
  if (es.info() != Eigen::Success || !(largest > 0)) return Matrix6d::Constant(NAN);
  return es.eigenvectors() * es.eigenvalues().cwiseMax(1e-6 * largest).asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace

int alignRigid(const PatternObjective& objective, const Eigen::VectorXd& X, Vertices& x, int maxIterations,
               double tolerance, double relativeDecrease, const RigidAlignOptions& options) {
  const double D = objective.modelSize();
  const Eigen::VectorXd w = objective.targetWeights(X);
  Eigen::Vector3d center = x.colwise().mean().transpose();
  Matrix6d H;
  Vector6d g;
  double E = evaluate(objective, w, x, center, H, g);
  double mu = 1e-6;
  Matrix6d own = Matrix6d::Constant(NAN);  // E's own Hessian, scaled (after gaussNewtonSteps)
  int it = 0;
  for (; it < maxIterations; ++it) {
    if (!g.allFinite() || g.isZero(0)) break;
    // Rotations are measured in radians, translations in meters: scale the rotation block by D.
    Vector6d s;
    s << Eigen::Vector3d::Constant(D), Eigen::Vector3d::Ones();
    // E's own Hessian once a call: it changes little near the minimum, and each costs six evaluations.
    if (it == options.gaussNewtonSteps) own = scaledDifferencedHessian(objective, w, x, center, g, s, D);
    const Matrix6d A0 = it >= options.gaussNewtonSteps && own.allFinite() ? own : s.asDiagonal() * H * s.asDiagonal();
    bool accepted = false;
    for (int tries = 0; tries < 12 && !accepted; ++tries) {
      Matrix6d A = A0;
      A.diagonal().array() += mu * (A.diagonal().maxCoeff() + 1e-300);
      const Vector6d step = -(s.asDiagonal() * A.ldlt().solve(s.asDiagonal() * g)).eval();
      Vertices trial = x;
      applyRigid(trial, center, step);
      const Eigen::Vector3d trialCenter = trial.colwise().mean().transpose();
      Matrix6d Ht;
      Vector6d gt;
      const double Et = evaluate(objective, w, trial, trialCenter, Ht, gt);
      if (options.stopAtJump && std::isfinite(Et) && Et > E) {
        const Vector6d scaledStep = step.cwiseQuotient(s);
        const double modelChange = std::abs(2 * g.dot(step) + scaledStep.dot(A0 * scaledStep));
        if (modelChange < 1e-9 * E && Et - E > 1e3 * modelChange) return it;
      }
      if (std::isfinite(Et) && Et <= E) {
        const bool small =
            step.head<3>().norm() * D + step.tail<3>().norm() < tolerance * D || E - Et < relativeDecrease * E;
        x = std::move(trial), E = Et, H = Ht, g = gt, center = trialCenter, accepted = true;
        mu = std::max(mu * 0.1, 1e-12);
        if (small) return it + 1;
      } else {
        mu *= 10;
      }
    }
    if (!accepted) break;
  }
  return it;
}

}  // namespace billow
