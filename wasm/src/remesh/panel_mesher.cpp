// Panel meshing for remeshing (Sec. 5.3): arc-length boundary resampling that keeps seam correspondence,
// CDT + refinement inside with the boundary protected, light smoothing, and barycentric location.
#include "remesh/panel_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "remesh/predicates.hpp"
#include "remesh/refine.hpp"
#include "util/error.hpp"
#include "util/vec2.hpp"

namespace billow {

namespace {

// Sorted, unique corners; vertex 0 when there are none.
std::vector<int> sortedCorners(const Points2& polygon, const std::vector<int>& corners) {
  std::vector<int> c = corners;
  for (int k : c)
    if (k < 0 || k >= polygon.rows()) throw Error("panel.bad-input", "A panel corner is not a boundary vertex.");
  std::sort(c.begin(), c.end());
  c.erase(std::unique(c.begin(), c.end()), c.end());
  if (c.empty()) c.push_back(0);
  return c;
}

// Polyline of piece k: polygon vertices from corner k to corner k + 1 (wrapping), both included.
Points2 piecePolyline(const Points2& polygon, const std::vector<int>& c, std::size_t k) {
  const int n = static_cast<int>(polygon.rows());
  const int a = c[k], b = c[(k + 1) % c.size()];
  const int count = (b - a + n - 1) % n + 2;  // b == a (one corner): the whole loop
  Points2 line(count, 2);
  for (int i = 0; i < count; ++i) line.row(i) = polygon.row((a + i) % n);
  return line;
}

double polylineLength(const Points2& line) {
  double len = 0;
  for (Eigen::Index i = 0; i + 1 < line.rows(); ++i) len += (line.row(i + 1) - line.row(i)).norm();
  return len;
}

double minAngleAt(const TriMesh& m, int f) {
  double best = 4;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector2d p = m.V.row(m.F(f, k)).head<2>().transpose();
    const Eigen::Vector2d q = m.V.row(m.F(f, (k + 1) % 3)).head<2>().transpose();
    const Eigen::Vector2d r = m.V.row(m.F(f, (k + 2) % 3)).head<2>().transpose();
    best = std::min(best, std::atan2(std::abs(cross2(q - p, r - p)), (q - p).dot(r - p)));
  }
  return best;
}

bool positive(const TriMesh& m, int f) {
  const Eigen::Vector2d p = m.V.row(m.F(f, 0)).head<2>().transpose();
  const Eigen::Vector2d q = m.V.row(m.F(f, 1)).head<2>().transpose();
  const Eigen::Vector2d r = m.V.row(m.F(f, 2)).head<2>().transpose();
  return cross2(q - p, r - p) > 0;
}

// Laplacian smoothing of interior vertices; a move is kept only if no incident triangle flips and the worst
// incident angle does not get worse.
void smooth(TriMesh& m, int firstInterior, int iterations) {
  const int nv = m.numVertices();
  std::vector<std::vector<int>> around(nv);
  for (int f = 0; f < m.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) around[m.F(f, k)].push_back(f);
  for (int it = 0; it < iterations; ++it)
    for (int v = firstInterior; v < nv; ++v) {
      Eigen::Vector2d avg = Eigen::Vector2d::Zero();
      int count = 0;
      double before = 4;
      for (int f : around[v]) {
        before = std::min(before, minAngleAt(m, f));
        for (int k = 0; k < 3; ++k)
          if (m.F(f, k) != v) avg += m.V.row(m.F(f, k)).head<2>().transpose(), ++count;
      }
      if (count == 0) continue;
      const Eigen::Vector2d old = m.V.row(v).head<2>().transpose();
      m.V.row(v).head<2>() = (avg / count).transpose();
      double after = 4;
      bool ok = true;
      for (int f : around[v]) {
        ok = ok && positive(m, f);
        after = std::min(after, minAngleAt(m, f));
      }
      if (!ok || after < before) m.V.row(v).head<2>() = old.transpose();
    }
}

}  // namespace

int segmentCountFor(double length, double h) {
  if (!(h > 0)) throw Error("panel.bad-input", "The target edge length must be positive.");
  return std::max(1, static_cast<int>(std::lround(length / h)));
}

