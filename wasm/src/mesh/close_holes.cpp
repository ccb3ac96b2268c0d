#include "mesh/close_holes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "flatten/flatten_boundary.hpp"
#include "remesh/refine.hpp"

namespace billow {
namespace {

// A cap over the loop: its rim seen along a direction it lies simply across (below), else laid on a circle,
// triangulated there (constrained Delaunay, refined to about the rim's edge length `rim` without points added on the
// rim), and lifted as a membrane stretched over the rim (each inner vertex at the cotangent-weighted mean of its
// neighbours), so a flat rim gets a flat cap and the cap never folds over itself where the rim lies simply across
// some plane. False, and nothing added, where the triangulation or the lifting fails.
bool membraneCap(const TriMesh& mesh, const std::vector<int>& loop, double rim, int& nextVertex,
                 std::vector<Eigen::RowVector3d>& added, std::vector<Eigen::Vector3i>& caps) {
  const int n = int(loop.size());
  Eigen::Matrix<double, Eigen::Dynamic, 3> rimPoints(n, 3);
  for (int i = 0; i < n; ++i) rimPoints.row(i) = mesh.V.row(loop[size_t(i)]);
  const Eigen::RowVector3d center = rimPoints.colwise().mean();
  const Eigen::Matrix<double, Eigen::Dynamic, 3> centered = rimPoints.rowwise() - center;
  // Seen along the loop's vector area (the direction it encloses most area across), else along the normal of the
  // plane that fits it best: a rim that winds round a curved part may lie simply in one and not in the other.
  Eigen::Vector3d vectorArea = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) vectorArea += centered.row(i).cross(centered.row((i + 1) % n)).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> fit(centered.transpose() * centered);
  Pslg pslg;
  pslg.points.resize(n, 2);
  pslg.segments.resize(n, 2);
  for (int i = 0; i < n; ++i) pslg.segments.row(i) << i, (i + 1) % n;
  bool counterclockwise = false, simple = false;
  for (const Eigen::Vector3d& normal : {Eigen::Vector3d(vectorArea), Eigen::Vector3d(fit.eigenvectors().col(0))}) {
    if (!(normal.norm() > 0)) continue;
    const Eigen::Vector3d w = normal.normalized(), u = w.unitOrthogonal(), v = w.cross(u);
    for (int i = 0; i < n; ++i)
      pslg.points.row(i) << centered.row(i).dot(u.transpose()), centered.row(i).dot(v.transpose());
    counterclockwise = signedArea(pslg.points) > 0;
    simple = isSimpleCcwPolygon(counterclockwise ? pslg.points : Points2(pslg.points.colwise().reverse()));
    if (simple) break;
  }
  if (!simple) {
    // A rim that crosses itself seen from both sides tried (one that winds round a car's body): laid on a circle by
    // its arc length, which any loop lies simply on. The membrane over it is then a harmonic map of the disc, a soap
    // film's shape, which may fold where the rim turns sharply back (a slot's narrow ends). Seen across a plane
    // instead, the cotangent weights reproduce the plane's own coordinates, so the cap is a graph over it.
    double length = 0;
    std::vector<double> along(static_cast<size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
      along[size_t(i)] = length;
      length += (centered.row((i + 1) % n) - centered.row(i)).norm();
    }
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * M_PI * along[size_t(i)] / length;
      pslg.points.row(i) << length / (2 * M_PI) * std::cos(angle), length / (2 * M_PI) * std::sin(angle);
    }
    counterclockwise = true;
  }
  // The membrane over a triangulation of the plane's rim, refined to maxEdge: the inner vertices' positions solve the
  // cotangent Laplace equation with the rim held. False where the triangulation or the solve fails.
  CdtResult cdt;
  Eigen::MatrixXd lifted;
  const auto membrane = [&](double maxEdge) {
    RefineOptions refineOptions;
    refineOptions.maxEdgeLength = maxEdge;
    refineOptions.allowBoundarySplits = false;
    refineOptions.maxSteinerPoints = 50 * n * n;
    cdt = triangulateRefined(pslg, refineOptions);
    for (int i = 0; i < n; ++i)  // every rim vertex its own point, first (no two seen at one place)
      if (cdt.inputToPoint[size_t(i)] != i) return false;
    const int inner = int(cdt.points.rows()) - n;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(std::max(inner, 1), 3);
    for (int f = 0; f < cdt.triangles.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        // The edge opposite corner k, weighted by half the cotangent of the angle there.
        const int a = cdt.triangles(f, (k + 1) % 3), b = cdt.triangles(f, (k + 2) % 3), c = cdt.triangles(f, k);
        const Vec2 ea = cdt.points.row(a) - cdt.points.row(c), eb = cdt.points.row(b) - cdt.points.row(c);
        const double w = 0.5 * ea.dot(eb) / std::max(std::abs(cross2(ea, eb)), 1e-300);
        for (const auto& [i, j] : {std::pair{a, b}, std::pair{b, a}}) {
          if (i < n) continue;
          entries.emplace_back(i - n, i - n, w);
          if (j >= n)
            entries.emplace_back(i - n, j - n, -w);
          else
            rhs.row(i - n) += w * rimPoints.row(j);
        }
      }
    lifted.resize(inner, 3);
    if (inner == 0) return true;
    Eigen::SparseMatrix<double> laplacian(inner, inner);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
    if (solver.info() != Eigen::Success) return false;
    lifted = solver.solve(rhs);
    return solver.info() == Eigen::Success && lifted.allFinite();
  };
  // Sized twice: a coarse membrane tells how much the lifting shrinks or stretches the plane's triangles (the
  // circle's disc is far larger than a long rim's film), and the cap is refined to the rim's edge length over it.
  if (!membrane(6 * rim)) return false;
  double planeArea = 0, liftedArea = 0;
  const auto at = [&](int p) -> Eigen::Vector3d {
    return p < n ? Eigen::Vector3d(rimPoints.row(p).transpose()) : Eigen::Vector3d(lifted.row(p - n).transpose());
  };
  for (int f = 0; f < cdt.triangles.rows(); ++f) {
    const int a = cdt.triangles(f, 0), b = cdt.triangles(f, 1), c = cdt.triangles(f, 2);
    planeArea += 0.5 * std::abs(cross2(cdt.points.row(b) - cdt.points.row(a), cdt.points.row(c) - cdt.points.row(a)));
    liftedArea += 0.5 * (at(b) - at(a)).cross(at(c) - at(a)).norm();
  }
  const double scale = planeArea > 0 && liftedArea > 0 ? std::sqrt(liftedArea / planeArea) : 1;
  if (!membrane(1.5 * rim / std::clamp(scale, 0.05, 20.0))) return false;
  const int points = int(cdt.points.rows()), inner = points - n;
  std::vector<int> vertex(static_cast<size_t>(points));
  for (int i = 0; i < n; ++i) vertex[size_t(i)] = loop[size_t(i)];
  for (int i = 0; i < inner; ++i) vertex[size_t(n + i)] = nextVertex++, added.push_back(lifted.row(i));
  // A rim edge a -> b is its triangle's; the cap's triangle along it runs b -> a. The triangulation's turn
  // counterclockwise, as the rim does when `counterclockwise`: then they are turned.
  for (int f = 0; f < cdt.triangles.rows(); ++f) {
    const int a = vertex[size_t(cdt.triangles(f, 0))], b = vertex[size_t(cdt.triangles(f, 1))],
              c = vertex[size_t(cdt.triangles(f, 2))];
    caps.push_back(counterclockwise ? Eigen::Vector3i(a, c, b) : Eigen::Vector3i(a, b, c));
  }
  return true;
}

