#include "pattern/internal_panels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "remesh/panel_mesher.hpp"
#include "util/error.hpp"
#include "util/union_find.hpp"

namespace billow {

double windingNumber(const TriMesh& mesh, const Eigen::Vector3d& x) {
  double w = 0;  // sum of the solid angles of the triangles seen from x (Van Oosterom and Strackee)
  for (int t = 0; t < mesh.numTriangles(); ++t) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(t, 0)).transpose() - x, b = mesh.V.row(mesh.F(t, 1)).transpose() - x,
                          c = mesh.V.row(mesh.F(t, 2)).transpose() - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    w += 2 * std::atan2(a.dot(b.cross(c)), den);
  }
  return w / (4 * M_PI);
}

namespace {

// Why a connection cannot be built: the tail of its problem message, in the designer's words.
struct ConnectionError {
  std::string why;
};

// The outer panels' vertices as one numbering, grouped as stitchPieces (build_pattern.cpp) will stitch them.
struct OuterGroups {
  int panels = 0;                     // the outer panels: out.panels[0 .. panels)
  std::vector<int> start;             // #panels + 1
  std::vector<int> root;              // per global vertex: its group
  std::vector<Eigen::Vector3d> mean;  // per group (root id): mean target position of its members [m]
  int rootOf(int p, int v) const { return root[start[p] + v]; }
  std::pair<int, int> where(int g) const {
    const int p = static_cast<int>(std::upper_bound(start.begin(), start.end(), g) - start.begin()) - 1;
    return {p, g - start[p]};
  }
};

OuterGroups groupOuter(const BuiltPattern& out) {
  OuterGroups g;
  g.panels = static_cast<int>(out.panels.size());
  g.start = {0};
  for (const BuiltPanel& b : out.panels) g.start.push_back(g.start.back() + static_cast<int>(b.targetPosition.rows()));
  const int n = g.start.back();
  UnionFind groups(n);
  for (int a = 0; a < g.panels; ++a)
    for (const PanelPiece& pa : out.panels[a].pieces) {
      if (pa.neighborPanel < 0) continue;
      const PanelPiece& pb = out.panels[pa.neighborPanel].pieces[pa.neighborPiece];
      const int last = static_cast<int>(pa.rows.size()) - 1;
      if (pb.rows.size() != pa.rows.size()) continue;
      for (int k = 0; k <= last; ++k)
        groups.unite(g.start[a] + pa.rows[k], g.start[pa.neighborPanel] + pb.rows[last - k]);
    }
  g.root.resize(n);
  g.mean.assign(n, Eigen::Vector3d::Zero());
  std::vector<int> count(n, 0);
  for (int i = 0; i < n; ++i) {
    g.root[i] = groups.find(i);
    const auto [p, v] = g.where(i);
    g.mean[g.root[i]] += out.panels[p].targetPosition.row(v).transpose();
    ++count[g.root[i]];
  }
  for (int r = 0; r < n; ++r)
    if (count[r]) g.mean[r] /= count[r];
  return g;
}

struct PieceRef {
  int panel = -1, piece = -1;
  bool valid() const { return panel >= 0; }
};

// One outer piece along a seam chain (and its partner), samples first..last of the chain.
struct Span {
  int first = 0, last = 0;
  PieceRef along, against;  // the outer pieces running with and against the chain; either may be missing
};

// A seam as read off the outer panels: samples in order along it.
struct SeamChain {
  std::vector<int> root;           // #samples: stitch group (global outer vertex id of its root)
  std::vector<Eigen::Vector3d> x;  // #samples: position on the target [m]
  std::vector<double> t;           // #samples: normalized arc length, 0 .. 1
  std::vector<double> flat;        // #samples - 1: mean flattened length of the outer panels' edges [m]
  std::vector<Span> spans;
  bool closed = false;
  double length = 0;  // on the target [m]