Points2 resamplePolyline(const Points2& polyline, int segments, Eigen::VectorXd* params) {
  if (polyline.rows() < 2 || segments < 1) throw Error("panel.bad-input", "Cannot resample this boundary piece.");
  const Eigen::Index m = polyline.rows();
  std::vector<double> cum(m, 0.0);
  for (Eigen::Index i = 1; i < m; ++i) cum[i] = cum[i - 1] + (polyline.row(i) - polyline.row(i - 1)).norm();
  const double total = cum.back();
  if (!(total > 0)) throw Error("panel.bad-input", "A boundary piece has zero length.");
  Points2 out(segments + 1, 2);
  if (params) params->resize(segments + 1);
  Eigen::Index edge = 0;
  for (int k = 0; k <= segments; ++k) {
    if (k == 0 || k == segments) {
      out.row(k) = polyline.row(k == 0 ? 0 : m - 1);
      if (params) (*params)(k) = k == 0 ? 0.0 : static_cast<double>(m - 1);
      continue;
    }
    const double s = total * k / segments;
    while (edge + 2 < m && cum[edge + 1] <= s) ++edge;
    const double len = cum[edge + 1] - cum[edge];
    const double t = len > 0 ? std::clamp((s - cum[edge]) / len, 0.0, 1.0) : 0.0;
    out.row(k) = (1 - t) * polyline.row(edge) + t * polyline.row(edge + 1);
    if (params) (*params)(k) = static_cast<double>(edge) + t;
  }
  return out;
}

ResampledBoundary resampleBoundary(const Points2& polygon, const std::vector<int>& corners,
                                   const std::vector<int>& segmentsPerPiece) {
  if (polygon.rows() < 3) throw Error("panel.bad-input", "A panel boundary needs at least 3 points.");
  const std::vector<int> c = sortedCorners(polygon, corners);
  if (segmentsPerPiece.size() != c.size())
    throw Error("panel.bad-input", "One segment count per boundary piece is needed.");
  const int n = static_cast<int>(polygon.rows());
  ResampledBoundary out;
  out.segmentsPerPiece = segmentsPerPiece;
  int total = 0;
  for (int s : segmentsPerPiece) total += s;
  if (total < 3) throw Error("panel.bad-input", "A panel boundary needs at least 3 segments.");
  out.points.resize(total, 2);
  out.param.resize(total);
  out.piece.resize(total);
  int row = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    Eigen::VectorXd local;
    const Points2 pts = resamplePolyline(piecePolyline(polygon, c, k), segmentsPerPiece[k], &local);
    out.cornerRows.push_back(row);
    for (Eigen::Index i = 0; i + 1 < pts.rows(); ++i, ++row) {
      out.points.row(row) = pts.row(i);
      const double g = c[k] + local(i);
      out.param(row) = g >= n ? g - n : g;
      out.piece(row) = static_cast<int>(k);
    }
  }
  return out;
}

ResampledBoundary resampleBoundary(const Points2& polygon, const std::vector<int>& corners, double h) {
  if (polygon.rows() < 3) throw Error("panel.bad-input", "A panel boundary needs at least 3 points.");
  const std::vector<int> c = sortedCorners(polygon, corners);
  std::vector<int> counts;
  for (std::size_t k = 0; k < c.size(); ++k)
    counts.push_back(segmentCountFor(polylineLength(piecePolyline(polygon, c, k)), h));
  // A single-corner loop needs 3 segments at least to stay a polygon.
  if (c.size() == 1) counts[0] = std::max(counts[0], 3);
  if (c.size() == 2) counts[0] = std::max(counts[0], 2);
  return resampleBoundary(polygon, c, counts);
}

int outlineCrossing(const Points2& polygon) {
  const int n = static_cast<int>(polygon.rows());
  const auto meet = [&](int i, int j) {
    const Eigen::Vector2d a = polygon.row(i), b = polygon.row((i + 1) % n), c = polygon.row(j),
                          d = polygon.row((j + 1) % n);
    const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    if (o1 == 0 && o2 == 0)  // collinear: they meet where their extents overlap
      return a.cwiseMin(b).x() <= c.cwiseMax(d).x() && c.cwiseMin(d).x() <= a.cwiseMax(b).x() &&
             a.cwiseMin(b).y() <= c.cwiseMax(d).y() && c.cwiseMin(d).y() <= a.cwiseMax(b).y();
    return o1 * o2 <= 0 && o3 * o4 <= 0;
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j)
      if ((j + 1) % n != i && meet(i, j)) return i;
  return -1;
}

namespace {

// An edge inside the panel between two outline points (a chord, as across a sharp tip or a strip one
// triangle wide) would lie on its twin where the panel across the seam is meshed alike (the two mirror
// pieces of a foil balloon): four triangles on one sewn edge. Each chord is split at its middle.
void splitChords(Cdt& cdt, int outlinePoints) {
  std::vector<char> onOutline(cdt.numVertices(), 0);
  for (int i = 0; i < outlinePoints; ++i) onOutline[cdt.inputVertex(i)] = 1;
  for (int splits = 0; splits < 4 * outlinePoints; ++splits) {
    int found = -1, edge = -1;
    for (int t = 0; t < cdt.numTriangles() && found < 0; ++t) {
      const Cdt::Tri& T = cdt.tri(t);
      if (!T.inside) continue;
      for (int i = 0; i < 3 && found < 0; ++i)
        if (!T.c[i] && onOutline[T.v[(i + 1) % 3]] && onOutline[T.v[(i + 2) % 3]]) found = t, edge = i;
    }
    if (found < 0) return;
    const Cdt::Tri& T = cdt.tri(found);
    cdt.insertPoint(0.5 * (cdt.point(T.v[(edge + 1) % 3]) + cdt.point(T.v[(edge + 2) % 3])), found);
    onOutline.resize(cdt.numVertices(), 0);
  }
}

}  // namespace

