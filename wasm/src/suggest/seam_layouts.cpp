#include "suggest/seam_layouts.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>

#include "export/layout.hpp"
#include "optimize/optimized_pattern.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "optimize/stopping_rule.hpp"
#include "seams/outline.hpp"
#include "seams/plane_section.hpp"
#include "seams/surface_distance.hpp"
#include "util/error.hpp"

namespace billow {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Control points of a proposed seam, as the section tool spaces them (web/src/app/section.js SECTION_SPACING).
constexpr double kSeamPointSpacing = 0.02;
constexpr int kMostGores = 24, kMostBands = 12;
// A layout is laid for as few as half the panels asked for (four fewer at small counts): a limb cut on its own, or
// opened, adds panels on most shapes (the penguin's 4 bands in two pieces along its outline make 12, not 8). A look
// that makes more than asked for is refused before it is built (lookAtLayout).
int fewestPanels(int asked) { return asked - std::max(4, asked / 2); }

// Which way a direction of the target's own coordinates points as the target stands: 0 side to side, 1 up, 2 front
// to back (the up frame's axes).
int viewAxis(const Eigen::Vector3d& direction, const UpAxis& up) {
  Eigen::Index k = 0;
  (upFrame(up) * direction).cwiseAbs().maxCoeff(&k);
  return int(k);
}

std::string axisName(int axis, const UpAxis& up) {
  static const char* names[] = {"side-to-side axis", "vertical axis", "front-to-back axis"};
  return names[viewAxis(Eigen::Vector3d::Unit(axis), up)];
}

std::string halvesName(const Eigen::Vector3d& normal, const UpAxis& up) {
  static const char* names[] = {"left and right halves", "top and bottom halves", "front and back halves"};
  return names[viewAxis(normal, up)];
}

// Where a plane across `axis` leaves `share` of the target's area below it.
struct AreaAlong {
  std::vector<std::pair<double, double>> coordinateArea;  // face centroids' coordinate, face area; sorted
  double total = 0;
  double at(double share) const {
    double walked = 0;
    for (const auto& [x, a] : coordinateArea)
      if ((walked += a) >= share * total) return x;
    return coordinateArea.empty() ? 0 : coordinateArea.back().first;
  }
};

// The target's faces: their centroids and areas.
struct Faces {
  Eigen::MatrixX3d centroid;
  Eigen::VectorXd area;
};

Faces facesOf(const TriMesh& mesh) {
  Faces out{Eigen::MatrixX3d(mesh.F.rows(), 3), Eigen::VectorXd(mesh.F.rows())};
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    out.centroid.row(f) = (a + b + c) / 3, out.area[f] = 0.5 * (b - a).cross(c - a).norm();
  }
  return out;
}

AreaAlong areaAlong(const Faces& faces, int axis) {
  AreaAlong out;
  for (Eigen::Index f = 0; f < faces.area.size(); ++f)
    out.coordinateArea.emplace_back(faces.centroid(f, axis), faces.area[f]);
  out.total = faces.area.sum();
  std::sort(out.coordinateArea.begin(), out.coordinateArea.end());
  return out;
}

// Control points of a proposed seam on `target` lie this far apart [its units].
double seamPointSpacing(const TriMesh& target) {
  return kSeamPointSpacing * (target.V.colwise().maxCoeff() - target.V.colwise().minCoeff()).norm();
}

