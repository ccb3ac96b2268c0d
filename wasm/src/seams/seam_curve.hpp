// Seam curves on the target (paper Sec. 3.2, "Seam Design"): the designer places control points; the seam
// runs along approximately shortest paths between them (geodesics metaphor), or, when smoothed, along a
// cubic Hermite (Catmull-Rom) spline through the points whose samples are projected onto the surface and
// joined by geodesics (DESIGN.md). Snapping links a new seam to the existing network so that T- and
// X-junctions meet exactly and segmentation sees closed regions.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "seams/geodesic.hpp"
#include "seams/surface_point.hpp"

namespace billow {

// Barycentric tolerance under which seam points merge with a vertex, an edge or each other. A seam laid along an
// outline passes a hair (1e-6) beside the vertices its rim lies on; cut there, they would stay inside one side
// behind sliver triangles and give it the rim's curvature (a star's tips all to the back panel). Control points
// are traced from where the cut takes them (buildSeamCurve).
inline constexpr double kSeamPointTolerance = 1e-5;

struct SeamSpec {
  std::vector<SurfacePoint> controls;  // at least 2 (3 when closed)
  bool closed = false;                 // closed loops join the last control point to the first
  double weight = 1.0;                 // sigma_i of Eq. 10: how firmly the seam stays where it is drawn
  bool smooth = false;                 // Hermite spline through the controls instead of plain geodesics
};

struct SeamCurveOptions {
  int samplesPerSpan = 6;   // spline samples between two control points (smooth seams)
  double maxDetour = 1.25;  // a smoothed span longer than this times the geodesic falls back to the geodesic
  GeodesicOptions geodesic;
};

// A polyline on the target. Consecutive points lie on a common face (faces[i] for points i, i+1); the points
// between control points lie on mesh edges or vertices. Closed curves repeat their first point at the end.
struct SeamCurve {
  std::vector<PathPoint> points;
  std::vector<int> faces;           // #points-1
  std::vector<int> controlIndices;  // index in points of each control point, in order
  bool closed = false;
  double weight = 1.0;
  double length = 0;
};

// Throws billow::Error("seams.too-few-points") when the spec has too few control points.
SeamCurve buildSeamCurve(const GeodesicSolver& solver, const SurfaceProjector& projector, const SeamSpec& spec,
                         const SeamCurveOptions& options = {});

struct SeamSnap {
  enum Kind { None, Control, OnCurve } kind = None;  // Control: a control point (end points included)
  int curve = -1;
  int piece = -1;  // OnCurve: the piece points[piece] -> points[piece + 1]
  SurfacePoint point;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double distance = 0;
};

// The closest point of an existing curve within radius of p (3D distance); control points win over
// the rest of the curve when both are within radius. A snapped point lies exactly on the curve's piece.
SeamSnap snapToSeams(const TriMesh& mesh, const MeshTopology& topo, const Eigen::Vector3d& p,
                     const std::vector<SeamCurve>& curves, double radius);

}  // namespace billow
