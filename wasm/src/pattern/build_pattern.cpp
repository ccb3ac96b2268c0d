#include "pattern/build_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

#include "flatten/interior_map.hpp"
#include "pattern/internal_panels.hpp"
#include "pattern/panel_stages.hpp"
#include "remesh/panel_mesher.hpp"
#include "simulate/sewn_pattern.hpp"
#include "util/clock.hpp"
#include "util/error.hpp"
#include "util/union_find.hpp"

namespace billow {

namespace {
constexpr double kMeshFill = 4.0 / 3.0;
}  // namespace

bool BuiltPattern::ok() const {
  return std::none_of(problems.begin(), problems.end(), [](const auto& p) { return p.severity == "error"; });
}

void keepSewnSeamsSimple(std::vector<int>& counts, const std::vector<std::array<int, 2>>& ends) {
  std::map<std::array<int, 2>, std::vector<int>> singleEdges;  // by their sorted ends
  for (size_t c = 0; c < counts.size(); ++c) {
    auto [a, b] = ends[c];
    if (a == b) {
      counts[c] = std::max(counts[c], 3);
    } else if (counts[c] == 1) {
      singleEdges[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(c));
    }
  }
  for (const auto& [pair, curves] : singleEdges)
    if (curves.size() > 1)
      for (int c : curves) counts[c] = 2;
}

double patternEdgeLength(double panelArea, const PatternBuildOptions& options) {
  if (options.edgeLength > 0) return options.edgeLength;
  if (!(panelArea > 0)) throw Error("pattern.empty", "There is no panel area to mesh.");
  // An equilateral triangle of edge h has area sqrt(3) h^2 / 4; the refined panel meshes hold about 4/3 as
  // many triangles as equilateral ones would (measured on spheres and the corpus), hence the factor.
  const int n = std::max(options.triangles, 8);
  return std::sqrt(kMeshFill * 4 * panelArea / (std::sqrt(3.0) * n));
}

namespace {

void addProblem(BuiltPattern& out, const Segmentation& seg, int s, const std::string& code, const std::string& severity,
                const std::string& message) {
  SegmentationProblem p;
  p.code = code, p.severity = severity, p.message = message, p.segment = s;
  p.location = seg.segments[s].labelPoint;
  out.problems.push_back(p);
}

// A segment whose flattening still folds over itself after every fallback (flatten.hpp): its panel's inside maps
// onto the target folded, so its balloon cannot take the target's shape. Placed where the folds are: the folded
// triangle nearest their mean (on a long tube or limb, the harmonic map's squeeze there underflows).
SegmentationProblem foldedProblem(const Segmentation& seg, const FlatSegment& fs) {
  const TriMesh& sub = fs.sub.mesh;
  const std::vector<int> next = boundaryNext(sub.F, sub.numVertices());
  std::vector<Eigen::Vector3d> folded;
  for (int t = 0; t < sub.numTriangles(); ++t)
    if (foldsPanel(sub.F, fs.flat.uv, next, t))
      folded.push_back((sub.V.row(sub.F(t, 0)) + sub.V.row(sub.F(t, 1)) + sub.V.row(sub.F(t, 2))).transpose() / 3);
  SegmentationProblem p;
  p.code = "pattern.flipped", p.severity = "warning", p.segment = fs.segment;
  p.location = seg.segments[fs.segment].labelPoint;
  if (!folded.empty()) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& c : folded) mean += c;
    mean /= static_cast<double>(folded.size());
    p.location = *std::min_element(folded.begin(), folded.end(), [&](const auto& x, const auto& y) {
      return (x - mean).squaredNorm() < (y - mean).squaredNorm();
    });
  }
  // Eq. 14 keeps the boundary's lengths, so a boundary blended to a circle encloses far more than the segment.
  std::string larger;
  if (fs.flat.areaRatio > 1.5) {
    char ratio[96];
    std::snprintf(ratio, sizeof ratio, " (laid flat it takes %.1f times its area on the model)", fs.flat.areaRatio);
    larger = ratio;
  }
  p.message = "Segment " + std::to_string(fs.segment + 1) + " cannot be laid flat without folding over itself " +
              seg.where(p.location) + larger +
              ": it wraps too far around the shape to be cut as one piece, so its panel will not inflate to the "
              "target's shape. A seam across it there lets it lie flat as two panels.";
  return p;
}

}  // namespace