// A layout's key, so one two families both make is tried once: its planes and meridians, rounded.
using ProposalKey = std::vector<std::array<long long, 5>>;
ProposalKey proposalKey(const LayoutProposal& proposal, double size) {
  const std::vector<SectionPlane>& planes = proposal.planes;
  const std::vector<Eigen::Vector3d>& meridians = proposal.meridians;
  ProposalKey key;
  if (proposal.outlineView >= 0) key.push_back({2, proposal.outlineView, 0, 0, 0});
  const auto rounded = [](double x) { return std::llround(x * 1e4); };
  for (const SectionPlane& p : planes) {
    // n and -n with -offset are one plane: the first non-zero component positive.
    Eigen::Vector3d n = p.normal;
    double d = p.offset;
    for (int k = 0; k < 3; ++k)
      if (std::abs(n[k]) > 1e-6) {
        if (n[k] < 0) n = -n, d = -d;
        break;
      }
    key.push_back({0, rounded(n.x()), rounded(n.y()), rounded(n.z()), rounded(d / size)});
  }
  for (const Eigen::Vector3d& m : meridians) key.push_back({1, rounded(m.x()), rounded(m.y()), rounded(m.z()), 0});
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace

std::string LayoutOpenings::description() const {
  std::string out;
  const auto add = [&](int n, const char* one, const char* many) {
    if (n == 0) return;
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + (n == 1 ? one : many);
  };
  add(tubeCuts, "cut that opens a tube", "cuts that open tubes");
  add(limbSeams, "seam around a limb", "seams around limbs");
  add(grazingLoops, "loop left out where it only grazed the shape", "loops left out where they only grazed the shape");
  return out;
}

int designSymmetryAxis(const Design& design) {
  const auto it = design.extra.find("symmetry");
  if (it == design.extra.end() || !it->is_object() || !it->contains("axis") || !(*it)["axis"].is_string()) return -1;
  const std::string axis = (*it)["axis"].get<std::string>();
  return axis == "x" ? 0 : axis == "y" ? 1 : axis == "z" ? 2 : -1;
}

int mirrorSymmetryAxis(const TriMesh& target, const SurfaceProjector& projector, double tolerance) {
  if (target.V.rows() == 0) return -1;
  const Eigen::Vector3d lo = target.V.colwise().minCoeff(), hi = target.V.colwise().maxCoeff();
  const double size = (hi - lo).norm();
  int best = -1;
  double bestRms = tolerance * size;
  for (int axis = 0; axis < 3; ++axis) {
    double sum = 0;
    for (int v = 0; v < target.V.rows(); ++v) {
      Eigen::Vector3d p = target.V.row(v);
      p[axis] = lo[axis] + hi[axis] - p[axis];
      double d = 0;
      projector.project(p, &d);
      sum += d * d;
    }
    const double rms = std::sqrt(sum / target.V.rows());
    if (rms < bestRms) best = axis, bestRms = rms;
  }
  return best;
}

std::vector<LayoutProposal> proposeLayouts(const TriMesh& target, const LayoutRequest& request) {
  std::vector<LayoutProposal> out;
  if (target.F.rows() == 0 || request.panels < 2) return out;
  const Eigen::Vector3d lo = target.V.colwise().minCoeff(), hi = target.V.colwise().maxCoeff();
  const double size = (hi - lo).norm();
  // The axes go through the area centroid; across a symmetry plane, through the box's middle, where the app's
  // symmetry plane lies (web/src/app/symmetry.js).
  const Faces faces = facesOf(target);
  Eigen::Vector3d center = (faces.centroid.transpose() * faces.area) / std::max(faces.area.sum(), 1e-300);
  const int s = request.symmetryAxis;
  if (s >= 0 && s < 3) center[s] = 0.5 * (lo[s] + hi[s]);
  std::vector<ProposalKey> seen;
  for (int axis = 0; axis < 3; ++axis) {
    const AreaAlong along = areaAlong(faces, axis);
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
    // Directions across the axis from u: the symmetry axis where there is one, so that the meridians at pi / 2 +
    // 2 pi i / g (or those turned by pi / g) are each other's mirror images, and the halving planes through u or w
    // their own.
    const Eigen::Vector3d u = Eigen::Vector3d::Unit(s >= 0 && s != axis ? s : (axis + 1) % 3), w = e.cross(u);
    for (int g = 2; g <= kMostGores; ++g)
      for (int k = 0; k <= kMostBands; ++k) {
        const int panels = g * (k + 1);
        if (panels > request.panels || panels < fewestPanels(request.panels)) continue;
        // Bands across the symmetry axis would be their own mirror image only at mirrored shares.
        if (k > 0 && axis == s) continue;
        for (int turn = 0; turn < 2; ++turn) {
          LayoutProposal p;
          p.axis = axis, p.gores = g, p.bands = k, p.center = center;
          if (g == 2) {
            const Eigen::Vector3d normal = e.cross(turn ? w : u);
            p.planes.push_back({normal, normal.dot(center)});
          } else {
            for (int i = 0; i < g; ++i) {
              const double theta = kPi / 2 + 2 * kPi * i / g - (turn ? kPi / g : 0);
              p.meridians.push_back(std::cos(theta) * u + std::sin(theta) * w);
            }
          }
          for (int j = 1; j <= k; ++j) p.planes.push_back({e, along.at(double(j) / (k + 1))});
          ProposalKey key = proposalKey(p, size);
          if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
          seen.push_back(std::move(key));
          const std::string across = axisName(axis, request.up);
          if (k == 0)
            p.name = g == 2 ? halvesName(p.planes[0].normal, request.up)
                            : std::to_string(g) + " gores around the " + across + (turn ? ", turned" : "");
          else
            p.name = std::to_string(k + 1) + " bands across the " + across +
                     (g == 2 ? ", in " + halvesName(p.planes[0].normal, request.up)
                             : ", each in " + std::to_string(g) + " gores" + (turn ? " (turned)" : ""));
          out.push_back(std::move(p));
        }
      }
  }
  // A front and a back along the outline seen along `view`, and k bands across another axis, each in two pieces.
  // Seen along any axis the outline is its own mirror image across the symmetry plane: seen across it (an animal from
  // its side, as a foil balloon is cut), the front and the back are each other's. The two pieces alone at any count:
  // where limbs leave every plane a tube to open (an octopus's coiled arms), the outline may be the one layout that
  // makes panels.
  for (int view = 0; view < 3; ++view) {
    static const char* from[] = {"from the side", "from above", "from the front"};
    const std::string outline =
        std::string("along the outline seen ") + from[viewAxis(Eigen::Vector3d::Unit(view), request.up)];
    for (int axis = 0; axis < 3; ++axis) {
      if (axis == view || axis == s) continue;
      const AreaAlong along = areaAlong(faces, axis);
      for (int k = 0; k <= kMostBands; ++k) {
        const int panels = 2 * (k + 1);
        if (panels > request.panels || (k > 0 && panels < fewestPanels(request.panels))) continue;
        LayoutProposal p;
        p.axis = axis, p.gores = 2, p.bands = k, p.center = center, p.outlineView = view;
        for (int j = 1; j <= k; ++j) p.planes.push_back({Eigen::Vector3d::Unit(axis), along.at(double(j) / (k + 1))});
        ProposalKey key = proposalKey(p, size);
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
        seen.push_back(std::move(key));
        p.name = k == 0 ? "front and back, sealed " + outline
                        : std::to_string(k + 1) + " bands across the " + axisName(axis, request.up) +
                              ", each in two pieces " + outline;
        out.push_back(std::move(p));
      }
    }
  }
  return out;
}

namespace {

struct Pole {
  SectionPoint point;
  bool found = false;
};

// Where the line through `center` along `direction` meets the surface first and last.
std::array<Pole, 2> axisPoles(const TriMesh& mesh, const Eigen::Vector3d& center, const Eigen::Vector3d& direction) {
  std::array<Pole, 2> poles;
  double tMin = INFINITY, tMax = -INFINITY;
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    // Moller-Trumbore, for the whole line.
    const Eigen::Vector3d e1 = b - a, e2 = c - a, q = direction.cross(e2);
    const double det = e1.dot(q);
    if (std::abs(det) < 1e-300) continue;
    const Eigen::Vector3d s = center - a;
    const double u = s.dot(q) / det;
    if (u < 0 || u > 1) continue;
    const Eigen::Vector3d r = s.cross(e1);
    const double v = direction.dot(r) / det;
    if (v < 0 || u + v > 1) continue;
    const double t = e2.dot(r) / det;
    for (int end = 0; end < 2; ++end) {
      if (end == 0 ? t >= tMin : t <= tMax) continue;
      (end == 0 ? tMin : tMax) = t;
      Pole& pole = poles[end];
      pole.found = true;
      pole.point.at.face = f, pole.point.at.bary = Eigen::Vector3d(1 - u - v, u, v);
      pole.point.position = center + t * direction;
    }
  }
  return poles;
}

DesignSeam makeSeam(const std::string& name, bool closed, const std::vector<SurfacePoint>& controls) {
  DesignSeam seam;
  seam.name = name, seam.closed = closed;
  for (const SurfacePoint& p : controls) {
    DesignPoint point;
    point.onSurface = true, point.surface = p;
    seam.points.push_back(point);
  }
  return seam;
}

size_t nearestPoint(const SectionLoop& loop, const Eigen::Vector3d& p, double& distance) {
  size_t best = 0;
  distance = INFINITY;
  for (size_t i = 0; i < loop.size(); ++i)
    if (const double d = (loop[i].position - p).norm(); d < distance) distance = d, best = i;
  return best;
}

}  // namespace

