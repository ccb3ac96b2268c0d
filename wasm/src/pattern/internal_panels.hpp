// Internal panels (Skouras et al. 2014, Sec. 3.2 and Fig. 2; DESIGN.md "Internal connections"): an internal
// connection joins two seams with a panel inside the target that carries no pressure load. It pulls the two
// seams towards each other (creases, concave features).
//   1. each seam is read off the outer panels as a chain of stitched samples: the outer pieces along it in
//      order, each sample one group of stitched panel vertices (position: the group's mean target position),
//      parameterized by normalized arc length t;
//   2. seam b is oriented to run the same way as seam a: the direction with the smaller summed distance
//      between matched points a(t) and b(t);
//   3. the panel's target is the ruled surface between a(t) and b(t), as a strip of triangles between the two
//      sample chains (zipped by t). A triangle strip has no interior vertex, so it unfolds into the plane
//      keeping every edge length; the seam edges take the outer panels' flattened lengths, so stitched edges
//      match;
//   4. its outline (seam a, the end ruling, seam b backwards, the start ruling; rulings resampled at h, and a
//      ruling of zero length where the two seams meet is one corner) is meshed at h (meshPanel) and
//      its interior vertices are mapped back onto the strip;
//   5. the samples along a seam are pieces sewn to the outer piece there that runs the other way: a one-way
//      partner (the outer pieces keep theirs), so stitching chains three panel vertices into one point.
// Seams are matched over their whole length. Closed seams are not supported yet (the strip between two loops
// is a band, not a disk): such a connection is a problem.
#pragma once
#include "pattern/build_pattern.hpp"

namespace billow {

// Adds one internal panel per options.connections to `out`, whose panels so far are the outer panels with
// their pieces paired (called before stitching). h: the pattern's edge length [m]. Fills out.connectionPanel.
// A connection that cannot be built becomes a problem (code "pattern.connection", severity "error") in the
// designer's words. Never throws for a bad connection.
void addInternalPanels(const TriMesh& target, const Segmentation& seg, const PatternBuildOptions& options, double h,
                       BuiltPattern& out);

// Generalized winding number of the closed, outward-oriented mesh around x: 1 inside, 0 outside.
double windingNumber(const TriMesh& mesh, const Eigen::Vector3d& x);

}  // namespace billow
