#include "simulate/coarse_start.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "flatten/segment_boundary.hpp"
#include "remesh/panel_mesher.hpp"
#include "simulate/gauss_seidel.hpp"
#include "simulate/initial_shape.hpp"
#include "util/clock.hpp"
#include "util/error.hpp"

namespace billow {
namespace {

double turnAngle(const Panel& panel, int a, int b, int c) {
  const Eigen::Vector2d u = panel.vertices.row(b) - panel.vertices.row(a);
  const Eigen::Vector2d w = panel.vertices.row(c) - panel.vertices.row(b);
  return std::abs(std::atan2(u.x() * w.y() - u.y() * w.x(), u.dot(w)));
}

// The boundary loops of a panel, each in the direction of its triangles: the outline first (counter-clockwise),
// then its holes (clockwise; a ring panel has one). Empty when the panel has no such boundary (its boundary
// touches itself, or it is in several pieces).
std::vector<std::vector<int>> boundaryLoops(const Panel& panel) {
  TriMesh flat;
  flat.V = Vertices::Zero(panel.vertices.rows(), 3);
  flat.V.leftCols(2) = panel.vertices;
  flat.F = panel.triangles;
  std::vector<std::vector<int>> loops;
  try {
    loops = findBoundaryLoops(flat);
  } catch (const Error&) {
    return {};
  }
  int outlines = 0;
  for (auto& loop : loops) {
    Points2 polygon(loop.size(), 2);
    for (size_t i = 0; i < loop.size(); ++i) polygon.row(i) = panel.vertices.row(loop[i]);
    if (signedArea(polygon) > 0) ++outlines, std::swap(loop, loops[0]);
  }
  if (outlines != 1) return {};
  return loops;
}

}  // namespace

std::optional<Pattern> coarsenPattern(const Pattern& pattern, const SewnMesh& mesh, double h) {
  const int numPanels = static_cast<int>(pattern.panels.size());
  if (!(h > 0)) return std::nullopt;
  std::vector<std::vector<std::vector<int>>> loops(numPanels);  // per panel: outline, then holes
  for (int p = 0; p < numPanels; ++p) {
    loops[p] = boundaryLoops(pattern.panels[p]);
    if (loops[p].empty()) return std::nullopt;
    for (const auto& loop : loops[p])
      if (loop.size() < 3) return std::nullopt;
  }
  // Which panels hold each simulation boundary edge: an edge's signature is the list of panels along it.
  std::unordered_map<std::uint64_t, std::vector<int>> edgePanels;
  for (int p = 0; p < numPanels; ++p)
    for (const auto& loop : loops[p])
      for (size_t i = 0; i < loop.size(); ++i) {
        auto& list = edgePanels[edgeKey(mesh.simVertex(p, loop[i]), mesh.simVertex(p, loop[(i + 1) % loop.size()]))];
        list.push_back(p);
      }
  for (auto& [key, list] : edgePanels) std::sort(list.begin(), list.end());
  // The panels at each simulation vertex.
  std::vector<std::vector<int>> vertexPanels(mesh.numVertices);
  for (int p = 0; p < numPanels; ++p)
    for (const auto& loop : loops[p])
      for (int v : loop) vertexPanels[mesh.simVertex(p, v)].push_back(p);
  for (auto& list : vertexPanels) std::sort(list.begin(), list.end());
  // Key simulation vertices: corners on any panel, and junctions: where a boundary changes partner (the
  // pole of a gored sphere, the ends of a free edge) or where panels meet that its edges do not join. Along
  // a seam shared by three panels (an internal connection sewn into a seam) no vertex is a key.
  constexpr double cornerAngle = 30.0 * M_PI / 180.0;
  std::vector<char> key(mesh.numVertices, 0);
  for (int p = 0; p < numPanels; ++p)
    for (const auto& loop : loops[p]) {
      const int n = static_cast<int>(loop.size());
      for (int i = 0; i < n; ++i) {
        const int a = loop[(i + n - 1) % n], b = loop[i], c = loop[(i + 1) % n];
        const int sa = mesh.simVertex(p, a), sb = mesh.simVertex(p, b), sc = mesh.simVertex(p, c);
        const auto& before = edgePanels[edgeKey(sa, sb)];
        const auto& after = edgePanels[edgeKey(sb, sc)];
        if (turnAngle(pattern.panels[p], a, b, c) > cornerAngle || before != after || vertexPanels[sb] != before)
          key[sb] = 1;
      }
    }
  // A loop without a key (a disc sewn all round to one other, a ring's hole) gets its smallest simulation
  // vertex, which the panel on the other side of it picks too.
  for (int p = 0; p < numPanels; ++p)
    for (const auto& loop : loops[p]) {
      int smallest = -1;
      bool any = false;
      for (int v : loop) {
        const int s = mesh.simVertex(p, v);
        any = any || key[s];
        if (smallest < 0 || s < smallest) smallest = s;
      }
      if (!any) key[smallest] = 1;
    }
  // Between keys, keep vertices about h apart (below); decided once per simulation vertex.
  std::vector<signed char> kept(mesh.numVertices, -1);
  for (int p = 0; p < numPanels; ++p)
    for (const auto& loop : loops[p]) {
      const int n = static_cast<int>(loop.size());
      int first = 0;
      while (!key[mesh.simVertex(p, loop[first])]) ++first;
      for (int i = 0; i < n;) {
        // The piece from key loop[first + i] to the next key.
        std::vector<int> piece{loop[(first + i) % n]};
        int j = i + 1;
        for (; j <= n; ++j) {
          piece.push_back(loop[(first + j) % n]);
          if (key[mesh.simVertex(p, piece.back())]) break;
        }
        i = j;
        for (int v : {piece.front(), piece.back()}) kept[mesh.simVertex(p, v)] = 1;
        bool decided = false;
        for (size_t k = 1; k + 1 < piece.size(); ++k) decided = decided || kept[mesh.simVertex(p, piece[k])] >= 0;
        if (decided) continue;
        // Every stride-th vertex, strides as even as the count allows: the seam rods (seam_rods.hpp) treat
        // consecutive seam vertices as evenly spaced, and a seam kept at spacings of 1 and 2 alternately
        // would be rippled by them.
        double length = 0;
        for (size_t k = 1; k < piece.size(); ++k)
          length += (pattern.panels[p].vertices.row(piece[k]) - pattern.panels[p].vertices.row(piece[k - 1])).norm();
        const int edges = static_cast<int>(piece.size()) - 1;
        const int stride = std::max(1, static_cast<int>(std::lround(h * edges / length)));
        const int segments = std::max(1, static_cast<int>(std::lround(double(edges) / stride)));
        for (int k = 1; k < edges; ++k) kept[mesh.simVertex(p, piece[k])] = 0;
        for (int s = 1; s < segments; ++s)
          kept[mesh.simVertex(p, piece[static_cast<int>(std::lround(double(s) * edges / segments))])] = 1;
      }
    }
  // Coarse panels: the kept boundary vertices of each loop in loop order, remeshed inside (meshPanel lists
  // them first, the outline's and then each hole's).
  Pattern coarse;
  coarse.material = pattern.material;
  coarse.pressure = pattern.pressure;
  std::map<int, std::vector<std::pair<int, int>>> atSimVertex;  // fine simulation vertex -> (panel, coarse vertex)
  for (int p = 0; p < numPanels; ++p) {
    std::vector<int> boundary;
    std::vector<Points2> polygons;
    for (const auto& loop : loops[p]) {
      const size_t start = boundary.size();
      for (int v : loop)
        if (kept[mesh.simVertex(p, v)] == 1) boundary.push_back(v);
      if (boundary.size() - start < 3) return std::nullopt;
      Points2 polygon(boundary.size() - start, 2);
      for (size_t i = start; i < boundary.size(); ++i)
        polygon.row(i - start) = pattern.panels[p].vertices.row(boundary[i]);
      polygons.push_back(std::move(polygon));
    }
    TriMesh m;
    try {
      m = meshPanel(polygons[0], h, {}, std::vector<Points2>(polygons.begin() + 1, polygons.end()));
    } catch (const Error&) {
      return std::nullopt;
    }
    Panel panel;
    panel.name = pattern.panels[p].name;
    panel.internal = pattern.panels[p].internal;
    panel.vertices = m.V.leftCols(2);
    panel.triangles = m.F;
    coarse.panels.push_back(std::move(panel));
    for (size_t i = 0; i < boundary.size(); ++i)
      atSimVertex[mesh.simVertex(p, boundary[i])].emplace_back(p, static_cast<int>(i));
  }
  for (const auto& [s, list] : atSimVertex)
    for (size_t i = 1; i < list.size(); ++i)
      coarse.stitches.push_back({list[i - 1].first, list[i - 1].second, list[i].first, list[i].second});
  flipPinchingEdges(coarse);
  return coarse;
}

Vertices prolongate(const Pattern& coarse, const SewnMesh& coarseMesh, const Vertices& x, const Pattern& fine,
                    const SewnMesh& fineMesh) {
  // Area-weighted vertex normals of the coarse outer surface (zero on vertices of internal panels only).
  Vertices normals = Vertices::Zero(coarseMesh.numVertices, 3);
  for (int f = 0; f < coarseMesh.numTriangles(); ++f) {
    if (!coarseMesh.outer[f]) continue;
    const Eigen::Vector3d a = x.row(coarseMesh.triangles(f, 0)), b = x.row(coarseMesh.triangles(f, 1)),
                          c = x.row(coarseMesh.triangles(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) normals.row(coarseMesh.triangles(f, k)) += n.transpose();
  }
  // Where three or more panel vertices meet (the gores' poles, an internal panel's seam) the surface has a
  // cone point or a crease and no tangent plane: no curving there (sphere3 at 60k: 27 -> 22 fine iterations).
  for (int v = 0; v < coarseMesh.numVertices; ++v) {
    const double l = normals.row(v).norm();
    if (coarseMesh.stitchedCount[v] >= 3)
      normals.row(v).setZero();
    else if (l > 0)
      normals.row(v) /= l;
  }
  Vertices out = Vertices::Zero(fineMesh.numVertices, 3);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(fineMesh.numVertices);
  for (size_t p = 0; p < fine.panels.size(); ++p) {
    const Panel& cp = coarse.panels[p];
    TriMesh flat;
    flat.V = Vertices::Zero(cp.vertices.rows(), 3);
    flat.V.leftCols(2) = cp.vertices;
    flat.F = cp.triangles;
    const TriangleLocator locator(flat);
    const Panel& fp = fine.panels[p];
    for (int v = 0; v < fp.vertices.rows(); ++v) {
      const BarycentricPoint b = locator.locate(fp.vertices.row(v).transpose());
      int corner[3];
      Eigen::Vector3d linear = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        corner[k] = coarseMesh.simVertex(static_cast<int>(p), cp.triangles(b.triangle, k));
        linear += b.weights[k] * x.row(corner[k]).transpose();
      }
      // Phong tessellation: the linear point projected onto each corner's tangent plane, blended alike.
      Eigen::Vector3d curved = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d xk = x.row(corner[k]), nk = normals.row(corner[k]);
        curved += b.weights[k] * (linear - (linear - xk).dot(nk) * nk);
      }
      const int s = fineMesh.simVertex(static_cast<int>(p), v);
      out.row(s) += curved.transpose();
      count[s] += 1;
    }
  }
  for (int s = 0; s < fineMesh.numVertices; ++s) out.row(s) /= std::max(count[s], 1.0);
  return out;
}