SegmentationProblem sewingProblem(const BuiltPattern& out, const Segmentation& seg, const Error& e) {
  const bool placed = e.panel >= 0 && e.panel < static_cast<int>(out.panels.size()) && e.vertex >= 0 &&
                      e.vertex < out.panels[e.panel].targetPosition.rows();
  const int s = placed ? out.panels[e.panel].segment : -1;
  SegmentationProblem p;
  p.code = "pattern.not-sewn", p.severity = "error", p.segment = s;
  if (placed) p.location = out.panels[e.panel].targetPosition.row(e.vertex).transpose();
  const std::string panel = placed ? out.pattern.panels[e.panel].name : "A panel";
  const std::string where = placed ? " " + seg.where(p.location) : "";
  if (e.code == "pattern.degenerate" || e.code == "pattern.non-manifold")
    p.message = panel + " would be sewn to itself" + where +
                ": its seams touch there. Move them apart there, or add a seam across the panel.";
  else
    p.message = panel + " cannot be sewn" + where + ": " + e.what();
  return p;
}

namespace {

std::string notDiskMessage(const Segment& s, int index) {
  std::string why = s.loops.empty() ? "it has no seam around it (a closed surface cannot be laid flat)"
                                    : "it has " + std::to_string(s.loops.size()) + " separate seam boundaries";
  if (s.genus > 0) why = "it goes around a handle";
  return "Segment " + std::to_string(index + 1) + " cannot be laid flat as one panel: " + why +
         ". Add a seam that cuts it open.";
}

// The pieces on both sides of a seam: (flat segment, piece) -> its partner, found by the reverse of its last edge.
using PieceId = std::pair<int, int>;
std::map<PieceId, PieceId> pairPieces(const std::vector<FlatSegment>& flats) {
  std::unordered_map<std::uint64_t, PieceId> byFirstEdge;
  for (int f = 0; f < static_cast<int>(flats.size()); ++f)
    for (int k = 0; k < static_cast<int>(flats[f].pieces.size()); ++k) {
      const auto& v = flats[f].pieces[k].vertices;
      byFirstEdge[directedKey(v[0], v[1])] = {f, k};
    }
  std::map<PieceId, PieceId> partner;
  for (int f = 0; f < static_cast<int>(flats.size()); ++f)
    for (int k = 0; k < static_cast<int>(flats[f].pieces.size()); ++k) {
      const auto& v = flats[f].pieces[k].vertices;
      const auto it = byFirstEdge.find(directedKey(v[v.size() - 1], v[v.size() - 2]));
      if (it != byFirstEdge.end() && flats[it->second.first].pieces[it->second.second].vertices.size() == v.size())
        partner[{f, k}] = it->second;
    }
  return partner;
}

// N per piece, equal on both sides (Sec. 5.3: matching vertices on both panels of a seam), the sewn seams kept
// a simple graph (keepSewnSeamsSimple; cut-mesh vertices are shared across a seam, so they name the sewn points).
void chooseSegmentCounts(std::vector<FlatSegment>& flats, const std::map<PieceId, PieceId>& partner, double h) {
  std::map<PieceId, int> curveOf;
  std::vector<int> counts;
  std::vector<std::array<int, 2>> ends;
  for (int f = 0; f < static_cast<int>(flats.size()); ++f)
    for (int k = 0; k < static_cast<int>(flats[f].pieces.size()); ++k) {
      if (curveOf.count({f, k})) continue;
      const BoundaryPiece& piece = flats[f].pieces[k];
      curveOf[{f, k}] = static_cast<int>(counts.size());
      const auto it = partner.find({f, k});
      if (it != partner.end()) curveOf[it->second] = static_cast<int>(counts.size());
      counts.push_back(segmentCountFor(piece.length, h));
      ends.push_back({piece.vertices.front(), piece.vertices.back()});
    }
  keepSewnSeamsSimple(counts, ends);
  for (int f = 0; f < static_cast<int>(flats.size()); ++f) {
    flats[f].segments.assign(flats[f].pieces.size(), 0);
    for (int k = 0; k < static_cast<int>(flats[f].pieces.size()); ++k) flats[f].segments[k] = counts[curveOf[{f, k}]];
  }
}

double edgeLength(const Panel& p, int a, int b) { return (p.vertices.row(a) - p.vertices.row(b)).norm(); }

// Stitches every sample k of a piece to sample N - k of its partner; the groups of panel vertices that
// are one point (three or more at corners) become chains of stitches. Fills the mismatch figures.
void stitchPieces(BuiltPattern& out) {
  const auto& panels = out.pattern.panels;
  std::vector<int> start{0};
  for (const Panel& p : panels) start.push_back(start.back() + static_cast<int>(p.vertices.rows()));
  UnionFind groupsOf(start.back());
  PatternFigures& fig = out.figures;
  for (int a = 0; a < static_cast<int>(panels.size()); ++a)
    for (const PanelPiece& pa : out.panels[a].pieces) {
      const int b = pa.neighborPanel;
      if (b < 0) continue;
      const PanelPiece& pb = out.panels[b].pieces[pa.neighborPiece];
      const int n = static_cast<int>(pa.rows.size()) - 1;
      double la = 0, lb = 0;
      for (int k = 0; k <= n; ++k) {
        const int va = pa.rows[k], vb = pb.rows[n - k];
        groupsOf.unite(start[a] + va, start[b] + vb);
        fig.maxStitchTargetDistance =
            std::max(fig.maxStitchTargetDistance,
                     (out.panels[a].targetPosition.row(va) - out.panels[b].targetPosition.row(vb)).norm());
        if (k == n) break;
        const double ea = edgeLength(panels[a], pa.rows[k], pa.rows[k + 1]);
        const double eb = edgeLength(panels[b], pb.rows[n - k - 1], pb.rows[n - k]);
        la += ea, lb += eb;
        fig.maxEdgeLengthMismatch = std::max(fig.maxEdgeLengthMismatch, std::abs(ea - eb) / (0.5 * (ea + eb)));
      }
      fig.maxSeamLengthMismatch = std::max(fig.maxSeamLengthMismatch, std::abs(la - lb) / (0.5 * (la + lb)));
    }
  std::map<int, std::vector<int>> groups;  // root -> members, in panel order
  for (int g = 0; g < start.back(); ++g) groups[groupsOf.find(g)].push_back(g);
  for (const auto& [root, members] : groups)
    for (size_t i = 1; i < members.size(); ++i) {
      const auto where = [&](int g) {
        const int p = static_cast<int>(std::upper_bound(start.begin(), start.end(), g) - start.begin()) - 1;
        return std::make_pair(p, g - start[p]);
      };
      const auto [p0, v0] = where(members[i - 1]);
      const auto [p1, v1] = where(members[i]);
      out.pattern.stitches.push_back({p0, v0, p1, v1});
    }
  flipPinchingEdges(out.pattern);
}

}  // namespace

