#include "suggest/seam_layouts.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

#include "export/layout.hpp"
#include "mesh/simplify.hpp"
#include "optimize/optimized_pattern.hpp"
#include "optimize/pattern_optimizer.hpp"
#include "optimize/stopping_rule.hpp"
#include "seams/mesh_topology.hpp"
#include "seams/outline.hpp"
#include "seams/plane_section.hpp"
#include "seams/surface_distance.hpp"
#include "suggest/segment_cuts.hpp"
#include "util/clock.hpp"
#include "util/error.hpp"

namespace billow {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Control points of a proposed seam, as the section tool spaces them (web/src/app/section.js SECTION_SPACING).
constexpr double kSeamPointSpacing = 0.02;
constexpr int kMostGores = 24, kMostBands = 12;
// Two pieces sewn around an outline puff up to about this share of its width (the Mylar balloon: 1.2 x its rim's
// radius, bench/README.md "The Mylar balloon against Paulsen"), and an internal connection can only pull them
// together: layouts held together inside are laid only along a view the target is thinner than that along.
constexpr double kPillowThickness = 0.6;

// A piece of a loop (its points in order) without the points at either end within `clearance` of its end points `from`
// and `to`, so no control point crowds them: still a run of neighbours on the loop, as sectionPathPoints needs. (Points
// left out in its middle, where the loop comes back near an end, joined two points that share no face: a control point
// off the surface, whose seams the app's workers then refused to read.)
SectionLoop withoutEnds(const SectionLoop& piece, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                        double clearance) {
  const auto nearEnd = [&](const SectionPoint& p) {
    return (p.position - from).norm() < clearance || (p.position - to).norm() < clearance;
  };
  size_t first = 0, last = piece.size();
  while (first < last && nearEnd(piece[first])) ++first;
  while (last > first && nearEnd(piece[last - 1])) --last;
  return SectionLoop(piece.begin() + long(first), piece.begin() + long(last));
}

// A layout is laid for as few as half the panels asked for (four fewer at small counts): a limb cut on its own, or
// opened, adds panels on most shapes (the penguin's 4 bands in two pieces along its outline make 12, not 8). A look
// that makes more than asked for is refused before it is built (lookAtLayout).
int fewestPanels(int asked) { return asked - std::max(4, asked / 2); }

// A limb a flat panel inside its root seam would cover less than this share of (P^2 / (4 pi A), as the segmentation's
// too-big-for-its-seam warning measures it at half this) is halved along its length.
constexpr double kLimbFlatShare = 0.5;
bool limbHalved(const Limb& limb) { return limb.girth * limb.girth / (4 * kPi * limb.area) < kLimbFlatShare; }

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

// A front and a back sealed along the outline seen along the target's own axis `view`.
std::string outlineName(int view, const UpAxis& up) {
  static const char* from[] = {"from the side", "from above", "from the front"};
  return std::string("along the outline seen ") + from[viewAxis(Eigen::Vector3d::Unit(view), up)];
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

// The target's own axis it is thinnest along (a cushion's or a letter's depth).
Eigen::Index thinnestAxis(const TriMesh& target) {
  Eigen::Index axis = 0;
  (target.V.colwise().maxCoeff() - target.V.colwise().minCoeff()).minCoeff(&axis);
  return axis;
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
  if (proposal.outlineView >= 0) key.push_back({2, proposal.outlineView, proposal.connected, 0, 0});
  if (!proposal.limbs.empty()) key.push_back({3, (long long)proposal.limbs.size(), 0, 0, 0});
  if (!proposal.creases.empty()) key.push_back({4, (long long)proposal.creases.size(), proposal.connected, 0, 0});
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

std::string LayoutEvaluation::description() const {
  std::string out;
  const auto add = [&](int n, const char* one, const char* many) {
    if (n == 0) return;
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + (n == 1 ? one : many);
  };
  add(opened.tubeCuts, "cut that opens a tube", "cuts that open tubes");
  add(opened.limbSeams, "seam around a limb", "seams around limbs");
  add(opened.limbEndCuts, "cut along a limb's end", "cuts along limbs' ends");
  add(opened.handleSeams, "seam around a handle", "seams around handles");
  add(opened.acrossCuts, "cut across a panel that would overlap itself when laid flat",
      "cuts across panels that would overlap themselves when laid flat");
  add(opened.grazingLoops, "loop left out where it only grazed the shape",
      "loops left out where they only grazed the shape");
  add(opened.crossingLoops, "loop left out that crossed itself", "loops left out that crossed themselves");
  add(int(connections.size()), "internal connection joining a band seam's front and back pieces inside",
      "internal connections joining the band seams' front and back pieces inside");
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
  // A proposal is kept unless one before it lays the same planes (two families can make one layout).
  const auto offer = [&](LayoutProposal p) {
    ProposalKey key = proposalKey(p, size);
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) return;
    seen.push_back(std::move(key));
    out.push_back(std::move(p));
  };
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
          const std::string across = axisName(axis, request.up);
          if (k == 0)
            p.name = g == 2 ? halvesName(p.planes[0].normal, request.up)
                            : std::to_string(g) + " gores around the " + across + (turn ? ", turned" : "");
          else
            p.name = std::to_string(k + 1) + " bands across the " + across +
                     (g == 2 ? ", in " + halvesName(p.planes[0].normal, request.up)
                             : ", each in " + std::to_string(g) + " gores" + (turn ? " (turned)" : ""));
          offer(std::move(p));
        }
      }
  }
  // A front and a back along the outline seen along `view`, and k bands across another axis, each in two pieces.
  // Seen along any axis the outline is its own mirror image across the symmetry plane: seen across it (an animal from
  // its side, as a foil balloon is cut), the front and the back are each other's. The two pieces alone at any count:
  // where limbs leave every plane a tube to open (an octopus's coiled arms), the outline may be the one layout that
  // makes panels.
  const Eigen::Vector3d extent = hi - lo;
  // Thin along a view: a pillow sewn round it would puff up past the target (kPillowThickness).
  const auto thinAlong = [&](Eigen::Index view) {
    return extent[view] < kPillowThickness * std::min(extent[(view + 1) % 3], extent[(view + 2) % 3]);
  };
  for (int view = 0; view < 3; ++view) {
    const bool thin = thinAlong(view);
    const std::string outline = outlineName(view, request.up);
    for (int axis = 0; axis < 3; ++axis) {
      if (axis == view || axis == s) continue;
      const AreaAlong along = areaAlong(faces, axis);
      for (int k = 0; k <= kMostBands; ++k)
        for (int connected = 0; connected < (k > 0 && thin ? 2 : 1); ++connected) {
          // Each band seam's connection is an internal panel to cut too.
          const int panels = 2 * (k + 1) + connected * k;
          if (panels > request.panels || (k > 0 && panels < fewestPanels(request.panels))) continue;
          LayoutProposal p;
          p.axis = axis, p.gores = 2, p.bands = k, p.center = center, p.outlineView = view, p.connected = connected;
          for (int j = 1; j <= k; ++j) p.planes.push_back({Eigen::Vector3d::Unit(axis), along.at(double(j) / (k + 1))});
          p.name = k == 0 ? "front and back, sealed " + outline
                          : std::to_string(k + 1) + " bands across the " + axisName(axis, request.up) +
                                ", each in two pieces " + outline;
          if (connected) p.name += ", held together inside";
          offer(std::move(p));
        }
    }
  }
  // Bands parted at the target's valleys across an axis (its neck, its waist), as a pattern maker chalks them: the
  // deepest valley, and as many of the deepest as the count leaves room for; in halves, or each in two pieces along the
  // outline seen across the axis.
  for (int axis = 0; axis < 3; ++axis) {
    if (axis == s) continue;
    const std::vector<Valley> valleys = findValleys(target, axis);
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
    for (size_t m = 1; m <= std::min(valleys.size(), size_t(kMostBands)); ++m) {
      if (m > 1 && m < std::min(valleys.size(), size_t(request.panels / 2 - 1))) continue;
      const int panels = 2 * int(m + 1);
      if (panels > request.panels) break;
      if (panels < fewestPanels(request.panels)) continue;
      std::vector<double> levels;
      for (size_t j = 0; j < m; ++j) levels.push_back(valleys[j].level);
      std::sort(levels.begin(), levels.end());
      const std::string bands =
          std::to_string(m + 1) + " bands across the " + axisName(axis, request.up) + ", parted where it narrows";
      for (int other = 0; other < 3; ++other) {
        if (other == axis) continue;
        for (int outline = 0; outline < 2; ++outline) {
          LayoutProposal p;
          p.axis = axis, p.gores = 2, p.bands = int(m), p.center = center, p.atValleys = true;
          if (outline) {
            p.outlineView = other;
          } else {
            const Eigen::Vector3d normal = Eigen::Vector3d::Unit(other);
            p.planes.push_back({normal, normal.dot(center)});
          }
          for (double level : levels) p.planes.push_back({e, level});
          p.name = bands + (outline ? ", each in two pieces " + outlineName(other, request.up)
                                    : ", in " + halvesName(p.planes[0].normal, request.up));
          offer(std::move(p));
        }
      }
    }
  }
  // Seams around limbs where they join the body, as a plush toy is patterned: each limb halved along its length where
  // a flat panel inside its root seam would not cover it well, the body in two halves by a plane through its middle.
  // The most elongated limbs that fit the count. Where the symmetry is kept, limbs in mirror pairs (or on the plane, on
  // their own), and the body halved by planes that are their own mirror images.
  {
    std::vector<std::vector<Limb>> groups;
    if (s >= 0)
      groups = mirrorSymmetricLimbs(target, findLimbs(target), s, center[s]);
    else
      for (Limb& limb : findLimbs(target)) groups.push_back({std::move(limb)});
    std::vector<char> body(size_t(target.F.rows()), 1);
    for (const std::vector<Limb>& group : groups)
      for (const Limb& limb : group)
        for (int f = 0; f < target.F.rows(); ++f)
          if (limb.faces[size_t(f)] == 1) body[size_t(f)] = 0;
    Eigen::Vector3d bodyCenter = Eigen::Vector3d::Zero();
    double bodyArea = 0;
    for (int f = 0; f < target.F.rows(); ++f)
      if (body[size_t(f)]) bodyCenter += faces.area[f] * faces.centroid.row(f).transpose(), bodyArea += faces.area[f];
    if (bodyArea > 0) bodyCenter /= bodyArea;
    if (s >= 0) bodyCenter[s] = center[s];
    Faces bodyFaces;
    {
      std::vector<int> kept;
      for (int f = 0; f < target.F.rows(); ++f)
        if (body[size_t(f)]) kept.push_back(f);
      bodyFaces.centroid.resize(Eigen::Index(kept.size()), 3), bodyFaces.area.resize(Eigen::Index(kept.size()));
      for (size_t i = 0; i < kept.size(); ++i)
        bodyFaces.centroid.row(Eigen::Index(i)) = faces.centroid.row(kept[i]),
        bodyFaces.area[Eigen::Index(i)] = faces.area[kept[i]];
    }
    for (size_t count = groups.size(); count >= 1; --count) {
      std::vector<Limb> limbs;
      for (size_t g = 0; g < count; ++g) limbs.insert(limbs.end(), groups[g].begin(), groups[g].end());
      int limbPanels = 0;
      for (const Limb& limb : limbs) limbPanels += limbHalved(limb) ? 2 : 1;
      if (limbPanels + 2 > request.panels) continue;
      const int halved = int(std::count_if(limbs.begin(), limbs.end(), limbHalved));
      const std::string around =
          "seams around " + std::to_string(limbs.size()) + (limbs.size() == 1 ? " limb" : " limbs") +
          (halved == 0                        ? ""
           : halved == 1 && limbs.size() == 1 ? ", halved along its length"
           : halved == int(limbs.size())      ? ", each halved along its length"
                                              : ", " + std::to_string(halved) + " halved along their length");
      // The body in halves, or in a front and a back along its outline seen along an axis (a plush fish's sides, a
      // mushroom's cap top and underside), and in as many bands across another axis as the count leaves room for, each
      // in two.
      for (int outline = 0; outline < 2; ++outline)
        for (int axis = 0; axis < 3; ++axis)
          for (int across = -1; across < 3; ++across) {
            if (across == axis || (across >= 0 && across == s)) continue;
            const int bands = across < 0 ? 0 : (request.panels - limbPanels) / 2 - 1;
            if ((across >= 0 && bands < 1) || limbPanels + 2 * (bands + 1) < fewestPanels(request.panels)) continue;
            LayoutProposal p;
            p.axis = across < 0 ? axis : across, p.gores = 2, p.bands = bands, p.center = bodyCenter, p.limbs = limbs;
            if (outline)
              p.outlineView = axis;
            else
              p.planes.push_back({Eigen::Vector3d::Unit(axis), bodyCenter[axis]});
            if (bands > 0) {
              const AreaAlong along = areaAlong(bodyFaces, across);
              for (int j = 1; j <= bands; ++j)
                p.planes.push_back({Eigen::Vector3d::Unit(across), along.at(double(j) / (bands + 1))});
            }
            const std::string bandsAcross =
                bands > 0 ? std::to_string(bands + 1) + " bands across the " + axisName(across, request.up) : "";
            p.name = around + ", the body in " +
                     (outline ? (bands > 0 ? bandsAcross + ", each in two pieces " : "two pieces ") +
                                    outlineName(axis, request.up)
                              : (bands > 0 ? bandsAcross + ", in " : "") + halvesName(p.planes[0].normal, request.up));
            offer(std::move(p));
          }
      break;  // the most limbs that fit: fewer would leave long limbs to the body's halves
    }
  }
  // Seams along the creases, as a cushion or a gusseted letter is patterned: the most that fit the count (where the
  // symmetry is kept, that are their own mirror image), alone and with each part halved by a plane through the middle
  // where the count leaves room for that.
  {
    const std::vector<Creases> sets = s >= 0 ? findCreases(target, s, center[s]) : findCreases(target);
    // The sets a layout may use: where the symmetry is kept, those that are their own mirror image.
    std::vector<char> usable(sets.size(), 1);
    if (s >= 0)
      for (size_t i = 0; i < sets.size(); ++i)
        usable[i] = mirrorSymmetric(target, sets[i].creases, s, center[s], seamPointSpacing(target));
    const auto alongName = [&](const Creases& set) {
      const size_t n = set.creases.size(), all = sets.front().creases.size();
      return n == all ? "along its " + std::to_string(n) + (n == 1 ? " crease" : " creases")
                      : "along " + std::to_string(n) + " of its " + std::to_string(all) + " creases";
    };
    for (size_t i = 0; i < sets.size(); ++i) {
      const Creases& set = sets[i];
      if (set.panels > request.panels || !usable[i]) continue;
      const std::string along = alongName(set);
      for (int axis = -1; axis < 3; ++axis) {
        if (axis >= 0 && 2 * set.panels > request.panels) break;
        LayoutProposal p;
        p.axis = std::max(axis, 0), p.gores = 2, p.center = center, p.creases = set.creases;
        if (axis >= 0) p.planes.push_back({Eigen::Vector3d::Unit(axis), center[axis]});
        p.name = along + (axis >= 0 ? ", each part in " + halvesName(p.planes[0].normal, request.up) : "");
        offer(std::move(p));
      }
      break;
    }
    // On a thin shape (a cushion, a letter), held together inside: its front, its back and the strip between them (the
    // fewest creases that still make three panels or more) and k bands across another axis, each loop's piece on the
    // front side and its piece on the back joined by an internal connection (two more panels and a connection a band).
    const Eigen::Index view = thinnestAxis(target);
    size_t held = sets.size();
    for (size_t i = sets.size(); i-- > 0 && held == sets.size();)
      if (sets[i].panels >= 3 && usable[i]) held = i;
    if (held < sets.size() && thinAlong(view))
      for (int axis = 0; axis < 3; ++axis) {
        if (axis == view || axis == s) continue;
        const AreaAlong bandsAlong = areaAlong(faces, axis);
        for (int k = 1; k <= kMostBands && sets[held].panels + 3 * k <= request.panels; ++k) {
          if (sets[held].panels + 3 * k < fewestPanels(request.panels)) continue;
          LayoutProposal p;
          p.axis = axis, p.gores = 2, p.bands = k, p.center = center, p.creases = sets[held].creases,
          p.connected = true;
          for (int j = 1; j <= k; ++j)
            p.planes.push_back({Eigen::Vector3d::Unit(axis), bandsAlong.at(double(j) / (k + 1))});
          p.name = alongName(sets[held]) + ", held together inside along " + std::to_string(k) +
                   (k == 1 ? " band" : " bands") + " across the " + axisName(axis, request.up);
          offer(std::move(p));
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

// Where a loop crosses a plane: on the straight piece between two of its points (in the face the later one names),
// with the index of the earlier.
struct LoopCrossing {
  SectionPoint point;
  size_t after = 0;
};

std::vector<LoopCrossing> planeCrossings(const TriMesh& mesh, const SectionLoop& loop, const SectionPlane& plane) {
  std::vector<LoopCrossing> out;
  for (size_t i = 0; i < loop.size(); ++i) {
    const SectionPoint& a = loop[i];
    const SectionPoint& b = loop[(i + 1) % loop.size()];
    const double sa = a.position.dot(plane.normal) - plane.offset, sb = b.position.dot(plane.normal) - plane.offset;
    if ((sa < 0) == (sb < 0)) continue;
    LoopCrossing c;
    c.after = i;
    c.point.position = a.position + sa / (sa - sb) * (b.position - a.position);
    const int f = b.at.face;
    c.point.at.face = f;
    c.point.at.bary = closestPointBarycentric(c.point.position, mesh.V.row(mesh.F(f, 0)), mesh.V.row(mesh.F(f, 1)),
                                              mesh.V.row(mesh.F(f, 2)));
    out.push_back(c);
  }
  return out;
}

// Makes `point` one of a seam's control points: in place of one within `near`, else between the two it lies between
// (the least detour), so that seams meeting it there meet it exactly. With `met`, the points earlier calls made control
// points, which are never replaced; this one is added to them. An open seam's ends stay its ends.
void passThrough(const TriMesh& mesh, std::vector<SurfacePoint>& controls, const SectionPoint& point, double near,
                 std::vector<Eigen::Vector3d>* met = nullptr, bool closed = true) {
  size_t best = 0;
  double detour = INFINITY;
  for (size_t j = 0; j + (closed ? 0 : 1) < controls.size(); ++j) {
    const Eigen::Vector3d a = position(mesh, controls[j]), b = position(mesh, controls[(j + 1) % controls.size()]);
    const bool kept = met && std::any_of(met->begin(), met->end(),
                                         [&](const Eigen::Vector3d& m) { return (m - a).norm() < 1e-9 * near; });
    if (!kept && (closed || j > 0) && (a - point.position).norm() < near) {
      controls[j] = point.at;
      if (met) met->push_back(point.position);
      return;
    }
    if (const double d = (a - point.position).norm() + (point.position - b).norm() - (a - b).norm(); d < detour)
      detour = d, best = j;
  }
  controls.insert(controls.begin() + long(best) + 1, point.at);
  if (met) met->push_back(point.position);
}

// A limbs proposal's seams: around each limb's root, the body's halving plane on the body, each halved limb's plane
// along it on that limb; a plane's piece on a part ends where it crosses the root seam, which passes through there.
std::vector<DesignSeam> limbSeams(const TriMesh& target, const LayoutProposal& proposal, double spacing) {
  const std::vector<Limb>& limbs = proposal.limbs;
  std::vector<std::vector<SurfacePoint>> rims;
  for (const Limb& limb : limbs) rims.push_back(sectionSeamPoints(target, limb.rootLoop, spacing));
  // Where pieces meet each rim: each a control point of it, none moved by a later one that lies close.
  std::vector<std::vector<Eigen::Vector3d>> meetings(limbs.size());
  const auto meet = [&](size_t limb, const SectionPoint& x) {
    passThrough(target, rims[limb], x, 0.25 * spacing, &meetings[limb]);
  };
  // The limb a loop point lies on, -1 on the body.
  const auto partOf = [&](const SectionPoint& p) {
    for (size_t i = 0; i < limbs.size(); ++i)
      if (onLimb(target, limbs[i], p.at.face, p.position)) return int(i);
    return -1;
  };
  std::vector<DesignSeam> pieces;
  // A seam along a limb that runs round its tip, with where it meets the root seam (none for a loop on the limb alone).
  struct AlongLimb {
    DesignSeam seam;
    double length = 0;
    std::optional<SectionPoint> from, to;
  };
  std::vector<AlongLimb> alongLimb;
  // The pieces of `loop` on `part`: each from where it crosses into the part to where it crosses out. On the body each
  // is laid; on a limb, the one that runs round its tip goes to `alongLimb`, and says whether there was one. With
  // `corners`, the loop's sharp turns are kept (an outline's, as the Outline tool keeps them: a seam that skipped one
  // would cut a tip off).
  const auto layPieces = [&](const SectionLoop& loop, int part, const std::string& name, bool corners = false) {
    const size_t n = loop.size();
    std::vector<int> on(n);
    for (size_t k = 0; k < n; ++k) on[k] = partOf(loop[k]);
    const size_t inside = size_t(std::count(on.begin(), on.end(), part));
    if (inside == 0) return false;
    if (inside == n) {
      // The body's own loop; on a limb, one along it round its tip, where the limb leaves the plane before its root (a
      // tentacle rising from the body; a cut from it to the root seam opens what lies between: openSegments), not one
      // across it.
      const auto nearTip = [&](const SectionPoint& p) {
        return (p.position - target.V.row(limbs[size_t(part)].tip).transpose()).norm() < limbs[size_t(part)].girth / 4;
      };
      if (part < 0) {
        pieces.push_back(makeSeam(name, true, sectionSeamPoints(target, loop, spacing, corners)));
        return true;
      }
      if (!std::any_of(loop.begin(), loop.end(), nearTip)) return false;
      alongLimb.push_back({makeSeam(name, true, sectionSeamPoints(target, loop, spacing, corners)), loopLength(loop),
                           std::nullopt, std::nullopt});
      return true;
    }
    // Where the loop crosses the root seam between points k and k + 1: where the level of the limb on either side is
    // zero, on the straight piece between them in the face the later one names (the level is linear there).
    const auto crossing = [&](size_t k, int limb) {
      const SectionPoint& a = loop[k];
      const SectionPoint& b = loop[(k + 1) % n];
      const int f = b.at.face;
      const double sa = limbLevel(target, limbs[size_t(limb)], f, a.position),
                   sb = limbLevel(target, limbs[size_t(limb)], f, b.position);
      SectionPoint x;
      x.position =
          (sa < 0) == (sb < 0) ? b.position : Eigen::Vector3d(a.position + sa / (sa - sb) * (b.position - a.position));
      x.at.face = f;
      x.at.bary = closestPointBarycentric(x.position, target.V.row(target.F(f, 0)), target.V.row(target.F(f, 1)),
                                          target.V.row(target.F(f, 2)));
      return x;
    };
    size_t start = 0;
    while (!(on[start] != part && on[(start + 1) % n] == part)) ++start;  // a step into the part
    // On a limb, the one piece that runs round its tip: others only nick its root.
    double nearestTip = INFINITY;
    std::optional<AlongLimb> roundTip;
    for (size_t step = 0; step < n; ++step) {
      const size_t k = (start + step) % n;
      if (!(on[k] != part && on[(k + 1) % n] == part)) continue;
      const int entered = part >= 0 ? part : on[k];
      SectionLoop path;
      size_t j = (k + 1) % n;
      for (; on[j] == part; j = (j + 1) % n) path.push_back(loop[j]);
      const size_t last = (j + n - 1) % n;
      const int left = part >= 0 ? part : on[j];
      const SectionPoint from = crossing(k, entered), to = crossing(last, left);
      if (loopLength(path) + (path.front().position - from.position).norm() < 2 * spacing) continue;  // a nick
      // Without its points at either end that lie within half a spacing of a root seam: where the piece meets one at a
      // glancing angle, the shortest paths between points closer than that would wander across it and cut a sliver off.
      // (Only at the ends: the points left must follow each other along the loop, each in the face of the one before.)
      const auto clear = [&](const SectionPoint& p) {
        return std::all_of(limbs.begin(), limbs.end(), [&](const Limb& limb) {
          return std::abs(limbLevel(target, limb, p.at.face, p.position)) >= 0.5 * spacing;
        });
      };
      size_t first = 0, end = path.size();
      while (first < end && !clear(path[first])) ++first;
      while (end > first && !clear(path[end - 1])) --end;
      const SectionLoop inner(path.begin() + long(first), path.begin() + long(end));
      std::vector<SurfacePoint> controls{from.at};
      if (inner.size() >= 2)
        for (const SurfacePoint& p : sectionPathPoints(target, inner, spacing, corners)) controls.push_back(p);
      controls.push_back(to.at);
      if (part < 0) {
        pieces.push_back(makeSeam(name, false, controls));
        meet(size_t(entered), from), meet(size_t(left), to);
        continue;
      }
      const Eigen::Vector3d tip = target.V.row(limbs[size_t(part)].tip);
      double nearest = INFINITY;
      for (const SectionPoint& p : path) nearest = std::min(nearest, (p.position - tip).norm());
      if (nearest < nearestTip)
        nearestTip = nearest, roundTip = AlongLimb{makeSeam(name, false, controls), loopLength(path), from, to};
    }
    if (roundTip && nearestTip < limbs[size_t(part)].girth / 4) {
      alongLimb.push_back(std::move(*roundTip));
      return true;
    }
    return part < 0;
  };
  const bool halving = proposal.outlineView < 0;
  if (!halving) {
    // The whole target's outline, laid on the body only: where a limb stands out of it, its pieces end at the root.
    const Eigen::Vector3d towards = Eigen::Vector3d::Unit(proposal.outlineView);
    const std::optional<Outline> outline = outlineSeenFrom(target, towards);
    if (!outline) throw Error("suggest.no-outline", "the shape shows no outline from there");
    layPieces(outline->loop, -1, "outline", true);
    // Seen through a handle, the front and back are rings: each hole's rim, and two sections across each ring, as the
    // outline layout cuts them open, on the body only.
    const std::vector<SectionLoop> across = acrossHandles(target, outline->loop, outline->holes, towards);
    for (const SectionLoop& hole : outline->holes) layPieces(hole, -1, "hole in the outline", true);
    for (const SectionLoop& loop : across) layPieces(loop, -1, "across a ring");
  }
  for (size_t j = 0; j < proposal.planes.size(); ++j)
    for (const SectionLoop& loop : planeSection(target, proposal.planes[j].normal, proposal.planes[j].offset))
      layPieces(loop, -1, halving && j == 0 ? std::string("halving seam") : "band " + std::to_string(j + !halving));
  // A limb is halved along its outline seen across its flattest direction (where the surface turns edge-on to that
  // view), which follows a tentacle's curl to its root where a plane would leave it.
  Eigen::MatrixX3d normals = Eigen::MatrixX3d::Zero(target.V.rows(), 3);
  for (int f = 0; f < target.F.rows(); ++f) {
    const Eigen::Vector3d a = target.V.row(target.F(f, 0)), b = target.V.row(target.F(f, 1)),
                          c = target.V.row(target.F(f, 2));
    const Eigen::RowVector3d area = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k) normals.row(target.F(f, k)) += area;
  }
  normals.rowwise().normalize();
  // Where that outline does not run round the tip (a limb twisted along its length), the outline seen across, then the
  // sections by planes through its middle along either.
  for (size_t i = 0; i < limbs.size(); ++i) {
    if (!limbHalved(limbs[i])) continue;
    const Limb& limb = limbs[i];
    bool laid = false;
    for (int kind = 0; kind < 4 && !laid; ++kind) {
      const Eigen::Vector3d n = kind % 2 == 0 ? limb.along.normal : limb.across;
      std::vector<SectionLoop> loops;
      if (kind < 2) {
        Eigen::VectorXd facing = normals * n;
        for (Eigen::Index v = 0; v < facing.size(); ++v)
          if (facing[v] == 0) facing[v] = 1e-12;
        loops = zeroLoops(target, facing);
      } else {
        loops = planeSection(target, n, n.dot(limb.center));
      }
      alongLimb.clear();
      for (const SectionLoop& loop : loops) laid |= layPieces(loop, int(i), "along limb " + std::to_string(i + 1));
      if (!laid) continue;
      // Of the seams that run round the tip, the longest, which runs the limb's length: another is a loop round a bump
      // near the tip (an ear on a head), which would cut a panel of its own off.
      const AlongLimb& longest =
          *std::max_element(alongLimb.begin(), alongLimb.end(),
                            [](const AlongLimb& a, const AlongLimb& b) { return a.length < b.length; });
      pieces.push_back(longest.seam);
      if (longest.from) meet(i, *longest.from), meet(i, *longest.to);
    }
  }
  std::vector<DesignSeam> seams;
  for (size_t i = 0; i < limbs.size(); ++i)
    seams.push_back(makeSeam("around limb " + std::to_string(i + 1), true, rims[i]));
  seams.insert(seams.end(), pieces.begin(), pieces.end());
  return seams;
}

// A creases proposal's seams: each crease, a loop closed or a chain from junction to junction (its ends there the very
// same surface points as the other chains'), then the loops of its planes; or, held together inside (a thin shape: a
// cushion, a letter), each plane loop's piece on the front side and its piece on the back, each from crease to crease,
// joined by an internal connection (to `connections`), the creases passing through where they meet.
std::vector<DesignSeam> creaseSeams(const TriMesh& target, const LayoutProposal& proposal, double spacing,
                                    std::vector<DesignConnection>* connections) {
  const MeshTopology topo = buildTopology(target);
  const std::vector<Crease>& creases = proposal.creases;
  std::vector<std::vector<SurfacePoint>> along(creases.size());
  std::vector<bool> closed(creases.size());
  for (size_t i = 0; i < creases.size(); ++i) {
    const Crease& crease = creases[i];
    const SectionLoop path = creasePath(target, topo, crease);
    // A chain from a junction round to the same junction (a star prism's outline where one crease crosses its side) is
    // a loop through that point: its first control point.
    const bool round = !crease.closed && crease.vertices.front() == crease.vertices.back();
    closed[i] = crease.closed || round;
    if (closed[i]) {
      along[i] = sectionSeamPoints(target, path, spacing, true);
      if (round) along[i].front() = vertexPoint(target, topo, crease.vertices.front());
    } else {
      along[i] = sectionPathPoints(target, path, spacing, true);
      along[i].front() = vertexPoint(target, topo, crease.vertices.front());
      along[i].back() = vertexPoint(target, topo, crease.vertices.back());
    }
  }
  std::vector<DesignSeam> pieces;
  std::vector<DesignConnection> joined;  // between pieces
  if (!proposal.connected) {
    for (const SectionPlane& plane : proposal.planes)
      for (const SectionLoop& loop : planeSection(target, plane.normal, plane.offset))
        pieces.push_back(makeSeam("halving seam", true, sectionSeamPoints(target, loop, spacing)));
  } else {
    const Eigen::Index view = thinnestAxis(target);
    std::vector<int> creaseOf(size_t(topo.numEdges()), -1);
    for (size_t i = 0; i < creases.size(); ++i)
      for (int e : creaseEdges(topo, creases[i])) creaseOf[size_t(e)] = int(i);
    // A loop through its junction keeps that point (the other creases end there); an open crease keeps its ends anyway.
    std::vector<std::vector<Eigen::Vector3d>> met(creases.size());
    for (size_t i = 0; i < creases.size(); ++i)
      if (closed[i] && !creases[i].closed) met[i].push_back(target.V.row(creases[i].vertices.front()).transpose());
    for (size_t j = 0; j < proposal.planes.size(); ++j)
      for (const SectionLoop& loop : planeSection(target, proposal.planes[j].normal, proposal.planes[j].offset)) {
        const size_t n = loop.size();
        // Where the loop crosses a crease: its points on a crease's edges.
        std::vector<size_t> at;
        std::vector<int> crease;
        for (size_t k = 0; k < n; ++k) {
          const SurfaceLocation l = locate(target, topo, loop[k].at);
          if (l.kind == SurfaceLocation::Edge && creaseOf[size_t(l.edge)] >= 0)
            at.push_back(k), crease.push_back(creaseOf[size_t(l.edge)]);
        }
        if (at.size() < 2) continue;
        // The pieces between them on the front side (facing along the view) and on the back.
        struct Piece {
          size_t from, to;  // indices into `at`
          SectionLoop inner;
        };
        std::vector<Piece> front, back;
        for (size_t c = 0; c < at.size(); ++c) {
          Piece piece{c, (c + 1) % at.size(), {}};
          double facing = 0;
          int count = 0;
          for (size_t k = (at[c] + 1) % n; k != at[piece.to]; k = (k + 1) % n, ++count) {
            const int f = loop[k].at.face;
            const Eigen::Vector3d a = target.V.row(target.F(f, 0)), b = target.V.row(target.F(f, 1)),
                                  e = target.V.row(target.F(f, 2));
            facing += (b - a).cross(e - a).normalized()[view];
            piece.inner.push_back(loop[k]);
          }
          piece.inner = withoutEnds(piece.inner, loop[at[c]].position, loop[at[piece.to]].position, 0.25 * spacing);
          if (count == 0) continue;
          if (facing > 0.7 * count) front.push_back(piece);
          if (facing < -0.7 * count) back.push_back(piece);
        }
        if (front.size() != 1 || back.size() != 1) continue;
        joined.push_back({{int(pieces.size()), int(pieces.size()) + 1}});
        for (const Piece* piece : {&front[0], &back[0]}) {
          std::vector<SurfacePoint> controls{loop[at[piece->from]].at};
          if (piece->inner.size() >= 2)
            for (const SurfacePoint& p : sectionPathPoints(target, piece->inner, spacing)) controls.push_back(p);
          controls.push_back(loop[at[piece->to]].at);
          pieces.push_back(
              makeSeam("band " + std::to_string(j + 1) + (piece == &front[0] ? ", front" : ", back"), false, controls));
          for (size_t end : {piece->from, piece->to}) {
            const size_t i = size_t(crease[end]);
            passThrough(target, along[i], loop[at[end]], 0.25 * spacing, &met[i], closed[i]);
          }
        }
      }
  }
  std::vector<DesignSeam> seams;
  for (size_t i = 0; i < creases.size(); ++i)
    seams.push_back(makeSeam("crease " + std::to_string(i + 1), closed[i], along[i]));
  seams.insert(seams.end(), pieces.begin(), pieces.end());
  if (connections)
    for (const DesignConnection& c : joined)
      connections->push_back({{c.seams[0] + int(creases.size()), c.seams[1] + int(creases.size())}});
  return seams;
}

}  // namespace

std::vector<DesignSeam> proposalSeams(const TriMesh& target, const LayoutProposal& proposal,
                                      std::vector<DesignConnection>* connections) {
  const double spacing = seamPointSpacing(target);
  if (!proposal.limbs.empty()) return limbSeams(target, proposal, spacing);
  if (!proposal.creases.empty()) return creaseSeams(target, proposal, spacing, connections);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(proposal.axis);
  std::array<Pole, 2> poles;
  if (!proposal.meridians.empty()) {
    poles = axisPoles(target, proposal.center, e);
    if (!poles[0].found || !poles[1].found)
      throw Error("suggest.no-poles", "its axis passes beside the shape, so its gores have no ends to meet at");
  }
  // Seams are named by what they are in the layout, short enough for the seam list and an internal panel's label.
  std::vector<DesignSeam> seams;
  // The planes' names: a halving plane's, then the bands' in order.
  const bool halving = proposal.outlineView < 0 && proposal.gores == 2;
  const auto planeName = [&](size_t j) {
    return halving && j == 0 ? std::string("halving seam") : "band " + std::to_string(j + (halving ? 0 : 1));
  };
  // Each plane's loops, and which of them are laid as two seams (a connected proposal's).
  std::vector<std::vector<SectionLoop>> planeLoops;
  for (const SectionPlane& plane : proposal.planes)
    planeLoops.push_back(planeSection(target, plane.normal, plane.offset));
  std::vector<std::vector<bool>> split;
  for (const std::vector<SectionLoop>& loops : planeLoops) split.emplace_back(loops.size(), false);
  if (proposal.outlineView >= 0) {
    const Eigen::Vector3d towards = Eigen::Vector3d::Unit(proposal.outlineView);
    const std::optional<Outline> outline = outlineSeenFrom(target, towards);
    if (!outline) throw Error("suggest.no-outline", "the shape shows no outline from there");
    // Corners kept, as the Outline tool keeps them: a seam that skipped a sharp turn would cut a tip off.
    std::vector<SurfacePoint> rim = sectionSeamPoints(target, outline->loop, spacing, true);
    seams.push_back({});
    // A connected proposal's band loops that cross the rim twice: a front and a back piece from crossing to crossing,
    // the rim passing through both.
    if (proposal.connected && outline->holes.empty())
      for (size_t j = 0; j < proposal.planes.size(); ++j) {
        const std::vector<SectionLoop>& loops = planeLoops[j];
        const std::vector<LoopCrossing> crossings = planeCrossings(target, outline->loop, proposal.planes[j]);
        for (size_t l = 0; l < loops.size(); ++l) {
          const SectionLoop& loop = loops[l];
          // The crossings on this loop, each with the piece of the loop it lies on.
          std::vector<LoopCrossing> on;
          for (const LoopCrossing& c : crossings)
            for (size_t i = 0; i < loop.size(); ++i) {
              const Eigen::Vector3d a = loop[i].position, ab = loop[(i + 1) % loop.size()].position - a;
              const double t =
                  std::clamp((c.point.position - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
              if ((a + t * ab - c.point.position).norm() < 1e-6 * spacing) {
                on.push_back({c.point, i});
                break;
              }
            }
          if (on.size() != 2 || (on[0].point.position - on[1].point.position).norm() < spacing) continue;
          const size_t first = seams.size();
          for (int piece = 0; piece < 2; ++piece) {
            const LoopCrossing& from = on[piece];
            const LoopCrossing& to = on[1 - piece];
            SectionLoop path;
            for (size_t i = (from.after + 1) % loop.size();; i = (i + 1) % loop.size()) {
              path.push_back(loop[i]);
              if (i == to.after) break;
            }
            path = withoutEnds(path, from.point.position, to.point.position, 0.25 * spacing);
            std::vector<SurfacePoint> controls{from.point.at};
            if (path.size() >= 2)
              for (const SurfacePoint& p : sectionPathPoints(target, path, spacing)) controls.push_back(p);
            controls.push_back(to.point.at);
            // Which side it lies on: the surface there faces the viewer, or away.
            double facing = 0;
            for (const SectionPoint& p : path) {
              const Eigen::Vector3d a = target.V.row(target.F(p.at.face, 0)), b = target.V.row(target.F(p.at.face, 1)),
                                    c = target.V.row(target.F(p.at.face, 2));
              facing += (b - a).cross(c - a).normalized().dot(towards);
            }
            seams.push_back(makeSeam(planeName(j) + (facing >= 0 ? ", front" : ", back"), false, controls));
          }
          for (const LoopCrossing& c : on) passThrough(target, rim, c.point, 0.25 * spacing);
          if (connections) connections->push_back({{int(first), int(first) + 1}});
          split[j][l] = true;
        }
      }
    seams[0] = makeSeam("outline", true, rim);
    // Seen through a handle, the front and back are rings: each hole's rim, and two sections across each ring where
    // they run around it (openSegments' cuts open the others).
    const std::vector<SectionLoop> across = acrossHandles(target, outline->loop, outline->holes, towards);
    for (const SectionLoop& hole : outline->holes)
      seams.push_back(makeSeam("hole in the outline", true, sectionSeamPoints(target, hole, spacing, true)));
    for (const SectionLoop& loop : across)
      seams.push_back(makeSeam("across a ring", true, sectionSeamPoints(target, loop, spacing)));
  }
  for (size_t m = 0; m < proposal.meridians.size(); ++m) {
    const Eigen::Vector3d& direction = proposal.meridians[m];
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
        if (onThisSide(loop))
          seams.push_back(makeSeam("around a limb", true, sectionSeamPoints(target, loop, spacing)));
        continue;
      }
      double d = 0;
      const size_t a = nearestPoint(loop, poles[0].point.position, d),
                   b = nearestPoint(loop, poles[1].point.position, d);
      for (int half = 0; half < 2; ++half) {
        // Pole to pole on either side of the loop, walked forward (a point keeps the face the walk crossed to reach
        // it) and the second side's points turned round after; its end points within a quarter spacing of a pole left
        // out (withoutEnds), so no control point crowds it.
        const Pole& from = poles[half];
        const Pole& to = poles[1 - half];
        const size_t n = loop.size(), start = half == 0 ? a : b, end = half == 0 ? b : a;
        SectionLoop side;
        for (size_t j = 1; j < n; ++j) {
          const size_t k = (start + j) % n;
          if (k == end) break;
          side.push_back(loop[k]);
        }
        if (!onThisSide(side)) continue;
        const SectionLoop piece = withoutEnds(side, from.point.position, to.point.position, 0.25 * spacing);
        std::vector<SurfacePoint> controls{from.point.at};
        if (piece.size() >= 2)
          for (const SurfacePoint& p : sectionPathPoints(target, piece, spacing)) controls.push_back(p);
        controls.push_back(to.point.at);
        if (half == 1) std::reverse(controls.begin(), controls.end());
        seams.push_back(makeSeam("meridian " + std::to_string(m + 1), false, controls));
      }
    }
  }
  for (size_t j = 0; j < planeLoops.size(); ++j)
    for (size_t l = 0; l < planeLoops[j].size(); ++l)
      if (!split[j][l])
        seams.push_back(makeSeam(planeName(j), true, sectionSeamPoints(target, planeLoops[j][l], spacing)));
  return seams;
}

namespace {

// Control points about `spacing` apart along a path of cut-mesh vertices (a loop when `closed`: at least three), its
// ends kept, as the layout's own seams are laid: traced between them, the seam follows the path.
std::vector<SurfacePoint> controlsAlong(const Segmentation& sg, const std::vector<int>& path, double spacing,
                                        bool closed) {
  const TriMesh& m = sg.mesh;
  const size_t n = path.size();
  std::vector<double> along{0};
  for (size_t i = 1; i < n + (closed ? 1 : 0); ++i)
    along.push_back(along.back() + (m.V.row(path[i % n]) - m.V.row(path[i - 1])).norm());
  const double total = along.back();
  const int pieces = std::max(closed ? 3 : 1, int(std::lround(total / spacing)));
  std::vector<SurfacePoint> controls;
  for (size_t i = 0, k = 0; i < n && int(k) < pieces; ++i)
    if (along[i] >= total * double(k) / pieces) controls.push_back(sg.vertexOrigin[size_t(path[i])]), ++k;
  if (!closed && n >= 2) controls.push_back(sg.vertexOrigin[size_t(path.back())]);
  return controls;
}

// How near a seam's end lies to a point of another seam that it ends on (the cut mesh's vertices are shared).
double endTolerance(const Segmentation& sg) {
  return 1e-9 * (sg.mesh.V.colwise().maxCoeff() - sg.mesh.V.colwise().minCoeff()).norm();
}

// The layout's own seams that cross themselves lose the control points where they turn back on themselves, the
// sharpest first, while one turns back by more than 120 degrees: where a plane grazes the body beside a limb's root,
// its loop runs out and back along a hairpin, and the shortest paths between its points there cross. A seam's ends
// stay, and so do the points other seams end on. The first `fixedSeams` seams are the designer's. Returns how many
// seams it changed.
int unfoldCrossingSeams(const DesignScene& scene, int fixedSeams, std::vector<DesignSeam>& seams) {
  constexpr double kFoldDeg = 60;  // the angle between the ways back and on at a point, below which it is a fold
  const double tiny = endTolerance(scene.segmentation);
  std::vector<Eigen::Vector3d> ends;
  for (const SeamCurve& c : scene.curves)
    if (!c.closed && !c.points.empty())
      ends.push_back(c.points.front().position), ends.push_back(c.points.back().position);
  const auto endOfAnother = [&](const Eigen::Vector3d& x) {
    return std::any_of(ends.begin(), ends.end(), [&](const Eigen::Vector3d& e) { return (e - x).norm() < tiny; });
  };
  std::vector<int> crossing;
  for (const SegmentationProblem& p : scene.segmentation.problems)
    if (p.code == "seam.self-crossing" && p.seam >= fixedSeams && p.seam < int(seams.size()) &&
        p.seam < int(scene.curves.size()) && std::find(crossing.begin(), crossing.end(), p.seam) == crossing.end())
      crossing.push_back(p.seam);
  int changed = 0;
  for (int s : crossing) {
    const SeamCurve& curve = scene.curves[size_t(s)];
    DesignSeam& seam = seams[size_t(s)];
    if (curve.controlIndices.size() != seam.points.size()) continue;
    std::vector<size_t> kept(seam.points.size());
    std::iota(kept.begin(), kept.end(), size_t(0));
    const auto at = [&](size_t k) { return curve.points[size_t(curve.controlIndices[kept[k]])].position; };
    while (kept.size() > (seam.closed ? 3u : 2u)) {
      const size_t n = kept.size();
      size_t fold = n;
      double sharpest = kFoldDeg * M_PI / 180;
      for (size_t k = seam.closed ? 0 : 1; k < (seam.closed ? n : n - 1); ++k) {
        if (endOfAnother(at(k))) continue;
        const Eigen::Vector3d back = at((k + n - 1) % n) - at(k), on = at((k + 1) % n) - at(k);
        const double angle = std::atan2(back.cross(on).norm(), back.dot(on));  // 0 where it turns right back
        if (angle < sharpest) sharpest = angle, fold = k;
      }
      if (fold == n) break;
      kept.erase(kept.begin() + long(fold));
    }
    if (kept.size() == seam.points.size()) continue;
    std::vector<DesignPoint> points;
    for (size_t i : kept) points.push_back(seam.points[i]);
    seam.points = std::move(points);
    ++changed;
  }
  return changed;
}

// Leaves the seams `which` (indices) out of `seams`: the internal connections that name one go with it, the others'
// indices follow the seams after it.
void eraseSeams(std::vector<int> which, std::vector<DesignSeam>& seams, std::vector<DesignConnection>& connections) {
  std::sort(which.rbegin(), which.rend());
  for (int seam : which) {
    seams.erase(seams.begin() + seam);
    std::vector<DesignConnection> kept;
    for (DesignConnection& c : connections) {
      if (std::find(c.seams.begin(), c.seams.end(), seam) != c.seams.end()) continue;
      for (int& i : c.seams) i -= i > seam;
      kept.push_back(std::move(c));
    }
    connections = std::move(kept);
  }
}

// Seams that make a layout's segments panels, where plane sections alone leave a segment that is not one: a segment
// between two loops or more (a plane across a limb leaves a tube, a limb's end cut off inside a band leaves a hole)
// gets cuts through it that join its loops (cutsJoiningLoops: the cuts that open a tube, as a designer would add
// them); a segment around handles a closed seam around each, none shorter than four of the panels' edges at
// `edgeLength` (loopsAroundHandles); a segment too big for its seam (a limb's end) is cut along its length through its
// tip where it is a disk and that leaves no piece too big (cutAlong), else gets the plane section across its longest
// extent where that loop lies within it, else across the next (around its limbs); a tiny or thin segment loses the
// shortest closed seam of the layout's own around it (a plane grazing a toe). The first `fixedSeams` seams are the
// designer's and stay. Counts what it did in `opened`; returns how many seams it added or removed.
int openSegments(const DesignScene& scene, double spacing, double edgeLength, int fixedSeams,
                 std::vector<DesignSeam>& seams, std::vector<DesignConnection>& connections, LayoutOpenings& opened) {
  const Segmentation& sg = scene.segmentation;
  int added = 0;
  // The segments each target face has a part in.
  std::vector<std::vector<int>> faceSegments(scene.target.F.rows());
  for (int f = 0; f < int(sg.faceOrigin.size()); ++f) {
    std::vector<int>& in = faceSegments[sg.faceOrigin[f]];
    if (std::find(in.begin(), in.end(), sg.faceSegment[f]) == in.end()) in.push_back(sg.faceSegment[f]);
  }
  // The grazing loops go first, on their own: of the layout's closed seams around a tiny or thin segment (a plane
  // grazing a toe, loops of several planes crossing on a flipper), the shortest that no other seam ends on goes, and
  // the segment joins its neighbour across it; where every such loop has seams ending on it (a limb's root), the
  // shortest of the layout's open seams along the segment (a piece that only nicks the root).
  const double tiny = endTolerance(sg);
  const auto endedOn = [&](int seam) {
    for (size_t other = 0; other < scene.curves.size(); ++other) {
      const SeamCurve& c = scene.curves[other];
      if (int(other) == seam || c.closed || c.points.empty()) continue;
      for (const Eigen::Vector3d& end : {c.points.front().position, c.points.back().position})
        for (const PathPoint& p : scene.curves[size_t(seam)].points)
          if ((p.position - end).norm() < tiny) return true;
    }
    return false;
  };
  std::vector<int> removed;
  for (const SegmentationProblem& problem : sg.problems) {
    if (problem.segment < 0 || (problem.code != "segment.sliver" && problem.code != "segment.thin")) continue;
    int shortest = -1;
    for (bool closed : {true, false}) {
      for (const BoundaryLoop& loop : sg.segments[problem.segment].loops)
        for (int seam : loop.seams)
          if (seam >= fixedSeams && seam < int(seams.size()) && seams[seam].closed == closed &&
              (shortest < 0 || scene.curves[seam].length < scene.curves[shortest].length) && !(closed && endedOn(seam)))
            shortest = seam;
      if (shortest >= 0) break;
    }
    if (shortest >= 0 && std::find(removed.begin(), removed.end(), shortest) == removed.end())
      removed.push_back(shortest);
  }
  if (!removed.empty()) {
    eraseSeams(removed, seams, connections);
    opened.grazingLoops += int(removed.size());
    return int(removed.size());
  }
  for (const SegmentationProblem& problem : sg.problems) {
    if (problem.segment < 0) continue;
    const Segment& segment = sg.segments[problem.segment];
    if (problem.code == "segment.not-disk" && segment.genus == 0 && segment.loops.size() >= 2) {
      for (std::vector<int> path : cutsJoiningLoops(sg, problem.segment)) {
        // From one side of a seam round to its other side (a ring's seam around its tube), the cut is a loop of its own
        // through that seam.
        const bool round = path.size() > 3 && path.front() == path.back();
        if (round) path.pop_back();
        seams.push_back(makeSeam("a cut that opens a tube", round, controlsAlong(sg, path, spacing, round)));
        ++added, ++opened.tubeCuts;
      }
    } else if (problem.code == "segment.not-disk" && segment.genus > 0) {
      for (const std::vector<int>& loop : loopsAroundHandles(sg, problem.segment, 4 * edgeLength)) {
        const std::vector<SurfacePoint> controls = controlsAlong(sg, loop, spacing, true);
        if (controls.size() < 3) continue;
        seams.push_back(makeSeam("a seam around a handle", true, controls));
        ++added, ++opened.handleSeams;
      }
    } else if (problem.code == "segment.too-big-for-seam") {
      // A limb's end or a head on its neck: halved along its length through its tip, two pieces where a section across
      // would leave a tube and an end still too big for its seam (a lion's tail, each of three rounds).
      if (const std::vector<int> path = cutAlong(sg, problem.segment, SegmentationOptions{}.minFlatShare);
          path.size() >= 3) {
        seams.push_back(makeSeam("a cut along a limb's end", false, controlsAlong(sg, path, spacing, false)));
        ++added, ++opened.limbEndCuts;
        continue;
      }
      const SegmentSpread spread = segmentSpread(sg, problem.segment);
      if (!(spread.area > 0)) continue;
      // Across its longest extent first; a cap over two limbs has none there, and gets the planes across the others
      // (around each limb).
      for (int direction = 2; direction >= 0; --direction) {
        const Eigen::Vector3d normal = spread.axes.col(direction);
        int laid = 0;
        for (const SectionLoop& loop : planeSection(scene.target, normal, normal.dot(spread.center))) {
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

// The share of the sheet the panels' cut pieces cover, nested as the cut file nests them; on a roll just wide enough
// where a piece is wider, whose width goes to `needed`.
double sheetUse(const Pattern& pattern, ExportOptions cut, double& needed) {
  // Per-seam allowances and fill valves name the design's own seams, not the layout's.
  cut.seamAllowance.clear(), cut.valves.clear();
  needed = 0;
  try {
    return layoutSheet(pattern, cut).nest.utilisation;
  } catch (const Error& e) {
    if (e.code != "export.sheet-too-narrow" || !(e.sheetWidth > cut.sheetWidth)) throw;
    cut.sheetWidth = needed = e.sheetWidth;
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

// evaluateLayout's first part: the seams traced and segmented, with those that open its segments into panels; ok
// when every segment is a panel. The scene keeps the segmentation for measureLayout.
LayoutEvaluation layLayout(DesignScene& scene, const std::vector<DesignSeam>& seams, int fixedSeams,
                           const EvaluateOptions& options, const std::vector<DesignConnection>& connections) {
  LayoutEvaluation out;
  out.seams = seams, out.connections = connections;
  const double spacing = seamPointSpacing(scene.target);
  // The panels' edge length at the resolution the layout is looked at (its panels' area about the target's).
  double area = 0;
  for (int f = 0; f < scene.target.numTriangles(); ++f) area += triangleArea(scene.target, f);
  PatternBuildOptions resolution;
  resolution.triangles = options.triangles;
  const double edgeLength = area > 0 ? patternEdgeLength(area, resolution) : 0;
  for (int round = 0, unfoldings = 0;; ++round) {
    scene.design.seams = out.seams, scene.design.connections = out.connections;
    try {
      traceDesignSeams(scene);
    } catch (const Error& e) {
      out.problem = e.what();
      return out;
    }
    segmentDesignScene(scene);
    // A seam that crosses itself is mended first, and the round is not counted: what opens the segments depends on
    // where it runs.
    if (unfoldings < 2 && unfoldCrossingSeams(scene, fixedSeams, out.seams) > 0) {
      ++unfoldings, --round;
      continue;
    }
    if (scene.segmentation.problems.empty() || round == options.openingRounds ||
        openSegments(scene, spacing, edgeLength, fixedSeams, out.seams, out.connections, out.opened) == 0)
      break;
  }
  const Segmentation& segmentation = scene.segmentation;
  if (!segmentation.problems.empty()) {
    out.problem = segmentation.problems.front().message;
    return out;
  }
  out.panels = int(segmentation.segments.size() + out.connections.size());
  for (const SeamCurve& curve : scene.curves) out.seamLength += curve.length;
  out.ok = true;
  return out;
}

// The panels of the layout on the scene layLayout left; a segment that would overlap itself when laid flat gets a cut
// across it where its outline crosses itself, as the builder's message advises, and the layout is laid again (in
// options.openingRounds rounds, to at most `panelsAtMost` panels). Empty, with out.problem, where they cannot be made.
std::optional<BuiltPattern> layoutPanels(DesignScene& scene, LayoutEvaluation& out, const EvaluateOptions& options,
                                         int fixedSeams, int panelsAtMost) {
  for (int round = 0;; ++round) {
    BuiltPattern built = buildDesignPattern(scene, options.triangles);
    if (built.ok()) return built;
    out.problem = built.problems.empty() ? "no panels" : built.problems.front().message;
    const auto overlap = std::find_if(built.problems.begin(), built.problems.end(), [](const SegmentationProblem& p) {
      return p.code == "pattern.overlaps" && p.segment >= 0;
    });
    if (overlap == built.problems.end() || round == options.openingRounds) return std::nullopt;
    const std::vector<int> path = cutAcross(scene.segmentation, overlap->segment, overlap->location);
    if (path.size() < 2) return std::nullopt;
    const std::string name = "a cut across a panel that would overlap itself";
    const auto cutsAcross = [&](const std::vector<DesignSeam>& seams) {
      return std::count_if(seams.begin(), seams.end(), [&](const DesignSeam& seam) { return seam.name == name; });
    };
    std::vector<DesignSeam> seams = out.seams;
    seams.push_back(
        makeSeam(name, false, controlsAlong(scene.segmentation, path, seamPointSpacing(scene.target), false)));
    LayoutEvaluation again = layLayout(scene, seams, fixedSeams, options, out.connections);
    // Laid again, the cut must stay (it is left out again where it cuts a sliver off).
    if (!again.ok || cutsAcross(again.seams) < cutsAcross(seams)) return std::nullopt;
    if (again.panels > panelsAtMost) {
      out.problem = "it makes " + std::to_string(again.panels) + " panels on this shape, with a cut across a panel " +
                    "that would overlap itself when laid flat";
      return std::nullopt;
    }
    again.opened.add(out.opened);
    ++again.opened.acrossCuts;
    out = std::move(again);
    out.ok = false;  // laid, not yet measured
  }
}

}  // namespace

// Cuts across panels that would overlap themselves, at most, in openIntoPanels: one action the designer waits for,
// where a suggestion tries many layouts (EvaluateOptions::openingRounds); a peel spiralling six times round the sphere
// takes seven.
constexpr int kOpeningRoundsOfOneAction = 8;

LayoutEvaluation openIntoPanels(DesignScene& scene, const std::vector<DesignSeam>& seams, int fixedSeams,
                                const std::vector<DesignConnection>& connections, int triangles) {
  EvaluateOptions options;
  options.triangles = triangles;
  LayoutEvaluation out = layLayout(scene, seams, fixedSeams, options, connections);
  // Closed seams of the laid ones that still cross themselves once their hairpins are taken out (a hole's rim traced
  // round a tight turn) are left out, and the rest laid and opened again from the start, so that no cut ends on them.
  std::vector<DesignSeam> current = seams;
  std::vector<DesignConnection> joined = connections;
  int leftOut = 0;
  for (int round = 0; !out.ok && round < 2; ++round) {
    std::vector<int> crossing;
    try {
      scene.design.seams = current, scene.design.connections = joined;
      traceDesignSeams(scene);
      segmentDesignScene(scene);
      if (unfoldCrossingSeams(scene, fixedSeams, current) > 0) {
        scene.design.seams = current;
        traceDesignSeams(scene);
        segmentDesignScene(scene);
      }
    } catch (const Error&) {
      break;
    }
    for (const SegmentationProblem& p : scene.segmentation.problems)
      if (p.code == "seam.self-crossing" && p.seam >= fixedSeams && p.seam < int(current.size()) &&
          current[size_t(p.seam)].closed && std::find(crossing.begin(), crossing.end(), p.seam) == crossing.end())
        crossing.push_back(p.seam);
    if (crossing.empty()) break;
    eraseSeams(crossing, current, joined);
    leftOut += int(crossing.size());
    out = layLayout(scene, current, fixedSeams, options, joined);
  }
  out.opened.crossingLoops += leftOut;
  // A segment that would overlap itself when laid flat gets a cut across it, as the builder's message advises (what a
  // suggested layout gets): the Outline of a deep shape, a boot seen from its front, leaves one.
  if (out.ok) {
    LayoutEvaluation cut = out;
    EvaluateOptions across = options;
    across.openingRounds = kOpeningRoundsOfOneAction;
    if (layoutPanels(scene, cut, across, fixedSeams, std::numeric_limits<int>::max())) {
      cut.ok = true;
      return cut;
    }
    // No cut lays it flat: the seams as they were, whose panels' message says where.
    scene.design.seams = out.seams, scene.design.connections = out.connections;
    traceDesignSeams(scene);
    segmentDesignScene(scene);
  }
  return out;
}

namespace {

// evaluateLayout's second part, on the scene layLayout left: the panels built, optimized and measured.
void measureLayout(DesignScene& scene, LayoutEvaluation& out, const EvaluateOptions& options, int fixedSeams,
                   int panelsAtMost) {
  out.ok = false;
  // A layout whose panels cannot be made or settled is not used, and says why (the pattern's own message: panels
  // sewn three to an edge where a cut meets a section, a fold).
  try {
    const std::optional<BuiltPattern> panels = layoutPanels(scene, out, options, fixedSeams, panelsAtMost);
    if (!panels) return;
    const BuiltPattern& built = *panels;
    OptimizeOptions oo = appStoppingRule();
    oo.stopping.maxIterations = options.maxIterations;
    oo.stopping.maxNewtonIterations = int(options.newtonPerIteration * options.maxIterations);
    oo.stopping.maxWork = 0;  // the bound above, the suggestion's own
    // A first look (no iteration) measures the flattened panels' own inflation, not their cut.
    oo.remeshing.cutPanels = options.maxIterations > 0;
    if (!scene.optimizationTarget)
      scene.optimizationTarget = std::make_shared<const OptimizationTarget>(scene.target, oo.imls);
    PatternOptimizer optimizer(scene.optimizationTarget, built, designSeamWeights(scene.design), oo);
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
    if (options.maxIterations > 0) out.sheetUse = sheetUse(out.pattern, options.cut, out.sheetNeeded);
  } catch (const Error& e) {
    out.problem = e.what();
    return;
  }
  out.ok = true;
}

}  // namespace

LayoutEvaluation evaluateLayout(DesignScene& scene, const std::vector<DesignSeam>& seams, int fixedSeams,
                                const EvaluateOptions& options, const std::vector<DesignConnection>& connections) {
  const Clock::time_point t0 = Clock::now();
  LayoutEvaluation out = layLayout(scene, seams, fixedSeams, options, connections);
  if (out.ok) measureLayout(scene, out, options, fixedSeams, std::numeric_limits<int>::max());
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

LayoutRank layoutRank(const LayoutEvaluation& layout) {
  return {layout.sheetNeeded > 0 ? 1.0 : 0.0, layout.distance, layout.seamLength};
}

LayoutRank lookRank(const LayoutEvaluation& look) { return {lookPromise(look), look.seamLength, 0.0}; }

std::vector<int> layoutsRanked(const std::vector<const LayoutEvaluation*>& layouts) {
  std::vector<int> order;
  for (int i = 0; i < int(layouts.size()); ++i)
    if (layouts[i]->ok) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int i, int j) { return layoutRank(*layouts[i]) < layoutRank(*layouts[j]); });
  return order;
}

std::string layoutFamily(const LayoutProposal& p) {
  // Two gores are halves, whose plane names them; more are gores around the axis, turned or not.
  Eigen::Index halving = -1;
  if (p.outlineView < 0 && p.gores == 2 && !p.planes.empty()) p.planes[0].normal.cwiseAbs().maxCoeff(&halving);
  return std::to_string(p.outlineView) + " " + std::to_string(p.axis) + " " + std::to_string(p.bands > 0) + " " +
         std::to_string(p.gores > 2) + " " + std::to_string(halving) + (p.connected ? " connected" : "") +
         (p.limbs.empty() ? "" : " limbs") + (p.creases.empty() ? "" : " creases") + (p.atValleys ? " valleys" : "");
}

std::vector<int> chooseLooks(const std::vector<LookChoice>& looks, int count, int ofOneFamily) {
  std::vector<int> order(looks.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return looks[a].rank < looks[b].rank; });
  std::vector<int> chosen;
  std::map<std::string, int> taken;
  for (int i : order)
    if (int(chosen.size()) < count && ++taken[looks[i].family] <= ofOneFamily) chosen.push_back(i);
  return chosen;
}

std::vector<int> looksToOptimize(const std::vector<const LayoutEvaluation*>& looks,
                                 const std::vector<std::string>& families, int count, int ofOneFamily) {
  std::vector<LookChoice> choices;
  std::vector<int> index;
  for (int i = 0; i < int(looks.size()); ++i)
    if (looks[i]->ok) choices.push_back({lookRank(*looks[i]), families[i]}), index.push_back(i);
  std::vector<int> chosen = chooseLooks(choices, count, ofOneFamily);
  for (int& i : chosen) i = index[i];
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
    std::vector<DesignConnection> connections;
    const std::vector<DesignSeam> laid = proposalSeams(scene.target, proposal, &connections);
    seams.insert(seams.end(), laid.begin(), laid.end());
    for (DesignConnection& c : connections)
      for (int& i : c.seams) i += int(kept.size());
    look = layLayout(scene, seams, int(kept.size()), options, connections);
  } catch (const Error& e) {
    look.problem = e.what();
  }
  // Refused before its panels are built and inflated: half the looks at 24 panels make too many.
  if (look.ok && look.panels > panelsAtMost)
    look.ok = false, look.problem = "it makes " + std::to_string(look.panels) + " panels on this shape";
  if (look.ok && std::any_of(looked.begin(), looked.end(),
                             [&](const std::vector<DesignSeam>& seams) { return sameSeams(seams, look.seams); }))
    look.ok = false, look.problem = "it ends with the same seams as a layout before it";
  if (look.ok) measureLayout(scene, look, options, int(kept.size()), panelsAtMost);
  look.ms = msSince(t0);
  return look;
}

std::unique_ptr<DesignScene> suggestionScene(const Design& design, const TriMesh& target) {
  std::optional<TriMesh> copy = workingCopy(target);
  if (!copy) return nullptr;
  Design own = design;
  own.seams.clear();
  own.connections.clear();
  return makeTargetScene(own, *copy);
}

}  // namespace billow
