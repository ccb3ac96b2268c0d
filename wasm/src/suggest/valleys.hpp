// A target's valleys across one of its own axes (a neck, a waist, where a tail or a fin root narrows): levels where
// the girth of its cross-section, the summed length of the plane section's loops, is least between wider parts on both
// sides. An inflated panel rounds over a valley; a seam laid in it lets the balloon pinch there, so a pattern maker
// chalks a band seam at the neck rather than at an even share of the height (issue 27).
#pragma once
#include <vector>

#include "mesh/tri_mesh.hpp"

namespace billow {

struct Valley {
  double level = 0;  // the plane's offset along the axis [target units]
  // 1 - its girth over the smaller of the widest girths on either side: 0.3 is a neck 30 % narrower than the head.
  double depth = 0;
};

// A valley shallower than this is left out: a band at an even share serves there as well.
constexpr double kValleyDepth = 0.2;

// The valleys across `axis`, deepest first; none within kValleyApart of the extent of a deeper one.
constexpr double kValleyApart = 0.08;
std::vector<Valley> findValleys(const TriMesh& target, int axis, double minDepth = kValleyDepth);

}  // namespace billow
