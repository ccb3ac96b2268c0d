#include "optimize/imls_distance.hpp"

#include <cmath>

#include "util/error.hpp"

namespace billow {

ImlsDistance::ImlsDistance(const TriMesh& target, const ImlsOptions& options)
    : target_(std::make_unique<TriMesh>(target)), blend_(options.blendThreshold) {
  const TriMesh& T = *target_;
  if (T.numVertices() == 0 || T.numTriangles() == 0) throw Error("optimize.empty-target", "The target is empty.");
  projector_ = std::make_unique<SurfaceProjector>(T);
  normals_ = Vertices::Zero(T.numVertices(), 3);
  faceNormals_.resize(T.numTriangles(), 3);
  double edgeSum = 0;
  for (int f = 0; f < T.numTriangles(); ++f) {
    const Eigen::Vector3d a = T.V.row(T.F(f, 0)), b = T.V.row(T.F(f, 1)), c = T.V.row(T.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);  // |n| = 2 x area: area weighting for free
    faceNormals_.row(f) = n.normalized();
    for (int k = 0; k < 3; ++k) normals_.row(T.F(f, k)) += n;
    edgeSum += (b - a).norm() + (c - b).norm() + (a - c).norm();
  }
  for (int v = 0; v < T.numVertices(); ++v) {
    const double len = normals_.row(v).norm();
    if (len > 0) normals_.row(v) /= len;
  }
  h_ = options.supportScale * edgeSum / (3.0 * T.numTriangles());
  origin_ = T.V.colwise().minCoeff().transpose();
  for (int v = 0; v < T.numVertices(); ++v) {
    const Eigen::Vector3d q = (T.V.row(v).transpose() - origin_) / h_;
    grid_[cellKey(int(std::floor(q.x())), int(std::floor(q.y())), int(std::floor(q.z())))].push_back(v);
  }
  bias_ = Eigen::VectorXd::Zero(T.numVertices());
  if (options.correctBias) {
    Eigen::VectorXd b(T.numVertices());
    for (int v = 0; v < T.numVertices(); ++v) {
      double d = 0, S = 0;
      b[v] = imls(T.V.row(v).transpose(), &d, nullptr, &S) ? d : 0;
    }
    bias_ = b;
  }
}

ImlsDistance::~ImlsDistance() = default;

long long ImlsDistance::cellKey(int i, int j, int k) const {
  const long long B = 1 << 20;  // cells per axis far beyond any mesh; offsets keep keys non-negative
  return ((static_cast<long long>(i) + B / 2) * B + (j + B / 2)) * B + (k + B / 2);
}

bool ImlsDistance::imls(const Eigen::Vector3d& x, double* d, Eigen::Vector3d* grad, double* weightSum,
                        Eigen::Vector3d* weightSumGrad) const {
  const Eigen::Vector3d q = (x - origin_) / h_;
  const int ci = int(std::floor(q.x())), cj = int(std::floor(q.y())), ck = int(std::floor(q.z()));
  const double h2 = h_ * h_;
  double N = 0, D = 0;  // numerator and denominator of Eq. 9
  Eigen::Vector3d gN = Eigen::Vector3d::Zero(), gD = Eigen::Vector3d::Zero();
  for (int i = ci - 1; i <= ci + 1; ++i)
    for (int j = cj - 1; j <= cj + 1; ++j)
      for (int k = ck - 1; k <= ck + 1; ++k) {
        const auto it = grid_.find(cellKey(i, j, k));
        if (it == grid_.end()) continue;
        for (int v : it->second) {
          const Eigen::Vector3d r = x - target_->V.row(v).transpose();
          const double s = 1 - r.squaredNorm() / h2;
          if (s <= 0) continue;
          const double s3 = s * s * s, phi = s3 * s;
          const Eigen::Vector3d gphi = (-8.0 * s3 / h2) * r;  // d phi / dx
          const Eigen::Vector3d n = normals_.row(v).transpose();
          const double nr = n.dot(r) - bias_[v];
          N += nr * phi, D += phi;
          gN += phi * n + nr * gphi, gD += gphi;
        }
      }
  *weightSum = D;
  if (D <= 0) return false;
  *d = N / D;
  if (grad) *grad = (gN - *d * gD) / D;
  if (weightSumGrad) *weightSumGrad = gD;
  return true;
}

double ImlsDistance::fallback(const Eigen::Vector3d& x, Eigen::Vector3d* grad) const {
  const SurfacePoint p = projector_->project(x);
  const Eigen::Vector3d n = faceNormals_.row(p.face).transpose(), r = x - position(*target_, p);
  const double len = r.norm();
  // Signed Euclidean distance (continuous across faces, unlike the face-plane distance); the sign from the
  // closest face's side.
  if (len < 1e-12 * h_) {
    if (grad) *grad = n;
    return r.dot(n);
  }
  const double s = r.dot(n) >= 0 ? 1.0 : -1.0;
  if (grad) *grad = s * r / len;
  return s * len;
}

double ImlsDistance::closestDistance(const Eigen::Vector3d& x) const {
  double d = 0;
  projector_->project(x, &d);
  return d;
}

double ImlsDistance::distance(const Eigen::Vector3d& x, Eigen::Vector3d* grad) const {
  double dI = 0, S = 0;
  Eigen::Vector3d gI = Eigen::Vector3d::Zero(), gS = Eigen::Vector3d::Zero();
  const bool inside = imls(x, &dI, &gI, &S, &gS);
  if (inside && S >= blend_) {
    if (grad) *grad = gI;
    return dI;
  }
  Eigen::Vector3d gF;
  const double dF = fallback(x, &gF);
  if (!inside) {
    if (grad) *grad = gF;
    return dF;
  }
  // C1 blend: w = 3t^2 - 2t^3, t = S / blend.
  const double t = S / blend_, w = t * t * (3 - 2 * t), dw = 6 * t * (1 - t) / blend_;
  if (grad) *grad = w * gI + (1 - w) * gF + (dI - dF) * dw * gS;
  return w * dI + (1 - w) * dF;
}

}  // namespace billow
