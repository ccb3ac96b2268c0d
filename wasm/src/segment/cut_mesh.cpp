// Cutting the target along seams (see cut_mesh.hpp): register every seam point once (vertex, edge + t or
// face + barycentric), then re-triangulate each touched face on its own.
#include "segment/cut_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "segment/face_triangulation.hpp"

namespace billow {

namespace {

// Every seam point gets one id; ids below #V are the target's vertices.
struct PointRegistry {
  const TriMesh& m;
  const MeshTopology& topo;
  double tol;
  std::vector<SurfacePoint> origin;
  std::vector<std::vector<std::pair<double, int>>> onEdge;  // per edge: (t, id)
  std::vector<std::vector<int>> inFace;                     // per face: ids inside

  PointRegistry(const TriMesh& mesh, const MeshTopology& t, double tolerance)
      : m(mesh), topo(t), tol(tolerance), onEdge(t.numEdges()), inFace(mesh.numTriangles()) {
    for (int v = 0; v < m.numVertices(); ++v) origin.push_back(vertexPoint(m, topo, v));
  }
  int fresh(const SurfacePoint& p) {
    origin.push_back(p);
    return static_cast<int>(origin.size()) - 1;
  }
  int addInFace(const SurfacePoint& p) {
    for (int id : inFace[p.face])
      if ((origin[id].bary - p.bary).cwiseAbs().maxCoeff() <= tol) return id;
    inFace[p.face].push_back(fresh(p));
    return inFace[p.face].back();
  }
  int add(const SurfacePoint& p) {
    const SurfaceLocation loc = locate(m, topo, p, tol);
    if (loc.kind == SurfaceLocation::Vertex) return loc.vertex;
    if (loc.kind == SurfaceLocation::Face) return addInFace(p);
    for (const auto& [t, id] : onEdge[loc.edge])
      if (std::abs(t - loc.t) <= tol) return id;
    const int id = fresh(edgePoint(m, topo, loc.edge, loc.t));
    onEdge[loc.edge].emplace_back(loc.t, id);
    return id;
  }
};

struct Piece {
  int a, b, face, seam;
};

// One target face with its seam points, in a 2D frame of the face.
struct FaceCut {
  std::vector<int> ids;
  std::vector<Eigen::Vector2d> pts;
  std::vector<Eigen::Vector3d> bary;
  std::vector<int> edgeMask;  // bit k: on the face edge from corner k to k+1
  Eigen::Vector2d P[3];

  int local(int id) const {
    for (size_t i = 0; i < ids.size(); ++i)
      if (ids[i] == id) return static_cast<int>(i);
    return -1;
  }
  int add(int id, const Eigen::Vector3d& w, int mask) {
    const int l = local(id);
    if (l >= 0) return l;
    ids.push_back(id), bary.push_back(w), edgeMask.push_back(mask);
    pts.push_back(w[0] * P[0] + w[1] * P[1] + w[2] * P[2]);
    return static_cast<int>(ids.size()) - 1;
  }
};

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

class Cutter {
 public:
  Cutter(const TriMesh& m, const MeshTopology& topo, const std::vector<SeamCurve>& seams, double tol)
      : m_(m), topo_(topo), seams_(seams), reg_(m, topo, tol), byFace_(m.numTriangles()) {}

  CutMesh run() {
    registerSeams();
    for (int f = 0; f < m_.numTriangles(); ++f) cutFace(f);
    out_.mesh.V.resize(static_cast<int>(reg_.origin.size()), 3);
    for (int i = 0; i < out_.mesh.V.rows(); ++i) out_.mesh.V.row(i) = position(m_, reg_.origin[i]).transpose();
    out_.mesh.F.resize(static_cast<int>(tris_.size()), 3);
    for (int t = 0; t < out_.mesh.F.rows(); ++t)
      for (int k = 0; k < 3; ++k) out_.mesh.F(t, k) = tris_[t][k];
    out_.vertexOrigin = reg_.origin;
    return std::move(out_);
  }

