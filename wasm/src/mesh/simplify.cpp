#include "mesh/simplify.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <queue>
#include <vector>

namespace billow {

namespace {

// A collapse of edge (a, b) into a, with the stamps of a and b when it was costed: a collapse that moved either
// since is stale. Its point is found again when it is made (the heap holds millions: small entries stay in cache).
struct Collapse {
  double cost = 0;
  int a = -1, b = -1;
  unsigned stampA = 0, stampB = 0;
};

// Cheapest first; equal costs by their vertices, so the copy does not depend on the heap's order.
struct CostlierFirstOut {
  bool operator()(const Collapse& x, const Collapse& y) const {
    if (x.cost != y.cost) return x.cost > y.cost;
    if (x.a != y.a) return x.a > y.a;
    return x.b > y.b;
  }
};

// 4 sqrt(3) area / (sum of squared edges): 1 for an equilateral triangle, 0 for a degenerate one.
double triangleShape(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  const double edges2 = (p1 - p0).squaredNorm() + (p2 - p1).squaredNorm() + (p0 - p2).squaredNorm();
  if (edges2 <= 0) return 0;
  return 2 * std::sqrt(3.0) * (p1 - p0).cross(p2 - p0).norm() / edges2;
}

// A collapse may leave no triangle this much less well shaped (unless it was already), nor turn a triangle's normal
// by more than about 75 degrees: a coarse copy with needles or folds would mislead the geodesics and the flattening
// that run on it.
constexpr double kMinShape = 0.1, kMinNormalCosine = 0.25;
constexpr double kLengthCost = 1e-4;  // times an edge's length^4, added to its cost (costed)

class Simplifier {
 public:
  explicit Simplifier(const TriMesh& mesh)
      : position_(size_t(mesh.numVertices())),
        face_(size_t(mesh.numTriangles())),
        faceAlive_(size_t(mesh.numTriangles()), 1),
        vertexFaces_(size_t(mesh.numVertices())),
        quadric_(size_t(mesh.numVertices()), Eigen::Matrix4d::Zero()),
        stamp_(size_t(mesh.numVertices()), 0),
        fixed_(size_t(mesh.numVertices()), 0),
        aliveFaces_(mesh.numTriangles()) {
    for (int v = 0; v < mesh.numVertices(); ++v) position_[size_t(v)] = mesh.V.row(v).transpose();
    std::vector<std::uint64_t> edges;  // each triangle's three, an edge once per triangle it is on
    edges.reserve(size_t(3 * mesh.numTriangles()));
    for (int f = 0; f < mesh.numTriangles(); ++f) {
      std::array<int, 3>& t = face_[size_t(f)];
      for (int k = 0; k < 3; ++k) t[size_t(k)] = mesh.F(f, k);
      for (int k = 0; k < 3; ++k) {
        vertexFaces_[size_t(t[size_t(k)])].push_back(f);
        edges.push_back(edgeKey(t[size_t(k)], t[size_t((k + 1) % 3)]));
      }
      // Each triangle's plane, weighted by its area (Garland and Heckbert's K_p), on each of its corners.
      const Eigen::Vector3d p0 = position_[size_t(t[0])], p1 = position_[size_t(t[1])], p2 = position_[size_t(t[2])];
      const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
      const double twiceArea = n.norm();
      if (twiceArea <= 0) continue;
      Eigen::Vector4d plane;
      plane << n / twiceArea, -n.dot(p0) / twiceArea;
      const Eigen::Matrix4d k = 0.5 * twiceArea * plane * plane.transpose();
      for (int c : t) quadric_[size_t(c)] += k;
    }
    // A boundary or a non-manifold edge stays as it is: the copy keeps the target's topology and its rims.
    std::sort(edges.begin(), edges.end());
    std::vector<std::uint64_t> shared;  // by exactly two triangles
    for (size_t i = 0, j = 0; i < edges.size(); i = j) {
      for (j = i; j < edges.size() && edges[j] == edges[i];) ++j;
      if (j - i == 2)
        shared.push_back(edges[i]);
      else
        fixed_[size_t(edges[i] >> 32)] = fixed_[size_t(edges[i] & 0xffffffffu)] = 1;
    }
    std::vector<Collapse> collapses;
    collapses.reserve(shared.size());
    for (const std::uint64_t key : shared) {
      const int a = int(key >> 32), b = int(key & 0xffffffffu);
      if (!fixed_[size_t(a)] && !fixed_[size_t(b)]) collapses.push_back(costed(a, b));
    }
    heap_ = decltype(heap_)(CostlierFirstOut(), std::move(collapses));
  }

