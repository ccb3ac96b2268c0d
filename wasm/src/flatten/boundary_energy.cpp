// Eq. 14 (Skouras et al. 2014; Wang 2008) with its exact gradient and Hessian. Each term depends on edge
// vectors d = Q_k+1 - Q_k only, so it is differentiated in those vectors and mapped to the vertices by the
// constant matrix A (d = A q_local): grad_q = A^T grad_d, hess_q = A^T hess_d A.
#include "flatten/boundary_energy.hpp"

#include <cmath>
#include <vector>

#include "util/vec2.hpp"

namespace billow {
namespace {

using Mat2 = Eigen::Matrix2d;

// Direction angle alpha(v) = atan2(v_y, v_x): gradient perp(v) / |v|^2 and its Hessian.
Vec2 directionGrad(const Vec2& v) { return Vec2(-v.y(), v.x()) / v.squaredNorm(); }
Mat2 directionHess(const Vec2& v) {
  const double x = v.x(), y = v.y(), r4 = v.squaredNorm() * v.squaredNorm();
  Mat2 h;
  h << 2 * x * y, y * y - x * x, y * y - x * x, -2 * x * y;
  return h / r4;
}

struct Assembler {
  Eigen::VectorXd* grad;
  std::vector<Eigen::Triplet<double>>* triplets;
  int n;
  // Scatter a term over consecutive polygon vertices first, first + 1, ... (mod n).
  void add(int first, const Eigen::MatrixXd& A, const Eigen::VectorXd& gd, const Eigen::MatrixXd& hd) {
    const int k = static_cast<int>(A.cols()) / 2;
    if (grad) {
      const Eigen::VectorXd g = A.transpose() * gd;
      for (int a = 0; a < k; ++a) grad->segment<2>(2 * ((first + a) % n)) += g.segment<2>(2 * a);
    }
    if (!triplets) return;
    const Eigen::MatrixXd h = A.transpose() * hd * A;
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b)
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c)
            triplets->emplace_back(2 * ((first + a) % n) + r, 2 * ((first + b) % n) + c, h(2 * a + r, 2 * b + c));
  }
};

// (1/l)(L - l)^2 on edge j: d = Q_j+1 - Q_j.
double lengthTerm(const Vec2& d, double l, int j, Assembler& out) {
  const double L = d.norm(), r = L - l, w = 1.0 / l;
  if (!out.grad && !out.triplets) return w * r * r;
  const Vec2 u = d / L;
  Eigen::MatrixXd A(2, 4);
  A << -Mat2::Identity(), Mat2::Identity();
  const Mat2 P = Mat2::Identity() - u * u.transpose();
  out.add(j, A, 2 * w * r * u, 2 * w * (u * u.transpose() + (r / L) * P));
  return w * r * r;
}

// lbar (Theta - theta)^2 at vertex j: Theta = pi - alpha(b) + alpha(a), a = Q_j - Q_j-1, b = Q_j+1 - Q_j.
double angleTerm(const Vec2& a, const Vec2& b, double Theta, double theta, double lbar, int j, Assembler& out) {
  const double r = Theta - theta;
  if (!out.grad && !out.triplets) return lbar * r * r;
  Eigen::Vector4d G;
  G << directionGrad(a), -directionGrad(b);
  Eigen::Matrix4d Hab = Eigen::Matrix4d::Zero();
  Hab.topLeftCorner<2, 2>() = directionHess(a);
  Hab.bottomRightCorner<2, 2>() = -directionHess(b);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 6);
  A.block<2, 2>(0, 0) = -Mat2::Identity();
  A.block<2, 2>(0, 2) = Mat2::Identity();
  A.block<2, 2>(2, 2) = -Mat2::Identity();
  A.block<2, 2>(2, 4) = Mat2::Identity();
  out.add(j + out.n - 1, A, 2 * lbar * r * G, 2 * lbar * (G * G.transpose() + r * Hab));
  return lbar * r * r;
}

}  // namespace

Eigen::VectorXd polygonAngles(const Points2& Q) {
  const int n = static_cast<int>(Q.rows());
  Eigen::VectorXd angles(n);
  for (int j = 0; j < n; ++j) {
    const Vec2 a = (Q.row(j) - Q.row((j + n - 1) % n)).transpose();
    const Vec2 b = (Q.row((j + 1) % n) - Q.row(j)).transpose();
    angles[j] = M_PI - std::atan2(cross2(a, b), a.dot(b));
  }
  return angles;
}

double boundaryEnergy(const Points2& Q, const BoundaryTargets& targets, Eigen::VectorXd* grad,
                      Eigen::SparseMatrix<double>* hess) {
  const int n = static_cast<int>(Q.rows());
  std::vector<Eigen::Triplet<double>> triplets;
  if (grad) *grad = Eigen::VectorXd::Zero(2 * n);
  if (hess) triplets.reserve(16 * n + 36 * n);
  Assembler out{grad, hess ? &triplets : nullptr, n};
  const Eigen::VectorXd Theta = polygonAngles(Q);
  double energy = 0;
  for (int j = 0; j < n; ++j) {
    const int prev = (j + n - 1) % n, next = (j + 1) % n;
    const Vec2 a = (Q.row(j) - Q.row(prev)).transpose(), b = (Q.row(next) - Q.row(j)).transpose();
    const double lbar = 0.5 * (targets.length[prev] + targets.length[j]);
    energy += lengthTerm(b, targets.length[j], j, out);
    energy += angleTerm(a, b, Theta[j], targets.angle[j], lbar, j, out);
  }
  if (hess) {
    hess->resize(2 * n, 2 * n);
    hess->setFromTriplets(triplets.begin(), triplets.end());
  }
  return energy;
}

}  // namespace billow
