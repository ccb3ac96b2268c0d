#include "seams/plane_section.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

namespace billow {

namespace {

uint64_t crossedEdgeKey(int a, int b) {
  const auto lo = static_cast<uint64_t>(std::min(a, b)), hi = static_cast<uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}

// The barycentric weights, in face f, of a point given in another face that shares its edge.
Eigen::Vector3d weightsInFace(const TriMesh& mesh, const SurfacePoint& p, int f) {
  if (p.face == f) return p.bary;
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k)
      if (mesh.F(p.face, k) == mesh.F(f, c)) w[c] = p.bary[k];
  return w;
}

}  // namespace

std::vector<SectionLoop> planeSection(const TriMesh& mesh, const Eigen::Vector3d& normal, double offset) {
  Eigen::VectorXd h = (mesh.V * normal).array() - offset;
  // A vertex on the plane goes to its positive side by a hair, so every crossing lies inside an edge.
  const double hair = 1e-9 * (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).norm();
  for (Eigen::Index v = 0; v < h.size(); ++v)
    if (std::abs(h[v]) < hair) h[v] = hair;
  return zeroLoops(mesh, h);
}

std::vector<SectionLoop> zeroLoops(const TriMesh& mesh, const Eigen::VectorXd& h) {
  const auto below = [&](int v) { return h[v] < 0; };
  struct Step {
    uint64_t edge;
    int face;
  };
  std::unordered_map<uint64_t, std::vector<Step>> next;  // crossed edge -> the cut faces on it
  std::unordered_map<uint64_t, std::array<int, 2>> ends;
  std::vector<uint64_t> order;  // crossed edges as first met, so the loops come out the same on every run
  for (int f = 0; f < mesh.F.rows(); ++f) {
    uint64_t crossed[2];
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      if (below(a) == below(b)) continue;
      const uint64_t e = crossedEdgeKey(a, b);
      if (n < 2) crossed[n] = e;
      ++n;
      if (ends.emplace(e, std::array<int, 2>{a, b}).second) order.push_back(e);
    }
    if (n != 2) continue;
    next[crossed[0]].push_back({crossed[1], f});
    next[crossed[1]].push_back({crossed[0], f});
  }
  const auto point = [&](uint64_t e, int face) {
    const auto [a, b] = ends.at(e);
    const double s = h[a] / (h[a] - h[b]);
    SectionPoint p;
    p.position = mesh.V.row(a).transpose() + s * (mesh.V.row(b) - mesh.V.row(a)).transpose();
    p.at.face = face;
    for (int c = 0; c < 3; ++c) p.at.bary[c] = mesh.F(face, c) == a ? 1 - s : mesh.F(face, c) == b ? s : 0;
    return p;
  };
  std::unordered_set<uint64_t> seen;
  std::vector<SectionLoop> loops;
  for (uint64_t start : order) {
    if (seen.count(start) || !next.count(start)) continue;
    const std::vector<Step>& around = next.at(start);
    // The start's point lies in the face the walk closes the loop across: the other cut face on its edge.
    int face = around.size() > 1 ? around[1].face : around[0].face;
    SectionLoop loop;
    for (uint64_t current = start; !seen.count(current);) {
      seen.insert(current);
      loop.push_back(point(current, face));
      const auto step = std::find_if(next.at(current).begin(), next.at(current).end(),
                                     [&](const Step& s) { return !seen.count(s.edge); });
      if (step == next.at(current).end()) break;
      current = step->edge, face = step->face;
    }
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

double loopLength(const SectionLoop& loop) {
  double total = 0;
  for (size_t i = 0; i < loop.size(); ++i) total += (loop[(i + 1) % loop.size()].position - loop[i].position).norm();
  return total;
}

namespace {

// The points at arc lengths `arcs` (ascending, from the first point) along the loop's points (closed: the last
// joined to the first), each in the face between its neighbours on the loop: a point between two crossings lies in
// the face the walk crossed from one to the other.
std::vector<SurfacePoint> pointsAt(const TriMesh& mesh, const SectionLoop& loop, bool closed,
                                   const std::vector<double>& arcs) {
  std::vector<SurfacePoint> out;
  const size_t spans = closed ? loop.size() : loop.size() - 1;
  const auto span = [&](size_t k) { return (loop[(k + 1) % loop.size()].position - loop[k].position).norm(); };
  size_t i = 0;
  double walked = 0;
  for (double want : arcs) {
    while (i + 1 < spans && walked + span(i) < want) walked += span(i++);
    const SectionPoint& a = loop[i];
    const SectionPoint& b = loop[(i + 1) % loop.size()];
    const double s = std::clamp((want - walked) / std::max(span(i), 1e-300), 0.0, 1.0);
    // b was reached across b's face, which also holds a's edge: both points' weights in that face. Where the two
    // share no face (a path with points left out), the nearer of them: weights of a point off the face would not sum
    // to 1, a point off the surface.
    const Eigen::Vector3d wa = weightsInFace(mesh, a.at, b.at.face);
    SurfacePoint p;
    if (std::abs(wa.sum() - 1) > 1e-9) {
      p = s < 0.5 ? a.at : b.at;
    } else {
      p.face = b.at.face;
      p.bary = (1 - s) * wa + s * b.at.bary;
    }
    out.push_back(p);
  }
  return out;
}

// Inserts into `arcs` (ascending arc lengths from the loop's first point, the first 0) the arc of the loop point
// farthest from the chord between two neighbouring arcs, while one strays from it by more than `stray`: the seam
// runs along shortest paths between its points, and one that skipped a sharp turn (a star's tip, a letter's
// corner) would cut it off and give it to the other side.
void keepTurns(const SectionLoop& loop, std::vector<double>& arcs, double stray) {
  constexpr size_t kMostPoints = 400;
  const size_t n = loop.size();
  std::vector<double> arcOf(n + 1, 0.0);
  for (size_t i = 1; i <= n; ++i) arcOf[i] = arcOf[i - 1] + (loop[i % n].position - loop[i - 1].position).norm();
  const double total = arcOf[n];
  // The last loop point at or before an arc length in [0, total].
  const auto after = [&](double arc) {
    return size_t(std::upper_bound(arcOf.begin(), arcOf.begin() + n, arc) - arcOf.begin()) - 1;
  };
  const auto at = [&](double arc) -> Eigen::Vector3d {
    const size_t k = after(arc);
    const double s = std::clamp((arc - arcOf[k]) / std::max(arcOf[k + 1] - arcOf[k], 1e-300), 0.0, 1.0);
    return loop[k].position + s * (loop[(k + 1) % n].position - loop[k].position);
  };
  for (size_t k = 0; k < arcs.size() && arcs.size() < kMostPoints; ++k) {
    const double a = arcs[k], b = k + 1 < arcs.size() ? arcs[k + 1] : total;
    const Eigen::Vector3d p = at(a), d = at(b) - p;
    const double dd = d.squaredNorm();
    double corner = -1, gap = stray;
    for (size_t i = after(a) + 1; i < n && arcOf[i] < b; ++i) {
      const Eigen::Vector3d& x = loop[i].position;
      const double t = dd > 0 ? std::clamp((x - p).dot(d) / dd, 0.0, 1.0) : 0.0;
      const double off = (x - (p + t * d)).norm();
      if (off > gap) gap = off, corner = arcOf[i];
    }
    if (corner > a) arcs.insert(arcs.begin() + long(k) + 1, corner), --k;
  }
}

}  // namespace

std::vector<SurfacePoint> sectionSeamPoints(const TriMesh& mesh, const SectionLoop& loop, double spacing,
                                            bool corners) {
  const double total = loopLength(loop);
  const int n = int(std::lround(std::clamp(total / std::max(spacing, 1e-300), 12.0, 160.0)));
  std::vector<double> arcs;
  for (int k = 0; k < n; ++k) arcs.push_back(k * total / n);
  if (corners) keepTurns(loop, arcs, 0.1 * total / n);
  return pointsAt(mesh, loop, true, arcs);
}

std::vector<SurfacePoint> sectionPathPoints(const TriMesh& mesh, const SectionLoop& path, double spacing,
                                            bool corners) {
  if (path.size() < 2) return {};
  double total = 0;
  for (size_t i = 0; i + 1 < path.size(); ++i) total += (path[i + 1].position - path[i].position).norm();
  const int n = std::max(1, int(std::lround(total / std::max(spacing, 1e-300))));
  std::vector<double> arcs;
  for (int k = 0; k <= n; ++k) arcs.push_back(k * total / n);
  // Taken as a loop, the path's closing piece holds no point of its own, so no turn is kept there.
  if (corners) keepTurns(path, arcs, 0.1 * total / n);
  arcs = std::vector<double>(arcs.begin() + 1, arcs.end() - 1);
  std::vector<SurfacePoint> out{path.front().at};
  for (const SurfacePoint& p : pointsAt(mesh, path, false, arcs)) out.push_back(p);
  out.push_back(path.back().at);
  return out;
}

}  // namespace billow