 private:
  void registerSeams() {
    for (int s = 0; s < static_cast<int>(seams_.size()); ++s) {
      const SeamCurve& c = seams_[s];
      std::vector<int> chain;
      for (const PathPoint& p : c.points) chain.push_back(reg_.add(p.point));
      for (size_t i = 0; i + 1 < chain.size(); ++i)
        if (chain[i] != chain[i + 1]) byFace_[c.faces[i]].push_back({chain[i], chain[i + 1], c.faces[i], s});
      // A seam passing twice through one point touches itself; points merged into one (a path through a vertex)
      // pass once.
      std::vector<int> passes;
      for (int id : chain)
        if (passes.empty() || passes.back() != id) passes.push_back(id);
      for (size_t i = 0; i < passes.size(); ++i)
        for (size_t j = i + 2; j < passes.size(); ++j)
          if (passes[i] == passes[j] && !(c.closed && i == 0 && j + 1 == passes.size()))
            out_.selfCrossings.push_back({s, position(m_, reg_.origin[passes[i]])});
      out_.seamVertices.push_back(std::move(chain));
    }
  }

  FaceCut collect(int f) {
    FaceCut fc;
    const Eigen::Vector3d v0 = m_.V.row(m_.F(f, 0)), v1 = m_.V.row(m_.F(f, 1)), v2 = m_.V.row(m_.F(f, 2));
    const Eigen::Vector3d u = (v1 - v0).normalized();
    fc.P[0] = {0, 0}, fc.P[1] = {(v1 - v0).norm(), 0}, fc.P[2] = {(v2 - v0).dot(u), (v2 - v0).cross(u).norm()};
    for (int k = 0; k < 3; ++k) fc.add(m_.F(f, k), Eigen::Vector3d::Unit(k), (1 << k) | (1 << ((k + 2) % 3)));
    for (int k = 0; k < 3; ++k) {
      const int e = topo_.faceEdges(f, k);
      for (const auto& [t, id] : reg_.onEdge[e]) {
        Eigen::Vector3d w = Eigen::Vector3d::Zero();
        w[topo_.cornerOf(m_, f, topo_.E(e, 0))] = 1 - t, w[topo_.cornerOf(m_, f, topo_.E(e, 1))] = t;
        fc.add(id, w, 1 << k);
      }
    }
    for (int id : reg_.inFace[f]) fc.add(id, reg_.origin[id].bary, 0);
    return fc;
  }

  void markSeam(int a, int b, int seam) { out_.seamEdge.emplace(edgeKey(a, b), seam); }

  // A piece along face edge k: every point of that edge between its ends joins the seam.
  void markAlongEdge(const FaceCut& fc, int la, int lb, int k, int seam) {
    const Eigen::Vector2d d = fc.P[(k + 1) % 3] - fc.P[k];
    const double ta = d.dot(fc.pts[la] - fc.P[k]), tb = d.dot(fc.pts[lb] - fc.P[k]);
    std::vector<std::pair<double, int>> on;
    for (size_t i = 0; i < fc.ids.size(); ++i) {
      const double t = d.dot(fc.pts[i] - fc.P[k]);
      if ((fc.edgeMask[i] >> k & 1) && t >= std::min(ta, tb) && t <= std::max(ta, tb)) on.emplace_back(t, fc.ids[i]);
    }
    std::sort(on.begin(), on.end());
    for (size_t i = 0; i + 1 < on.size(); ++i) markSeam(on[i].second, on[i + 1].second, seam);
  }

  void cutFace(int f);