  int last() const { return static_cast<int>(x.size()) - 1; }
  Eigen::Vector3d at(double s) const {
    const int i = std::clamp(static_cast<int>(std::upper_bound(t.begin(), t.end(), s) - t.begin()) - 1, 0, last() - 1);
    const double d = t[i + 1] - t[i];
    const double f = d > 0 ? std::clamp((s - t[i]) / d, 0.0, 1.0) : 0.0;
    return (1 - f) * x[i] + f * x[i + 1];
  }
  void reverse() {
    std::reverse(root.begin(), root.end());
    std::reverse(x.begin(), x.end());
    std::reverse(flat.begin(), flat.end());
    std::reverse(t.begin(), t.end());
    for (double& s : t) s = 1 - s;
    std::reverse(spans.begin(), spans.end());
    for (Span& sp : spans) {
      const int first = last() - sp.last, lastSample = last() - sp.first;
      sp.first = first, sp.last = lastSample;
      std::swap(sp.along, sp.against);
    }
  }
};

const PanelPiece& pieceOf(const BuiltPattern& out, PieceRef r) { return out.panels[r.panel].pieces[r.piece]; }

double flatEdge(const BuiltPattern& out, int panel, int u, int v) {
  return (out.pattern.panels[panel].vertices.row(u) - out.pattern.panels[panel].vertices.row(v)).norm();
}

// The chain of seam `seam` over the outer panels. Throws ConnectionError when it is not one line of samples.
SeamChain chainOf(const BuiltPattern& out, const OuterGroups& g, int seam, const std::string& name) {
  struct Edge {
    int u = -1, v = -1;  // groups at the start and end of `along`
    PieceRef along, against;
  };
  std::vector<Edge> edges;
  std::set<std::pair<int, int>> seen;
  for (int p = 0; p < g.panels; ++p)
    for (int k = 0; k < static_cast<int>(out.panels[p].pieces.size()); ++k) {
      const PanelPiece& piece = out.panels[p].pieces[k];
      if (piece.seam != seam || !seen.insert({p, k}).second) continue;
      Edge e;
      e.along = {p, k};
      e.u = g.rootOf(p, piece.rows.front()), e.v = g.rootOf(p, piece.rows.back());
      if (piece.neighborPanel >= 0 && piece.neighborPanel < g.panels &&
          seen.insert({piece.neighborPanel, piece.neighborPiece}).second)
        e.against = {piece.neighborPanel, piece.neighborPiece};
      edges.push_back(e);
    }
  if (edges.empty()) throw ConnectionError{"no panel was built along seam " + name + "."};
  std::map<int, std::vector<int>> at;  // group -> edges that start or end there
  for (int i = 0; i < static_cast<int>(edges.size()); ++i) at[edges[i].u].push_back(i), at[edges[i].v].push_back(i);
  std::vector<int> ends;
  for (const auto& [node, list] : at) {
    if (list.size() > 2) throw ConnectionError{"seam " + name + " crosses itself."};
    if (list.size() == 1) ends.push_back(node);
  }
  if (!ends.empty() && ends.size() != 2)
    throw ConnectionError{"seam " + name + " is not one line of built panels (a panel beside it is missing)."};
  SeamChain c;
  c.closed = ends.empty();
  int cur = c.closed ? edges[0].u : ends[0];
  std::vector<char> used(edges.size(), 0);
  for (size_t step = 0; step < edges.size(); ++step) {
    int next = -1;
    for (int i : at[cur])
      if (!used[i]) next = i;
    if (next < 0) break;
    used[next] = 1;
    const Edge& e = edges[next];
    const bool forward = e.u == cur;
    Span span;
    span.along = forward ? e.along : e.against;
    span.against = forward ? e.against : e.along;
    // Rows in chain order, from whichever piece there is (global vertex ids), and their flattened edges.
    std::vector<int> rows;
    if (span.along.valid()) {
      for (int r : pieceOf(out, span.along).rows) rows.push_back(g.start[span.along.panel] + r);
    } else {
      const auto& rev = pieceOf(out, span.against).rows;
      for (auto it = rev.rbegin(); it != rev.rend(); ++it) rows.push_back(g.start[span.against.panel] + *it);
    }
    const int n = static_cast<int>(rows.size()) - 1;
    span.first = c.x.empty() ? 0 : c.last();
    for (int k = c.x.empty() ? 0 : 1; k <= n; ++k) {
      c.root.push_back(g.root[rows[k]]);
      c.x.push_back(g.mean[g.root[rows[k]]]);
    }
    for (int k = 0; k < n; ++k) {
      double sum = 0;
      int count = 0;
      if (span.along.valid()) {
        const auto& r = pieceOf(out, span.along).rows;
        sum += flatEdge(out, span.along.panel, r[k], r[k + 1]), ++count;
      }
      if (span.against.valid()) {
        const auto& r = pieceOf(out, span.against).rows;
        sum += flatEdge(out, span.against.panel, r[n - k], r[n - k - 1]), ++count;
      }
      c.flat.push_back(sum / count);
    }
    span.last = c.last();
    c.spans.push_back(span);
    cur = forward ? e.v : e.u;
  }
  if (std::find(used.begin(), used.end(), 0) != used.end())
    throw ConnectionError{"seam " + name + " is not one line of built panels (a panel beside it is missing)."};
  c.t.assign(c.x.size(), 0.0);
  for (int i = 1; i <= c.last(); ++i) c.t[i] = c.t[i - 1] + (c.x[i] - c.x[i - 1]).norm();
  c.length = c.t.back();
  if (!(c.length > 0)) throw ConnectionError{"seam " + name + " has no length."};
  for (double& s : c.t) s /= c.length;
  c.t.back() = 1;
  return c;
}

// Summed distance between a(t) and b(t) (b reversed: b(1 - t)) at evenly spaced t.
double matchCost(const SeamChain& a, const SeamChain& b, bool reversed) {
  constexpr int K = 64;
  double cost = 0;
  for (int k = 0; k <= K; ++k) {
    const double s = double(k) / K;
    cost += (a.at(s) - b.at(reversed ? 1 - s : s)).norm();
  }
  return cost;
}

// The ruled surface between the matched chains as a strip of triangles, and its unfolding into the plane.
struct Strip {
  std::vector<Eigen::Vector3d> x;                    // a's samples, then b's that are not a's (where the seams meet)
  std::vector<int> aVertex, bVertex;                 // sample -> strip vertex
  std::vector<std::array<int, 3>> triangle;          // counterclockwise in the layout: a below, b above, t to the right
  std::map<std::pair<int, int>, double> seamLength;  // seam edges: the outer panels' flattened length [m]
  Points2 uv;                                        // the unfolding [m]

