#include "seams/outline.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_set>
#include <utility>

namespace billow {

namespace {

constexpr double kAwayFromZero = 1e-6;
// A vertex whose normal is within this of square to the view (n . towards, about 3 degrees) lies on a part seen
// edge-on: a letter's or a box's side wall, a flat sole seen from the side.
constexpr double kEdgeOn = 0.05;

Eigen::VectorXd vertexAreas(const TriMesh& mesh) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(mesh.V.rows());
  for (int f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) area[mesh.F(f, k)] += triangleArea(mesh, f) / 3;
  return area;
}

std::vector<std::vector<int>> vertexNeighbours(const TriMesh& mesh) {
  std::vector<std::vector<int>> around(mesh.V.rows());
  for (int f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      around[a].push_back(b), around[b].push_back(a);
    }
  return around;
}

// Where the surface is seen edge-on its facing is zero up to round-off, and the contour would run wherever that
// round-off put it: along a letter's front edge rather than round the middle of its side wall, back and forth across
// a flat sole. There the field is interpolated from around (harmonic, uniform weights), so the contour runs midway
// between the parts that face the viewer and those that face away, as a foil letter's seal does. An edge-on vertex
// between a part that faces the viewer and one that faces away (a pillow's rim, a star's tip) keeps its value: the
// contour passes through it.
void fillEdgeOn(const std::vector<std::vector<int>>& around, Eigen::VectorXd& facing) {
  const Eigen::Index nv = facing.size();
  const auto edgeOn = [&](int v) { return std::abs(facing[v]) < kEdgeOn; };
  std::vector<int> unknown(nv, -1);
  int count = 0;
  for (Eigen::Index v = 0; v < nv; ++v) {
    if (!edgeOn(int(v))) continue;
    bool front = false, back = false;
    for (int w : around[v])
      if (!edgeOn(w)) (facing[w] > 0 ? front : back) = true;
    if (!(front && back)) unknown[v] = count++;
  }
  if (count == 0) return;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(count);
  for (Eigen::Index v = 0; v < nv; ++v) {
    if (unknown[v] < 0) continue;
    std::vector<int> ring = around[v];
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    // A part seen edge-on all over (no face turned either way around it) stays at zero: the tiny diagonal term.
    entries.emplace_back(unknown[v], unknown[v], ring.size() + 1e-9);
    for (int w : ring)
      if (unknown[w] >= 0)
        entries.emplace_back(unknown[v], unknown[w], -1.0);
      else
        rhs[unknown[v]] += facing[w];
  }
  Eigen::SparseMatrix<double> laplacian(count, count);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  const Eigen::VectorXd filled = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !filled.allFinite()) return;
  for (Eigen::Index v = 0; v < nv; ++v)
    if (unknown[v] >= 0)
      facing[v] = std::abs(filled[unknown[v]]) < kAwayFromZero ? std::copysign(kAwayFromZero, filled[unknown[v]])
                                                               : filled[unknown[v]];
}

// Per vertex, n . towards over the area-weighted vertex normal, kept away from zero so the sides read the same here
// as where the contour is drawn; where seen edge-on, from around (fillEdgeOn; around: vertexNeighbours).
Eigen::VectorXd facingField(const TriMesh& mesh, const std::vector<std::vector<int>>& around,
                            const Eigen::Vector3d& towards) {
  Vertices normal = Vertices::Zero(mesh.V.rows(), 3);
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::RowVector3d twiceArea = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k) normal.row(mesh.F(f, k)) += twiceArea;
  }
  Eigen::VectorXd facing(mesh.V.rows());
  for (Eigen::Index v = 0; v < facing.size(); ++v) {
    const double length = normal.row(v).norm();
    facing[v] = length > 0 ? normal.row(v).dot(towards.transpose()) / length : 0;
    if (std::abs(facing[v]) < kAwayFromZero) facing[v] = facing[v] > 0 ? kAwayFromZero : -kAwayFromZero;
  }
  fillEdgeOn(around, facing);
  return facing;
}

