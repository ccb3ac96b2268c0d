// Surface points and closest-point projection (see surface_point.hpp). The tree is a median split on the
// longest axis of the triangle centers; queries descend the nearer child first and prune boxes farther
// than the best distance found so far.
#include "seams/surface_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace billow {

Eigen::Vector3d position(const TriMesh& mesh, const SurfacePoint& p) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) x += p.bary[k] * mesh.V.row(mesh.F(p.face, k)).transpose();
  return x;
}

// Voronoi-region tests on the triangle (vertices, then edges, then the interior).
Eigen::Vector3d closestPointBarycentric(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, aq = q - a;
  const double d1 = ab.dot(aq), d2 = ac.dot(aq);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bq = q - b;
  const double d3 = ab.dot(bq), d4 = ac.dot(bq);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const Eigen::Vector3d cq = q - c;
  const double d5 = ab.dot(cq), d6 = ac.dot(cq);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double s = d1 / (d1 - d3);
    return {1 - s, s, 0};
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double s = d2 / (d2 - d6);
    return {1 - s, 0, s};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - s, s};
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};  // degenerate triangle
  const double v = vb / denom, w = vc / denom;
  return {1 - v - w, v, w};
}

SurfaceProjector::SurfaceProjector(const TriMesh& mesh) : mesh_(mesh) {
  const int nf = mesh.numTriangles();
  order_.resize(nf);
  std::vector<Eigen::Vector3d> centers(nf);
  for (int f = 0; f < nf; ++f) {
    order_[f] = f;
    centers[f] = (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3.0;
  }
  nodes_.reserve(2 * nf / 4 + 2);
  if (nf > 0) build(0, nf, centers);
}

int SurfaceProjector::build(int begin, int end, std::vector<Eigen::Vector3d>& centers) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(Node());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  Eigen::Vector3d clo = lo, chi = hi;
  for (int i = begin; i < end; ++i) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d x = mesh_.V.row(mesh_.F(order_[i], k)).transpose();
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    }
    clo = clo.cwiseMin(centers[order_[i]]), chi = chi.cwiseMax(centers[order_[i]]);
  }
  nodes_[id].lo = lo, nodes_[id].hi = hi, nodes_[id].begin = begin, nodes_[id].end = end;
  if (end - begin <= 4) return id;
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const int mid = (begin + end) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return centers[a][axis] < centers[b][axis]; });
  const int l = build(begin, mid, centers);
  const int r = build(mid, end, centers);
  nodes_[id].left = l, nodes_[id].right = r;
  return id;
}

namespace {
double boxDistance2(const Eigen::Vector3d& q, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return (lo - q).cwiseMax(q - hi).cwiseMax(0.0).squaredNorm();
}
}  // namespace

void SurfaceProjector::measure(int f, const Eigen::Vector3d& q, SurfacePoint& best, double& best2) const {
  const Eigen::Vector3d a = mesh_.V.row(mesh_.F(f, 0)), b = mesh_.V.row(mesh_.F(f, 1)), c = mesh_.V.row(mesh_.F(f, 2));
  const Eigen::Vector3d w = closestPointBarycentric(q, a, b, c);
  const double d2 = (w[0] * a + w[1] * b + w[2] * c - q).squaredNorm();
  if (d2 < best2 || (d2 == best2 && f < best.face)) best2 = d2, best.face = f, best.bary = w;
}

SurfacePoint SurfaceProjector::closestAmong(const std::vector<int>& faces, const Eigen::Vector3d& q) const {
  SurfacePoint best;
  double best2 = std::numeric_limits<double>::max();
  for (int f : faces) measure(f, q, best, best2);
  return best;
}

SurfacePoint SurfaceProjector::project(const Eigen::Vector3d& q, double* distance, int hintFace) const {
  SurfacePoint best;
  double best2 = std::numeric_limits<double>::max();
  if (nodes_.empty()) return best;
  if (hintFace >= 0 && hintFace < mesh_.numTriangles()) measure(hintFace, q, best, best2);
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (boxDistance2(q, n.lo, n.hi) > best2) continue;  // not >=: an equally close face may have a lower index
    if (n.left < 0) {
      for (int i = n.begin; i < n.end; ++i) measure(order_[i], q, best, best2);
      continue;
    }
    const double dl = boxDistance2(q, nodes_[n.left].lo, nodes_[n.left].hi);
    const double dr = boxDistance2(q, nodes_[n.right].lo, nodes_[n.right].hi);
    const bool leftFirst = dl <= dr;
    if (top + 2 > 128) continue;  // depth is ~log2(F / 4); never reached for sane meshes
    stack[top++] = leftFirst ? n.right : n.left;
    stack[top++] = leftFirst ? n.left : n.right;
  }
  if (distance) *distance = std::sqrt(best2);
  return best;
}

void SurfaceProjector::facesWithin(const Eigen::Vector3d& q, double radius, std::vector<int>& out) const {
  if (nodes_.empty()) return;
  const double r2 = radius * radius;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (boxDistance2(q, n.lo, n.hi) > r2) continue;
    if (n.left < 0) {
      for (int i = n.begin; i < n.end; ++i) {
        SurfacePoint p;
        double d2 = std::numeric_limits<double>::max();
        measure(order_[i], q, p, d2);
        if (d2 <= r2) out.push_back(order_[i]);
      }
      continue;
    }
    if (top + 2 > 128) continue;
    stack[top++] = n.right;
    stack[top++] = n.left;
  }
}

}  // namespace billow
