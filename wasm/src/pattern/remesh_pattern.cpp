#include "pattern/remesh_pattern.hpp"

#include <algorithm>
#include <cmath>

#include "remesh/panel_mesher.hpp"
#include "util/error.hpp"
#include "util/union_find.hpp"

namespace billow {

namespace {

double pieceLength(const Panel& panel, const PanelPiece& piece) {
  double length = 0;
  for (size_t k = 0; k + 1 < piece.rows.size(); ++k)
    length += (panel.vertices.row(piece.rows[k + 1]) - panel.vertices.row(piece.rows[k])).norm();
  return length;
}

// Segments per piece: one count for all the pieces sewn together (union of neighbour links), from their mean
// length, the sewn seams kept a simple graph (keepSewnSeamsSimple); the sewn points are the pieces' end rows
// united across their stitches.
std::vector<std::vector<int>> segmentCounts(const BuiltPattern& built, double h) {
  std::vector<int> first{0}, firstRow{0};
  for (size_t p = 0; p < built.panels.size(); ++p) {
    first.push_back(first.back() + static_cast<int>(built.panels[p].pieces.size()));
    firstRow.push_back(firstRow.back() + static_cast<int>(built.pattern.panels[p].vertices.rows()));
  }
  UnionFind groups(first.back()), points(firstRow.back());
  for (size_t p = 0; p < built.panels.size(); ++p)
    for (size_t k = 0; k < built.panels[p].pieces.size(); ++k) {
      const PanelPiece& piece = built.panels[p].pieces[k];
      if (piece.neighborPanel < 0) continue;
      groups.unite(first[p] + k, first[piece.neighborPanel] + piece.neighborPiece);
      const PanelPiece& other = built.panels[piece.neighborPanel].pieces[piece.neighborPiece];
      points.unite(firstRow[p] + piece.rows.front(), firstRow[piece.neighborPanel] + other.rows.back());
      points.unite(firstRow[p] + piece.rows.back(), firstRow[piece.neighborPanel] + other.rows.front());
    }
  std::vector<double> sum(first.back(), 0.0);
  std::vector<int> count(first.back(), 0);
  for (size_t p = 0; p < built.panels.size(); ++p)
    for (size_t k = 0; k < built.panels[p].pieces.size(); ++k) {
      const int g = groups.find(first[p] + k);
      sum[g] += pieceLength(built.pattern.panels[p], built.panels[p].pieces[k]);
      ++count[g];
    }
  std::vector<int> curveOf(first.back(), -1), counts;
  std::vector<std::array<int, 2>> ends;
  for (size_t p = 0; p < built.panels.size(); ++p)
    for (size_t k = 0; k < built.panels[p].pieces.size(); ++k) {
      const int g = groups.find(first[p] + k);
      if (curveOf[g] >= 0) continue;
      const PanelPiece& piece = built.panels[p].pieces[k];
      curveOf[g] = static_cast<int>(counts.size());
      counts.push_back(segmentCountFor(sum[g] / count[g], h));
      ends.push_back({points.find(firstRow[p] + piece.rows.front()), points.find(firstRow[p] + piece.rows.back())});
    }
  keepSewnSeamsSimple(counts, ends);
  std::vector<std::vector<int>> out(built.panels.size());
  for (size_t p = 0; p < built.panels.size(); ++p)
    for (size_t k = 0; k < built.panels[p].pieces.size(); ++k)
      out[p].push_back(counts[curveOf[groups.find(first[p] + k)]]);
  return out;
}

struct Carried {
  Vertices target, inflated;  // per new panel vertex
};

// Panel p meshed anew: its pieces resampled (counts[k] segments each), its interior at edge length h; the
// target and inflated positions carried over. Pieces of `bp` are replaced by the new rows.
Panel remeshPanel(const Panel& old, const BuiltPanel& oldBuilt, const Vertices& oldInflated,
                  const std::vector<int>& counts, double h, BuiltPanel& bp, Carried& carried) {
  const int np = static_cast<int>(oldBuilt.pieces.size());
  for (int k = 0; k < np; ++k)
    if (oldBuilt.pieces[k].rows.back() != oldBuilt.pieces[(k + 1) % np].rows.front())
      throw Error("pattern.remesh-failed", "The pieces of a panel do not follow each other around its outline.");
  int boundary = 0;
  for (int n : counts) boundary += n;
  Points2 outline(boundary, 2);
  Vertices target(boundary, 3), inflated(boundary, 3);
  std::vector<int> seam(boundary, -1);
  std::vector<char> corner(boundary, 0);
  // The seam corners the pattern marks (Panel::seamCorners) go to the new outline vertex nearest along the piece.
  std::vector<char> marked(old.vertices.rows(), 0);
  if (old.seamCorners)
    for (int v : *old.seamCorners) marked[v] = 1;
  std::vector<int> seamCorners;
  int row = 0;
  for (int k = 0; k < np; ++k) {
    const PanelPiece& piece = oldBuilt.pieces[k];
    Points2 polyline(piece.rows.size(), 2);
    for (size_t i = 0; i < piece.rows.size(); ++i) polyline.row(i) = old.vertices.row(piece.rows[i]);
    Eigen::VectorXd param;
    const Points2 points = resamplePolyline(polyline, counts[k], &param);
    PanelPiece& renewed = bp.pieces[k];
    renewed.rows.clear();
    for (int i = 0; i <= counts[k]; ++i) {
      const int r = (row + i) % boundary;
      renewed.rows.push_back(r);
      if (i == counts[k]) break;  // the next piece's first point
      const int e = std::min(static_cast<int>(param(i)), static_cast<int>(piece.rows.size()) - 2);
      const double s = param(i) - e;
      const int a = piece.rows[e], b = piece.rows[e + 1];
      outline.row(r) = points.row(i);
      target.row(r) = (1 - s) * oldBuilt.targetPosition.row(a) + s * oldBuilt.targetPosition.row(b);
      inflated.row(r) = (1 - s) * oldInflated.row(a) + s * oldInflated.row(b);
      seam[r] = piece.seam;
      corner[r] = i == 0;
    }
    for (int j = 0; j + 1 < static_cast<int>(piece.rows.size()); ++j) {  // the last row is the next piece's first
      if (!marked[piece.rows[j]]) continue;
      int nearest = 0;
      for (int i = 1; i <= counts[k]; ++i)
        if (std::abs(param(i) - j) < std::abs(param(nearest) - j)) nearest = i;
      seamCorners.push_back((row + nearest) % boundary);
    }
    row += counts[k];
  }
  const TriMesh mesh = meshPanel(outline, h);
  const int nv = mesh.numVertices();
  Panel panel;
  panel.name = old.name;
  panel.internal = old.internal;
  panel.vertices = mesh.V.leftCols(2);
  panel.triangles = mesh.F;
  if (old.seamCorners) {
    std::sort(seamCorners.begin(), seamCorners.end());
    seamCorners.erase(std::unique(seamCorners.begin(), seamCorners.end()), seamCorners.end());
    panel.seamCorners = std::move(seamCorners);
  }
  carried.target.resize(nv, 3);
  carried.inflated.resize(nv, 3);
  carried.target.topRows(boundary) = target;
  carried.inflated.topRows(boundary) = inflated;
  TriMesh flat;
  flat.V.setZero(old.vertices.rows(), 3);
  flat.V.leftCols(2) = old.vertices;
  flat.F = old.triangles;
  const TriangleLocator locator(flat);
  for (int v = boundary; v < nv; ++v) {
    const BarycentricPoint at = locator.locate(panel.vertices.row(v).transpose());
    carried.target.row(v).setZero();
    carried.inflated.row(v).setZero();
    for (int c = 0; c < 3; ++c) {
      const int u = old.triangles(at.triangle, c);
      carried.target.row(v) += at.weights[c] * oldBuilt.targetPosition.row(u);
      carried.inflated.row(v) += at.weights[c] * oldInflated.row(u);
    }
  }
  bp.boundaryVertices = boundary;
  bp.targetPosition = carried.target;
  bp.targetPoint.assign(nv, SurfacePoint{});  // not carried: the optimizer uses targetPosition
  bp.seam = seam;
  bp.seam.resize(nv, -1);
  bp.corner = corner;
  bp.corner.resize(nv, 0);
  return panel;
}

}  // namespace

double minPanelAngleDeg(const Pattern& pattern) {
  double least = 180;
  for (const Panel& panel : pattern.panels)
    for (int t = 0; t < panel.triangles.rows(); ++t)
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector2d o = panel.vertices.row(panel.triangles(t, c));
        const Eigen::Vector2d a = Eigen::Vector2d(panel.vertices.row(panel.triangles(t, (c + 1) % 3))) - o;
        const Eigen::Vector2d b = Eigen::Vector2d(panel.vertices.row(panel.triangles(t, (c + 2) % 3))) - o;
        const double angle = std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b)) * 180 / M_PI;
        least = std::min(least, angle);
      }
  return least;
}