// Changes the sign of `values` where needed so that its positive and its negative side are each one edge-connected
// piece and no vertex pinches a side: its zero set is then one loop on a shape without handles. Parts of a side that
// are not its largest change sides, the positive side's first. False when a side is empty.
bool splitInTwo(const TriMesh& mesh, const std::vector<std::vector<int>>& around, Eigen::VectorXd& values,
                Outline& out) {
  const Eigen::Index nv = values.size();
  const Eigen::VectorXd area = vertexAreas(mesh);
  // Keeps the largest edge-connected part of a side; the others change sides. How many changed, or -1 when the side
  // is empty.
  const auto keepLargest = [&](bool positive) {
    std::vector<int> part(nv, -1);
    std::vector<double> sizes;
    std::vector<int> stack;
    for (Eigen::Index s = 0; s < nv; ++s) {
      if (part[s] >= 0 || (values[s] > 0) != positive) continue;
      const int id = int(sizes.size());
      double size = 0;
      part[s] = id, stack.assign(1, int(s));
      while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        size += area[v];
        for (int w : around[v])
          if (part[w] < 0 && (values[w] > 0) == positive) part[w] = id, stack.push_back(w);
      }
      sizes.push_back(size);
    }
    if (sizes.empty()) return -1;
    const int largest = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    for (Eigen::Index v = 0; v < nv; ++v)
      if (part[v] >= 0 && part[v] != largest)
        values[v] = positive ? -std::max(values[v], kAwayFromZero) : std::max(-values[v], kAwayFromZero);
    return int(sizes.size()) - 1;
  };
  // A vertex whose ring of neighbours changes side more than twice pinches its side: the zero set would pass it
  // twice, as two loops touching. It goes to the other side, which joins across it.
  const auto pinches = [&] {
    std::vector<int> changes(nv, 0);
    for (int f = 0; f < mesh.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.F(f, (k + 1) % 3), b = mesh.F(f, (k + 2) % 3);
        if ((values[a] > 0) != (values[b] > 0)) ++changes[mesh.F(f, k)];
      }
    int flipped = 0;
    for (Eigen::Index v = 0; v < nv; ++v)
      if (changes[v] > 2) values[v] = values[v] > 0 ? -kAwayFromZero : kAwayFromZero, ++flipped;
    return flipped;
  };
  for (int round = 0; round < 20; ++round) {
    const int positive = keepLargest(true), negative = keepLargest(false);
    if (positive < 0 || negative < 0) return false;
    out.movedToBack += positive, out.movedToFront += negative;
    if (pinches() == 0) break;
  }
  return true;
}

double totalLength(const std::vector<SectionLoop>& loops) {
  double sum = 0;
  for (const SectionLoop& loop : loops) sum += loopLength(loop);
  return sum;
}