std::vector<DesignSeam> proposalSeams(const TriMesh& target, const LayoutProposal& proposal) {
  const double spacing = seamPointSpacing(target);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(proposal.axis);
  std::array<Pole, 2> poles;
  if (!proposal.meridians.empty()) {
    poles = axisPoles(target, proposal.center, e);
    if (!poles[0].found || !poles[1].found)
      throw Error("suggest.no-poles", "its axis passes beside the shape, so its gores have no ends to meet at");
  }
  std::vector<DesignSeam> seams;
  const auto name = [&] { return proposal.name + ", seam " + std::to_string(seams.size() + 1); };
  if (proposal.outlineView >= 0) {
    const Eigen::Vector3d towards = Eigen::Vector3d::Unit(proposal.outlineView);
    const std::optional<Outline> outline = outlineSeenFrom(target, towards);
    if (!outline) throw Error("suggest.no-outline", "the shape shows no outline from there");
    // Corners kept, as the Outline tool keeps them: a seam that skipped a sharp turn would cut a tip off.
    seams.push_back(makeSeam(name(), true, sectionSeamPoints(target, outline->loop, spacing, true)));
    // Seen through a handle, the front and back are rings: each hole's rim, and two sections across each ring.
    const std::vector<SectionLoop> across = acrossHandles(target, outline->loop, outline->holes, towards);
    if (across.size() != 2 * outline->holes.size())
      throw Error("suggest.no-outline", "its outline makes rings on this shape that no section cuts open");
    for (const SectionLoop& hole : outline->holes)
      seams.push_back(makeSeam(name(), true, sectionSeamPoints(target, hole, spacing, true)));
    for (const SectionLoop& loop : across)
      seams.push_back(makeSeam(name(), true, sectionSeamPoints(target, loop, spacing)));
  }
  for (const Eigen::Vector3d& direction : proposal.meridians) {
    const Eigen::Vector3d normal = e.cross(direction).normalized();
    const std::vector<SectionLoop> loops = planeSection(target, normal, normal.dot(proposal.center));
    // Which side of the axis a loop (or a piece of one) lies on: its points' mean along the direction.
    const auto onThisSide = [&](const SectionLoop& points) {
      double along = 0;
      for (const SectionPoint& p : points) along += (p.position - proposal.center).dot(direction);
      return along > 0;
    };
    // The loop through both poles: of its two pieces from pole to pole, the one on this side is the meridian.
    size_t poleLoop = loops.size();
    double best = INFINITY;
    for (size_t l = 0; l < loops.size(); ++l) {
      double d0 = 0, d1 = 0;
      nearestPoint(loops[l], poles[0].point.position, d0), nearestPoint(loops[l], poles[1].point.position, d1);
      if (std::max(d0, d1) < best) best = std::max(d0, d1), poleLoop = l;
    }
    if (best > 5 * spacing)
      throw Error("suggest.no-poles", "its gores do not all pass through both ends of its axis on this shape");
    for (size_t l = 0; l < loops.size(); ++l) {
      const SectionLoop& loop = loops[l];
      if (l != poleLoop) {  // a limb the plane cuts on its own, on this side
        if (onThisSide(loop)) seams.push_back(makeSeam(name(), true, sectionSeamPoints(target, loop, spacing)));
        continue;
      }
      double d = 0;
      const size_t a = nearestPoint(loop, poles[0].point.position, d),
                   b = nearestPoint(loop, poles[1].point.position, d);
      for (int half = 0; half < 2; ++half) {
        // Pole to pole on either side of the loop, walked forward (a point keeps the face the walk crossed to reach
        // it) and the second side's points turned round after; loop points within a quarter spacing of a pole left
        // out, so no control point crowds it.
        const Pole& from = poles[half];
        const Pole& to = poles[1 - half];
        const size_t n = loop.size(), start = half == 0 ? a : b, end = half == 0 ? b : a;
        SectionLoop piece, side;
        for (size_t j = 1; j < n; ++j) {
          const size_t k = (start + j) % n;
          if (k == end) break;
          side.push_back(loop[k]);
          if ((loop[k].position - from.point.position).norm() >= 0.25 * spacing &&
              (loop[k].position - to.point.position).norm() >= 0.25 * spacing)
            piece.push_back(loop[k]);
        }
        if (!onThisSide(side)) continue;
        std::vector<SurfacePoint> controls{from.point.at};
        if (piece.size() >= 2)
          for (const SurfacePoint& p : sectionPathPoints(target, piece, spacing)) controls.push_back(p);
        controls.push_back(to.point.at);
        if (half == 1) std::reverse(controls.begin(), controls.end());
        seams.push_back(makeSeam(name(), false, controls));
      }
    }
  }
  for (const SectionPlane& plane : proposal.planes)
    for (const SectionLoop& loop : planeSection(target, plane.normal, plane.offset))
      seams.push_back(makeSeam(name(), true, sectionSeamPoints(target, loop, spacing)));
  return seams;
}

