// Remeshing during pattern optimization (Skouras et al. 2014, Sec. 5.3). As the optimizer moves the panel
// vertices, triangles of the rest (2D) mesh can degrade; then every panel is meshed again from its current
// outline:
//   1. the boundary pieces that are sewn together (two panels across a seam, and an internal panel's side
//      sewn onto them) get one segment count N = max(1, round(L / h)), L their mean current 2D length;
//   2. each piece is resampled by its own 2D arc length into N segments, corners kept exactly;
//   3. the interior is meshed anew at edge length h (meshPanel: constrained Delaunay refinement);
//   4. stitches are made again (sample k of a piece to sample N - k of its partner);
//   5. what each panel vertex carries comes over: the target position (s_j of Eq. 10 on seams) and the
//      inflated position, along the old piece on the boundary and by barycentric location inside; a seam corner
//      the pattern marks, to the nearest new outline vertex along its piece.
#pragma once
#include <vector>

#include "pattern/build_pattern.hpp"

namespace billow {

// The smallest angle [degrees] of the panels' rest triangles (2D).
double minPanelAngleDeg(const Pattern& pattern);

struct RemeshedPattern {
  BuiltPattern built;              // panels, stitches, pieces, target positions; pattern.inflated carried
  std::vector<Vertices> inflated;  // per panel, #v by 3: the carried inflated positions (= built.pattern.inflated)
};

// built: the pattern as optimized so far (its panels' current vertices, the pieces and targets of the
// builder); inflated: per panel, the inflated position of every panel vertex [m]; h: the edge length [m].
// Throws billow::Error("pattern.remesh-failed") when a panel's outline no longer bounds a simple polygon
// (the caller keeps the old mesh).
RemeshedPattern remeshPattern(const BuiltPattern& built, const std::vector<Vertices>& inflated, double h);

}  // namespace billow