  double length(int u, int v) const {
    const auto it = seamLength.find(std::minmax(u, v));
    return it != seamLength.end() ? it->second : (x[u] - x[v]).norm();
  }
};

Strip zipStrip(const SeamChain& a, const SeamChain& b) {
  Strip s;
  const int na = a.last(), nb = b.last();
  for (int i = 0; i <= na; ++i) s.aVertex.push_back(i), s.x.push_back(a.x[i]);
  for (int j = 0; j <= nb; ++j) {
    if (j == 0 && b.root[0] == a.root[0]) {
      s.bVertex.push_back(s.aVertex[0]);
    } else if (j == nb && b.root[nb] == a.root[na]) {
      s.bVertex.push_back(s.aVertex[na]);
    } else {
      s.bVertex.push_back(static_cast<int>(s.x.size()));
      s.x.push_back(b.x[j]);
    }
  }
  for (int i = 0; i < na; ++i) s.seamLength[std::minmax(s.aVertex[i], s.aVertex[i + 1])] = a.flat[i];
  for (int j = 0; j < nb; ++j) s.seamLength[std::minmax(s.bVertex[j], s.bVertex[j + 1])] = b.flat[j];
  // Rulings a(t) - b(t): advance along the seam whose next sample comes first in t.
  for (int i = 0, j = 0; i < na || j < nb;) {
    const bool alongA = j == nb || (i < na && a.t[i + 1] <= b.t[j + 1]);
    const std::array<int, 3> tri = alongA ? std::array<int, 3>{s.aVertex[i], s.aVertex[i + 1], s.bVertex[j]}
                                          : std::array<int, 3>{s.aVertex[i], s.bVertex[j + 1], s.bVertex[j]};
    alongA ? ++i : ++j;
    if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) s.triangle.push_back(tri);
  }
  return s;
}