  const TriMesh& m_;
  const MeshTopology& topo_;
  const std::vector<SeamCurve>& seams_;
  PointRegistry reg_;
  std::vector<std::vector<Piece>> byFace_;
  std::vector<std::array<int, 3>> tris_;
  CutMesh out_;
};

void Cutter::cutFace(int f) {
  // Most faces no seam touches: kept as they are, without the frame and lists a cut face needs.
  if (byFace_[f].empty() && reg_.inFace[f].empty() && reg_.onEdge[topo_.faceEdges(f, 0)].empty() &&
      reg_.onEdge[topo_.faceEdges(f, 1)].empty() && reg_.onEdge[topo_.faceEdges(f, 2)].empty()) {
    tris_.push_back({m_.F(f, 0), m_.F(f, 1), m_.F(f, 2)});
    out_.faceOrigin.push_back(f);
    return;
  }
  FaceCut fc = collect(f);
  const double scale = (fc.P[1] - fc.P[0]).norm() + (fc.P[2] - fc.P[1]).norm() + fc.P[2].norm();
  const double eps = 1e-10 * scale;
  struct Inner {
    int la, lb, seam;
    std::vector<std::pair<double, int>> splits;
  };
  std::vector<Inner> inner;
  for (const Piece& p : byFace_[f]) {
    const int la = fc.local(p.a), lb = fc.local(p.b);
    if (la < 0 || lb < 0) {
      ++out_.unrecoveredPieces;
      continue;
    }
    const int common = fc.edgeMask[la] & fc.edgeMask[lb];
    if (common) {
      markAlongEdge(fc, la, lb, common & 1 ? 0 : (common & 2 ? 1 : 2), p.seam);
      continue;
    }
    inner.push_back({la, lb, p.seam, {}});
  }
  // crossings between pieces: new points inside the face
  for (size_t i = 0; i < inner.size(); ++i)
    for (size_t j = i + 1; j < inner.size(); ++j) {
      Inner &p = inner[i], &q = inner[j];
      if (p.la == q.la || p.la == q.lb || p.lb == q.la || p.lb == q.lb) continue;
      const Eigen::Vector2d a = fc.pts[p.la], b = fc.pts[p.lb], c = fc.pts[q.la], d = fc.pts[q.lb];
      const double o1 = cross2(b - a, c - a), o2 = cross2(b - a, d - a);
      const double o3 = cross2(d - c, a - c), o4 = cross2(d - c, b - c);
      const double lp = (b - a).norm(), lq = (d - c).norm();
      if (!((o1 > eps * lp && o2 < -eps * lp) || (o1 < -eps * lp && o2 > eps * lp))) continue;
      if (!((o3 > eps * lq && o4 < -eps * lq) || (o3 < -eps * lq && o4 > eps * lq))) continue;
      const double s = o3 / (o3 - o4), u = o1 / (o1 - o2);
      SurfacePoint x;
      x.face = f, x.bary = (1 - s) * fc.bary[p.la] + s * fc.bary[p.lb];
      const int id = reg_.addInFace(x);
      const int lx = fc.add(id, reg_.origin[id].bary, 0);
      p.splits.emplace_back(s, lx), q.splits.emplace_back(u, lx);
      if (p.seam == q.seam) out_.selfCrossings.push_back({p.seam, position(m_, x)});
    }
  // points lying on a piece (T-junctions, control points of other seams): split the piece there
  std::vector<std::pair<int, int>> constraints;
  for (Inner& p : inner) {
    const Eigen::Vector2d a = fc.pts[p.la], d = fc.pts[p.lb] - a;
    for (size_t i = 0; i < fc.pts.size(); ++i) {
      const double t = d.dot(fc.pts[i] - a) / d.squaredNorm();
      if (static_cast<int>(i) == p.la || static_cast<int>(i) == p.lb || t <= 0 || t >= 1) continue;
      if (std::abs(cross2(d, fc.pts[i] - a)) <= eps * d.norm()) p.splits.emplace_back(t, static_cast<int>(i));
    }
    p.splits.emplace_back(0.0, p.la), p.splits.emplace_back(1.0, p.lb);
    std::sort(p.splits.begin(), p.splits.end());
    for (size_t i = 0; i + 1 < p.splits.size(); ++i) {
      const int u = p.splits[i].second, w = p.splits[i + 1].second;
      if (u == w) continue;
      constraints.emplace_back(u, w);
      markSeam(fc.ids[u], fc.ids[w], p.seam);
    }
  }
  if (fc.ids.size() == 3) {
    tris_.push_back({m_.F(f, 0), m_.F(f, 1), m_.F(f, 2)});
    out_.faceOrigin.push_back(f);
    return;
  }
  int failed = 0;
  for (const auto& t : triangulateFace(fc.pts, constraints, &failed)) {
    tris_.push_back({fc.ids[t[0]], fc.ids[t[1]], fc.ids[t[2]]});
    out_.faceOrigin.push_back(f);
  }
  out_.unrecoveredPieces += failed;
}

}  // namespace

CutMesh cutAlongSeams(const TriMesh& target, const MeshTopology& topo, const std::vector<SeamCurve>& seams,
                      double tol) {
  return Cutter(target, topo, seams, tol).run();
}

}  // namespace billow
