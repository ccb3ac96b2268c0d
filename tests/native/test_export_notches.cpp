// Notches: at equal arc lengths on both sides of every seam, measured the way the sides run when sewn, so
// matching notches are the same sewn point; plus a notch at every junction.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "export/notches.hpp"
#include "simulate/example_patterns.hpp"

using namespace billow;

namespace {

std::map<int, std::vector<double>> arcsPerPanel(const std::vector<Notch>& notches, int seam) {
  std::map<int, std::vector<double>> out;
  for (const Notch& n : notches)
    if (n.seam == seam && !n.junction) out[n.panel].push_back(n.arc);
  for (auto& [panel, arcs] : out) std::sort(arcs.begin(), arcs.end());
  return out;
}

}  // namespace

TEST(Notches, EqualArcLengthsOnBothSidesOfEverySeam) {
  for (const char* name : {"mylar", "pillow", "sphere3", "sphere3-internal"}) {
    SCOPED_TRACE(name);
    ExampleOptions eo;
    eo.triangles = 600;
    const Pattern p = examplePattern(name, eo);
    const Outlines out = buildOutlines(p);
    const std::vector<Notch> notches = placeNotches(p, out, 0.05);
    for (const Seam& s : out.seams) {
      const auto arcs = arcsPerPanel(notches, s.id);
      if (s.a.panel == s.b.panel) continue;
      ASSERT_EQ(arcs.size(), 2u);
      const auto& A = arcs.at(s.a.panel);
      const auto& B = arcs.at(s.b.panel);
      ASSERT_EQ(A.size(), B.size());
      EXPECT_GE(A.size(), size_t(0.5 * s.a.length / 0.05) - 1);
      for (size_t k = 0; k < A.size(); ++k) EXPECT_NEAR(A[k], B[k], 1e-12);
      // Measured along the sides: the point at arc s really is s from the seam start along the panel edge.
      for (const Notch& n : notches)
        if (n.seam == s.id && !n.junction) {
          EXPECT_LE(n.arc, std::min(s.a.length, s.b.length));
        }
    }
  }
}

TEST(Notches, MatchingNotchesAreTheSameSewnPoint) {
  // The pillow's back is the front mirrored in y with the same vertex numbers: the notch at arc s on the
  // front must be the mirror image of the notch at arc s on the back.
  ExampleOptions eo;
  eo.triangles = 500;
  const Pattern p = examplePattern("pillow", eo);
  const Outlines out = buildOutlines(p);
  const std::vector<Notch> notches = placeNotches(p, out, 0.04);
  int matched = 0;
  for (const Notch& a : notches) {
    if (a.panel != 0) continue;
    for (const Notch& b : notches)
      if (b.panel == 1 && b.seam == a.seam && std::abs(b.arc - a.arc) < 1e-12 && a.junction == b.junction) {
        EXPECT_NEAR(a.point.x(), b.point.x(), 1e-12);
        EXPECT_NEAR(a.point.y(), -b.point.y(), 1e-12);
        ++matched;
      }
  }
  EXPECT_GE(matched, int(1.2 / 0.04) - 2);
}

TEST(Notches, JunctionsAreNotchedOncePerPanel) {
  ExampleOptions eo;
  eo.triangles = 400;
  const Pattern p = examplePattern("sphere3", eo);
  const Outlines out = buildOutlines(p);
  const std::vector<Notch> notches = placeNotches(p, out, 0);
  // Each gore has two junctions (its tips), shared by its two seams: 2 notches per gore.
  for (int g = 0; g < 3; ++g) {
    int count = 0;
    for (const Notch& n : notches) count += n.panel == g;
    EXPECT_EQ(count, 2);
  }
}
