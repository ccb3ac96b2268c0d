#include "optimize/imls_distance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

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
  // The fallback's pseudo-normals: vertex sums by corner angle, and each edge's two faces.
  angleNormals_ = Vertices::Zero(T.numVertices(), 3);
  faceAcross_.assign(size_t(3) * T.numTriangles(), -1);
  std::unordered_map<std::uint64_t, int> edgeFace;
  edgeFace.reserve(size_t(3) * T.numTriangles());
  const auto edgeKey = [](int u, int v) {
    return (std::uint64_t(std::min(u, v)) << 32) | std::uint32_t(std::max(u, v));
  };
  for (int f = 0; f < T.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = T.F(f, k), u = T.F(f, (k + 1) % 3), w = T.F(f, (k + 2) % 3);
      const Eigen::Vector3d e1 = T.V.row(u) - T.V.row(v), e2 = T.V.row(w) - T.V.row(v);
      angleNormals_.row(v) += std::atan2(e1.cross(e2).norm(), e1.dot(e2)) * faceNormals_.row(f);
      const auto [it, fresh] = edgeFace.emplace(edgeKey(u, w), 3 * f + k);
      if (!fresh && it->second >= 0) {
        faceAcross_[size_t(3) * f + k] = it->second / 3;
        faceAcross_[size_t(it->second)] = f;
        it->second = -1;  // a third face on this edge (non-manifold) keeps its own normal
      }
    }
  h_ = options.supportScale * edgeSum / (3.0 * T.numTriangles());
  origin_ = T.V.colwise().minCoeff().transpose();
  // Cells of size h, the 27 around a query's holding every kernel within h. A long, thin target lying
  // diagonally would need ~(#V / 20)^3 of them: coarser cells bound them by ~8 #V.
  const Eigen::Vector3d extent = T.V.colwise().maxCoeff().transpose() - origin_;
  const auto cells = [&](double size) { return ((extent / size).array().floor() + 1).prod(); };
  cell_ = h_;
  if (!(cells(cell_) < INFINITY)) cell_ = INFINITY;  // degenerate (h = 0): one cell, not an endless loop
  while (cells(cell_) > 8.0 * T.numVertices() + 4096) cell_ *= 1.25;
  std::vector<Eigen::Vector3i> ijk(T.numVertices());
  for (int v = 0; v < T.numVertices(); ++v) {
    const Eigen::Vector3d q = (T.V.row(v).transpose() - origin_) / cell_;
    for (int a = 0; a < 3; ++a) {
      ijk[v][a] = int(std::floor(std::max(0.0, q[a])));  // max: NaN to 0
      dims_[a] = std::max(dims_[a], ijk[v][a] + 1);
    }
  }
  // Counting sort by cell, stable: vertex ids ascend within a cell.
  std::vector<int> cellOf(T.numVertices());
  cellStart_.assign(size_t(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
  for (int v = 0; v < T.numVertices(); ++v) {
    cellOf[v] = (ijk[v].x() * dims_[1] + ijk[v].y()) * dims_[2] + ijk[v].z();
    ++cellStart_[cellOf[v] + 1];
  }
  for (size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  std::vector<int> next(cellStart_.begin(), cellStart_.end() - 1), order(T.numVertices());
  for (int v = 0; v < T.numVertices(); ++v) order[next[cellOf[v]]++] = v;
  kernelPos_.resize(T.numVertices()), kernelNormal_.resize(T.numVertices());
  kernelBias_.assign(T.numVertices(), 0.0);
  for (int k = 0; k < T.numVertices(); ++k) {
    kernelPos_[k] = T.V.row(order[k]).transpose();
    kernelNormal_[k] = normals_.row(order[k]).transpose();
  }
  if (options.correctBias) {
    std::vector<double> b(T.numVertices());
    for (int k = 0; k < T.numVertices(); ++k) {
      double d = 0, S = 0;
      b[k] = imls(kernelPos_[k], &d, nullptr, &S) ? d : 0;
    }
    kernelBias_ = std::move(b);
  }
}

ImlsDistance::~ImlsDistance() = default;

// The sums of Eq. 9 over the kernels reaching x: returns D = sum phi_k and sets N, and with Gradient their
// gradients gN and gD (else left alone).
template <bool Gradient>
double ImlsDistance::accumulate(const Eigen::Vector3d& x, double& sumN, Eigen::Vector3d& sumGN,
                                Eigen::Vector3d& sumGD) const {
  // Local sums: through the references, they might alias the kernels and would be stored at every kernel.
  double N = 0, D = 0;
  Eigen::Vector3d gN = Eigen::Vector3d::Zero(), gD = Eigen::Vector3d::Zero();
  sumN = 0;
  // The 27 cells around x's cell hold every kernel that reaches x (cells are at least h wide).
  const Eigen::Vector3d q = (x - origin_) / cell_;
  // Also keeps NaN and huge coordinates out of the int conversions.
  if (!(q.x() >= -1 && q.x() < dims_[0] + 1 && q.y() >= -1 && q.y() < dims_[1] + 1 && q.z() >= -1 &&
        q.z() < dims_[2] + 1))
    return 0;
  const int ci = int(std::floor(q.x())), cj = int(std::floor(q.y())), ck = int(std::floor(q.z()));
  const int i0 = std::max(ci - 1, 0), i1 = std::min(ci + 1, dims_[0] - 1);
  const int j0 = std::max(cj - 1, 0), j1 = std::min(cj + 1, dims_[1] - 1);
  const int k0 = std::max(ck - 1, 0), k1 = std::min(ck + 1, dims_[2] - 1);
  const double h2 = h_ * h_;
  // Two passes: the kernels within h are gathered first, without a branch per kernel (about two thirds of
  // those visited are farther, at random: mispredictions), then summed, in the same order.
  constexpr int kBatch = 128;
  int near[kBatch];
  double nearR2[kBatch];
  int m = 0;
  const auto sum = [&] {
    for (int t = 0; t < m; ++t) {
      const int v = near[t];
      const Eigen::Vector3d r = x - kernelPos_[v];
      const double s = 1 - nearR2[t] / h2;
      if (s <= 0) continue;
      const double s3 = s * s * s, phi = s3 * s;
      const Eigen::Vector3d& n = kernelNormal_[v];
      const double nr = n.dot(r) - kernelBias_[v];
      N += nr * phi, D += phi;
      if constexpr (Gradient) {
        const Eigen::Vector3d gphi = (-8.0 * s3 / h2) * r;  // d phi / dx
        gN += phi * n + nr * gphi, gD += gphi;
      }
    }
    m = 0;
  };
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j) {
      // A column's cells k0..k1: one contiguous run of kernels.
      const int column = (i * dims_[1] + j) * dims_[2], end = cellStart_[column + k1 + 1];
      for (int v = cellStart_[column + k0]; v < end; ++v) {
        if (m == kBatch) sum();
        const Eigen::Vector3d r = x - kernelPos_[v];
        const double r2 = r.squaredNorm();
        near[m] = v, nearR2[m] = r2;
        m += r2 < h2;  // else s <= 0
      }
    }
  sum();
  sumN = N;
  if constexpr (Gradient) sumGN = gN, sumGD = gD;
  return D;
}

bool ImlsDistance::imls(const Eigen::Vector3d& x, double* d, Eigen::Vector3d* grad, double* weightSum,
                        Eigen::Vector3d* weightSumGrad) const {
  double N = 0;  // numerator and denominator of Eq. 9
  Eigen::Vector3d gN = Eigen::Vector3d::Zero(), gD = Eigen::Vector3d::Zero();
  const double D = grad || weightSumGrad ? accumulate<true>(x, N, gN, gD) : accumulate<false>(x, N, gN, gD);
  *weightSum = D;
  if (D <= 0) return false;
  *d = N / D;
  if (grad) *grad = (gN - *d * gD) / D;
  if (weightSumGrad) *weightSumGrad = gD;
  return true;
}

double ImlsDistance::fallback(const Eigen::Vector3d& x, Eigen::Vector3d* grad, ClosestFaceCache* cache) const {
  SurfacePoint p;
  if (cache && cache->reach >= 0 && (x - cache->center).squaredNorm() <= cache->reach * cache->reach) {
    p = projector_->closestAmong(cache->faces, x);
  } else {
    double d = 0;
    p = projector_->project(x, &d, cache && !cache->faces.empty() ? cache->faces.front() : -1);
    if (cache) {
      // A reach of a fiftieth of the kernels' radius: about ten candidates for a point several edges off the
      // target, and the rigid alignment's steps, most of the evaluations, stay within it (bench/README.md).
      cache->center = x, cache->reach = 0.02 * h_;
      cache->faces.clear();
      projector_->facesWithin(x, d + 2 * cache->reach, cache->faces);
      // The closest first: the next renewal's search hint.
      const auto closest = std::find(cache->faces.begin(), cache->faces.end(), p.face);
      if (closest != cache->faces.end()) std::iter_swap(cache->faces.begin(), closest);
    }
  }
  // The pseudo-normal at p: a vertex's where two weights are zero, an edge's where one is.
  Eigen::Vector3d n = faceNormals_.row(p.face).transpose();
  const int zeros = int(p.bary[0] == 0) + int(p.bary[1] == 0) + int(p.bary[2] == 0);
  if (zeros == 2) {
    int k = 0;
    p.bary.maxCoeff(&k);
    n = angleNormals_.row(target_->F(p.face, k)).transpose();
  } else if (zeros == 1) {
    int k = 0;
    p.bary.minCoeff(&k);
    const int across = faceAcross_[size_t(3) * p.face + k];
    if (across >= 0) n += faceNormals_.row(across).transpose();
  }
  if (n.squaredNorm() > 0) n.normalize();
  const Eigen::Vector3d r = x - position(*target_, p);
  const double len = r.norm();
  // Signed Euclidean distance (continuous across faces, unlike the face-plane distance), signed by the
  // pseudo-normal's side.
  if (len < 1e-12 * h_) {
    if (grad) *grad = n;
    return r.dot(n);
  }
  const double s = r.dot(n) >= 0 ? 1.0 : -1.0;
  if (grad) *grad = s * r / len;
  return s * len;
}

double ImlsDistance::closestDistance(const Eigen::Vector3d& x, int* face) const {
  double d = 0;
  const SurfacePoint p = projector_->project(x, &d, face ? *face : -1);
  if (face) *face = p.face;
  return d;
}

double ImlsDistance::distance(const Eigen::Vector3d& x, Eigen::Vector3d* grad, ClosestFaceCache* cache) const {
  double dI = 0, S = 0;
  Eigen::Vector3d gI = Eigen::Vector3d::Zero(), gS = Eigen::Vector3d::Zero();
  // Without grad, no gradients at all (the optimizer's energy-only evaluations).
  const bool inside = imls(x, &dI, grad ? &gI : nullptr, &S, grad ? &gS : nullptr);
  if (inside && S >= blend_) {
    if (grad) *grad = gI;
    return dI;
  }
  Eigen::Vector3d gF;
  const double dF = fallback(x, grad ? &gF : nullptr, cache);
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