namespace {

// Inflates the coarse version of `pattern` (recursively started) and prolongates; empty when not possible.
Vertices coarseToFine(const Pattern& pattern, const SewnMesh& mesh, const InflateOptions& options,
                      StartReport& report) {
  const double triangles = mesh.numTriangles() / options.coarseStartRatio;
  double area = 0;  // of all panels, at rest
  for (const ElementRest& rest : mesh.rest) area += rest.area;
  // Equilateral triangles of edge h have area sqrt(3)/4 h^2.
  const double h = std::sqrt(4 * area / (std::sqrt(3.0) * triangles));
  std::optional<Pattern> coarse = coarsenPattern(pattern, mesh, h);
  if (!coarse) return {};
  SewnMesh coarseMesh;
  try {
    coarseMesh = sewPattern(*coarse);
  } catch (const Error&) {
    return {};
  }
  // Coarsening that hardly coarsens (seams dense with corners) is no use.
  if (coarseMesh.numTriangles() > 0.6 * mesh.numTriangles()) return {};
  InflateOptions coarseOptions = options;
  coarseOptions.seamRods = nullptr;  // the coarse mesh's own rods (same stiffness)
  coarseOptions.tolerance = std::max(options.tolerance, options.coarseTolerance);
  coarseOptions.maxIterations = std::min(options.maxIterations, options.coarseMaxIterations);
  Vertices x0;
  if (coarseMesh.numTriangles() >= options.coarseStartTriangles)
    x0 = coarseToFine(*coarse, coarseMesh, coarseOptions, report);
  else
    x0 = bareStart(*coarse, coarseMesh);
  const int coarseTriangles = coarseMesh.numTriangles();
  InflationSolver solver(std::move(coarseMesh), pattern.material, pattern.pressure, coarseOptions, x0);
  while (solver.step(50) == InflateState::Running) {
  }
  ++report.levels;
  report.coarseIterations += solver.iterations();
  if (report.coarseTriangles == 0 || coarseTriangles < report.coarseTriangles) report.coarseTriangles = coarseTriangles;
  if (solver.state() == InflateState::Failed || !solver.positions().allFinite()) return {};
  Vertices x = prolongate(*coarse, solver.mesh(), solver.positions(), pattern, mesh);
  const GaussSeidelReport sweeps =
      gaussSeidelSweeps(mesh, pattern.material, pattern.pressure, options, x, options.gaussSeidelSweeps);
  report.gaussSeidelMs += sweeps.ms;
  report.residualProlongated = sweeps.residualBefore;
  report.residualAfterGaussSeidel = sweeps.residualAfter;
  return x;
}

}  // namespace

Vertices startPositions(const Pattern& pattern, const SewnMesh& mesh, const InflateOptions& options,
                        StartReport* report) {
  Vertices x = startFromInflated(pattern, mesh);
  if (x.rows() == mesh.numVertices) return x;
  StartReport local;
  StartReport& r = report ? *report : local;
  r = StartReport{};
  if (options.coarseStartTriangles > 0 && mesh.numTriangles() >= options.coarseStartTriangles &&
      options.coarseStartRatio > 1) {
    const auto t0 = Clock::now();
    x = coarseToFine(pattern, mesh, options, r);
    r.coarseMs = msSince(t0);
    if (x.rows() == mesh.numVertices && x.allFinite()) return x;
    r.levels = 0;
  }
  return bareStart(pattern, mesh);
}

}  // namespace billow