void stitchBuiltPattern(BuiltPattern& built) {
  built.pattern.stitches.clear();
  built.figures.maxEdgeLengthMismatch = built.figures.maxSeamLengthMismatch = 0;
  built.figures.maxStitchTargetDistance = 0;
  stitchPieces(built);
  built.figures.stitches = static_cast<int>(built.pattern.stitches.size());
}

BuiltPattern buildPattern(const TriMesh& target, const Segmentation& seg, const PatternBuildOptions& options) {
  const auto t0 = Clock::now();
  BuiltPattern out;
  out.pattern.material = options.material;
  out.pattern.pressure = options.pressure;
  out.segmentPanel.assign(seg.segments.size(), -1);
  const SeamGraph graph = analyzeSeams(seg);

  // 1. Flatten every disk segment (Sec. 5.2).
  std::vector<FlatSegment> flats;
  for (int s = 0; s < static_cast<int>(seg.segments.size()); ++s) {
    if (!seg.segments[s].isDisk) {
      addProblem(out, seg, s, "pattern.not-disk", "error", notDiskMessage(seg.segments[s], s));
      continue;
    }
    try {
      flats.push_back(flattenForPattern(seg, graph, s));
      if (flats.back().flat.flippedTriangles > 0) out.problems.push_back(foldedProblem(seg, flats.back()));
    } catch (const Error& e) {
      addProblem(out, seg, s, "pattern.flatten-failed", "error",
                 "Segment " + std::to_string(s + 1) + " could not be laid flat: " + e.what());
    }
  }
  out.figures.flattenMs = msSince(t0);

  // 2.-3. Matching boundary samples on both sides of every seam, then the panel meshes (Sec. 5.3). The
  // triangle count is set on the flattened panels (their area is smaller than the segments' on curved parts).
  const auto t1 = Clock::now();
  double flatArea = 0;
  for (const auto& fs : flats) flatArea += fs.flat.areaRatio * seg.segments[fs.segment].area;
  const double h = flats.empty() ? options.edgeLength : patternEdgeLength(flatArea, options);
  out.figures.edgeLength = h;
  const std::map<PieceId, PieceId> partner = pairPieces(flats);
  chooseSegmentCounts(flats, partner, h);
  std::vector<int> flatPanel(flats.size(), -1);
  for (size_t f = 0; f < flats.size(); ++f) {
    Panel panel;
    BuiltPanel built;
    try {
      meshFlatSegment(target, seg, flats[f], h, panel, built);
    } catch (const Error& e) {
      out.problems.push_back(meshProblem(seg, flats[f], e));
      continue;
    }
    flatPanel[f] = static_cast<int>(out.panels.size());
    out.segmentPanel[flats[f].segment] = flatPanel[f];
    panel.name = "Panel " + std::to_string(flats[f].segment + 1);  // the number of its segment on the model
    panel.internal = false;
    out.pattern.inflated.push_back(built.targetPosition);
    out.pattern.panels.push_back(std::move(panel));
    out.panels.push_back(std::move(built));
  }
  for (size_t f = 0; f < flats.size(); ++f) {
    if (flatPanel[f] < 0) continue;
    for (int k = 0; k < static_cast<int>(flats[f].pieces.size()); ++k) {
      PanelPiece& pp = out.panels[flatPanel[f]].pieces[k];
      const auto it = partner.find({static_cast<int>(f), k});
      if (it != partner.end() && flatPanel[it->second.first] >= 0) {
        pp.neighborPanel = flatPanel[it->second.first];
        pp.neighborPiece = it->second.second;
      } else {
        addProblem(out, seg, flats[f].segment, "pattern.open-seam", "warning",
                   "A seam of panel " + std::to_string(flats[f].segment + 1) +
                       " has no panel on its other side, so it stays open.");
      }
    }
  }

  // 3b. Internal panels, sewn onto the outer panels' seam samples (stitched with them below).
  addInternalPanels(target, seg, options, h, out);
  out.figures.meshMs = msSince(t1);

  // 4. Stitches (of the outer and the internal panels).
  stitchPieces(out);
  // 5. The panels sewn, as the simulation will sew them: a seam that touches itself or another where the
  // segmentation saw none (two corners of a triangle stitched together) is a problem with a place here, not
  // an error when the optimization starts.
  if (out.ok()) try {
      (void)sewPattern(out.pattern);
    } catch (const Error& e) {
      out.problems.push_back(sewingProblem(out, seg, e));
    }
  PatternFigures& fig = out.figures;
  fig.panels = static_cast<int>(out.pattern.panels.size());
  for (const Panel& p : out.pattern.panels) {
    fig.internalPanels += p.internal;
    fig.triangles += static_cast<int>(p.triangles.rows());
    fig.vertices += static_cast<int>(p.vertices.rows());
  }
  fig.stitches = static_cast<int>(out.pattern.stitches.size());
  fig.totalMs = msSince(t0);
  return out;
}

}  // namespace billow