RemeshedPattern remeshPattern(const BuiltPattern& built, const std::vector<Vertices>& inflated, double h) {
  if (!(h > 0) || inflated.size() != built.panels.size())
    throw Error("pattern.remesh-failed", "Remeshing needs an edge length and the inflated positions of every panel.");
  const std::vector<std::vector<int>> counts = segmentCounts(built, h);
  RemeshedPattern out;
  out.built = built;
  out.built.pattern.panels.clear();
  out.built.pattern.inflated.clear();
  for (size_t p = 0; p < built.panels.size(); ++p) {
    const Panel& old = built.pattern.panels[p];
    if (built.panels[p].pieces.empty()) {  // nothing sewn to it: kept as it is
      out.built.pattern.panels.push_back(old);
      out.inflated.push_back(inflated[p]);
      continue;
    }
    Carried carried;
    try {
      out.built.pattern.panels.push_back(
          remeshPanel(old, built.panels[p], inflated[p], counts[p], h, out.built.panels[p], carried));
    } catch (const Error& e) {
      throw Error("pattern.remesh-failed",
                  "Panel " + std::to_string(p + 1) + " could not be meshed again: " + e.what());
    }
    out.inflated.push_back(std::move(carried.inflated));
  }
  out.built.pattern.inflated = out.inflated;
  stitchBuiltPattern(out.built);
  PatternFigures& fig = out.built.figures;
  fig.triangles = fig.vertices = 0;
  for (const Panel& panel : out.built.pattern.panels) {
    fig.triangles += static_cast<int>(panel.triangles.rows());
    fig.vertices += static_cast<int>(panel.vertices.rows());
  }
  fig.edgeLength = h;
  return out;
}

}  // namespace billow
