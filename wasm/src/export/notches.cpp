#include "export/notches.hpp"

#include <cmath>

namespace billow {

std::vector<Notch> placeNotches(const Pattern& pattern, const Outlines& outlines, double spacing) {
  std::vector<Notch> out;
  auto add = [&](const Seam& seam, const SeamSide& side, double s, bool junction) {
    const SidePoint sp = pointAlongSide(pattern, outlines, side, s);
    for (const Notch& n : out)  // a junction shared by two seams gets one notch per panel
      if (junction && n.junction && n.panel == side.panel && (n.point - sp.point).norm() < 1e-9) return;
    out.push_back({side.panel, seam.id, sp.edge, s, sp.point, sp.normal, junction});
  };
  for (const Seam& seam : outlines.seams) {
    const SeamSide* sides[2] = {&seam.a, &seam.b};
    for (const SeamSide* side : sides) {
      add(seam, *side, 0.0, true);
      if (!seam.closed) add(seam, *side, side->length, true);
    }
    if (!(spacing > 0)) continue;
    const double length = 0.5 * (seam.a.length + seam.b.length);
    const int intervals = std::max(1, int(std::lround(length / spacing)));
    const double step = length / intervals;
    // Notches closer than a quarter step to either side's far end would crowd the junction notch there.
    const double end = std::min(seam.a.length, seam.b.length) - 0.25 * step;
    for (int k = 1; k < intervals && k * step < end; ++k)
      for (const SeamSide* side : sides) add(seam, *side, k * step, false);
  }
  return out;
}

}  // namespace billow