// Where the surface is seen nearly edge-on the contour's depth is ill-set: across a flat base seen from the side, or
// along a coarse mesh's long triangles, it bends around a single vertex whose value is near zero (one a pinch moved,
// one that kept its zero beside a part that changed sides), and back: a spike in depth that the seam, and a foil
// piece cut along it, would follow. The vertex a spike's tip lies nearest takes the largest value of its neighbours on
// its side, which moves the crossings off it as far as they allow, and the contour is traced again; a move is kept
// where the contour got shorter (a vertex moved can also send it round another way), the largest spikes first, for a
// few rounds. A spike is a point whose neighbours on the loop are closer to each other than half its distance from
// them (a turn of more than 90 degrees) and that stands off their chord, across the view, by less than a quarter of
// that: a sharp turn seen from the front (a star's tip, a letter's corner) is the outline itself. Signs do not change,
// so the sides stay as splitInTwo left them. The same rule as web/src/app/section.js's fairInDepth.
constexpr int kFairRounds = 4, kFairTries = 16;
std::vector<SectionLoop> fairInDepth(const TriMesh& mesh, const std::vector<std::vector<int>>& around,
                                     Eigen::VectorXd& values, const Eigen::Vector3d& towards) {
  const auto across = [&](const Eigen::Vector3d& d) -> Eigen::Vector3d { return d - d.dot(towards) * towards; };
  std::vector<SectionLoop> loops = zeroLoops(mesh, values);
  double length = totalLength(loops);
  int tries = 0;
  for (int round = 0; round < kFairRounds; ++round) {
    std::map<int, double> tips;  // vertex -> how far its spike stands off
    for (const SectionLoop& loop : loops) {
      // The loop without repeats (a crossing at a vertex is listed once per edge it ends, one near a vertex nearly so).
      const double apart = 1e-3 * loopLength(loop) / double(loop.size());
      std::vector<const SectionPoint*> points;
      for (size_t i = 0; i < loop.size(); ++i)
        if ((loop[i].position - loop[(i + 1) % loop.size()].position).norm() > apart) points.push_back(&loop[i]);
      const size_t n = points.size();
      if (n < 4) continue;
      for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d& a = points[(i + n - 1) % n]->position;
        const Eigen::Vector3d& tip = points[i]->position;
        const Eigen::Vector3d& b = points[(i + 1) % n]->position;
        const Eigen::Vector3d chord = b - a, off = tip - a;
        const double t = std::clamp(off.dot(chord) / std::max(chord.squaredNorm(), 1e-300), 0.0, 1.0);
        const double stand = (off - t * chord).norm();
        if (!(stand > 0.5 * chord.norm() + 1e-12)) continue;
        // Across the view: the tip's distance from the chord's line as seen from `towards`.
        const Eigen::Vector3d c = across(chord), o = across(off);
        const double seen = c.norm() > 1e-12 ? (o - o.dot(c) / c.squaredNorm() * c).norm() : o.norm();
        if (seen >= 0.25 * stand) continue;
        Eigen::Index k;
        points[i]->at.bary.maxCoeff(&k);
        double& farthest = tips[mesh.F(points[i]->at.face, int(k))];
        farthest = std::max(farthest, stand);
      }
    }
    // The largest spikes first, each kept where it shortens the contour.
    std::vector<std::pair<int, double>> order(tips.begin(), tips.end());
    std::stable_sort(order.begin(), order.end(), [](const auto& p, const auto& q) { return p.second > q.second; });
    bool changed = false;
    for (const auto& spike : order) {
      if (tries >= kFairTries) break;
      const int v = spike.first;
      double largest = 0;
      for (int w : around[v])
        if ((values[w] > 0) == (values[v] > 0) && std::abs(values[w]) > std::abs(largest)) largest = values[w];
      if (!(std::abs(largest) > std::abs(values[v]))) continue;
      ++tries;
      const double kept = values[v];
      values[v] = largest;
      std::vector<SectionLoop> traced = zeroLoops(mesh, values);
      const double tracedLength = totalLength(traced);
      if (tracedLength < length)
        loops = std::move(traced), length = tracedLength, changed = true;
      else
        values[v] = kept;
    }
    if (!changed) break;
  }
  return loops;
}

}  // namespace

std::optional<Outline> outlineSeenFrom(const TriMesh& mesh, const Eigen::Vector3d& towards) {
  const std::vector<std::vector<int>> around = vertexNeighbours(mesh);
  Eigen::VectorXd facing = facingField(mesh, around, towards);
  Outline out;
  if (!splitInTwo(mesh, around, facing, out)) return std::nullopt;
  std::vector<SectionLoop> loops = fairInDepth(mesh, around, facing, towards);
  if (loops.empty()) return std::nullopt;
  const auto longest = std::max_element(loops.begin(), loops.end(), [](const SectionLoop& a, const SectionLoop& b) {
    return loopLength(a) < loopLength(b);
  });
  out.loop = std::move(*longest);
  for (auto it = loops.begin(); it != loops.end(); ++it)
    if (it != longest) out.holes.push_back(std::move(*it));
  return out;
}