// A cap edge between two rim vertices that the mesh already has with two triangles (a flap on the rim folded over the
// hole, whose triangle the cap takes as an ear) would have four: each such edge is split at a new vertex, the mean of
// its two cap triangles' corners, and those two triangles into four. Cap triangles from `first` on.
void splitRepeatedEdges(const TriMesh& mesh, const std::unordered_map<std::uint64_t, int>& uses, size_t first,
                        int& nextVertex, std::vector<Eigen::RowVector3d>& added, std::vector<Eigen::Vector3i>& caps) {
  const int oldVertices = mesh.numVertices();
  const auto at = [&](int v) -> Eigen::RowVector3d {
    return v < oldVertices ? Eigen::RowVector3d(mesh.V.row(v)) : added[size_t(v - oldVertices)];
  };
  const auto repeated = [&](int a, int b) {
    if (a >= oldVertices || b >= oldVertices) return false;
    const auto it = uses.find(edgeKey(a, b));
    return it != uses.end() && it->second >= 2;
  };
  for (size_t f = first; f < caps.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = caps[f](k), b = caps[f]((k + 1) % 3);
      if (!repeated(a, b)) continue;
      size_t g = first;  // the cap triangle across a -> b runs b -> a
      int j = -1;
      for (; g < caps.size() && j < 0; ++g)
        for (int i = 0; i < 3; ++i)
          if (caps[g](i) == b && caps[g]((i + 1) % 3) == a) j = i;
      if (j < 0) continue;  // a cap that does not close over the edge: left, and the mesh's check will say so
      --g;
      const int p = caps[f]((k + 2) % 3), q = caps[g]((j + 2) % 3), m = nextVertex++;
      added.push_back(0.25 * (at(a) + at(b) + at(p) + at(q)));
      caps[f] = Eigen::Vector3i(a, m, p), caps[g] = Eigen::Vector3i(b, m, q);
      caps.emplace_back(m, b, p), caps.emplace_back(m, a, q);
      k = -1;  // this triangle's other edges again, as it now is
    }
}

}  // namespace

