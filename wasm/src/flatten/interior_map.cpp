// Laplacian interior solve and flip repair for the initial flattening (Skouras et al. 2014, Sec. 5.2).
// Positive weights with a convex boundary give an embedding (Tutte; Floater 2003); the cotangent weights are
// clamped to stay positive, and uniform weights are the fallback. A non-convex boundary can still force
// flips: those are repaired locally, vertex by vertex, by raising the smallest signed area of its triangles.
#include "flatten/interior_map.hpp"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "util/vec2.hpp"

namespace billow {
namespace {

using Triplet = Eigen::Triplet<double>;

double signedArea2(const Points2& uv, int a, int b, int c) {
  return cross2((uv.row(b) - uv.row(a)).transpose(), (uv.row(c) - uv.row(a)).transpose());
}

// Symmetric edge weights w_ij (#V by #V): 1 per edge, or (cot alpha + cot beta) / 2 measured in 3D.
Eigen::SparseMatrix<double> edgeWeights(const TriMesh& m, LaplacianWeights weights, double clamp) {
  std::vector<Triplet> t;
  t.reserve(6 * m.numTriangles());
  for (int f = 0; f < m.numTriangles(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int i = m.F(f, (c + 1) % 3), j = m.F(f, (c + 2) % 3), k = m.F(f, c);
      double w = 0.5;  // uniform: each interior edge is seen by two triangles
      if (weights == LaplacianWeights::Cotangent) {
        const Eigen::Vector3d a = m.V.row(i) - m.V.row(k), b = m.V.row(j) - m.V.row(k);
        w = 0.5 * a.dot(b) / std::max(a.cross(b).norm(), 1e-300);
      }
      t.emplace_back(i, j, w);
      t.emplace_back(j, i, w);
    }
  Eigen::SparseMatrix<double> W(m.numVertices(), m.numVertices());
  W.setFromTriplets(t.begin(), t.end());
  if (weights == LaplacianWeights::Cotangent) {
    const double floor = clamp * W.coeffs().cwiseAbs().mean();
    for (double& w : W.coeffs()) w = std::isfinite(w) ? std::max(w, floor) : floor;
  }
  return W;
}

// Untangling after Freitag and Plassmann: the position p of a vertex that maximizes the smallest signed area
// of its triangles, a small linear program in (p, t): max t s.t. cross2(b - a, p - a) >= t for every link
// edge (a, b). For an interior vertex the link is closed, so t is bounded and the optimum is a vertex where
// three constraints are active: try every triple.
bool maxMinAreaPosition(const std::vector<std::pair<int, int>>& link, const Points2& uv, Vec2& best, double& bestT) {
  const int k = static_cast<int>(link.size());
  std::vector<Eigen::Vector3d> rows(k);  // constraint: n . p - c >= t, as (n.x, n.y, c)
  for (int e = 0; e < k; ++e) {
    const Vec2 a = uv.row(link[e].first).transpose(), b = uv.row(link[e].second).transpose();
    const Vec2 normal(-(b - a).y(), (b - a).x());
    rows[e] << normal, normal.dot(a);
  }
  bool found = false;
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j)
      for (int l = j + 1; l < k; ++l) {
        Eigen::Matrix3d M;
        Eigen::Vector3d rhs;
        int r = 0;
        for (int e : {i, j, l}) {
          M.row(r) << rows[e].x(), rows[e].y(), -1;
          rhs[r++] = rows[e].z();
        }
        const Eigen::FullPivLU<Eigen::Matrix3d> lu(M);
        if (!lu.isInvertible()) continue;
        const Eigen::Vector3d x = lu.solve(rhs);  // (p, t)
        if (found && x.z() <= bestT) continue;
        bool feasible = true;
        for (int e = 0; e < k && feasible; ++e)
          feasible = rows[e].head<2>().dot(x.head<2>()) - rows[e].z() >= x.z() - 1e-12 * (1 + std::abs(x.z()));
        if (!feasible) continue;
        best = x.head<2>();
        bestT = x.z();
        found = true;
      }
  return found;
}

// Moves v when that raises the smallest signed area of its triangles.
void untangleVertex(const std::vector<std::pair<int, int>>& link, Points2& uv, int v) {
  double current = std::numeric_limits<double>::infinity();
  for (auto [a, b] : link) current = std::min(current, signedArea2(uv, v, a, b));
  Vec2 p;
  double t;
  if (maxMinAreaPosition(link, uv, p, t) && t > current) uv.row(v) = p.transpose();
}

}  // namespace

InteriorLaplacian::InteriorLaplacian(const TriMesh& segment, const std::vector<char>& isBoundary, double clamp)
    : segment_(segment), isBoundary_(isBoundary), clamp_(clamp), index_(segment.numVertices(), -1) {
  for (int v = 0; v < segment.numVertices(); ++v)
    if (!isBoundary[v]) index_[v] = interior_++;
}

InteriorLaplacian::System& InteriorLaplacian::system(LaplacianWeights weights) {
  std::unique_ptr<System>& s = weights == LaplacianWeights::Cotangent ? cotangent_ : uniform_;
  if (s) return *s;
  s = std::make_unique<System>();
  s->W = edgeWeights(segment_, weights, weights == LaplacianWeights::Cotangent ? clamp_ : 0);
  std::vector<Triplet> t;
  t.reserve(s->W.nonZeros() + interior_);
  for (int j = 0; j < s->W.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(s->W, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (index_[i] < 0) continue;
      t.emplace_back(index_[i], index_[i], it.value());
      if (index_[j] >= 0) t.emplace_back(index_[i], index_[j], -it.value());
    }
  Eigen::SparseMatrix<double> A(interior_, interior_);
  A.setFromTriplets(t.begin(), t.end());
  s->ldlt.compute(A);
  return *s;
}

void InteriorLaplacian::solve(LaplacianWeights weights, Points2& uv) {
  if (interior_ == 0) return;
  System& s = system(weights);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(interior_, 2);
  for (int j = 0; j < s.W.outerSize(); ++j) {
    if (index_[j] >= 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(s.W, j); it; ++it) {
      const int i = index_[it.row()];
      if (i >= 0) rhs.row(i) += it.value() * uv.row(j);
    }
  }
  const Eigen::MatrixXd x = s.ldlt.solve(rhs);
  for (int v = 0; v < segment_.numVertices(); ++v)
    if (index_[v] >= 0) uv.row(v) = x.row(index_[v]);
}

Eigen::VectorXd InteriorLaplacian::conformalAngleShift() {
  const int n = segment_.numVertices();
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(n);
  if (interior_ == 0) return shift;
  Eigen::VectorXd defect = Eigen::VectorXd::Constant(interior_, 2 * M_PI);  // Omega_I: 2 pi minus the angle sum
  for (int f = 0; f < segment_.numTriangles(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int v = segment_.F(f, c);
      if (index_[v] < 0) continue;
      const Eigen::Vector3d a = segment_.V.row(segment_.F(f, (c + 1) % 3)) - segment_.V.row(v);
      const Eigen::Vector3d b = segment_.V.row(segment_.F(f, (c + 2) % 3)) - segment_.V.row(v);
      defect[index_[v]] -= std::atan2(a.cross(b).norm(), a.dot(b));
    }
  System& s = system(LaplacianWeights::Cotangent);
  const Eigen::VectorXd u = s.ldlt.solve(defect);
  if (s.ldlt.info() != Eigen::Success || !u.allFinite()) return shift;
  for (int j = 0; j < s.W.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(s.W, j); it; ++it) {
      const int b = static_cast<int>(it.row());
      if (isBoundary_[b] && index_[j] >= 0) shift[b] -= it.value() * u[index_[j]];
    }
  return shift;
}

bool isFlipped(const Triangles& F, const Points2& uv, int f) {
  return !(signedArea2(uv, F(f, 0), F(f, 1), F(f, 2)) > 0);
}

std::vector<int> boundaryNext(const Triangles& F, int numVertices) {
  std::unordered_set<std::uint64_t> directed;
  for (int f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) directed.insert(directedKey(F(f, c), F(f, (c + 1) % 3)));
  std::vector<int> next(numVertices, -1);
  for (int f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = F(f, c), b = F(f, (c + 1) % 3);
      if (!directed.count(directedKey(b, a))) next[a] = b;
    }
  return next;
}

bool foldsPanel(const Triangles& F, const Points2& uv, const std::vector<int>& next, int f) {
  if (!isFlipped(F, uv, f)) return false;
  bool allOnBoundary = true, boundaryEdge = false;
  for (int c = 0; c < 3; ++c) {
    allOnBoundary = allOnBoundary && next[F(f, c)] >= 0;
    boundaryEdge = boundaryEdge || next[F(f, c)] == F(f, (c + 1) % 3);
  }
  return !(allOnBoundary && boundaryEdge);
}

int countFolds(const Triangles& F, const Points2& uv, const std::vector<int>& next) {
  int folds = 0;
  for (int f = 0; f < F.rows(); ++f)
    if (foldsPanel(F, uv, next, f)) ++folds;
  return folds;
}

int untangle(const Triangles& F, const std::vector<int>& next, int sweeps, Points2& uv) {
  const int n = static_cast<int>(uv.rows());
  std::vector<std::vector<std::pair<int, int>>> link(n);
  for (int f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) link[F(f, c)].emplace_back(F(f, (c + 1) % 3), F(f, (c + 2) % 3));
  int flipped = countFolds(F, uv, next);
  for (int s = 0; s < sweeps && flipped > 0; ++s) {
    // The vertices of folding triangles and, as sweeps go by, more rings around them: moving a neighbour often
    // makes room for a vertex that cannot be untangled on its own.
    std::vector<char> active(n, 0);
    for (int f = 0; f < F.rows(); ++f)
      if (foldsPanel(F, uv, next, f))
        for (int c = 0; c < 3; ++c) active[F(f, c)] = 1;
    for (int ring = 0; ring < std::min(1 + s / 3, 8); ++ring) {
      std::vector<char> grown = active;
      for (int v = 0; v < n; ++v)
        if (active[v])
          for (auto [a, b] : link[v]) grown[a] = grown[b] = 1;
      active.swap(grown);
    }
    for (int v = 0; v < n; ++v)
      if (active[v] && next[v] < 0) untangleVertex(link[v], uv, v);
    flipped = countFolds(F, uv, next);
  }
  return flipped;
}

}  // namespace billow
