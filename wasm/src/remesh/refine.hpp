// Delaunay refinement (Ruppert 1995, with Chew's and Shewchuk's refinements) for the remesher (Sec. 5.3):
// split encroached segments, insert circumcenters of skinny or large triangles. Segments next to small input
// angles are split on concentric shells (powers of two from the corner), and skinny triangles that only exist
// because of a small input angle are left alone, so refinement terminates for any input angle.
#pragma once
#include <limits>

#include "remesh/cdt.hpp"

namespace billow {

struct RefineOptions {
  // Triangles with a smaller angle are refined. Ruppert's proof covers 20.7 degrees; up to about 33 degrees
  // terminates in practice. Near input angles below this bound, bad triangles may remain.
  double minAngleDeg = 25;
  double maxArea = std::numeric_limits<double>::infinity();        // larger triangles are refined
  double maxEdgeLength = std::numeric_limits<double>::infinity();  // triangles with a longer edge are refined
  int maxSteinerPoints = 1000000;  // safety cap on inserted points (segment splits included)
  // false: no point is ever inserted on a segment (the boundary vertices stay exactly as given, e.g. so that
  // both sides of a seam keep matching vertices); circumcenters that would encroach a segment are then not
  // inserted, so quality next to the boundary depends on the boundary spacing.
  bool allowBoundarySplits = true;
};

struct RefineStats {
  int steinerPoints = 0;     // all inserted points
  int segmentSplits = 0;     // of which on segments
  int skippedTriangles = 0;  // bad triangles left alone (small input angle, protected boundary)
  bool hitSteinerCap = false;
};

// Refines cdt in place.
RefineStats refine(Cdt& cdt, const RefineOptions& options = {});

// One shot: CDT of pslg, then refinement.
CdtResult triangulateRefined(const Pslg& pslg, const RefineOptions& options = {}, RefineStats* stats = nullptr);

}  // namespace billow
