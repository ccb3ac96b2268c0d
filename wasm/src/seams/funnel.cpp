// Funnel algorithm over an unfolded triangle strip (see funnel.hpp).
#include "seams/funnel.hpp"

#include <array>
#include <cmath>

#include "util/error.hpp"
#include "util/vec2.hpp"

namespace billow {

namespace {

struct Portal {
  Vec2 left = Vec2::Zero(), right = Vec2::Zero();
  int leftId = -1, rightId = -1;  // mesh vertices, -1 for the path's own end points
};

struct Apex {
  Vec2 p;
  int vertex;
  int portal;
};

// Third corner c of a triangle on the right of the directed segment a->b, from its 3D edge lengths.
Vec2 placeRight(const Vec2& a, const Vec2& b, double la, double lb) {
  const double d = (b - a).norm();
  const Vec2 u = (b - a) / d;
  const double x = (la * la - lb * lb + d * d) / (2 * d);
  const double y = std::sqrt(std::max(la * la - x * x, 0.0));
  return a + x * u + y * Vec2(u.y(), -u.x());
}

double dist3(const TriMesh& m, int a, int b) { return (m.V.row(a) - m.V.row(b)).norm(); }

// 2D corners of every strip face (in F order) and the portals between consecutive faces.
void unfold(const TriMesh& m, const MeshTopology& topo, const std::vector<int>& strip,
            std::vector<std::array<Vec2, 3>>& P, std::vector<Portal>& portals) {
  const int n = static_cast<int>(strip.size());
  P.resize(n);
  const int f0 = strip[0];
  const int a0 = m.F(f0, 0), b0 = m.F(f0, 1), c0 = m.F(f0, 2);
  P[0][0] = Vec2(0, 0);
  P[0][1] = Vec2(dist3(m, a0, b0), 0);
  P[0][2] = placeRight(P[0][1], P[0][0], dist3(m, b0, c0), dist3(m, a0, c0));
  portals.assign(n + 1, Portal());
  for (int i = 1; i < n; ++i) {
    const int g = strip[i - 1], f = strip[i];
    int k = 0;
    while (k < 3 && (topo.cornerOf(m, f, m.F(g, k)) < 0 || topo.cornerOf(m, f, m.F(g, (k + 1) % 3)) < 0)) ++k;
    if (k == 3) throw Error("seams.internal", "A seam path could not be followed across the shape.");
    const int a = m.F(g, k), b = m.F(g, (k + 1) % 3);
    const int ka = topo.cornerOf(m, f, a), kb = topo.cornerOf(m, f, b), kc = 3 - ka - kb;
    P[i][ka] = P[i - 1][k];
    P[i][kb] = P[i - 1][(k + 1) % 3];
    // f holds b->a, so its third corner is on the right of a->b
    P[i][kc] = placeRight(P[i][ka], P[i][kb], dist3(m, a, m.F(f, kc)), dist3(m, b, m.F(f, kc)));
    portals[i].left = P[i][kb], portals[i].leftId = b;
    portals[i].right = P[i][ka], portals[i].rightId = a;
  }
}

Vec2 planar(const std::array<Vec2, 3>& P, const SurfacePoint& s) {
  return s.bary[0] * P[0] + s.bary[1] * P[1] + s.bary[2] * P[2];
}

// The funnel proper: the apexes of the shortest path through the portals.
std::vector<Apex> funnel(const std::vector<Portal>& portals) {
  const int last = static_cast<int>(portals.size()) - 1;
  std::vector<Apex> apexes{{portals[0].left, -1, 0}};
  Vec2 apex = portals[0].left, L = apex, R = apex;
  int apexId = -1, lId = -1, rId = -1, li = 0, ri = 0;
  auto isApex = [&](const Vec2& x, int id) { return (id >= 0 && id == apexId) || (x - apex).squaredNorm() == 0; };
  for (int i = 1, guard = 0; i <= last && guard < 8 * (last + 2) * (last + 2); ++i, ++guard) {
    const Portal& q = portals[i];
    if (cross2(R - apex, q.right - apex) >= 0) {  // the right side narrows
      if (isApex(R, rId) || cross2(L - apex, q.right - apex) <= 0) {
        R = q.right, rId = q.rightId, ri = i;
      } else {  // crosses the left side: the left corner becomes the apex
        apex = L, apexId = lId;
        apexes.push_back({L, lId, li});
        R = L, rId = lId, ri = li, i = li;
        continue;
      }
    }
    if (cross2(L - apex, q.left - apex) <= 0) {  // the left side narrows
      if (isApex(L, lId) || cross2(R - apex, q.left - apex) >= 0) {
        L = q.left, lId = q.leftId, li = i;
      } else {
        apex = R, apexId = rId;
        apexes.push_back({R, rId, ri});
        L = R, lId = rId, li = ri, i = ri;
        continue;
      }
    }
  }
  apexes.push_back({portals[last].left, -1, last});
  return apexes;
}

PathPoint meshVertexPoint(const TriMesh& m, const MeshTopology& topo, int v, int face) {
  PathPoint p;
  p.vertex = v;
  p.point.face = face;
  p.point.bary[topo.cornerOf(m, face, v)] = 1;
  p.position = m.V.row(v).transpose();
  return p;
}

// Where the segment A->B crosses portal k (from its right end, t = 0, to its left end, t = 1).
PathPoint crossing(const TriMesh& m, const MeshTopology& topo, const Portal& q, int face, const Apex& A,
                   const Apex& B) {
  if (q.rightId == A.vertex || q.rightId == B.vertex) return meshVertexPoint(m, topo, q.rightId, face);
  if (q.leftId == A.vertex || q.leftId == B.vertex) return meshVertexPoint(m, topo, q.leftId, face);
  const Vec2 d = q.left - q.right, s = B.p - A.p;
  const double den = cross2(s, d);
  double t = std::abs(den) > 1e-300 ? cross2(s, A.p - q.right) / den : 0.5;
  t = std::min(1.0, std::max(0.0, t));
  if (t < 1e-12) return meshVertexPoint(m, topo, q.rightId, face);
  if (t > 1 - 1e-12) return meshVertexPoint(m, topo, q.leftId, face);
  PathPoint p;
  p.edge = topo.edgeBetween(q.rightId, q.leftId);
  p.t = q.rightId == topo.E(p.edge, 0) ? t : 1 - t;
  p.point.face = face;
  p.point.bary[topo.cornerOf(m, face, q.rightId)] = 1 - t;
  p.point.bary[topo.cornerOf(m, face, q.leftId)] = t;
  p.position = position(m, p.point);
  return p;
}

bool samePoint(const PathPoint& a, const PathPoint& b) {
  if (a.vertex >= 0 || b.vertex >= 0) return a.vertex == b.vertex;
  return (a.position - b.position).squaredNorm() == 0;
}

}  // namespace

StripPath straightenInStrip(const TriMesh& m, const MeshTopology& topo, const std::vector<int>& strip,
                            const SurfacePoint& a, const SurfacePoint& b) {
  const int n = static_cast<int>(strip.size());
  std::vector<std::array<Vec2, 3>> P;
  std::vector<Portal> portals;
  unfold(m, topo, strip, P, portals);
  portals[0].left = portals[0].right = planar(P[0], a);
  portals[n].left = portals[n].right = planar(P[n - 1], b);
  const std::vector<Apex> apexes = funnel(portals);

  StripPath out;
  GeodesicPath& g = out.path;
  auto endPoint = [&](const SurfacePoint& s) {
    PathPoint p;
    p.point = s;
    p.position = position(m, s);
    const SurfaceLocation loc = locate(m, topo, s, 1e-12);
    if (loc.kind == SurfaceLocation::Vertex) p.vertex = loc.vertex;
    if (loc.kind == SurfaceLocation::Edge) p.edge = loc.edge, p.t = loc.t;
    return p;
  };
  g.points.push_back(endPoint(a));
  size_t j = 0;
  for (int k = 1; k < n; ++k) {
    while (j + 1 < apexes.size() && apexes[j + 1].portal <= k && apexes[j + 1].portal < n) ++j;
    const PathPoint p = crossing(m, topo, portals[k], strip[k], apexes[j], apexes[j + 1]);
    if (samePoint(p, g.points.back())) continue;  // zero-length piece: keep the later face
    g.faces.push_back(strip[k - 1]);
    g.points.push_back(p);
  }
  const PathPoint e = endPoint(b);
  if (!samePoint(e, g.points.back()) || g.points.size() == 1) {
    g.faces.push_back(strip[n - 1]);
    g.points.push_back(e);
  } else {
    g.points.back() = e;
  }
  // Faces must hold both ends of their piece: a dropped zero-length piece moved the face forward.
  for (size_t i = 0; i < g.faces.size(); ++i) {
    SurfacePoint t0, t1;
    const auto holds = [&](int f) {
      return expressInFace(m, topo, g.points[i].point, f, t0, 1e-9) &&
             expressInFace(m, topo, g.points[i + 1].point, f, t1, 1e-9);
    };
    if (!holds(g.faces[i]) && holds(g.points[i + 1].point.face)) g.faces[i] = g.points[i + 1].point.face;
  }
  for (size_t i = 0; i + 1 < g.points.size(); ++i) g.length += (g.points[i + 1].position - g.points[i].position).norm();
  for (size_t i = 1; i + 1 < apexes.size(); ++i) {
    const Vec2 u = apexes[i].p - apexes[i - 1].p, w = apexes[i + 1].p - apexes[i].p;
    if (apexes[i].vertex < 0 || u.squaredNorm() == 0 || w.squaredNorm() == 0) continue;
    out.wraps.push_back({apexes[i].vertex, apexes[i].portal, std::abs(std::atan2(cross2(u, w), u.dot(w)))});
  }
  return out;
}

}  // namespace billow