// Lays the strip flat triangle by triangle: each new vertex is placed from its two lengths to the shared edge,
// on the counterclockwise side. No interior vertex, so no length changes.
void unfold(Strip& s) {
  s.uv = Points2::Zero(static_cast<Eigen::Index>(s.x.size()), 2);
  std::vector<char> placed(s.x.size(), 0);
  for (const auto& tri : s.triangle) {
    int unknown = 0, k = -1;
    for (int c = 0; c < 3; ++c)
      if (!placed[tri[c]]) ++unknown, k = c;
    if (unknown == 3) {
      s.uv.row(tri[0]) << 0, 0;
      s.uv.row(tri[1]) << s.length(tri[0], tri[1]), 0;
      placed[tri[0]] = placed[tri[1]] = 1;
      unknown = 1, k = 2;
    }
    if (unknown == 0) continue;
    if (unknown != 1) throw Error("pattern.internal-strip", "the strip between the seams is not connected");
    const int p = tri[(k + 1) % 3], q = tri[(k + 2) % 3], r = tri[k];
    const Eigen::Vector2d P = s.uv.row(p).transpose(), Q = s.uv.row(q).transpose();
    const double d = (Q - P).norm(), lp = s.length(p, r), lq = s.length(q, r);
    if (!(d > 0)) throw Error("pattern.internal-strip", "the seams have samples at one point");
    const Eigen::Vector2d u = (Q - P) / d, n(-u.y(), u.x());
    const double along = (lp * lp - lq * lq + d * d) / (2 * d);
    s.uv.row(r) = (P + along * u + std::sqrt(std::max(0.0, lp * lp - along * along)) * n).transpose();
    placed[r] = 1;
  }
}

// A boundary row of the internal panel: at fraction f from strip vertex u to strip vertex v (v = u, f = 0 at
// a seam sample).
struct Row {
  int u = 0, v = 0;
  double f = 0;
  int seam = -1;
};

// A seam as the designer knows it: its name in quotes, else its number (1-based).
std::string seamLabel(const PatternBuildOptions& o, int s, bool quoted) {
  if (s >= 0 && s < static_cast<int>(o.seamNames.size()) && !o.seamNames[s].empty())
    return quoted ? "\"" + o.seamNames[s] + "\"" : o.seamNames[s];
  return std::to_string(s + 1);
}

