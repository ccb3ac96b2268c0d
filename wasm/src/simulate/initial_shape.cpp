#include "simulate/initial_shape.hpp"

#include <Eigen/SVD>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <random>

#include "simulate/enclosed_volume.hpp"

namespace billow {
namespace {

std::vector<std::vector<int>> neighbours(const SewnMesh& mesh, bool outerOnly) {
  std::vector<std::vector<int>> adj(mesh.numVertices);
  for (int f = 0; f < mesh.numTriangles(); ++f) {
    if (outerOnly && !mesh.outer[f]) continue;
    for (int k = 0; k < 3; ++k) {
      adj[mesh.triangles(f, k)].push_back(mesh.triangles(f, (k + 1) % 3));
      adj[mesh.triangles(f, (k + 1) % 3)].push_back(mesh.triangles(f, k));
    }
  }
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  return adj;
}

double signedVolume(const SewnMesh& mesh, const Vertices& x) {
  double v = 0;
  for (int f = 0; f < mesh.numTriangles(); ++f)
    if (mesh.outer[f])
      v += triangleVolume(x.row(mesh.triangles(f, 0)), x.row(mesh.triangles(f, 1)), x.row(mesh.triangles(f, 2)));
  return v;
}

int inwardTriangles(const SewnMesh& mesh, const Vertices& x) {
  int n = 0;
  for (int f = 0; f < mesh.numTriangles(); ++f) {
    if (!mesh.outer[f]) continue;
    const Eigen::Vector3d a = x.row(mesh.triangles(f, 0)), b = x.row(mesh.triangles(f, 1)),
                          c = x.row(mesh.triangles(f, 2));
    if ((b - a).cross(c - a).dot(a + b + c) <= 0) ++n;
  }
  return n;
}

// Spectral embedding of the vertices in `ids` (uniform Laplacian over `adj`), rows on the unit sphere.
Vertices spectralSphere(const std::vector<int>& ids, const std::vector<std::vector<int>>& adj, int numVertices) {
  const int n = static_cast<int>(ids.size());
  std::vector<int> local(numVertices, -1);
  for (int i = 0; i < n; ++i) local[ids[i]] = i;
  std::vector<Eigen::Triplet<double>> trip;
  double meanDegree = 0;
  for (int i = 0; i < n; ++i) {
    const auto& a = adj[ids[i]];
    meanDegree += double(a.size()) / n;
    trip.emplace_back(i, i, double(a.size()));
    for (int j : a)
      if (local[j] >= 0) trip.emplace_back(i, local[j], -1.0);
  }
  // A small shift makes L positive definite; the constant null vector is projected out every iteration.
  for (int i = 0; i < n; ++i) trip.emplace_back(i, i, 1e-6 * meanDegree);
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(L);
  std::mt19937 rng(12345);
  std::normal_distribution<double> gauss;
  Eigen::MatrixXd Y(n, 3);
  for (int i = 0; i < Y.size(); ++i) Y.data()[i] = gauss(rng);
  for (int it = 0; it < 40; ++it) {
    Y.rowwise() -= Y.colwise().mean();
    Y = Eigen::HouseholderQR<Eigen::MatrixXd>(Y).householderQ() * Eigen::MatrixXd::Identity(n, 3);
    Y = ldlt.solve(Y);
  }
  Y.rowwise() -= Y.colwise().mean();
  Y = Eigen::HouseholderQR<Eigen::MatrixXd>(Y).householderQ() * Eigen::MatrixXd::Identity(n, 3);
  Vertices out(n, 3);
  for (int i = 0; i < n; ++i) {
    const double norm = Y.row(i).norm();
    out.row(i) = norm > 0 ? Eigen::RowVector3d(Y.row(i) / norm) : Eigen::RowVector3d(1, 0, 0);
  }
  return out;
}

}  // namespace

Vertices sphericalStart(const SewnMesh& mesh) {
  const auto adjOuter = neighbours(mesh, true);
  std::vector<int> ids;
  for (int v = 0; v < mesh.numVertices; ++v)
    if (!adjOuter[v].empty()) ids.push_back(v);
  const Vertices sphere = spectralSphere(ids, adjOuter, mesh.numVertices);
  Vertices x = Vertices::Zero(mesh.numVertices, 3);
  for (size_t i = 0; i < ids.size(); ++i) x.row(ids[i]) = sphere.row(i);
  if (signedVolume(mesh, x) < 0) x.col(0) *= -1;

  // Projected Laplacian relaxation on the unit sphere until every outer triangle faces outwards.
  for (int it = 0; it < 500 && (it < 10 || inwardTriangles(mesh, x) > 0); ++it) {
    Vertices next = x;
    for (int v : ids) {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (int j : adjOuter[v]) sum += x.row(j);
      next.row(v) = sum / double(adjOuter[v].size());
    }
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for (int v : ids) centre += next.row(v) / double(ids.size());
    for (int v : ids) {
      const Eigen::RowVector3d p = next.row(v) - centre;
      if (p.norm() > 0) x.row(v) = p.normalized();
    }
  }
  x *= std::sqrt(mesh.outerArea / (4 * M_PI));

  // Internal-only vertices: harmonic interpolation of the outer ones.
  const auto adjAll = neighbours(mesh, false);
  std::vector<int> inner;
  for (int v = 0; v < mesh.numVertices; ++v)
    if (adjOuter[v].empty()) inner.push_back(v);
  for (int it = 0; it < 2000 && !inner.empty(); ++it)
    for (int v : inner) {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (int j : adjAll[v]) sum += x.row(j);
      if (!adjAll[v].empty()) x.row(v) = sum / double(adjAll[v].size());
    }
  return x;
}

Vertices startFromInflated(const Pattern& pattern, const SewnMesh& mesh) {
  if (pattern.inflated.size() != pattern.panels.size()) return {};
  Vertices x = Vertices::Zero(mesh.numVertices, 3);
  for (size_t p = 0; p < pattern.panels.size(); ++p)
    for (int v = 0; v < pattern.inflated[p].rows(); ++v)
      x.row(mesh.simVertex(int(p), v)) +=
          pattern.inflated[p].row(v) / double(mesh.stitchedCount[mesh.simVertex(int(p), v)]);
  return x;
}

namespace {

// A dome over a flat panel's outline: per panel vertex, z = 1/2 sqrt(2 h) with -div grad h = 1 inside and
// h = 0 on the outline (cotangent Laplacian, lumped areas); across a strip of half-width b, an ellipse b/2
// high. Empty when the solve fails.
Eigen::VectorXd domeHeights(const Panel& panel) {
  const int nv = int(panel.vertices.rows());
  std::vector<char> boundary(nv, 0);
  for (int v : outlineVertices(panel)) boundary[v] = 1;
  std::vector<int> index(nv, -1);
  int ni = 0;
  for (int v = 0; v < nv; ++v)
    if (!boundary[v]) index[v] = ni++;
  std::vector<Eigen::Triplet<double>> L;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(ni);
  for (int t = 0; t < panel.triangles.rows(); ++t) {
    const int v[3] = {panel.triangles(t, 0), panel.triangles(t, 1), panel.triangles(t, 2)};
    const Eigen::Vector2d P[3] = {panel.vertices.row(v[0]), panel.vertices.row(v[1]), panel.vertices.row(v[2])};
    const Eigen::Vector2d e1 = P[1] - P[0], e2 = P[2] - P[0];
    const double area = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
    for (int k = 0; k < 3; ++k) {
      if (index[v[k]] >= 0) rhs[index[v[k]]] += area / 3;
      const int i = v[(k + 1) % 3], j = v[(k + 2) % 3];
      const Eigen::Vector2d u = P[(k + 1) % 3] - P[k], w = P[(k + 2) % 3] - P[k];
      const double c = 0.5 * u.dot(w) / std::max(1e-300, std::abs(u.x() * w.y() - u.y() * w.x()));  // cot / 2
      for (const auto& [r, s] : {std::pair{i, j}, std::pair{j, i}}) {
        if (index[r] < 0) continue;
        L.emplace_back(index[r], index[r], c);
        if (index[s] >= 0) L.emplace_back(index[r], index[s], -c);
      }
    }
  }
  Eigen::SparseMatrix<double> A(ni, ni);
  A.setFromTriplets(L.begin(), L.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) return {};
  const Eigen::VectorXd h = solver.solve(rhs);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(nv);
  for (int v = 0; v < nv; ++v)
    if (index[v] >= 0) z[v] = 0.5 * std::sqrt(2 * std::max(0.0, h[index[v]]));
  return z;
}

}  // namespace

std::optional<Vertices> foldedStart(const Pattern& pattern, const SewnMesh& mesh) {
  if (pattern.panels.size() != 2 || pattern.panels[0].internal || pattern.panels[1].internal) return std::nullopt;
  const Panel &a = pattern.panels[0], &b = pattern.panels[1];
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> pairs;  // (on b, on a)
  for (const Stitch& s : pattern.stitches) {
    if (s.panelA == 0 && s.panelB == 1) pairs.push_back({b.vertices.row(s.vertexB), a.vertices.row(s.vertexA)});
    if (s.panelA == 1 && s.panelB == 0) pairs.push_back({b.vertices.row(s.vertexA), a.vertices.row(s.vertexB)});
  }
  if (pairs.size() < 3) return std::nullopt;
  Eigen::Vector2d cb = Eigen::Vector2d::Zero(), ca = Eigen::Vector2d::Zero();
  for (const auto& [q, p] : pairs) cb += q, ca += p;
  cb /= double(pairs.size()), ca /= double(pairs.size());
  Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
  for (const auto& [q, p] : pairs) H += (q - cb) * (p - ca).transpose();
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix2d R = svd.matrixV() * svd.matrixU().transpose();
  if (R.determinant() > 0) return std::nullopt;  // not mirror images: no fold
  double residual = 0, extent = 0;
  for (const auto& [q, p] : pairs) residual += (R * (q - cb) + ca - p).squaredNorm(), extent += (p - ca).squaredNorm();
  if (residual > 0.01 * extent) return std::nullopt;
  Vertices x = Vertices::Zero(mesh.numVertices, 3);
  std::vector<int> count(mesh.numVertices, 0);
  for (int p = 0; p < 2; ++p) {
    const Panel& panel = pattern.panels[p];
    const Eigen::VectorXd z = domeHeights(panel);
    if (z.size() != panel.vertices.rows()) return std::nullopt;
    // Outward is +z for the first panel (counterclockwise seen from outside), -z for the mirrored second.
    const double side = p == 0 ? 1 : -1;
    for (int v = 0; v < panel.vertices.rows(); ++v) {
      const Eigen::Vector2d q = panel.vertices.row(v);
      const Eigen::Vector2d flat = p == 0 ? q : Eigen::Vector2d(R * (q - cb) + ca);
      const int s = mesh.simVertex(p, v);
      x.row(s) += Eigen::RowVector3d(flat.x(), flat.y(), side * z[v]);
      ++count[s];
    }
  }
  for (int s = 0; s < mesh.numVertices; ++s) {
    if (!count[s]) return std::nullopt;
    x.row(s) /= count[s];
  }
  return x;
}

Vertices bareStart(const Pattern& pattern, const SewnMesh& mesh) {
  if (auto folded = foldedStart(pattern, mesh)) return *folded;
  return sphericalStart(mesh);
}

}  // namespace billow
