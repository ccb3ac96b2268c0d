// Segmentation and its problem report (see segmentation.hpp).
#include "segment/segmentation.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <set>

#include "mesh/location.hpp"
#include "segment/segment_topology.hpp"
#include "util/text.hpp"

namespace billow {

double loopLength(const TriMesh& m, const BoundaryLoop& loop) {
  double sum = 0;
  for (size_t i = 0; i < loop.vertices.size(); ++i)
    sum += (m.V.row(loop.vertices[(i + 1) % loop.vertices.size()]) - m.V.row(loop.vertices[i])).norm();
  return sum;
}

namespace {

// A segment's mean width: twice its area over its boundary's length (a strip of width w and length L has
// area wL and boundary about 2L; a disk of radius r gives r).
double meanWidth(const TriMesh& m, const Segment& s) {
  double perimeter = 0;
  for (const BoundaryLoop& loop : s.loops) perimeter += loopLength(m, loop);
  return perimeter > 0 ? 2 * s.area / perimeter : std::numeric_limits<double>::infinity();
}

// Each vertex's distance to the nearest seam along the mesh's edges (multi-source Dijkstra from the segments'
// boundaries). A path into another segment crosses a seam first, so it is the distance within its own segment.
std::vector<double> distanceToSeams(const TriMesh& m, const std::vector<Segment>& segments) {
  const int nv = m.numVertices();
  std::vector<int> start(nv + 1, 0), next;
  for (int t = 0; t < m.numTriangles(); ++t)
    for (int k = 0; k < 3; ++k) start[m.F(t, k) + 1] += 2;
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  next.resize(start[nv]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int t = 0; t < m.numTriangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = m.F(t, k);
      next[fill[v]++] = m.F(t, (k + 1) % 3), next[fill[v]++] = m.F(t, (k + 2) % 3);
    }
  std::vector<double> d(nv, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (const Segment& s : segments)
    for (const BoundaryLoop& loop : s.loops)
      for (int v : loop.vertices)
        if (d[v] > 0) d[v] = 0, queue.push({0.0, v});
  while (!queue.empty()) {
    const auto [dv, v] = queue.top();
    queue.pop();
    if (dv > d[v]) continue;
    for (int e = start[v]; e < start[v + 1]; ++e) {
      const int w = next[e];
      const double dw = dv + (m.V.row(w) - m.V.row(v)).norm();
      if (dw < d[w]) d[w] = dw, queue.push({dw, w});
    }
  }
  return d;
}

// Where a segment is shown and named: the centroid of its triangle farthest from its seams, in its middle rather
// than beside a seam (the area centroid of most of a sphere lies inside it, as near one seam as any); without
// seams, the triangle nearest its area centroid.
Eigen::Vector3d segmentPoint(const TriMesh& m, const Segment& s, const std::vector<double>& toSeams) {
  auto centroid = [&](int t) {
    return ((m.V.row(m.F(t, 0)) + m.V.row(m.F(t, 1)) + m.V.row(m.F(t, 2))) / 3.0).transpose().eval();
  };
  if (!s.loops.empty()) {
    int best = s.triangles.front();
    double farthest = -1;
    for (int t : s.triangles) {
      const double d = toSeams[m.F(t, 0)] + toSeams[m.F(t, 1)] + toSeams[m.F(t, 2)];
      if (d > farthest) farthest = d, best = t;
    }
    return centroid(best);
  }
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int t : s.triangles) c += centroid(t) / static_cast<double>(s.triangles.size());
  Eigen::Vector3d best = centroid(s.triangles.front());
  for (int t : s.triangles)
    if ((centroid(t) - c).squaredNorm() < (best - c).squaredNorm()) best = centroid(t);
  return best;
}

void junctions(const CutMesh& cut, Segmentation& out) {
  const int nv = out.mesh.numVertices();
  std::vector<int> degree(nv, 0);
  for (const auto& [key, seam] : cut.seamEdge) ++degree[key >> 32], ++degree[key & 0xffffffffu];
  std::vector<std::set<int>> around(nv);
  for (int t = 0; t < out.mesh.numTriangles(); ++t)
    for (int k = 0; k < 3; ++k)
      if (degree[out.mesh.F(t, k)] > 0) around[out.mesh.F(t, k)].insert(out.faceSegment[t]);
  for (int v = 0; v < nv; ++v) {
    const int segments = static_cast<int>(around[v].size());
    if (degree[v] == 0 || (degree[v] == 2 && segments < 3)) continue;
    out.junctions.push_back({v, out.mesh.V.row(v).transpose(), segments, degree[v]});
  }
}

void segmentProblems(double totalArea, const SegmentationOptions& options, Segmentation& out) {
  const double diagonal = (out.boxMax - out.boxMin).norm();
  const std::vector<double> toSeams = distanceToSeams(out.mesh, out.segments);
  for (int s = 0; s < static_cast<int>(out.segments.size()); ++s) {
    Segment& seg = out.segments[s];
    seg.labelPoint = segmentPoint(out.mesh, seg, toSeams);
    SegmentationProblem p;
    p.segment = s, p.location = seg.labelPoint;
    // "Segment 3, near the top left of the shape,": the number the model shows, and where it is.
    const std::string where = std::to_string(s + 1) + ", " + out.where(p.location) + ",";
    const int loops = static_cast<int>(seg.loops.size());
    if (!seg.isDisk) {
      p.code = "segment.not-disk", p.severity = "error";
      if (loops == 0)
        p.message = "Segment " + where +
                    " has no seam around it yet: draw a closed seam to cut the shape into "
                    "panels.";
      else if (seg.genus > 0)
        p.message = "Segment " + where + " wraps around a handle: add a seam across it so it can be cut open.";
      else if (loops == 2) {
        // A tube, or a part with a loop drawn inside it: either way two separate seam loops bound it, and a
        // seam from one to the other opens it. It is placed on the shorter loop, where that seam would start.
        const BoundaryLoop& inner =
            loopLength(out.mesh, seg.loops[0]) <= loopLength(out.mesh, seg.loops[1]) ? seg.loops[0] : seg.loops[1];
        const auto seamOf = [](const BoundaryLoop& l) { return l.seams.empty() ? -1 : l.seams.front(); };
        const int a = seamOf(seg.loops[0]), b = seamOf(seg.loops[1]);
        p.location = out.mesh.V.row(inner.vertices.front()).transpose();
        const std::string between = a >= 0 && b >= 0 && a != b ? " (seams " + std::to_string(std::min(a, b) + 1) +
                                                                     " and " + std::to_string(std::max(a, b) + 1) + ")"
                                                               : "";
        p.message = "Segment " + std::to_string(s + 1) + " lies between two separate seam loops" + between + ", " +
                    out.where(p.location) +
                    ": a tube, or a part with a loop drawn inside it. Add a seam from one loop to the other so it "
                    "can be cut open.";
      } else
        p.message = "Segment " + where + " has " + plural(loops - 1, "hole") +
                    ": connect its inner seams to its outer seam so it can be flattened.";
      out.problems.push_back(p);
    }
    if (seg.area < options.minSegmentAreaRatio * totalArea) {
      p.code = "segment.sliver", p.severity = "warning";
      p.message = "Segment " + where + " is tiny: move its seams apart or remove one of them.";
      out.problems.push_back(p);
    } else if (const double width = meanWidth(out.mesh, seg); width < options.minSegmentWidthRatio * diagonal) {
      // Two seams run side by side (a loop closed early, a seam drawn along another): a strip too thin to sew.
      char percent[32];
      std::snprintf(percent, sizeof percent, "%.1f %%", 100 * width / diagonal);
      p.code = "segment.thin", p.severity = "warning";
      p.message = "Segment " + where + " is a thin strip (about " + percent +
                  " of the shape's size wide): move its seams apart or remove one of them.";
      out.problems.push_back(p);
    }
    if (seg.isDisk) {
      // A flat panel inside a seam of length P has at most the disk's area P^2/(4 pi): a segment far larger (a
      // fingertip's loop around a whole hand, a limb closed by a ring at its root) inflates to a small ball that
      // leaves most of it out, however its panel is optimized.
      const double perimeter = loopLength(out.mesh, seg.loops.front());
      const double share = perimeter * perimeter / (4 * M_PI * seg.area);
      if (share < options.minFlatShare) {
        char percent[32];
        std::snprintf(percent, sizeof percent, "%.0f %%", std::max(1.0, std::round(100 * share)));
        p.code = "segment.too-big-for-seam", p.severity = "warning";
        p.message = "Segment " + where + " is too big for the seam around it: a flat panel inside that seam covers " +
                    "at most " + percent + " of it, so its panel inflates to a small ball. Add seams across it " +
                    "(along a limb, around a bump) so each part can lie nearly flat.";
        out.problems.push_back(p);
      }
    }
  }
}

void seamProblems(const CutMesh& cut, Segmentation& out) {
  std::set<int> reported;
  for (const SeamJunction& j : out.junctions) {
    if (j.seamEdges != 1) continue;
    // which seam ends here
    int seam = -1;
    for (size_t s = 0; s < cut.seamVertices.size() && seam < 0; ++s)
      if (!cut.seamVertices[s].empty() &&
          (cut.seamVertices[s].front() == j.vertex || cut.seamVertices[s].back() == j.vertex))
        seam = static_cast<int>(s);
    if (seam < 0 || !reported.insert(seam).second) continue;  // TODO: stray degree-1 seam vertices (see report)
    SegmentationProblem p;
    p.code = "seam.dangling", p.severity = "warning", p.seam = seam, p.location = j.position;
    p.message = "Seam " + std::to_string(seam + 1) + " ends in the middle of a segment " + out.where(j.position) +
                "; it will be cut as a slit. Extend it to another seam to close the region.";
    out.problems.push_back(p);
  }
  std::set<int> crossed;
  for (const auto& c : cut.selfCrossings) {
    if (!crossed.insert(c.seam).second) continue;
    SegmentationProblem p;
    p.code = "seam.self-crossing", p.severity = "warning", p.seam = c.seam, p.location = c.position;
    p.message = "Seam " + std::to_string(c.seam + 1) + " crosses itself " + out.where(c.position) +
                ": move its points so it does not loop over itself.";
    out.problems.push_back(p);
  }
  if (cut.unrecoveredPieces > 0) {
    SegmentationProblem p;
    p.code = "seam.not-cut", p.severity = "error";
    p.message = "Part of a seam could not be cut into the shape (" + plural(cut.unrecoveredPieces, "piece") +
                "): move its points slightly.";
    out.problems.push_back(p);
  }
}

}  // namespace

std::string Segmentation::where(const Eigen::Vector3d& p) const { return describeLocation(p, boxMin, boxMax, up); }

bool Segmentation::ok() const {
  for (const SegmentationProblem& p : problems)
    if (p.severity == "error") return false;
  return true;
}

Segmentation segmentTarget(const TriMesh& target, const MeshTopology& topo, const std::vector<SeamCurve>& seams,
                           const SegmentationOptions& options) {
  CutMesh cut = cutAlongSeams(target, topo, seams, options.tolerance);
  Segmentation out;
  out.mesh = std::move(cut.mesh);
  out.vertexOrigin = std::move(cut.vertexOrigin);
  out.faceOrigin = std::move(cut.faceOrigin);
  out.seamVertices = cut.seamVertices;
  labelSegments(cut, out);
  junctions(cut, out);
  out.boxMin = target.V.colwise().minCoeff().transpose(), out.boxMax = target.V.colwise().maxCoeff().transpose();
  out.up = options.up;
  double area = 0;
  for (const Segment& s : out.segments) area += s.area;
  segmentProblems(area, options, out);
  seamProblems(cut, out);
  // Seams that cut nothing apart make no pattern: say so, or the designer sees seams and nothing else.
  if (out.segments.size() == 1 && !seams.empty()) {
    SegmentationProblem p;
    p.code = "segment.one-piece", p.severity = "error", p.segment = 0, p.location = out.segments[0].labelPoint;
    p.message =
        "The seams do not cut the shape apart yet: it is still one piece, and a balloon needs at least two panels. "
        "Close a seam into a loop, or run its ends into other seams.";
    out.problems.push_back(p);
  }
  return out;
}

}  // namespace billow
