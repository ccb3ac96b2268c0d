#include "suggest/limbs.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>

#include "seams/mesh_topology.hpp"
#include "seams/surface_point.hpp"

namespace billow {

namespace {

constexpr int kTipCandidates = 24;  // farthest points tried as tips
constexpr int kRadii = 96;          // geodesic radii sampled from each tip
// A limb is less than this share of the surface (a body's half seen from its end is not a limb).
constexpr double kLimbAreaShare = 0.3;
// Its root is the last radius where the cap's elongation stands within this share of its highest.
constexpr double kRootPlateau = 0.9;

// The length of the level set {d = r} within triangle a, b, c (d linear over it).
double levelLength(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double da, double db,
                   double dc, double r) {
  Eigen::Vector3d ends[2];
  int n = 0;
  const Eigen::Vector3d* p[3] = {&a, &b, &c};
  const double d[3] = {da, db, dc};
  for (int k = 0; k < 3 && n < 2; ++k) {
    const double s = d[k] - r, t = d[(k + 1) % 3] - r;
    if ((s < 0) == (t < 0)) continue;
    ends[n++] = *p[k] + s / (s - t) * (*p[(k + 1) % 3] - *p[k]);
  }
  return n == 2 ? (ends[0] - ends[1]).norm() : 0;
}

// Area-weighted centroid and covariance of the faces marked in `on` (value 1).
void faceMoments(const TriMesh& mesh, const std::vector<char>& on, Eigen::Vector3d& center, Eigen::Matrix3d& covariance,
                 double& area) {
  center.setZero(), covariance.setZero(), area = 0;
  for (int f = 0; f < mesh.F.rows(); ++f) {
    if (on[size_t(f)] != 1) continue;
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const double at = 0.5 * (b - a).cross(c - a).norm();
    const Eigen::Vector3d m = (a + b + c) / 3;
    center += at * m, covariance += at * m * m.transpose(), area += at;
  }
  if (area > 0) center /= area, covariance = covariance / area - center * center.transpose();
}

// The target's edges (MeshTopology) with their lengths, and its faces' areas.
struct MeshGraph {
  MeshTopology topology;
  Eigen::VectorXd edgeLength, area;
};

MeshGraph meshGraph(const TriMesh& mesh) {
  MeshGraph out{buildTopology(mesh), {}, Eigen::VectorXd(mesh.F.rows())};
  out.edgeLength.resize(out.topology.numEdges());
  for (int e = 0; e < out.topology.numEdges(); ++e)
    out.edgeLength[e] = (mesh.V.row(out.topology.E(e, 0)) - mesh.V.row(out.topology.E(e, 1))).norm();
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    out.area[f] = 0.5 * (b - a).cross(c - a).norm();
  }
  return out;
}

// Shortest distances along edges from `source`.
Eigen::VectorXd edgeDistances(const MeshGraph& graph, int source) {
  Eigen::VectorXd d = Eigen::VectorXd::Constant(Eigen::Index(graph.topology.neighbors.size()), INFINITY);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  d[source] = 0, queue.push({0, source});
  while (!queue.empty()) {
    const auto [dv, v] = queue.top();
    queue.pop();
    if (dv > d[v]) continue;
    for (const auto& [w, e] : graph.topology.neighbors[size_t(v)])
      if (dv + graph.edgeLength[e] < d[w]) d[w] = dv + graph.edgeLength[e], queue.push({d[w], w});
  }
  return d;
}

// The limb's faces beyond its root loop (from its tip's, not across the loop's), its area, girth and the plane along
// it; false where the loop does not close it off.
bool closeOff(const TriMesh& mesh, const MeshGraph& graph, Limb& limb) {
  limb.faces.assign(size_t(mesh.F.rows()), 0);
  for (const SectionPoint& p : limb.rootLoop) limb.faces[size_t(p.at.face)] = 2;
  int start = -1;
  for (int f = 0; f < mesh.F.rows() && start < 0; ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.F(f, k) == limb.tip && limb.faces[size_t(f)] == 0) start = f;
  if (start < 0) return false;
  std::vector<int> stack{start};
  limb.faces[size_t(start)] = 1;
  double area = 0;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    area += graph.area[f];
    for (int k = 0; k < 3; ++k) {
      const int e = graph.topology.faceEdges(f, k), g = graph.topology.edgeFaces(e, 0) == f
                                                            ? graph.topology.edgeFaces(e, 1)
                                                            : graph.topology.edgeFaces(e, 0);
      if (limb.faces[size_t(g)] == 0) limb.faces[size_t(g)] = 1, stack.push_back(g);
    }
  }
  if (area > 2 * kLimbAreaShare * graph.area.sum()) return false;
  Eigen::Vector3d center;
  Eigen::Matrix3d covariance;
  faceMoments(mesh, limb.faces, center, covariance, limb.area);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  limb.along = {eig.eigenvectors().col(0), eig.eigenvectors().col(0).dot(center)};
  limb.across = eig.eigenvectors().col(1), limb.center = center;
  limb.girth = loopLength(limb.rootLoop);
  return true;
}