TriMesh meshPanel(const Points2& boundary, double h, const PanelMeshOptions& options,
                  const std::vector<Points2>& holes) {
  const int outer = static_cast<int>(boundary.rows());
  if (outer < 3 || !(h > 0)) throw Error("panel.bad-input", "A panel needs at least 3 boundary points and h > 0.");
  const double outlineArea = signedArea(boundary);
  if (!(outlineArea > 0)) throw Error("panel.clockwise", "The panel outline must run counter-clockwise.");
  int n = outer;
  for (const Points2& hole : holes) {
    if (hole.rows() < 3) throw Error("panel.bad-input", "A hole in a panel needs at least 3 points.");
    if (!(signedArea(hole) < 0)) throw Error("panel.clockwise", "A hole in a panel must run clockwise.");
    n += static_cast<int>(hole.rows());
  }
  // The outline and its holes, one closed chain of segments each: the CDT keeps what lies inside an odd
  // number of them, the panel without its holes.
  Pslg pslg;
  pslg.points.resize(n, 2);
  pslg.segments.resize(n, 2);
  int row = 0;
  auto append = [&](const Points2& loop) {
    const int first = row, size = static_cast<int>(loop.rows());
    for (int i = 0; i < size; ++i, ++row) {
      pslg.points.row(row) = loop.row(i);
      pslg.segments.row(row) << row, first + (i + 1) % size;
    }
  };
  append(boundary);
  for (const Points2& hole : holes) append(hole);
  Cdt cdt(pslg);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (cdt.inputVertex(i) == cdt.inputVertex(j))
        throw Error("panel.repeated-vertex", "The panel outline visits point " + std::to_string(i) + " twice.");
  if (cdt.numVertices() != n + 3) throw Error("panel.self-intersecting", "The panel outline crosses itself.");
  RefineOptions ro;
  ro.minAngleDeg = options.minAngleDeg;
  ro.maxEdgeLength = options.maxEdgeFactor * h;
  ro.maxSteinerPoints = options.maxSteinerPoints;
  ro.allowBoundarySplits = false;
  refine(cdt, ro);
  splitChords(cdt, n);
  const CdtResult r = cdt.result();
  TriMesh mesh;
  mesh.V = Vertices::Zero(r.points.rows(), 3);
  mesh.V.leftCols<2>() = r.points;
  mesh.F = r.triangles;
  if (!holes.empty()) {
    // A hole outside the outline or inside another hole would be meshed as panel: the area tells.
    double expected = outlineArea, meshed = 0;
    for (const Points2& hole : holes) expected += signedArea(hole);
    for (int f = 0; f < mesh.numTriangles(); ++f)
      meshed += 0.5 * cross2((r.points.row(mesh.F(f, 1)) - r.points.row(mesh.F(f, 0))).transpose(),
                             (r.points.row(mesh.F(f, 2)) - r.points.row(mesh.F(f, 0))).transpose());
    if (std::abs(meshed - expected) > 1e-9 * outlineArea)
      throw Error("panel.bad-hole", "A hole in a panel must lie inside its outline and outside its other holes.");
  }
  smooth(mesh, n, options.smoothingIterations);
  return mesh;
}

// ---- Barycentric location ----

namespace {

Eigen::Vector2d xy(const TriMesh& m, int v) { return m.V.row(v).head<2>().transpose(); }

// Closest point of triangle (a, b, c) to p, as barycentric weights (Ericson's region tests, in 2D).
Eigen::Vector3d closestWeights(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                               const Eigen::Vector2d& c) {
  const double area = cross2(b - a, c - a);
  if (area > 0) {
    const double wa = cross2(b - p, c - p) / area, wb = cross2(c - p, a - p) / area;
    const Eigen::Vector3d w(wa, wb, 1 - wa - wb);
    if (w.minCoeff() >= 0) return w;
  }
  // Outside (or degenerate): the closest point on the three edges.
  Eigen::Vector3d best(1, 0, 0);
  double bestD = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d v[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector2d& s = v[k];
    const Eigen::Vector2d& e = v[(k + 1) % 3];
    const double len2 = (e - s).squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - s).dot(e - s) / len2, 0.0, 1.0) : 0.0;
    const double d = (s + t * (e - s) - p).squaredNorm();
    if (d < bestD) {
      bestD = d;
      best.setZero();
      best(k) = 1 - t;
      best((k + 1) % 3) = t;
    }
  }
  return best;
}

}  // namespace

