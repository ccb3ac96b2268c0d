// Registration notches: marks on both panels of a seam at the same arc length from the seam's start
// junction, measured the way the two sides run when sewn (SeamSide), so that matching notches meet when the
// pieces are pinned together; plus a notch at every seam junction (where a seam ends on a panel).
// A seam of length L gets round(L / spacing) equal intervals (L = mean of its two sides); notch k sits at
// arc length k * L / intervals on BOTH sides, so a length mismatch shows up only at the far junction.
#pragma once
#include <vector>

#include "export/outline.hpp"

namespace billow {

struct Notch {
  int panel = -1;
  int seam = -1;       // the seam that placed it
  int edge = -1;       // loop edge it lies on
  double arc = 0;      // arc length from the seam's start [m]
  Vec2 point, normal;  // on the sewing line [m], outward unit normal
  bool junction = false;
};

// spacing [m]; 0 = junction notches only. Junction notches shared by two seams are placed once per panel.
std::vector<Notch> placeNotches(const Pattern& pattern, const Outlines& outlines, double spacing);

}  // namespace billow