  TriMesh run(int triangles) {
    while (aliveFaces_ > triangles && !heap_.empty()) {
      const Collapse c = heap_.top();
      heap_.pop();
      // Stale: a vertex collapsed away or moved since (a collapse stamps both its vertices).
      if (stamp_[size_t(c.a)] != c.stampA || stamp_[size_t(c.b)] != c.stampB) continue;
      if (aliveFaces_ - 2 < triangles) break;
      Eigen::Vector3d p;
      costed(c.a, c.b, &p);
      if (!keepsSurface(c.a, c.b, p)) continue;
      collapse(c.a, c.b, p);
    }
    return compacted();
  }

 private:
  // The vertices sharing a triangle with v, into `out` (kept between calls: millions of them).
  void neighbours(int v, std::vector<int>& out) const {
    out.clear();
    for (int f : vertexFaces_[size_t(v)])
      for (int c : face_[size_t(f)])
        if (c != v) out.push_back(c);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  // The collapse of (a, b) to the point of least error: where the quadric's minimum is not unique (a flat or a
  // cylindrical patch), the one nearest the edge's midpoint, along the directions the quadric does not hold.
  Collapse costed(int a, int b, Eigen::Vector3d* at = nullptr) const {
    const Eigen::Matrix4d q = quadric_[size_t(a)] + quadric_[size_t(b)];
    const Eigen::Matrix3d A = q.topLeftCorner<3, 3>();
    const Eigen::Vector3d rhs = -q.topRightCorner<3, 1>();
    const Eigen::Vector3d mid = 0.5 * (position_[size_t(a)] + position_[size_t(b)]);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(A);
    const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
    Eigen::Vector3d p = mid;
    const Eigen::Vector3d residual = rhs - A * mid;
    for (int k = 0; k < 3; ++k) {
      const double lambda = eig.eigenvalues()(k);
      if (lambda > 1e-6 * largest && lambda > 0) {
        const Eigen::Vector3d e = eig.eigenvectors().col(k);
        p += e.dot(residual) / lambda * e;
      }
    }
    // Never farther than the edge's length from its midpoint: the minimum of a nearly singular quadric can lie
    // far away, where the planes it sums no longer describe the surface.
    const double length = (position_[size_t(a)] - position_[size_t(b)]).norm();
    if ((p - mid).norm() > length) p = mid;
    if (at) *at = p;
    Collapse c;
    c.a = a, c.b = b;
    c.stampA = stamp_[size_t(a)], c.stampB = stamp_[size_t(b)];
    const Eigen::Vector4d h(p.x(), p.y(), p.z(), 1);
    // Plus a little of the edge's length: where the surface is flat (a scan's planar stretch, a mesh split in four)
    // every collapse is free, and shorter edges first keep the triangles even instead of fanning out of one vertex.
    c.cost = std::max(0.0, h.dot(q * h)) + kLengthCost * std::pow(length, 4);
    return c;
  }

  // Whether collapsing (a, b) into p leaves a manifold of the same topology (the link condition: a and b have
  // exactly the two neighbours of the triangles on their edge in common) whose triangles neither turn over nor
  // become needles.
  bool keepsSurface(int a, int b, const Eigen::Vector3d& p) {
    neighbours(a, aroundA_);
    neighbours(b, aroundB_);
    size_t common = 0;
    for (size_t i = 0, j = 0; i < aroundA_.size() && j < aroundB_.size();)
      if (aroundA_[i] < aroundB_[j])
        ++i;
      else if (aroundB_[j] < aroundA_[i])
        ++j;
      else
        ++common, ++i, ++j;
    if (common != 2) return false;
    if (aroundA_.size() + aroundB_.size() <= 6) return false;  // a tetrahedron's last collapse
    for (int v : {a, b})
      for (int f : vertexFaces_[size_t(v)]) {
        const std::array<int, 3>& t = face_[size_t(f)];
        if (std::count(t.begin(), t.end(), a) + std::count(t.begin(), t.end(), b) == 2) continue;  // removed
        std::array<Eigen::Vector3d, 3> before, after;
        for (int k = 0; k < 3; ++k) {
          before[size_t(k)] = position_[size_t(t[size_t(k)])];
          after[size_t(k)] = t[size_t(k)] == a || t[size_t(k)] == b ? p : before[size_t(k)];
        }
        const Eigen::Vector3d n0 = (before[1] - before[0]).cross(before[2] - before[0]);
        const Eigen::Vector3d n1 = (after[1] - after[0]).cross(after[2] - after[0]);
        if (n1.dot(n0) <= kMinNormalCosine * n0.norm() * n1.norm()) return false;
        const double shape = triangleShape(after[0], after[1], after[2]);
        if (shape < kMinShape && shape < triangleShape(before[0], before[1], before[2])) return false;
      }
    return true;
  }

  void collapse(int a, int b, const Eigen::Vector3d& p) {
    std::vector<int>& facesOfA = vertexFaces_[size_t(a)];
    for (int f : vertexFaces_[size_t(b)]) {
      std::array<int, 3>& t = face_[size_t(f)];
      if (std::find(t.begin(), t.end(), a) != t.end()) {
        faceAlive_[size_t(f)] = 0;
        --aliveFaces_;
        for (int c : t)
          if (c != b) {
            std::vector<int>& list = vertexFaces_[size_t(c)];
            list.erase(std::find(list.begin(), list.end(), f));
          }
      } else {
        std::replace(t.begin(), t.end(), b, a);
        facesOfA.push_back(f);
      }
    }
    vertexFaces_[size_t(b)].clear();
    position_[size_t(a)] = p;
    quadric_[size_t(a)] += quadric_[size_t(b)];
    ++stamp_[size_t(a)];
    ++stamp_[size_t(b)];
    neighbours(a, aroundA_);
    for (int w : aroundA_)
      if (!fixed_[size_t(w)]) heap_.push(costed(a, w));
  }

  TriMesh compacted() const {
    std::vector<int> index(position_.size(), -1);
    int vertices = 0;
    for (size_t f = 0; f < face_.size(); ++f)
      if (faceAlive_[f])
        for (int c : face_[f])
          if (index[size_t(c)] < 0) index[size_t(c)] = vertices++;
    TriMesh out;
    out.V.resize(vertices, 3);
    out.F.resize(aliveFaces_, 3);
    for (size_t v = 0; v < position_.size(); ++v)
      if (index[v] >= 0) out.V.row(index[v]) = position_[v].transpose();
    int row = 0;
    for (size_t f = 0; f < face_.size(); ++f)
      if (faceAlive_[f]) {
        for (int k = 0; k < 3; ++k) out.F(row, k) = index[size_t(face_[f][size_t(k)])];
        ++row;
      }
    return out;
  }

  std::vector<Eigen::Vector3d> position_;
  std::vector<std::array<int, 3>> face_;
  std::vector<char> faceAlive_;
  std::vector<std::vector<int>> vertexFaces_;
  std::vector<Eigen::Matrix4d> quadric_;
  std::vector<unsigned> stamp_;
  std::vector<char> fixed_;
  int aliveFaces_ = 0;
  std::vector<int> aroundA_, aroundB_;  // neighbours' scratch
  std::priority_queue<Collapse, std::vector<Collapse>, CostlierFirstOut> heap_;
};

}  // namespace

TriMesh simplifiedCopy(const TriMesh& mesh, int triangles) {
  if (mesh.numTriangles() <= triangles) return mesh;
  return Simplifier(mesh).run(triangles);
}

std::optional<TriMesh> workingCopy(const TriMesh& target) {
  if (target.numTriangles() <= 2 * kWorkingTargetTriangles) return std::nullopt;
  return simplifiedCopy(target, kWorkingTargetTriangles);
}

}  // namespace billow