// The internal panel of a connection between the chains a (its pieces run along a) and b (against b).
void buildInternalPanel(const TriMesh& target, const BuiltPattern& outer, const OuterGroups& g, const SeamChain& a,
                        const SeamChain& b, int seamA, int seamB, double h, Panel& panel, BuiltPanel& built) {
  const int na = a.last(), nb = b.last();
  const bool startMet = a.root[0] == b.root[0], endMet = a.root[na] == b.root[nb];
  // The straight rulings between the seams must run inside the target.
  constexpr int K = 24;
  for (int k = 1; k < K; ++k) {
    const Eigen::Vector3d p = a.at(double(k) / K), q = b.at(double(k) / K);
    if ((q - p).norm() < 2 * h) continue;
    for (double f : {0.25, 0.5, 0.75})
      if (windingNumber(target, p + f * (q - p)) < 0.5)
        throw ConnectionError{
            "a panel stretched straight between them would pass outside the shape (the seams do not face each "
            "other across its inside)."};
  }
  Strip s = zipStrip(a, b);
  unfold(s);

  // The outline: seam a forwards, the end ruling, seam b backwards, the start ruling.
  std::vector<Row> rows;
  std::vector<int> bRow(nb + 1, -1);
  for (int i = 0; i <= na; ++i) rows.push_back({s.aVertex[i], s.aVertex[i], 0, seamA});
  const auto ruling = [&](int u, int v) {
    const int n = segmentCountFor((s.x[u] - s.x[v]).norm(), h);
    for (int k = 1; k < n; ++k) rows.push_back({u, v, double(k) / n, -1});
  };
  if (!endMet) ruling(s.aVertex[na], s.bVertex[nb]);
  for (int j = nb; j >= 0; --j) {
    if ((j == nb && endMet) || (j == 0 && startMet)) {
      bRow[j] = j == nb ? na : 0;
      continue;
    }
    bRow[j] = static_cast<int>(rows.size());
    rows.push_back({s.bVertex[j], s.bVertex[j], 0, seamB});
  }
  if (!startMet) ruling(s.bVertex[0], s.aVertex[0]);
  const int nrows = static_cast<int>(rows.size());
  if (nrows < 3) throw ConnectionError{"the seams are too short to hold a panel between them."};

  // Pieces in outline order, each from its start corner to the next one.
  built.pieces.clear();
  const auto addPiece = [&](int from, int to, int seam, PieceRef partner, double length) {
    PanelPiece pp;
    for (int r = from;; r = (r + 1) % nrows) {
      pp.rows.push_back(r);
      if (r == to) break;
    }
    pp.seam = seam;
    pp.neighborPanel = partner.panel, pp.neighborPiece = partner.piece;
    pp.targetLength = length;
    built.pieces.push_back(std::move(pp));
  };
  for (const Span& sp : a.spans)
    addPiece(sp.first, sp.last, seamA, sp.against, pieceOf(outer, sp.against).targetLength);
  if (!endMet) addPiece(na, bRow[nb], -1, {}, (a.x[na] - b.x[nb]).norm());
  for (auto it = b.spans.rbegin(); it != b.spans.rend(); ++it)
    addPiece(bRow[it->last], bRow[it->first], seamB, it->along, pieceOf(outer, it->along).targetLength);
  if (!startMet) addPiece(bRow[0], 0, -1, {}, (a.x[0] - b.x[0]).norm());

  // Mesh the outline at h; interior vertices are mapped back onto the strip.
  Points2 outline(nrows, 2);
  for (int r = 0; r < nrows; ++r)
    outline.row(r) = (1 - rows[r].f) * s.uv.row(rows[r].u) + rows[r].f * s.uv.row(rows[r].v);
  const TriMesh mesh = meshPanel(outline, h);
  const int nv = mesh.numVertices();
  panel.vertices = mesh.V.leftCols<2>();
  panel.triangles = mesh.F;
  built.segment = -1;
  built.boundaryVertices = nrows;
  built.targetPosition.resize(nv, 3);
  built.targetPoint.assign(nv, SurfacePoint{});
  built.seam.assign(nv, -1);
  built.corner.assign(nv, 0);
  built.interior = "ruled";
  for (const PanelPiece& pp : built.pieces) built.corner[pp.rows.front()] = 1;
  // Sample rows: the stitch group's position and surface point (of its first outer panel vertex).
  std::map<int, int> sampleGroup;  // strip vertex -> group
  for (int i = 0; i <= na; ++i) sampleGroup[s.aVertex[i]] = a.root[i];
  for (int j = 0; j <= nb; ++j) sampleGroup.emplace(s.bVertex[j], b.root[j]);
  for (int r = 0; r < nrows; ++r) {
    const Row& row = rows[r];
    built.targetPosition.row(r) = ((1 - row.f) * s.x[row.u] + row.f * s.x[row.v]).transpose();
    built.seam[r] = row.seam;
    if (row.seam >= 0) {
      const auto [p, v] = g.where(sampleGroup.at(row.u));
      built.targetPoint[r] = outer.panels[p].targetPoint[v];
    }
  }
  TriMesh flat;
  flat.V = Vertices::Zero(static_cast<Eigen::Index>(s.x.size()), 3);
  flat.V.leftCols<2>() = s.uv;
  flat.F.resize(static_cast<Eigen::Index>(s.triangle.size()), 3);
  double area2 = 0, area3 = 0;
  for (size_t t = 0; t < s.triangle.size(); ++t) {
    const auto& tri = s.triangle[t];
    flat.F.row(t) << tri[0], tri[1], tri[2];
    const Eigen::Vector2d e1 = (s.uv.row(tri[1]) - s.uv.row(tri[0])).transpose(),
                          e2 = (s.uv.row(tri[2]) - s.uv.row(tri[0])).transpose();
    area2 += 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
    area3 += 0.5 * (s.x[tri[1]] - s.x[tri[0]]).cross(s.x[tri[2]] - s.x[tri[0]]).norm();
  }
  built.flattenAreaRatio = area3 > 0 ? area2 / area3 : 1;
  const TriangleLocator locator(flat);
  for (int r = nrows; r < nv; ++r) {
    const BarycentricPoint bp = locator.locate(mesh.V.row(r).head<2>().transpose());
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) x += bp.weights[k] * s.x[flat.F(bp.triangle, k)];
    built.targetPosition.row(r) = x.transpose();
  }
}

