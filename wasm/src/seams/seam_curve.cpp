// Seam curves and snapping (see seam_curve.hpp).
#include "seams/seam_curve.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>

#include "seams/mesh_topology.hpp"
#include "util/error.hpp"
#include "util/vec2.hpp"

namespace billow {

namespace {

// Appends path to curve, sharing the joint point.
void appendPath(SeamCurve& curve, const GeodesicPath& path) {
  const size_t skip = curve.points.empty() ? 0 : 1;
  curve.points.insert(curve.points.end(), path.points.begin() + skip, path.points.end());
  curve.faces.insert(curve.faces.end(), path.faces.begin(), path.faces.end());
  curve.length += path.length;
}

// Catmull-Rom tangents, one-sided at the ends of an open curve.
std::vector<Eigen::Vector3d> tangents(const std::vector<Eigen::Vector3d>& c, bool closed) {
  const int n = static_cast<int>(c.size());
  std::vector<Eigen::Vector3d> m(n);
  for (int i = 0; i < n; ++i) {
    const int prev = closed ? (i + n - 1) % n : std::max(i - 1, 0);
    const int next = closed ? (i + 1) % n : std::min(i + 1, n - 1);
    m[i] = (c[next] - c[prev]) / double(next - prev == 0 ? 1 : (closed ? 2 : next - prev));
  }
  return m;
}

Eigen::Vector3d hermite(const Eigen::Vector3d& p0, const Eigen::Vector3d& m0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& m1, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

// One span of a smoothed seam: spline samples projected onto the target, joined by geodesics. Falls back to
// the plain geodesic when the projected samples make a detour (a sample landed on another part of the shape).
GeodesicPath smoothSpan(const GeodesicSolver& solver, const SurfaceProjector& projector, const SurfacePoint& a,
                        const SurfacePoint& b, const Eigen::Vector3d (&hermiteData)[4], const GeodesicPath& direct,
                        const SeamCurveOptions& options) {
  GeodesicPath out;
  SurfacePoint from = a;
  for (int j = 1; j <= options.samplesPerSpan; ++j) {
    const double s = double(j) / (options.samplesPerSpan + 1);
    const SurfacePoint to =
        projector.project(hermite(hermiteData[0], hermiteData[1], hermiteData[2], hermiteData[3], s));
    const GeodesicPath piece = solver.path(from, to, options.geodesic);
    out.points.insert(out.points.end(), piece.points.begin() + (out.points.empty() ? 0 : 1), piece.points.end());
    out.faces.insert(out.faces.end(), piece.faces.begin(), piece.faces.end());
    out.length += piece.length;
    from = to;
  }
  const GeodesicPath last = solver.path(from, b, options.geodesic);
  out.points.insert(out.points.end(), last.points.begin() + 1, last.points.end());
  out.faces.insert(out.faces.end(), last.faces.begin(), last.faces.end());
  out.length += last.length;
  if (out.length > options.maxDetour * direct.length + 1e-12) return direct;
  return out;
}

// Whether 2D segments ab and cd cross or touch (barycentric coordinates of one face: an affine frame, so
// crossing there is crossing on the face).
bool segmentsMeetInFace(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                        const Eigen::Vector2d& d) {
  const double eps = 1e-12;
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a), d3 = cross2(d - c, a - c),
               d4 = cross2(d - c, b - c);
  if (((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) && ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps)))
    return true;
  const auto onSegment = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return std::abs(cross2(q - p, r - p)) <= eps && (r - p).dot(r - q) <= eps;  // r on pq
  };
  return onSegment(a, b, c) || onSegment(a, b, d) || onSegment(c, d, a) || onSegment(c, d, b);
}

// The spans (by index) whose pieces cross or touch a piece of another span, or of the same span away from it:
// a seam that loops over itself cuts no sound region. Pieces are compared within the faces they share.
std::vector<char> crossingSpans(const GeodesicSolver& solver, const std::vector<GeodesicPath>& spans, bool closed) {
  struct Piece {
    int span, index;
    Eigen::Vector2d a, b;
  };
  std::unordered_map<int, std::vector<Piece>> byFace;
  int index = 0;
  for (int k = 0; k < static_cast<int>(spans.size()); ++k)
    for (size_t i = 0; i < spans[k].faces.size(); ++i, ++index) {
      SurfacePoint pa, pb;
      const int f = spans[k].faces[i];
      if (!expressInFace(solver.mesh(), solver.topology(), spans[k].points[i].point, f, pa) ||
          !expressInFace(solver.mesh(), solver.topology(), spans[k].points[i + 1].point, f, pb))
        continue;
      byFace[f].push_back({k, index, pa.bary.tail<2>(), pb.bary.tail<2>()});
    }
  const int total = index;
  std::vector<char> crossing(spans.size(), 0);
  for (const auto& [face, pieces] : byFace)
    for (size_t i = 0; i < pieces.size(); ++i)
      for (size_t j = i + 1; j < pieces.size(); ++j) {
        const int gap = std::abs(pieces[i].index - pieces[j].index);
        if (gap <= 1 || (closed && gap == total - 1)) continue;  // neighbours share their joint
        if (segmentsMeetInFace(pieces[i].a, pieces[i].b, pieces[j].a, pieces[j].b))
          crossing[pieces[i].span] = crossing[pieces[j].span] = 1;
      }
  return crossing;
}

