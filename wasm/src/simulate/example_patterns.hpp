// Example patterns with well-shaped triangles at about a requested count:
//   mylar   two discs of radius `size` sewn along their rims (Paulsen's Mylar balloon, DESIGN.md)
//   pillow  two rectangles `size` wide and `aspect` x `size` long sewn along their edges (squares by default;
//           long ones are the sausages and tubes of flat-cut inflatables)
//   gusset-pillow  the pillow's two rectangles joined by a strip `size`/4 wide sewn around both (its ends sewn
//           together); the length is rounded to whole square cells
//   ring    two flat rings of outer radius `size`, the hole half as wide
//   letter-L, letter-C, star, heart   two pieces `size` high cut to that outline (a foil letter, star, heart)
//   cube    six squares of side `size`
//   sphere3 three lune-shaped gores of a sphere of radius `size` (each spans 120 degrees of longitude)
//   sphere3-internal  sphere3 plus an internal panel (a narrower gore) joining two of its seams
#pragma once
#include <string>
#include <vector>

#include "simulate/sewn_pattern.hpp"

namespace billow {

struct ExampleOptions {
  int triangles = 3000;  // about this many in total
  double size = 0.3;     // [m], see above
  double aspect = 1;     // pillow, gusset-pillow: length over width
  double pressure = 1000.0;
  Material material;  // foil defaults
};

const std::vector<std::string>& exampleNames();

// Throws billow::Error("example.unknown") for other names, "example.bad-value" for silly options.
Pattern examplePattern(const std::string& name, const ExampleOptions& options = {});

// The Mylar balloon's two figures, from an inflated `mylar` example (panel vertex 0 of each disc is its
// centre; the axis runs through the two centres, the mid-plane through the sewn rim).
//   rimRadius      mean distance of the rim vertices from the axis.
//   thickness      2 x the mean height above the mid-plane of the vertices at 0.15..0.3 rim radii from the
//                  axis, each extrapolated to the axis with Paulsen's profile z(0) = z(x) + x^3 / (3 r^2)
//                  (from z' = x^2 / sqrt(r^4 - x^4)). The pole itself is avoided: the inextensible solution
//                  has a meridional tension ~ p r^2 / (2x) that is singular there, so any finite-E sheet
//                  forms a small spike at the pole that sharpens as the mesh is refined.
//   poleThickness  the plain distance between the two centres (spike included).
struct MylarShape {
  double rimRadius = 0, thickness = 0, poleThickness = 0;
};
MylarShape measureMylar(const SewnMesh& mesh, const Vertices& x);

// Paulsen (Amer. Math. Monthly 1994): rim radius = a / 1.31103, thickness = 1.19814 x rim radius.
constexpr double kMylarRimOverDisc = 1.0 / 1.31103;
constexpr double kMylarThicknessOverRim = 1.19814;

}  // namespace billow