std::optional<SectionLoop> sectionThrough(const TriMesh& mesh, const Eigen::Vector3d& position, int face,
                                          const Eigen::Vector3d& normal) {
  std::vector<SectionLoop> loops = planeSection(mesh, normal, position.dot(normal));
  if (loops.empty()) return std::nullopt;
  for (SectionLoop& loop : loops)
    if (std::any_of(loop.begin(), loop.end(), [&](const SectionPoint& p) { return p.at.face == face; }))
      return std::move(loop);
  const auto gap = [&](const SectionLoop& loop) {
    double d = std::numeric_limits<double>::infinity();
    for (const SectionPoint& p : loop) d = std::min(d, (p.position - position).norm());
    return d;
  };
  return std::move(*std::min_element(loops.begin(), loops.end(),
                                     [&](const SectionLoop& a, const SectionLoop& b) { return gap(a) < gap(b); }));
}

namespace {

// How many times `loop` crosses a loop of the plane {p . normal = offset} that passes through `faces`: where two
// consecutive points of the loop lie on either side of the plane, in one of those faces (a zeroLoops point names the
// face of the step that reaches it; the plane's other loops pass through other faces). A point within `hair` of the
// plane is on its positive side, as a vertex there is to planeSection (a loop point at a vertex is rounded off it).
int crossings(const SectionLoop& loop, const std::unordered_set<int>& faces, const Eigen::Vector3d& normal,
              double offset, double hair) {
  const auto below = [&](const SectionPoint& p) { return p.position.dot(normal) - offset < -hair; };
  int n = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const SectionPoint& b = loop[(i + 1) % loop.size()];
    if (below(loop[i]) != below(b) && faces.count(b.at.face)) ++n;
  }
  return n;
}

}  // namespace