// A tip whose cap grows as a tube: the radii its root may lie at, the farthest first (rootRadii, from where the cap's
// elongation last stands near its highest back to its highest).
struct TipProfile {
  int tip = -1;
  Eigen::VectorXd d;  // distances from the tip along the surface
  double elongation = 0;
  std::vector<double> rootRadii;
};

std::optional<TipProfile> tipProfile(const TriMesh& mesh, const MeshGraph& graph, int tip, Eigen::VectorXd d) {
  const Eigen::VectorXd& faceArea = graph.area;
  const double total = faceArea.sum();
  // The radius within which the cap holds kLimbAreaShare of the surface.
  std::vector<std::pair<double, double>> entry;  // a face's farthest corner, its area
  for (int f = 0; f < mesh.F.rows(); ++f)
    entry.push_back({std::max({d[mesh.F(f, 0)], d[mesh.F(f, 1)], d[mesh.F(f, 2)]}), faceArea[f]});
  std::sort(entry.begin(), entry.end());
  double rMax = 0, walked = 0;
  for (const auto& [r, a] : entry) {
    if ((walked += a) > kLimbAreaShare * total) break;
    rMax = r;
  }
  if (!(rMax > 0)) return std::nullopt;
  std::vector<double> ratio(kRadii + 1, 0.0);
  for (int j = 1; j <= kRadii; ++j) {
    const double r = rMax * j / kRadii;
    double girth = 0;
    for (int f = 0; f < mesh.F.rows(); ++f) {
      const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
      if (std::min({d[a], d[b], d[c]}) >= r || std::max({d[a], d[b], d[c]}) < r) continue;
      girth += levelLength(mesh.V.row(a), mesh.V.row(b), mesh.V.row(c), d[a], d[b], d[c], r);
    }
    if (girth > 0) ratio[size_t(j)] = M_PI * r / girth;
  }
  // Past the tip's own rounding (the first eighth), where the cap is longest for its width; then on along the plateau.
  size_t best = kRadii / 8;
  for (size_t j = best; j <= kRadii; ++j)
    if (ratio[j] > ratio[best]) best = j;
  if (ratio[best] < kLimbElongation) return std::nullopt;
  size_t root = best;
  while (root < kRadii && ratio[root + 1] >= kRootPlateau * ratio[best]) ++root;
  TipProfile out{tip, std::move(d), ratio[best], {}};
  for (size_t j = root + 1; j-- > best;) out.rootRadii.push_back(rMax * double(j) / kRadii);
  return out;
}

// The limb whose tip and level are `limb`'s: its root the level's zero set, if that is one loop round the limb (not
// wrapped round something) that closes it off.
std::optional<Limb> limbWithLevel(const TriMesh& mesh, const MeshGraph& graph, Limb limb) {
  if (!(limb.level[limb.tip] < 0)) return std::nullopt;
  std::vector<SectionLoop> rims = zeroLoops(mesh, limb.level);
  if (rims.size() != 1) return std::nullopt;
  limb.rootLoop = std::move(rims.front());
  if (!closeOff(mesh, graph, limb)) return std::nullopt;
  return limb;
}

// The limb of `profile` whose root lies at radius r.
std::optional<Limb> limbAt(const TriMesh& mesh, const MeshGraph& graph, const TipProfile& profile, double r) {
  Limb limb;
  limb.tip = profile.tip, limb.elongation = profile.elongation;
  limb.level = profile.d.array() - r;
  for (Eigen::Index v = 0; v < limb.level.size(); ++v)
    if (limb.level[v] == 0) limb.level[v] = 1e-12 * r;
  return limbWithLevel(mesh, graph, std::move(limb));
}

bool overlap(const Limb& a, const Limb& b) {
  for (size_t f = 0; f < a.faces.size(); ++f)
    if (a.faces[f] && b.faces[f]) return true;
  return false;
}

}  // namespace

double limbLevel(const TriMesh& target, const Limb& limb, int face, const Eigen::Vector3d& p) {
  const Eigen::Vector3d w = closestPointBarycentric(p, target.V.row(target.F(face, 0)), target.V.row(target.F(face, 1)),
                                                    target.V.row(target.F(face, 2)));
  return w[0] * limb.level[target.F(face, 0)] + w[1] * limb.level[target.F(face, 1)] +
         w[2] * limb.level[target.F(face, 2)];
}

bool onLimb(const TriMesh& target, const Limb& limb, int face, const Eigen::Vector3d& p) {
  const char on = limb.faces[size_t(face)];
  return on == 1 || (on == 2 && limbLevel(target, limb, face, p) < 0);
}