int closeHoles(TriMesh& mesh) {
  // Boundary half-edges a -> b: their edge has one triangle, in which a comes before b.
  std::unordered_map<std::uint64_t, int> uses;
  for (int f = 0; f < mesh.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) ++uses[edgeKey(mesh.F(f, k), mesh.F(f, (k + 1) % 3))];
  const size_t numVertices = size_t(mesh.numVertices());
  std::vector<int> next(numVertices, -1), outgoing(numVertices, 0);  // a -> b, and how many start at a
  std::vector<int> starts;  // in the triangles' order, so native and wasm builds close the holes alike
  for (int f = 0; f < mesh.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      if (uses[edgeKey(a, b)] == 1) next[size_t(a)] = b, ++outgoing[size_t(a)], starts.push_back(a);
    }
  std::vector<Eigen::RowVector3d> added;
  std::vector<Eigen::Vector3i> caps;
  int nextVertex = mesh.numVertices();
  std::vector<char> done(numVertices, 0);
  int closed = 0;
  for (const int start : starts) {
    if (done[size_t(start)]) continue;
    // Followed until it comes back; a vertex two boundary edges start at makes the hole not simple.
    std::vector<int> loop;
    bool simple = true;
    for (int v = start; v >= 0 && !done[size_t(v)]; v = next[size_t(v)]) {
      done[size_t(v)] = 1, loop.push_back(v);
      simple = simple && outgoing[size_t(v)] == 1;
    }
    simple = simple && next[size_t(loop.back())] == start;
    const int n = int(loop.size());
    if (!simple || n < 3) continue;
    double rim = 0;  // the mean rim edge
    for (int i = 0; i < n; ++i) rim += (mesh.V.row(loop[size_t(i)]) - mesh.V.row(loop[size_t((i + 1) % n)])).norm() / n;
    const size_t first = caps.size();
    if (!membraneCap(mesh, loop, rim, nextVertex, added, caps)) continue;
    splitRepeatedEdges(mesh, uses, first, nextVertex, added, caps);
    ++closed;
  }
  const int oldV = mesh.numVertices(), oldF = mesh.numTriangles();
  mesh.V.conservativeResize(oldV + int(added.size()), 3);
  for (size_t i = 0; i < added.size(); ++i) mesh.V.row(oldV + int(i)) = added[i];
  mesh.F.conservativeResize(oldF + int(caps.size()), 3);
  for (size_t i = 0; i < caps.size(); ++i) mesh.F.row(oldF + int(i)) = caps[i].transpose();
  return closed;
}

}  // namespace billow
