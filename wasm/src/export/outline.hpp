// Panel outlines and seams: each panel's boundary loop and, per boundary edge, the seam it belongs to.
// A seam is a maximal run of boundary edges sewn to one run of edges of one other panel (or of the same
// panel elsewhere, as on a cone); boundary edges not sewn to anything are free edges (openings, hems).
// Seam ids are stable (panel order, then loop order from the panel's first junction) and shared by both
// panels of the seam.
#pragma once
#include <vector>

#include "export/polygon.hpp"
#include "pattern/pattern.hpp"

namespace billow {

struct PanelOutline {
  std::vector<int> loop;      // #b panel vertex indices, counterclockwise; edge i runs loop[i] -> loop[(i+1) % b]
  std::vector<int> edgeSeam;  // #b seam id of edge i, -1 for a free edge
  Polygon2 points(const Panel& panel, double scale = 1.0) const;  // loop positions x scale
};

// One side of a seam: panel edges listed in the seam's own direction. Both sides of a seam start at the same
// sewn point (the seam's start junction) and run the same way when sewn; `forward` says whether that way is
// the panel's counterclockwise loop order (side a: always) or against it (side b of a correctly mirrored pair).
struct SeamSide {
  int panel = -1;
  std::vector<int> edges;  // loop edge indices in seam order
  bool forward = true;
  double length = 0;  // [m]
};

struct Seam {
  int id = 0;
  SeamSide a, b;
  bool closed = false;  // the seam is a whole loop with no junction (the Mylar rim); starts at a's loop[0]
  // False when b's edges already belong to another seam: a third panel (an internal connection) sewn onto
  // an existing seam. Such edges keep the other seam's id in PanelOutline::edgeSeam.
  bool shared = true;
  double mismatch() const { return a.length > b.length ? a.length - b.length : b.length - a.length; }  // [m]
};

struct Outlines {
  std::vector<PanelOutline> panels;
  std::vector<Seam> seams;
  double maxMismatch = 0;  // [m], over all seams
};

// Throws billow::Error("export.panel-shape") when a panel's boundary is not a single loop (a hole or a
// pinched corner).
Outlines buildOutlines(const Pattern& pattern);

// A point at arc length s [m] from a seam side's start (clamped to the side), with the outward unit normal
// of the panel there and the loop edge it lies on.
struct SidePoint {
  Vec2 point, normal;
  int edge = -1;
};
SidePoint pointAlongSide(const Pattern& pattern, const Outlines& outlines, const SeamSide& side, double s);

}  // namespace billow