std::vector<Limb> findLimbs(const TriMesh& target) {
  std::vector<Limb> out;
  const int nv = int(target.V.rows()), nf = int(target.F.rows());
  if (nv < 4 || nf < 4) return out;
  const MeshGraph graph = meshGraph(target);
  // Tips: the farthest points, each the farthest from those before (a limb's end is far from everything).
  Eigen::VectorXd nearestTip = edgeDistances(graph, 0);  // the first tip: the farthest from any vertex
  std::vector<TipProfile> candidates;
  for (int i = 0; i < kTipCandidates; ++i) {
    Eigen::Index tip = 0;
    nearestTip.maxCoeff(&tip);
    if (!std::isfinite(nearestTip[tip]) || (i > 0 && nearestTip[tip] <= 0)) break;
    Eigen::VectorXd d = edgeDistances(graph, int(tip));
    nearestTip = i == 0 ? d : nearestTip.cwiseMin(d);
    if (std::optional<TipProfile> profile = tipProfile(target, graph, int(tip), std::move(d)))
      candidates.push_back(std::move(*profile));
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const TipProfile& a, const TipProfile& b) { return a.elongation > b.elongation; });
  // Each at its farthest root that leaves the limbs before it whole (arms that meet at a starfish's middle each end
  // short of it).
  for (const TipProfile& profile : candidates)
    for (double r : profile.rootRadii) {
      std::optional<Limb> limb = limbAt(target, graph, profile, r);
      if (!limb) continue;
      if (std::any_of(out.begin(), out.end(), [&](const Limb& other) { return overlap(*limb, other); })) continue;
      out.push_back(std::move(*limb));
      break;
    }
  return out;
}

std::vector<std::vector<Limb>> mirrorSymmetricLimbs(const TriMesh& target, const std::vector<Limb>& limbs, int axis,
                                                    double mid) {
  std::vector<std::vector<Limb>> out;
  const MeshGraph graph = meshGraph(target);
  const SurfaceProjector projector(target);
  const double extent = target.V.col(axis).maxCoeff() - target.V.col(axis).minCoeff();
  const auto reflect = [&](Eigen::Vector3d p) { return p[axis] = 2 * mid - p[axis], p; };
  // Each vertex's mirror image on the surface, once.
  std::vector<SurfacePoint> image;
  for (Eigen::Index v = 0; v < target.V.rows(); ++v) image.push_back(projector.project(reflect(target.V.row(v))));
  const auto reflected = [&](const Eigen::VectorXd& level) {
    Eigen::VectorXd mirrored(level.size());
    for (Eigen::Index v = 0; v < level.size(); ++v) {
      const SurfacePoint& p = image[size_t(v)];
      mirrored[v] = p.bary[0] * level[target.F(p.face, 0)] + p.bary[1] * level[target.F(p.face, 1)] +
                    p.bary[2] * level[target.F(p.face, 2)];
      if (mirrored[v] == 0) mirrored[v] = 1e-12 * extent;
    }
    return mirrored;
  };
  const auto withLevel = [&](Limb limb, const Eigen::VectorXd& level, int tip) {
    limb.level = level, limb.tip = tip;
    return limbWithLevel(target, graph, std::move(limb));
  };
  for (const Limb& limb : limbs) {
    const double side = target.V(limb.tip, axis) - mid;
    std::vector<Limb> group;
    if (std::abs(side) < 0.05 * extent) {
      // On the plane (a tail, a trunk): its level made its own mirror image, halved along the plane.
      std::optional<Limb> own = withLevel(limb, 0.5 * (limb.level + reflected(limb.level)), limb.tip);
      if (!own) continue;
      own->along = {Eigen::Vector3d::Unit(axis), mid};
      own->across = Eigen::Vector3d::Unit(axis);  // no other halving is its own mirror image
      group.push_back(std::move(*own));
    } else {
      // With its mirror image on the other side.
      Eigen::Index tip = 0;
      (target.V.rowwise() - reflect(target.V.row(limb.tip)).transpose()).rowwise().squaredNorm().minCoeff(&tip);
      std::optional<Limb> twin = withLevel(limb, reflected(limb.level), int(tip));
      if (!twin || overlap(limb, *twin)) continue;
      Eigen::Vector3d a = limb.along.normal;
      a[axis] = -a[axis];
      twin->along = {a, a.dot(reflect(limb.along.normal * limb.along.offset))};
      twin->across = limb.across, twin->across[axis] = -limb.across[axis], twin->center = reflect(limb.center);
      group.push_back(limb), group.push_back(std::move(*twin));
    }
    const bool overlaps = std::any_of(out.begin(), out.end(), [&](const std::vector<Limb>& other) {
      for (const Limb& a : group)
        for (const Limb& b : other)
          if (overlap(a, b)) return true;
      return false;
    });
    if (!group.empty() && !overlaps) out.push_back(std::move(group));
  }
  return out;
}

}  // namespace billow