TriangleLocator::TriangleLocator(const TriMesh& mesh2d) : mesh_(mesh2d) {
  const int nf = mesh2d.numTriangles();
  if (nf == 0 || mesh2d.numVertices() == 0) return;
  lo_ = mesh2d.V.leftCols<2>().colwise().minCoeff().transpose();
  const Eigen::Vector2d hi = mesh2d.V.leftCols<2>().colwise().maxCoeff().transpose();
  const Eigen::Vector2d ext = (hi - lo_).cwiseMax(1e-300);
  // About two triangles per cell.
  cell_ = std::max(std::sqrt(ext.x() * ext.y() * 2.0 / nf), 1e-9 * ext.maxCoeff());
  nx_ = std::clamp(static_cast<int>(ext.x() / cell_) + 1, 1, 4096);
  ny_ = std::clamp(static_cast<int>(ext.y() / cell_) + 1, 1, 4096);
  cell_ = std::max(ext.x() / nx_, ext.y() / ny_) * (1 + 1e-9);
  auto range = [&](int f, int& x0, int& x1, int& y0, int& y1) {
    Eigen::Vector2d a = xy(mesh_, mesh_.F(f, 0)), b = a;
    for (int k = 1; k < 3; ++k) {
      a = a.cwiseMin(xy(mesh_, mesh_.F(f, k)));
      b = b.cwiseMax(xy(mesh_, mesh_.F(f, k)));
    }
    x0 = std::clamp(static_cast<int>((a.x() - lo_.x()) / cell_), 0, nx_ - 1);
    x1 = std::clamp(static_cast<int>((b.x() - lo_.x()) / cell_), 0, nx_ - 1);
    y0 = std::clamp(static_cast<int>((a.y() - lo_.y()) / cell_), 0, ny_ - 1);
    y1 = std::clamp(static_cast<int>((b.y() - lo_.y()) / cell_), 0, ny_ - 1);
  };
  start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (int f = 0; f < nf; ++f) {
    int x0, x1, y0, y1;
    range(f, x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) ++start_[y * nx_ + x + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  items_.resize(start_.back());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int f = 0; f < nf; ++f) {
    int x0, x1, y0, y1;
    range(f, x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) items_[fill[y * nx_ + x]++] = f;
  }
}

BarycentricPoint TriangleLocator::closestIn(int cell, const Eigen::Vector2d& p, BarycentricPoint best) const {
  for (int k = start_[cell]; k < start_[cell + 1]; ++k) {
    const int f = items_[k];
    const Eigen::Vector2d a = xy(mesh_, mesh_.F(f, 0)), b = xy(mesh_, mesh_.F(f, 1)), c = xy(mesh_, mesh_.F(f, 2));
    const Eigen::Vector3d w = closestWeights(p, a, b, c);
    const double d = (w(0) * a + w(1) * b + w(2) * c - p).norm();
    if (best.triangle < 0 || d < best.distance) {
      best.triangle = f;
      best.weights = w;
      best.distance = d;
    }
  }
  return best;
}

BarycentricPoint TriangleLocator::locate(const Eigen::Vector2d& p) const {
  BarycentricPoint best;
  if (start_.empty()) return best;
  const int cx = std::clamp(static_cast<int>(std::floor((p.x() - lo_.x()) / cell_)), 0, nx_ - 1);
  const int cy = std::clamp(static_cast<int>(std::floor((p.y() - lo_.y()) / cell_)), 0, ny_ - 1);
  // Rings of cells around p's (clamped) cell until no closer triangle can exist.
  const double outside = std::max(
      {lo_.x() - p.x(), p.x() - (lo_.x() + nx_ * cell_), lo_.y() - p.y(), p.y() - (lo_.y() + ny_ * cell_), 0.0});
  for (int ring = 0; ring <= std::max(nx_, ny_); ++ring) {
    for (int y = cy - ring; y <= cy + ring; ++y)
      for (int x = cx - ring; x <= cx + ring; ++x) {
        if (x < 0 || y < 0 || x >= nx_ || y >= ny_) continue;
        if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;
        best = closestIn(y * nx_ + x, p, best);
      }
    if (best.triangle >= 0 && best.distance <= std::max(outside, ring * cell_) + 1e-12 * cell_) break;
  }
  best.inside = best.distance <= 1e-12 * cell_;
  if (best.inside) best.distance = 0;
  return best;
}

BarycentricPoint barycentricLocate(const TriMesh& mesh2d, const Eigen::Vector2d& p) {
  return TriangleLocator(mesh2d).locate(p);
}

}  // namespace billow
