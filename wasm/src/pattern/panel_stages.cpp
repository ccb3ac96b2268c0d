#include "pattern/panel_stages.hpp"

#include <cmath>
#include <unordered_map>

#include "remesh/panel_mesher.hpp"
#include "util/error.hpp"

namespace billow {

FlatSegment flattenForPattern(const Segmentation& seg, const SeamGraph& graph, int segment,
                              const FlattenOptions& options) {
  FlatSegment fs;
  fs.segment = segment;
  fs.sub = extractSegment(seg, segment);
  fs.flat = flattenSegment(fs.sub.mesh, options);
  std::vector<int> loop;
  for (int v : fs.flat.boundary) loop.push_back(fs.sub.vertexCut[v]);
  fs.pieces = splitLoop(seg, graph, loop);
  return fs;
}

SurfacePoint targetPointOf(const TriMesh& target, const Segmentation& seg, int t, const Eigen::Vector3d& w) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) p += w[k] * seg.mesh.V.row(seg.mesh.F(t, k)).transpose();
  // Cut triangles lie inside their target triangle, so p is in its plane: plain barycentric weights.
  SurfacePoint sp;
  sp.face = seg.faceOrigin[t];
  const auto corner = [&](int k) -> Eigen::Vector3d { return target.V.row(target.F(sp.face, k)).transpose(); };
  sp.bary = closestPointBarycentric(p, corner(0), corner(1), corner(2));
  return sp;
}

namespace {

// Directed edge (a, b) of the segment mesh -> (triangle, corner of a).
std::unordered_map<std::uint64_t, std::pair<int, int>> directedEdgeCorners(const TriMesh& m) {
  std::unordered_map<std::uint64_t, std::pair<int, int>> e;
  for (int t = 0; t < m.numTriangles(); ++t)
    for (int k = 0; k < 3; ++k) e[directedKey(m.F(t, k), m.F(t, (k + 1) % 3))] = {t, k};
  return e;
}

}  // namespace

void meshFlatSegment(const TriMesh& target, const Segmentation& seg, const FlatSegment& fs, double h, Panel& panel,
                     BuiltPanel& built) {
  const std::vector<int>& loop = fs.flat.boundary;
  const int n = static_cast<int>(loop.size());
  Points2 polygon(n, 2);
  for (int i = 0; i < n; ++i) polygon.row(i) = fs.flat.uv.row(loop[i]);
  std::vector<int> corners;
  for (const BoundaryPiece& p : fs.pieces) corners.push_back(p.start);  // increasing: pieces keep loop order
  const ResampledBoundary rb = resampleBoundary(polygon, corners, fs.segments);
  const TriMesh mesh = meshPanel(rb.points, h);
  const int nv = mesh.numVertices(), nb = static_cast<int>(rb.points.rows());

  panel.vertices = mesh.V.leftCols<2>();
  panel.triangles = mesh.F;
  built.segment = fs.segment;
  built.boundaryVertices = nb;
  built.targetPosition.resize(nv, 3);
  built.targetPoint.assign(nv, SurfacePoint{});
  built.seam.assign(nv, -1);
  built.corner.assign(nv, 0);
  built.flattenAreaRatio = fs.flat.areaRatio;
  built.interior = fs.flat.interior;
  const TriMesh& sub = fs.sub.mesh;

  // Boundary rows: on flattened edge (i, i + 1) at fraction s; the same fraction of the 3D edge.
  const auto edges = directedEdgeCorners(sub);
  for (int r = 0; r < nb; ++r) {
    int i = static_cast<int>(std::floor(rb.param(r)));
    double s = rb.param(r) - i;
    i = ((i % n) + n) % n;
    const int a = loop[i], b = loop[(i + 1) % n];
    built.targetPosition.row(r) = (1 - s) * sub.V.row(a) + s * sub.V.row(b);
    const auto [t, k] = edges.at(directedKey(a, b));
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    w[k] = 1 - s, w[(k + 1) % 3] = s;
    built.targetPoint[r] = targetPointOf(target, seg, fs.sub.faceCut[t], w);
    built.seam[r] = fs.pieces[rb.piece(r)].seam;
  }
  for (int k = 0; k < static_cast<int>(fs.pieces.size()); ++k) built.corner[rb.cornerRows[k]] = 1;

  // Interior rows: barycentric location in the flattened segment, evaluated on the 3D segment.
  TriMesh flat2d;
  flat2d.V = Vertices::Zero(sub.numVertices(), 3);
  flat2d.V.leftCols<2>() = fs.flat.uv;
  flat2d.F = sub.F;
  const TriangleLocator locator(flat2d);
  for (int r = nb; r < nv; ++r) {
    const BarycentricPoint bp = locator.locate(mesh.V.row(r).head<2>().transpose());
    Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 3; ++k) x += bp.weights[k] * sub.V.row(sub.F(bp.triangle, k));
    built.targetPosition.row(r) = x;
    built.targetPoint[r] = targetPointOf(target, seg, fs.sub.faceCut[bp.triangle], bp.weights);
  }

  // Pieces: rows from corner k to corner k + 1 (wrapping), N + 1 of them.
  built.pieces.clear();
  for (int k = 0; k < static_cast<int>(fs.pieces.size()); ++k) {
    PanelPiece pp;
    for (int j = 0; j <= rb.segmentsPerPiece[k]; ++j) pp.rows.push_back((rb.cornerRows[k] + j) % nb);
    pp.seam = fs.pieces[k].seam;
    pp.neighborSegment = fs.pieces[k].neighborSegment;
    pp.targetLength = fs.pieces[k].length;
    built.pieces.push_back(std::move(pp));
  }
}

SegmentationProblem meshProblem(const Segmentation& seg, const FlatSegment& fs, const Error& e) {
  SegmentationProblem p;
  p.segment = fs.segment, p.severity = "error", p.location = seg.segments[fs.segment].labelPoint;
  const std::string segment = "Segment " + std::to_string(fs.segment + 1);
  if (e.code != "panel.self-intersecting" && e.code != "panel.repeated-vertex" && e.code != "panel.clockwise") {
    p.code = "pattern.mesh-failed";
    p.message = segment + " could not be made into a panel: " + e.what();
    return p;
  }
  const std::vector<int>& loop = fs.flat.boundary;
  Points2 polygon(loop.size(), 2);
  for (size_t i = 0; i < loop.size(); ++i) polygon.row(i) = fs.flat.uv.row(loop[i]);
  const int crossing = outlineCrossing(polygon);
  if (crossing >= 0) p.location = fs.sub.mesh.V.row(loop[crossing]).transpose();
  p.code = "pattern.overlaps";
  p.message = segment + " would overlap itself when laid flat, " + seg.where(p.location) +
              ": a seam across it there lets it lie flat as two panels.";
  return p;
}

}  // namespace billow
