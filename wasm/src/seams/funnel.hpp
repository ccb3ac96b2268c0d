// Shortest path inside a strip of triangles (internal to the geodesic solver): unfold the strip into the
// plane, run the funnel algorithm (Lee & Preparata 1984, in the simple form popularised by Mononen) and
// map the crossings back onto the mesh edges.
#pragma once
#include <vector>

#include "seams/geodesic.hpp"

namespace billow {

struct StripPath {
  GeodesicPath path;
  struct Wrap {
    int vertex;   // a mesh vertex the path bends around
    int portal;   // the strip edge (between strip[portal-1] and strip[portal]) where it happens
    double turn;  // turning angle of the path there, in the unfolded plane (radians, >= 0)
  };
  std::vector<Wrap> wraps;
};

// strip: faces, consecutive ones sharing an edge; a lies in strip.front(), b in strip.back().
StripPath straightenInStrip(const TriMesh& mesh, const MeshTopology& topo, const std::vector<int>& strip,
                            const SurfacePoint& a, const SurfacePoint& b);

}  // namespace billow