// The pieces the internal panel is sewn to must exist: against a (its a-side runs along a) and along b.
bool sewable(const SeamChain& a, const SeamChain& b) {
  for (const Span& sp : a.spans)
    if (!sp.against.valid()) return false;
  for (const Span& sp : b.spans)
    if (!sp.along.valid()) return false;
  return true;
}

}  // namespace

void addInternalPanels(const TriMesh& target, const Segmentation& seg, const PatternBuildOptions& options, double h,
                       BuiltPattern& out) {
  out.connectionPanel.assign(options.connections.size(), -1);
  if (options.connections.empty()) return;
  const OuterGroups g = groupOuter(out);
  const int numSeams = static_cast<int>(seg.seamVertices.size());
  for (int c = 0; c < static_cast<int>(options.connections.size()); ++c) {
    const int sa = options.connections[c].seamA, sb = options.connections[c].seamB;
    const std::string na = seamLabel(options, sa, true), nb = seamLabel(options, sb, true);
    SegmentationProblem problem;
    problem.code = "pattern.connection", problem.severity = "error", problem.seam = sa;
    try {
      for (int s : {sa, sb})
        if (s < 0 || s >= numSeams)
          throw ConnectionError{"there is no seam " + std::to_string(s + 1) + " (the design has " +
                                std::to_string(numSeams) + (numSeams == 1 ? " seam)." : " seams).")};
      if (sa == sb) throw ConnectionError{"it joins a seam to itself; an internal panel spans two different seams."};
      SeamChain a = chainOf(out, g, sa, na), b = chainOf(out, g, sb, nb);
      problem.location = 0.5 * (a.at(0.5) + b.at(0.5));
      if (a.closed || b.closed)
        throw ConnectionError{"internal panels between closed seams are not supported yet; join two open seams."};
      if (matchCost(a, b, true) < matchCost(a, b, false)) b.reverse();
      // The seams may meet at their ends (a corner of the panel) but nowhere else.
      const std::set<int> onA(a.root.begin(), a.root.end());
      for (int j = 0; j <= b.last(); ++j) {
        const bool metEnd = (j == 0 && b.root[0] == a.root[0]) || (j == b.last() && b.root[j] == a.root[a.last()]);
        if (onA.count(b.root[j]) && !metEnd)
          throw ConnectionError{"the seams cross or touch each other; an internal panel needs two seams apart."};
      }
      // Its pieces along a run along a (sewn to the outer pieces running against a), along b against b; when
      // only the mirror image can be sewn (a panel beside a seam is missing), build that.
      const bool swap = !sewable(a, b);
      if (swap && !sewable(b, a))
        throw ConnectionError{"a panel beside one of the seams was not built, so there is nothing to sew it to."};
      Panel panel;
      BuiltPanel built;
      try {
        buildInternalPanel(target, out, g, swap ? b : a, swap ? a : b, swap ? sb : sa, swap ? sa : sb, h, panel, built);
      } catch (const Error& e) {
        const bool overlaps =
            e.code == "panel.self-intersecting" || e.code == "panel.repeated-vertex" || e.code == "panel.clockwise";
        throw ConnectionError{overlaps ? "the panel between them would overlap itself when laid flat (the seams "
                                         "twist or curve too much around each other)."
                                       : std::string(e.what())};
      }
      built.connection = c;
      panel.name = "internal " + std::to_string(c + 1) + " (seams " + seamLabel(options, sa, false) + "|" +
                   seamLabel(options, sb, false) + ")";
      panel.internal = true;
      out.connectionPanel[c] = static_cast<int>(out.panels.size());
      out.pattern.inflated.push_back(built.targetPosition);
      out.pattern.panels.push_back(std::move(panel));
      out.panels.push_back(std::move(built));
    } catch (const ConnectionError& e) {
      problem.message = "The internal connection between seams " + na + " and " + nb + " cannot be built: " + e.why;
      out.problems.push_back(problem);
    }
  }
}

}  // namespace billow
