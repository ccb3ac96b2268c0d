#include "simulate/initial_shape.hpp"

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

}  // namespace billow
