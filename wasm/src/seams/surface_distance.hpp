// Signed distance from points to a closed target surface, for the "distance to target" view of an
// inflated shape: positive outside the target (the shape bulges), negative inside (it falls short).
#pragma once
#include <Eigen/Core>

#include "mesh/tri_mesh.hpp"
#include "seams/surface_point.hpp"

namespace billow {

// Per row of `points`: the distance to the closest point of `target`, signed by the side of the closest
// triangle's plane the point is on (outward normals: the target is a closed, outward-oriented mesh).
// Exact in magnitude; the sign is the closest triangle's, which can only err within a hair of an edge.
Eigen::VectorXd signedDistances(const TriMesh& target, const SurfaceProjector& projector, const Vertices& points);

struct DistanceSummary {
  double rms = 0, max = 0;  // of |d|, over the diagonal given
};

// RMS and max of |distances| over the points that are corners of `surface` (all points when it has no
// rows: the outer surface of an inflated shape, since internal panels are not meant to lie on the target),
// divided by `diagonal` (the target's bounding-box diagonal).
DistanceSummary summarizeDistances(const Eigen::VectorXd& distances, const Triangles& surface, double diagonal);

}  // namespace billow