// p on the vertex or edge the cut merges it with (kSeamPointTolerance), in p's face. Traced from a hair beside
// a vertex, seams that share an end leave it through edge points just beyond the tolerance, which the cut keeps
// apart: their common end splits into stubs a hair long (gores carried onto libigl's bumpy cube).
SurfacePoint onMergedFeature(const SurfacePoint& p) {
  SurfacePoint q = p;
  bool merged = false;
  for (int k = 0; k < 3; ++k)
    if (std::abs(q.bary[k]) <= kSeamPointTolerance) q.bary[k] = 0, merged = true;
  if (merged) q.bary /= q.bary.sum();
  return q;
}

}  // namespace

SeamCurve buildSeamCurve(const GeodesicSolver& solver, const SurfaceProjector& projector, const SeamSpec& spec,
                         const SeamCurveOptions& options) {
  const int n = static_cast<int>(spec.controls.size());
  if (n < 2 || (spec.closed && n < 3))
    throw Error("seams.too-few-points",
                spec.closed ? "A closed seam needs at least three points." : "A seam needs at least two points.");
  SeamCurve curve;
  curve.closed = spec.closed, curve.weight = spec.weight;
  std::vector<SurfacePoint> controls(n);
  std::vector<Eigen::Vector3d> c(n);
  for (int i = 0; i < n; ++i) {
    controls[i] = onMergedFeature(spec.controls[i]);
    c[i] = position(solver.mesh(), controls[i]);
  }
  const std::vector<Eigen::Vector3d> m = tangents(c, spec.closed);
  const int count = spec.closed ? n : n - 1;
  std::vector<GeodesicPath> direct(count), spans(count);
  for (int i = 0; i < count; ++i) {
    const int j = (i + 1) % n;
    spans[i] = direct[i] = solver.path(controls[i], controls[j], options.geodesic);
    if (spec.smooth && options.samplesPerSpan > 0) {
      const Eigen::Vector3d data[4] = {c[i], m[i], c[j], m[j]};
      spans[i] = smoothSpan(solver, projector, controls[i], controls[j], data, direct[i], options);
    }
  }
  // A smoothed span that makes the seam cross itself (the spline overshooting on a tight or concave turn)
  // falls back to the surface path, where the designer's points put it.
  if (spec.smooth) {
    const std::vector<char> crossing = crossingSpans(solver, spans, spec.closed);
    for (int i = 0; i < count; ++i)
      if (crossing[i]) spans[i] = direct[i];
  }
  for (const GeodesicPath& span : spans) {
    curve.controlIndices.push_back(curve.points.empty() ? 0 : static_cast<int>(curve.points.size()) - 1);
    appendPath(curve, span);
  }
  if (!spec.closed) curve.controlIndices.push_back(static_cast<int>(curve.points.size()) - 1);
  if (spec.closed) curve.points.back() = curve.points.front();  // the same point, exactly
  return curve;
}

namespace {

// Closest point of piece i of the curve to p, as a surface point in the piece's face.
SeamSnap snapToPiece(const TriMesh& mesh, const MeshTopology& topo, const Eigen::Vector3d& p, const SeamCurve& c,
                     int i) {
  SeamSnap s;
  const PathPoint &a = c.points[i], &b = c.points[i + 1];
  const Eigen::Vector3d d = b.position - a.position;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::min(1.0, std::max(0.0, (p - a.position).dot(d) / len2)) : 0.0;
  s.kind = SeamSnap::OnCurve, s.piece = i;
  SurfacePoint pa, pb;
  if (t <= 1e-9 || !expressInFace(mesh, topo, a.point, c.faces[i], pa) ||
      !expressInFace(mesh, topo, b.point, c.faces[i], pb)) {
    s.point = a.point, s.position = a.position;
  } else if (t >= 1 - 1e-9) {
    s.point = b.point, s.position = b.position;
  } else {
    s.point.face = c.faces[i];
    s.point.bary = (1 - t) * pa.bary + t * pb.bary;
    s.position = position(mesh, s.point);
  }
  s.distance = (s.position - p).norm();
  return s;
}

}  // namespace

SeamSnap snapToSeams(const TriMesh& mesh, const MeshTopology& topo, const Eigen::Vector3d& p,
                     const std::vector<SeamCurve>& curves, double radius) {
  SeamSnap control, onCurve;
  control.distance = onCurve.distance = std::numeric_limits<double>::infinity();
  for (int ci = 0; ci < static_cast<int>(curves.size()); ++ci) {
    const SeamCurve& c = curves[ci];
    for (int k : c.controlIndices) {
      const double d = (c.points[k].position - p).norm();
      if (d <= radius && d < control.distance) {
        control.kind = SeamSnap::Control, control.curve = ci, control.piece = k;
        control.point = c.points[k].point, control.position = c.points[k].position, control.distance = d;
      }
    }
    for (int i = 0; i + 1 < static_cast<int>(c.points.size()); ++i) {
      SeamSnap s = snapToPiece(mesh, topo, p, c, i);
      if (s.distance <= radius && s.distance < onCurve.distance) onCurve = s, onCurve.curve = ci;
    }
  }
  if (control.kind != SeamSnap::None) return control;
  if (onCurve.kind != SeamSnap::None) return onCurve;
  return SeamSnap();
}

}  // namespace billow
