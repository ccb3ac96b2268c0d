// Edge connectivity and point location (see mesh_topology.hpp).
#include "seams/mesh_topology.hpp"

#include <cmath>
#include <string>

#include "util/error.hpp"

namespace billow {

int MeshTopology::edgeBetween(int a, int b) const {
  for (const auto& [u, e] : neighbors[a])
    if (u == b) return e;
  return -1;
}

int MeshTopology::cornerOf(const TriMesh& mesh, int f, int v) const {
  for (int k = 0; k < 3; ++k)
    if (mesh.F(f, k) == v) return k;
  return -1;
}

int MeshTopology::rotate(const TriMesh& mesh, int f, int v, int dir) const {
  const int k = cornerOf(mesh, f, v);
  if (k < 0) return -1;
  const int e = faceEdges(f, dir > 0 ? k : (k + 2) % 3);
  return edgeFaces(e, 0) == f ? edgeFaces(e, 1) : edgeFaces(e, 0);
}

MeshTopology buildTopology(const TriMesh& mesh) {
  MeshTopology t;
  const int nv = mesh.numVertices(), nf = mesh.numTriangles();
  t.neighbors.assign(nv, {});
  t.vertexFace.assign(nv, -1);
  t.angleSum.assign(nv, 0.0);
  t.faceEdges.resize(nf, 3);
  std::vector<std::pair<int, int>> ends;
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3), c = mesh.F(f, (k + 2) % 3);
      t.vertexFace[a] = f;
      const Eigen::Vector3d u = mesh.V.row(b) - mesh.V.row(a), w = mesh.V.row(c) - mesh.V.row(a);
      t.angleSum[a] += std::atan2(u.cross(w).norm(), u.dot(w));
      int e = t.edgeBetween(a, b);
      if (e < 0) {
        e = static_cast<int>(ends.size());
        ends.emplace_back(std::min(a, b), std::max(a, b));
        faces.emplace_back();
        t.neighbors[a].emplace_back(b, e);
        t.neighbors[b].emplace_back(a, e);
      }
      faces[e].push_back(f);
      t.faceEdges(f, k) = e;
    }
  }
  t.E.resize(static_cast<int>(ends.size()), 2);
  t.edgeFaces.resize(static_cast<int>(ends.size()), 2);
  for (int e = 0; e < static_cast<int>(ends.size()); ++e) {
    if (faces[e].size() != 2)
      throw Error("seams.not-closed", "Seams need a closed shape: an edge of this target has " +
                                          std::to_string(faces[e].size()) + " triangles instead of 2.");
    t.E(e, 0) = ends[e].first, t.E(e, 1) = ends[e].second;
    t.edgeFaces(e, 0) = faces[e][0], t.edgeFaces(e, 1) = faces[e][1];
  }
  return t;
}

SurfaceLocation locate(const TriMesh& mesh, const MeshTopology& topo, const SurfacePoint& p, double tol) {
  SurfaceLocation loc;
  loc.face = p.face;
  int zeros = 0, nonzero = -1;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(p.bary[k]) <= tol)
      ++zeros;
    else
      nonzero = k;
  }
  if (zeros >= 2) {
    loc.kind = SurfaceLocation::Vertex;
    loc.vertex = mesh.F(p.face, nonzero);
    return loc;
  }
  for (int k = 0; k < 3; ++k) {
    if (std::abs(p.bary[k]) > tol) continue;
    // zero weight at corner k: the point is on the edge from corner k+1 to k+2
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    loc.kind = SurfaceLocation::Edge;
    loc.edge = topo.faceEdges(p.face, a);
    const double s = p.bary[b] / (p.bary[a] + p.bary[b]);  // from F(face,a) to F(face,b)
    loc.t = mesh.F(p.face, a) == topo.E(loc.edge, 0) ? s : 1 - s;
    return loc;
  }
  return loc;
}

SurfacePoint vertexPoint(const TriMesh& mesh, const MeshTopology& topo, int v) {
  SurfacePoint p;
  p.face = topo.vertexFace[v];
  p.bary[topo.cornerOf(mesh, p.face, v)] = 1.0;
  return p;
}

SurfacePoint edgePoint(const TriMesh& mesh, const MeshTopology& topo, int e, double t) {
  SurfacePoint p;
  p.face = topo.edgeFaces(e, 0);
  p.bary[topo.cornerOf(mesh, p.face, topo.E(e, 0))] = 1 - t;
  p.bary[topo.cornerOf(mesh, p.face, topo.E(e, 1))] = t;
  return p;
}

bool expressInFace(const TriMesh& mesh, const MeshTopology& topo, const SurfacePoint& p, int f, SurfacePoint& out,
                   double tol) {
  if (p.face == f) return out = p, true;
  const SurfaceLocation loc = locate(mesh, topo, p, tol);
  out = SurfacePoint();
  out.face = f;
  if (loc.kind == SurfaceLocation::Vertex) {
    const int k = topo.cornerOf(mesh, f, loc.vertex);
    if (k < 0) return false;
    out.bary[k] = 1.0;
    return true;
  }
  if (loc.kind == SurfaceLocation::Edge) {
    const int k0 = topo.cornerOf(mesh, f, topo.E(loc.edge, 0)), k1 = topo.cornerOf(mesh, f, topo.E(loc.edge, 1));
    if (k0 < 0 || k1 < 0) return false;
    out.bary[k0] = 1 - loc.t, out.bary[k1] = loc.t;
    return true;
  }
  return false;
}

}  // namespace billow