namespace {

// Seams that make a layout's segments panels, where plane sections alone leave a segment that is not one: a segment
// between two loops or more (a plane across a limb leaves a tube, a limb's end cut off inside a band leaves a hole)
// gets, from each of its loops but the longest, a seam to its nearest point of another loop (the cut that opens a
// tube, as a designer would add it); a segment too big for its seam (a limb's end) gets the plane section across
// its longest extent where that loop lies within it, else across the next (around its limbs); a tiny or thin segment
// loses the shortest closed seam of the layout's own around it (a plane grazing a toe). The first `fixedSeams` seams
// are the designer's and stay. Counts what it did in `opened`; returns how many seams it added or removed.
int openSegments(const DesignScene& scene, double spacing, int fixedSeams, std::vector<DesignSeam>& seams,
                 LayoutOpenings& opened) {
  const Segmentation& sg = scene.segmentation;
  const TriMesh& cut = sg.mesh;
  int added = 0;
  // The segments each target face has a part in.
  std::vector<std::vector<int>> faceSegments(scene.target.F.rows());
  for (int f = 0; f < int(sg.faceOrigin.size()); ++f) {
    std::vector<int>& in = faceSegments[sg.faceOrigin[f]];
    if (std::find(in.begin(), in.end(), sg.faceSegment[f]) == in.end()) in.push_back(sg.faceSegment[f]);
  }
  // The grazing loops go first, on their own: of the layout's closed seams around a tiny or thin segment (a plane
  // grazing a toe, loops of several planes crossing on a flipper), the shortest goes, and the segment joins its
  // neighbour across it.
  std::vector<int> removed;
  for (const SegmentationProblem& problem : sg.problems) {
    if (problem.segment < 0 || (problem.code != "segment.sliver" && problem.code != "segment.thin")) continue;
    int shortest = -1;
    for (const BoundaryLoop& loop : sg.segments[problem.segment].loops)
      for (int seam : loop.seams)
        if (seam >= fixedSeams && seam < int(seams.size()) && seams[seam].closed &&
            (shortest < 0 || scene.curves[seam].length < scene.curves[shortest].length))
          shortest = seam;
    if (shortest >= 0 && std::find(removed.begin(), removed.end(), shortest) == removed.end())
      removed.push_back(shortest);
  }
  if (!removed.empty()) {
    std::sort(removed.rbegin(), removed.rend());
    for (int seam : removed) seams.erase(seams.begin() + seam);
    opened.grazingLoops += int(removed.size());
    return int(removed.size());
  }
  for (const SegmentationProblem& problem : sg.problems) {
    if (problem.segment < 0) continue;
    const Segment& segment = sg.segments[problem.segment];
    if (problem.code == "segment.not-disk" && segment.genus == 0 && segment.loops.size() >= 2) {
      size_t outer = 0;
      for (size_t l = 1; l < segment.loops.size(); ++l)
        if (loopLength(cut, segment.loops[l]) > loopLength(cut, segment.loops[outer])) outer = l;
      for (size_t l = 0; l < segment.loops.size(); ++l) {
        if (l == outer) continue;
        int from = -1, to = -1;
        double best = INFINITY;
        for (size_t o = 0; o < segment.loops.size(); ++o) {
          if (o == l) continue;
          for (int a : segment.loops[l].vertices)
            for (int b : segment.loops[o].vertices)
              if (const double d = (cut.V.row(a) - cut.V.row(b)).squaredNorm(); d < best) best = d, from = a, to = b;
        }
        if (from < 0) continue;
        seams.push_back(makeSeam("a cut that opens a tube", false, {sg.vertexOrigin[from], sg.vertexOrigin[to]}));
        ++added, ++opened.tubeCuts;
      }
    } else if (problem.code == "segment.too-big-for-seam") {
      Eigen::Vector3d center = Eigen::Vector3d::Zero();
      Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
      double area = 0;
      for (int t : segment.triangles) {
        const Eigen::Vector3d a = cut.V.row(cut.F(t, 0)), b = cut.V.row(cut.F(t, 1)), c = cut.V.row(cut.F(t, 2));
        const double at = 0.5 * (b - a).cross(c - a).norm();
        const Eigen::Vector3d m = (a + b + c) / 3;
        center += at * m, second += at * m * m.transpose(), area += at;
      }
      if (!(area > 0)) continue;
      center /= area;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(second / area - center * center.transpose());
      // Across its longest extent first; a cap over two limbs has none there, and gets the planes across the others
      // (around each limb).
      for (int direction = 2; direction >= 0; --direction) {
        const Eigen::Vector3d normal = eig.eigenvectors().col(direction);
        int laid = 0;
        for (const SectionLoop& loop : planeSection(scene.target, normal, normal.dot(center))) {
          const bool inside = std::all_of(loop.begin(), loop.end(), [&](const SectionPoint& p) {
            const std::vector<int>& in = faceSegments[p.at.face];
            return std::find(in.begin(), in.end(), problem.segment) != in.end();
          });
          if (!inside) continue;
          seams.push_back(makeSeam("a seam around a limb", true, sectionSeamPoints(scene.target, loop, spacing)));
          ++laid;
        }
        if (laid > 0) {
          added += laid, opened.limbSeams += laid;
          break;
        }
      }
    }
  }
  return added;
}

// The share of the sheet the panels' cut pieces cover, nested as the cut file nests them (the default seam allowance
// and roll width; a roll just wide enough where a piece is wider).
double sheetUse(const Pattern& pattern) {
  ExportOptions cut;
  try {
    return layoutSheet(pattern, cut).nest.utilisation;
  } catch (const Error& e) {
    if (e.code != "export.sheet-too-narrow" || !(e.sheetWidth > cut.sheetWidth)) throw;
    cut.sheetWidth = e.sheetWidth;
    return layoutSheet(pattern, cut).nest.utilisation;
  }
}

// The optimizer's current shape as a card draws it: its outer triangles on their own vertices, each vertex's distance
// as the inflated pane colors it (signedDistances, as measureDistance gives the app) over the diagonal the
// optimizer's own figures are over.
LayoutBalloon balloonOf(const PatternOptimizer& optimizer, const DesignScene& scene) {
  const SewnMesh& mesh = optimizer.mesh();
  const Vertices& x = optimizer.inflated();
  LayoutBalloon b;
  std::vector<int> vertexOf(size_t(x.rows()), -1);
  b.triangles.resize(std::count(mesh.outer.begin(), mesh.outer.end(), 1), 3);
  int vertices = 0;
  for (int f = 0, row = 0; f < mesh.numTriangles(); ++f) {
    if (!mesh.outer[size_t(f)]) continue;
    for (int k = 0; k < 3; ++k) {
      int& v = vertexOf[size_t(mesh.triangles(f, k))];
      if (v < 0) v = vertices++;
      b.triangles(row, k) = v;
    }
    b.panel.push_back(mesh.trianglePanel[size_t(f)]);
    ++row;
  }
  b.positions.resize(vertices, 3);
  for (int i = 0; i < x.rows(); ++i)
    if (vertexOf[size_t(i)] >= 0) b.positions.row(vertexOf[size_t(i)]) = x.row(i);
  b.distance = signedDistances(scene.target, *scene.projector, b.positions) / optimizer.objective().modelSize();
  return b;
}

}  // namespace

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// evaluateLayout's first part: the seams traced and segmented, with those that open its segments into panels; ok
// when every segment is a panel. The scene keeps the segmentation for measureLayout.
LayoutEvaluation layLayout(DesignScene& scene, const std::vector<DesignSeam>& seams, int fixedSeams,
                           const EvaluateOptions& options) {
  LayoutEvaluation out;
  out.seams = seams;
  const double spacing = seamPointSpacing(scene.target);
  for (int round = 0;; ++round) {
    scene.design.seams = out.seams;
    try {
      traceDesignSeams(scene);
    } catch (const Error& e) {
      out.problem = e.what();
      return out;
    }
    segmentDesignScene(scene);
    if (scene.segmentation.problems.empty() || round == options.openingRounds ||
        openSegments(scene, spacing, fixedSeams, out.seams, out.opened) == 0)
      break;
  }
  const Segmentation& segmentation = scene.segmentation;
  if (!segmentation.problems.empty()) {
    out.problem = segmentation.problems.front().message;
    return out;
  }
  out.panels = int(segmentation.segments.size());
  for (const SeamCurve& curve : scene.curves) out.seamLength += curve.length;
  out.ok = true;
  return out;
}

