#include "mesh/close_holes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "flatten/flatten_boundary.hpp"
#include "remesh/refine.hpp"

namespace billow {
namespace {

// A cap over the loop: its rim seen along a direction it lies simply across (below), triangulated (constrained
// Delaunay, refined to about the rim's edge length `rim` without points added on the rim), and lifted off that
// plane as a membrane stretched over the rim (each inner vertex at the cotangent-weighted mean of its neighbours),
// so a flat rim gets a flat cap and the cap never folds over itself. False, and nothing added, where the rim seen
// so crosses itself.
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
  if (!simple) return false;
  RefineOptions refineOptions;
  refineOptions.maxEdgeLength = 1.5 * rim;
  refineOptions.allowBoundarySplits = false;
  refineOptions.maxSteinerPoints = 50 * n * n;
  const CdtResult cdt = triangulateRefined(pslg, refineOptions);
  // Every rim vertex its own point, first (no two seen at one place).
  for (int i = 0; i < n; ++i)
    if (cdt.inputToPoint[size_t(i)] != i) return false;
  const int points = int(cdt.points.rows()), inner = points - n;
  // The membrane: the inner vertices' positions solve the cotangent Laplace equation with the rim held.
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
  Eigen::MatrixXd lifted(inner, 3);
  if (inner > 0) {
    Eigen::SparseMatrix<double> laplacian(inner, inner);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
    if (solver.info() != Eigen::Success) return false;
    lifted = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !lifted.allFinite()) return false;
  }
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
    Eigen::RowVector3d center = Eigen::RowVector3d::Zero();
    double rim = 0, radius = 0;
    for (int i = 0; i < n; ++i) {
      center += mesh.V.row(loop[size_t(i)]) / n;
      rim += (mesh.V.row(loop[size_t(i)]) - mesh.V.row(loop[size_t((i + 1) % n)])).norm() / n;
    }
    if (membraneCap(mesh, loop, rim, nextVertex, added, caps)) {
      ++closed;
      continue;
    }
    // Where the rim seen along its plane crosses itself: rings drawn towards its centroid.
    for (int i = 0; i < n; ++i) radius += (mesh.V.row(loop[size_t(i)]) - center).norm() / n;
    // Rings about one rim edge apart; a ring keeps every other vertex of the one outside it once they would stand
    // closer than 0.6 of an edge, so the cap's triangles stay about the rim's size.
    const int rings = std::max(1, int(std::lround(radius / std::max(rim, 1e-300))));
    std::vector<int> outer = loop, from(static_cast<size_t>(n));  // ring vertices, the rim vertex each is drawn from
    for (int i = 0; i < n; ++i) from[size_t(i)] = i;
    const auto strip = [&](const std::vector<int>& o, const std::vector<int>& inner, const std::vector<int>& first) {
      // Inner vertex i stands over outer vertex first[i]; the outer ones up to the next inner one's are joined to
      // it, the first half to inner i, the rest to inner i + 1, with one triangle across between them.
      const int m = int(o.size()), k = int(inner.size());
      for (int i = 0; i < k; ++i) {
        const int a = first[size_t(i)], b = i + 1 < k ? first[size_t(i + 1)] : m;
        const int mid = a + (b - a + 1) / 2, u = inner[size_t(i)], w = inner[size_t((i + 1) % k)];
        for (int s = a; s < mid; ++s) caps.emplace_back(o[size_t((s + 1) % m)], o[size_t(s)], u);
        caps.emplace_back(o[size_t(mid % m)], u, w);
        for (int s = mid; s < b; ++s) caps.emplace_back(o[size_t((s + 1) % m)], o[size_t(s)], w);
      }
    };
    for (int j = 1; j < rings; ++j) {
      const double t = 1.0 - double(j) / rings;
      const int m = int(outer.size());
      const bool halve = m >= 8 && 2 * M_PI * radius * t / m < 0.6 * rim;
      std::vector<int> inner, first, innerFrom;
      for (int i = 0; i < m; i += halve ? 2 : 1) {
        if (halve && i + 1 == m) break;  // an odd ring's last vertex joins the block before
        inner.push_back(nextVertex++), first.push_back(i), innerFrom.push_back(from[size_t(i)]);
        added.push_back(center + t * (mesh.V.row(loop[size_t(from[size_t(i)])]) - center));
      }
      strip(outer, inner, first);
      outer = std::move(inner), from = std::move(innerFrom);
    }
    const int middle = nextVertex++;
    added.push_back(center);
    const int m = int(outer.size());
    for (int i = 0; i < m; ++i) caps.emplace_back(outer[size_t((i + 1) % m)], outer[size_t(i)], middle);
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
