// Sewing: union-find over stitched panel vertices, then checks that the outer surface closes.
#include "simulate/sewn_pattern.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include "remesh/predicates.hpp"
#include "util/error.hpp"
#include "util/union_find.hpp"

namespace billow {
namespace {

std::string panelLabel(const Pattern& p, int panel) {
  const std::string& name = p.panels[panel].name;
  return name.empty() ? "panel " + std::to_string(panel) : "panel '" + name + "'";
}

void checkIndices(const Pattern& p, const PatternLimits& limits) {
  if (p.panels.empty()) throw Error("pattern.empty", "The pattern has no panels.");
  if (static_cast<long long>(p.panels.size()) > limits.maxPanels)
    throw Error("pattern.too-large", "The pattern has more than " + std::to_string(limits.maxPanels) + " panels.");
  long long triangles = 0;
  for (size_t i = 0; i < p.panels.size(); ++i) {
    const Panel& panel = p.panels[i];
    triangles += panel.triangles.rows();
    if (panel.triangles.rows() == 0) throw Error("pattern.empty", panelLabel(p, int(i)) + " has no triangles.");
    if (panel.triangles.size() &&
        (panel.triangles.minCoeff() < 0 || panel.triangles.maxCoeff() >= panel.vertices.rows()))
      throw Error("pattern.bad-index",
                  panelLabel(p, int(i)) + " has a triangle that refers to a vertex it does not have.");
    if (!panel.vertices.allFinite())
      throw Error("pattern.degenerate", panelLabel(p, int(i)) + " has a vertex with an invalid coordinate.");
    if (panel.seamCorners)
      for (int v : *panel.seamCorners)
        if (v < 0 || v >= panel.vertices.rows())
          throw Error("pattern.bad-index", panelLabel(p, int(i)) + " has a seam corner at a vertex it does not have.");
  }
  if (triangles > limits.maxTriangles)
    throw Error("pattern.too-large", "The pattern has " + std::to_string(triangles) +
                                         " triangles; Billow simulates at most " + std::to_string(limits.maxTriangles) +
                                         ". Use a coarser resolution.");
  for (size_t s = 0; s < p.stitches.size(); ++s) {
    const Stitch& st = p.stitches[s];
    const int n = static_cast<int>(p.panels.size());
    const bool ok = st.panelA >= 0 && st.panelA < n && st.panelB >= 0 && st.panelB < n && st.vertexA >= 0 &&
                    st.vertexB >= 0 && st.vertexA < p.panels[st.panelA].vertices.rows() &&
                    st.vertexB < p.panels[st.panelB].vertices.rows();
    if (!ok)
      throw Error("pattern.bad-index",
                  "Stitch " + std::to_string(s) + " refers to a panel or vertex that does not exist.");
  }
}

// Stitches join panel boundary vertices only (a stitch in a panel's interior is a drawing mistake); the panel
// vertices they join, as sets.
UnionFind stitchedVertices(const Pattern& p, const SewnMesh& m,
                           const std::vector<std::map<std::pair<int, int>, std::pair<int, int>>>& boundary) {
  const int numPanels = static_cast<int>(p.panels.size());
  std::vector<std::vector<char>> onBoundary(numPanels);
  for (int i = 0; i < numPanels; ++i) {
    onBoundary[i].assign(p.panels[i].vertices.rows(), 0);
    for (const auto& [key, e] : boundary[i]) onBoundary[i][key.first] = onBoundary[i][key.second] = 1;
  }
  UnionFind uf(m.panelVertexStart.back());
  for (size_t s = 0; s < p.stitches.size(); ++s) {
    const Stitch& st = p.stitches[s];
    if (!onBoundary[st.panelA][st.vertexA] || !onBoundary[st.panelB][st.vertexB])
      throw Error("pattern.not-boundary", "Stitch " + std::to_string(s) + " sews a vertex inside " +
                                              panelLabel(p, onBoundary[st.panelA][st.vertexA] ? st.panelB : st.panelA) +
                                              "; stitches may only join panel edges.");
    uf.unite(m.panelVertexStart[st.panelA] + st.vertexA, m.panelVertexStart[st.panelB] + st.vertexB);
  }
  return uf;
}

// One simulation vertex per set of stitched panel vertices, numbered by first appearance: deterministic for a
// given file.
void numberSimulationVertices(UnionFind& uf, SewnMesh& m) {
  m.simVertexOf.assign(m.panelVertexStart.back(), -1);
  std::vector<int> rootIndex(m.panelVertexStart.back(), -1);
  for (int g = 0; g < m.panelVertexStart.back(); ++g) {
    const int r = uf.find(g);
    if (rootIndex[r] < 0) {
      rootIndex[r] = m.numVertices++;
      m.stitchedCount.push_back(0);
    }
    m.simVertexOf[g] = rootIndex[r];
    ++m.stitchedCount[rootIndex[r]];
  }
}

// SewnMesh::seamCorner: the marks of a panel that has them; else where the outline turns by more than 45 degrees,
// the rest angles of the panel's triangles summed over its vertices sewn into one point (a gusset strip's two
// ends, sewn together, continue its seam).
void markSeamCorners(const Pattern& p, SewnMesh& m) {
  m.seamCorner.assign(m.panelVertexStart.back(), 0);
  for (size_t i = 0; i < p.panels.size(); ++i) {
    const Panel& panel = p.panels[i];
    const int start = m.panelVertexStart[i];
    if (panel.seamCorners) {
      for (int v : *panel.seamCorners) m.seamCorner[start + v] = 1;
      continue;
    }
    const std::vector<int> outline = outlineVertices(panel);
    std::map<int, double> angle;  // simulation vertex -> the panel's rest angles there
    for (int v : outline) angle[m.simVertexOf[start + v]] = 0;
    for (int f = 0; f < panel.triangles.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        const auto at = angle.find(m.simVertexOf[start + panel.triangles(f, k)]);
        if (at == angle.end()) continue;
        const Eigen::Vector2d a = panel.vertices.row(panel.triangles(f, k)).transpose();
        const Eigen::Vector2d u = panel.vertices.row(panel.triangles(f, (k + 1) % 3)).transpose() - a;
        const Eigen::Vector2d w = panel.vertices.row(panel.triangles(f, (k + 2) % 3)).transpose() - a;
        at->second += std::atan2(std::abs(u.x() * w.y() - u.y() * w.x()), u.dot(w));
      }
    for (int v : outline) m.seamCorner[start + v] = std::abs(M_PI - angle[m.simVertexOf[start + v]]) > M_PI / 4;
  }
}

// The simulation triangles with their rest shapes; flat, clockwise or self-sewn triangles are refused.
void sewTriangles(const Pattern& p, SewnMesh& m) {
  const int numPanels = static_cast<int>(p.panels.size());
  const long long triangles = numTriangles(p);
  m.triangles.resize(triangles, 3);
  m.rest.resize(triangles);
  m.outer.resize(triangles);
  m.trianglePanel.resize(triangles);
  double edgeSum = 0;
  int t = 0;
  for (int i = 0; i < numPanels; ++i) {
    const Panel& panel = p.panels[i];
    for (int k = 0; k < panel.triangles.rows(); ++k, ++t) {
      const Eigen::Vector2d X0 = panel.vertices.row(panel.triangles(k, 0)),
                            X1 = panel.vertices.row(panel.triangles(k, 1)),
                            X2 = panel.vertices.row(panel.triangles(k, 2));
      m.rest[t] = makeElementRest(X0, X1, X2);
      const double scale = std::max({(X1 - X0).squaredNorm(), (X2 - X1).squaredNorm(), (X0 - X2).squaredNorm()});
      if (!(m.rest[t].area > 1e-12 * scale))
        throw Error("pattern.degenerate", panelLabel(p, i) + " has a triangle (" + std::to_string(k) +
                                              ") that is flat, or clockwise: panel triangles must be counterclockwise "
                                              "as seen from outside.");
      for (int c = 0; c < 3; ++c) m.triangles(t, c) = m.simVertexOf[m.panelVertexStart[i] + panel.triangles(k, c)];
      if (m.triangles(t, 0) == m.triangles(t, 1) || m.triangles(t, 1) == m.triangles(t, 2) ||
          m.triangles(t, 0) == m.triangles(t, 2))
        throw Error("pattern.degenerate",
                    panelLabel(p, i) + " has a triangle (" + std::to_string(k) + ") with two corners sewn together.", i,
                    panel.triangles(k, 0));
      m.outer[t] = !panel.internal;
      m.trianglePanel[t] = i;
      if (!panel.internal) m.outerArea += m.rest[t].area;
      edgeSum +=
          std::sqrt((X1 - X0).squaredNorm()) + std::sqrt((X2 - X1).squaredNorm()) + std::sqrt((X0 - X2).squaredNorm());
    }
  }
  m.meanEdgeLength = edgeSum / (3.0 * double(triangles));
}

// The outer surface must close: every sewn edge is used once in each direction by outer triangles.
void checkClosed(const Pattern& p, const SewnMesh& m) {
  std::map<std::pair<int, int>, std::pair<int, int>> uses;  // directed edge -> (count, triangle)
  for (int f = 0; f < m.numTriangles(); ++f) {
    if (!m.outer[f]) continue;
    for (int c = 0; c < 3; ++c) {
      auto& u = uses[{m.triangles(f, c), m.triangles(f, (c + 1) % 3)}];
      ++u.first;
      u.second = f;
    }
  }
  if (uses.empty()) throw Error("pattern.open", "The pattern has no outer panel: nothing holds the air.");
  // The panel of an outer triangle and its vertex at sewn vertex v: where an edge fails, for Error's place.
  const auto panelVertexAt = [&](int f, int v) {
    const int i = m.trianglePanel[f];
    for (int k = m.panelVertexStart[i]; k < m.panelVertexStart[i + 1]; ++k)
      if (m.simVertexOf[k] == v) return std::pair{i, k - m.panelVertexStart[i]};
    return std::pair{i, -1};
  };
  for (const auto& [e, u] : uses) {
    if (u.first <= 1 && uses.count({e.second, e.first})) continue;  // sewn once each way: as it should be
    const std::string where = panelLabel(p, m.trianglePanel[u.second]);
    const auto [panel, vertex] = panelVertexAt(u.second, e.first);
    if (u.first > 1)
      throw Error(
          uses.count({e.second, e.first}) ? "pattern.non-manifold" : "pattern.orientation",
          uses.count({e.second, e.first})
              ? "More than two outer panels meet along one edge of " + where + "; use an internal panel instead."
              : "Two outer panels along a seam of " + where + " face opposite ways; one panel is flipped.",
          panel, vertex);
    throw Error("pattern.open",
                "An edge of " + where +
                    " is not sewn to another panel, so the balloon would leak. Stitch both ends of "
                    "every outer panel edge to a matching edge.",
                panel, vertex);
  }
}

// Sewn boundary edges of different lengths (DESIGN.md: Eq. 11 wants them equal), as warnings.
void warnSeamLengths(const Pattern& p, const std::vector<std::map<std::pair<int, int>, std::pair<int, int>>>& boundary,
                     SewnMesh& m) {
  const int numPanels = static_cast<int>(p.panels.size());
  std::map<std::pair<int, int>, std::pair<double, int>> sewnLength;  // sim edge -> (length, panel)
  for (int i = 0; i < numPanels; ++i)
    for (const auto& [key, e] : boundary[i]) {
      const int a = m.simVertex(i, e.first), b = m.simVertex(i, e.second);
      const double len = (p.panels[i].vertices.row(e.first) - p.panels[i].vertices.row(e.second)).norm();
      auto it = sewnLength.find(std::minmax(a, b));
      if (it == sewnLength.end()) {
        sewnLength[std::minmax(a, b)] = {len, i};
        continue;
      }
      const double mismatch = std::abs(len - it->second.first) / std::max(len, it->second.first);
      if (mismatch > 1e-3 && m.warnings.size() < 100)  // a badly drawn pattern would otherwise list every edge
        m.warnings.push_back({"pattern.seam-length",
                              "A seam between " + panelLabel(p, it->second.second) + " and " + panelLabel(p, i) +
                                  " joins edges whose lengths differ by " + std::to_string(mismatch * 100) +
                                  " %; the seam will pucker.",
                              mismatch});
    }
}

}  // namespace

SewnMesh sewPattern(const Pattern& p, const PatternLimits& limits) {
  checkIndices(p, limits);
  const int numPanels = static_cast<int>(p.panels.size());
  SewnMesh m;
  m.panelVertexStart.assign(numPanels + 1, 0);
  for (int i = 0; i < numPanels; ++i)
    m.panelVertexStart[i + 1] = m.panelVertexStart[i] + int(p.panels[i].vertices.rows());
  std::vector<std::map<std::pair<int, int>, std::pair<int, int>>> boundary(numPanels);
  for (int i = 0; i < numPanels; ++i) boundary[i] = outlineEdges(p.panels[i]);
  UnionFind uf = stitchedVertices(p, m, boundary);
  numberSimulationVertices(uf, m);
  markSeamCorners(p, m);
  sewTriangles(p, m);
  checkClosed(p, m);
  warnSeamLengths(p, boundary, m);
  return m;
}

std::vector<int> seamCorners(const SewnMesh& mesh, int panel) {
  std::vector<int> corners;
  for (int g = mesh.panelVertexStart[panel]; g < mesh.panelVertexStart[panel + 1]; ++g)
    if (mesh.seamCorner[g]) corners.push_back(g - mesh.panelVertexStart[panel]);
  return corners;
}

Triangles outerTriangles(const SewnMesh& mesh) {
  Triangles out(std::count(mesh.outer.begin(), mesh.outer.end(), 1), 3);
  int k = 0;
  for (int f = 0; f < mesh.numTriangles(); ++f)
    if (mesh.outer[f]) out.row(k++) = mesh.triangles.row(f);
  return out;
}

std::vector<Vertices> panelPositions(const SewnMesh& mesh, const Vertices& x) {
  const int panels = static_cast<int>(mesh.panelVertexStart.size()) - 1;
  std::vector<Vertices> out(std::max(panels, 0));
  for (int p = 0; p < panels; ++p) {
    out[p].resize(mesh.panelVertexStart[p + 1] - mesh.panelVertexStart[p], 3);
    for (int v = 0; v < out[p].rows(); ++v) out[p].row(v) = x.row(mesh.simVertex(p, v));
  }
  return out;
}

namespace {

// Flips the edge from corner c to c + 1 of triangle t to the other diagonal of the quad it shares with its
// neighbour, when that quad is convex and `accept` takes the new edge's ends.
template <class Accept>
bool flipEdge(Panel& panel, int t, int c, const Accept& accept) {
  Triangles& F = panel.triangles;
  const int a = F(t, c), b = F(t, (c + 1) % 3), apex = F(t, (c + 2) % 3);
  const auto at = [&](int v) -> Eigen::Vector2d { return panel.vertices.row(v).transpose(); };
  for (int u = 0; u < F.rows(); ++u)
    for (int k = 0; k < 3; ++k) {
      if (F(u, k) != b || F(u, (k + 1) % 3) != a) continue;
      const int d = F(u, (k + 2) % 3);
      if (orient2d(at(a), at(d), at(apex)) <= 0 || orient2d(at(d), at(b), at(apex)) <= 0 || !accept(apex, d))
        return false;
      F.row(t) << a, d, apex;
      F.row(u) << d, b, apex;
      return true;
    }
  return false;  // on the panel's outline
}

}  // namespace

int flipPinchingEdges(Pattern& pattern) {
  std::vector<int> start{0};
  for (const Panel& panel : pattern.panels) start.push_back(start.back() + static_cast<int>(panel.vertices.rows()));
  UnionFind point(start.back());
  for (const Stitch& s : pattern.stitches) point.unite(start[s.panelA] + s.vertexA, start[s.panelB] + s.vertexB);
  int flips = 0;
  for (int pass = 0; pass < 100; ++pass) {
    std::map<std::pair<int, int>, std::vector<std::array<int, 3>>> uses;  // sewn edge -> (panel, triangle, corner)
    for (int p = 0; p < static_cast<int>(pattern.panels.size()); ++p) {
      if (pattern.panels[p].internal) continue;  // sewn onto seams on purpose (an internal connection)
      const Triangles& F = pattern.panels[p].triangles;
      for (int t = 0; t < F.rows(); ++t)
        for (int c = 0; c < 3; ++c)
          uses[{point.find(start[p] + F(t, c)), point.find(start[p] + F(t, (c + 1) % 3))}].push_back({p, t, c});
    }
    bool flipped = false;
    for (const auto& [edge, at] : uses) {
      if (edge.first != edge.second && at.size() < 2) continue;
      for (const auto& [p, t, c] : at) {
        const auto isNew = [&, p = p](int u, int v) {
          const int su = point.find(start[p] + u), sv = point.find(start[p] + v);
          return su != sv && !uses.count({su, sv}) && !uses.count({sv, su});
        };
        if ((flipped = flipEdge(pattern.panels[p], t, c, isNew))) break;
      }
      if (flipped) break;
    }
    if (!flipped) break;  // none left, or none a flip mends (sewPattern says where)
    ++flips;
  }
  return flips;
}

}  // namespace billow