// evaluateLayout's second part, on the scene layLayout left: the panels built, optimized and measured.
void measureLayout(DesignScene& scene, LayoutEvaluation& out, const EvaluateOptions& options) {
  out.ok = false;
  // A layout whose panels cannot be made or settled is not used, and says why (the pattern's own message: panels
  // sewn three to an edge where a cut meets a section, a fold).
  try {
    const BuiltPattern built = buildDesignPattern(scene, options.triangles);
    if (!built.ok()) {
      out.problem = built.problems.empty() ? "no panels" : built.problems.front().message;
      return;
    }
    OptimizeOptions oo = appStoppingRule();
    oo.stopping.maxIterations = options.maxIterations;
    // A first look (no iteration) measures the flattened panels' own inflation, not their cut.
    oo.remeshing.cutPanels = options.maxIterations > 0;
    PatternOptimizer optimizer(scene.target, built, designSeamWeights(scene.design), oo);
    while (optimizer.step(5) == OptimizeState::Running) {
    }
    if (optimizer.state() == OptimizeState::Failed || optimizer.history().empty()) {
      out.problem = optimizer.message();
      return;
    }
    const OptimizeRecord& last = optimizer.history().back();
    out.inflatedToTarget = last.distanceRms, out.targetToInflated = last.targetDistanceRms;
    out.distance = std::max(out.inflatedToTarget, out.targetToInflated);
    out.iterations = optimizer.iterations();
    out.pattern = optimizedPattern(optimizer);
    out.balloon = balloonOf(optimizer, scene);
    if (options.maxIterations > 0) out.sheetUse = sheetUse(out.pattern);
  } catch (const Error& e) {
    out.problem = e.what();
    return;
  }
  out.ok = true;
}

}  // namespace