std::vector<SectionLoop> acrossHandles(const TriMesh& mesh, const SectionLoop& rim,
                                       const std::vector<SectionLoop>& holes, const Eigen::Vector3d& towards) {
  // Every few points of a long loop: the cut's place need not be exact.
  const auto every = [](const SectionLoop& loop, size_t most) {
    const size_t stride = std::max<size_t>(1, (loop.size() + most - 1) / most);
    SectionLoop some;
    for (size_t i = 0; i < loop.size(); i += stride) some.push_back(loop[i]);
    return some;
  };
  const auto nearestOn = [](const SectionLoop& loop, const Eigen::Vector3d& p) {
    return size_t(std::min_element(loop.begin(), loop.end(),
                                   [&](const SectionPoint& a, const SectionPoint& b) {
                                     return (a.position - p).squaredNorm() < (b.position - p).squaredNorm();
                                   }) -
                  loop.begin());
  };
  const double hair = 1e-9 * boundingDiagonal(mesh);
  const SectionLoop rimPoints = every(rim, 400);
  std::vector<SectionLoop> out;
  for (size_t h = 0; h < holes.size(); ++h) {
    const SectionLoop some = every(holes[h], 200);
    const size_t n = some.size();
    if (n < 3) continue;
    // The section through the hole's point `i` straight across its line there (the plane along the view, across the
    // line's tangent), where it runs around the ring: across the rim and this hole once each (a ring seen through) or
    // twice (a torus seen from its side, whose inner contour is no hole one sees through), no other hole, and nowhere
    // along a piece of their lines. A section that grazes its hole, crosses a wavering rim more often, runs along a
    // flat wall seen edge-on or crosses another hole cuts slivers off (a statue's legs, its base seen edge-on).
    // Not at a corner (a letter's hole's), where the line has no one tangent: turning by more than 30 degrees between
    // the points a 24th of the loop to either side (nearer, a coarse mesh's contour zig-zags across a wall seen
    // edge-on; a circle turns 15 degrees there).
    const size_t w = std::max<size_t>(2, (n + 12) / 24);
    const auto cut = [&](size_t i) -> std::optional<SectionLoop> {
      const auto seen = [&](const Eigen::Vector3d& d) { return Eigen::Vector3d(d - d.dot(towards) * towards); };
      const Eigen::Vector3d before = seen(some[i].position - some[(i + n - w % n) % n].position),
                            after = seen(some[(i + w) % n].position - some[i].position);
      if (!(before.dot(after) > std::sqrt(3.0) / 2 * before.norm() * after.norm())) return std::nullopt;
      const Eigen::Vector3d unit = (before + after).normalized();
      std::optional<SectionLoop> section = sectionThrough(mesh, some[i].position, some[i].at.face, unit);
      if (!section) return std::nullopt;
      const double offset = some[i].position.dot(unit);
      std::unordered_set<int> faces;
      for (const SectionPoint& p : *section) faces.insert(p.at.face);
      const auto inPlane = [&](const SectionPoint& x) { return std::abs(x.position.dot(unit) - offset) <= hair; };
      for (const SectionLoop* loop : {&holes[h], &rim})
        for (size_t k = 0; k < loop->size(); ++k)
          if (inPlane((*loop)[k]) && inPlane((*loop)[(k + 1) % loop->size()])) return std::nullopt;
      const auto around = [&](const SectionLoop& loop) {
        const int crossed = crossings(loop, faces, unit, offset, hair);
        return crossed == 1 || crossed == 2;
      };
      if (!around(rim)) return std::nullopt;
      for (size_t other = 0; other < holes.size(); ++other)
        if (other == h ? !around(holes[other]) : crossings(holes[other], faces, unit, offset, hair) > 0)
          return std::nullopt;
      return section;
    };
    std::vector<double> gap(n);
    for (size_t k = 0; k < n; ++k)
      gap[k] = (rimPoints[nearestOn(rimPoints, some[k].position)].position - some[k].position).norm();
    const size_t nearest = size_t(std::min_element(gap.begin(), gap.end()) - gap.begin());
    // The cut where the ring is narrowest: through the middle of a stretch as narrow (a letter's straight stroke, where
    // a cut at its end would leave a sliver at the corner), else through the narrowest point.
    const double within = gap[nearest] * 1.01 + hair;
    size_t ahead = 0, behind = 0;
    while (ahead + 1 < n && gap[(nearest + ahead + 1) % n] <= within) ++ahead;
    while (behind + ahead + 1 < n && gap[(nearest + n - behind - 1) % n] <= within) ++behind;
    Eigen::Vector3d middle = Eigen::Vector3d::Zero();
    for (const SectionPoint& p : some) middle += p.position;
    middle /= double(n);
    std::vector<size_t> narrowFirst(n);
    std::iota(narrowFirst.begin(), narrowFirst.end(), size_t{0});
    std::sort(narrowFirst.begin(), narrowFirst.end(), [&](size_t a, size_t b) { return gap[a] < gap[b]; });
    for (const size_t k : {(nearest + n + ahead / 2 - behind / 2) % n, nearest}) {
      std::optional<SectionLoop> narrowest = cut(k);
      if (!narrowest) continue;
      // The other cut opposite it across the hole's middle, else farthest from it, else where the ring is narrowest a
      // quarter of the hole or more away (a letter B's hole has its other stroke opposite, not the rim).
      size_t farthest = k;
      for (size_t j = 0; j < n; ++j)
        if ((some[j].position - some[k].position).norm() > (some[farthest].position - some[k].position).norm())
          farthest = j;
      std::vector<size_t> places = {nearestOn(some, 2 * middle - some[k].position), farthest};
      for (const size_t j : narrowFirst)
        if (std::min((j + n - k) % n, (k + n - j) % n) >= n / 4 && places.size() < 6) places.push_back(j);
      for (const size_t j : places)
        if (std::optional<SectionLoop> opposite = cut(j)) {
          out.push_back(std::move(*narrowest)), out.push_back(std::move(*opposite));
          break;
        }
      break;
    }
  }
  return out;
}

}  // namespace billow