LayoutEvaluation evaluateLayout(DesignScene& scene, const std::vector<DesignSeam>& seams, int fixedSeams,
                                const EvaluateOptions& options) {
  const Clock::time_point t0 = Clock::now();
  LayoutEvaluation out = layLayout(scene, seams, fixedSeams, options);
  if (out.ok) measureLayout(scene, out, options);
  out.ms = msSince(t0);
  return out;
}

namespace {

// The same lines on the surface, their names aside.
bool sameSeams(const std::vector<DesignSeam>& a, const std::vector<DesignSeam>& b) {
  const auto same = [](const DesignSeam& s, const DesignSeam& t) {
    return s.closed == t.closed && s.points.size() == t.points.size() &&
           std::equal(s.points.begin(), s.points.end(), t.points.begin(),
                      [](const DesignPoint& p, const DesignPoint& q) {
                        return p.onSurface == q.onSurface && p.surface.face == q.surface.face &&
                               p.surface.bary == q.surface.bary && p.position == q.position;
                      });
  };
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), same);
}

}  // namespace

double lookPromise(const LayoutEvaluation& look) { return look.targetToInflated; }

std::string layoutFamily(const LayoutProposal& p) {
  // Two gores are halves, whose plane names them; more are gores around the axis, turned or not.
  Eigen::Index halving = -1;
  if (p.outlineView < 0 && p.gores == 2 && !p.planes.empty()) p.planes[0].normal.cwiseAbs().maxCoeff(&halving);
  return std::to_string(p.outlineView) + " " + std::to_string(p.axis) + " " + std::to_string(p.bands > 0) + " " +
         std::to_string(p.gores > 2) + " " + std::to_string(halving);
}

std::vector<int> looksToOptimize(const std::vector<const LayoutEvaluation*>& looks,
                                 const std::vector<std::string>& families, int count, int ofOneFamily) {
  std::vector<int> order;
  for (int i = 0; i < int(looks.size()); ++i)
    if (looks[i]->ok) order.push_back(i);
  // The seam length (sewing time) breaks ties, then the order they were proposed in, as in the app.
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return lookPromise(*looks[a]) != lookPromise(*looks[b]) ? lookPromise(*looks[a]) < lookPromise(*looks[b])
                                                            : looks[a]->seamLength < looks[b]->seamLength;
  });
  std::vector<int> chosen;
  std::map<std::string, int> taken;
  for (int i : order)
    if (int(chosen.size()) < count && ++taken[families[i]] <= ofOneFamily) chosen.push_back(i);
  return chosen;
}

LayoutEvaluation lookAtLayout(DesignScene& scene, const LayoutProposal& proposal, const std::vector<DesignSeam>& kept,
                              int panelsAtMost, const std::vector<std::vector<DesignSeam>>& looked,
                              EvaluateOptions options) {
  options.maxIterations = 0;
  const Clock::time_point t0 = Clock::now();
  LayoutEvaluation look;
  try {
    std::vector<DesignSeam> seams = kept;
    const std::vector<DesignSeam> laid = proposalSeams(scene.target, proposal);
    seams.insert(seams.end(), laid.begin(), laid.end());
    look = layLayout(scene, seams, int(kept.size()), options);
  } catch (const Error& e) {
    look.problem = e.what();
  }
  // Refused before its panels are built and inflated: half the looks at 24 panels make too many.
  if (look.ok && look.panels > panelsAtMost)
    look.ok = false, look.problem = "it makes " + std::to_string(look.panels) + " panels on this shape";
  if (look.ok && std::any_of(looked.begin(), looked.end(),
                             [&](const std::vector<DesignSeam>& seams) { return sameSeams(seams, look.seams); }))
    look.ok = false, look.problem = "it ends with the same seams as a layout before it";
  if (look.ok) measureLayout(scene, look, options);
  look.ms = msSince(t0);
  return look;
}

}  // namespace billow
