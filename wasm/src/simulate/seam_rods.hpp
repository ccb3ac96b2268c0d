// Seam stiffness: each seam line resists bending like a thin rod.
//
// Why: the relaxed membrane (tension field theory, no bending) lets a seam crimp at the scale of the mesh at
// no cost, and a crimped seam encloses more volume. On the Mylar balloon the rim scallops (its radius varies
// by ~2 % from vertex to vertex), so refining the mesh moves the shape away from Paulsen's instead of towards
// it (thickness / rim 1.1999 at 700 triangles, 1.2123 at 3k, 1.2210 at 6k; Paulsen 1.1981), and Newton
// creeps for a hundred iterations while the scallops grow (162 iterations at 15k). A seam is a strip of
// doubled, stitched or sealed sheet, stiffer than the panels; modelling that stiffness removes the
// mesh-scale crimps (bench/README.md "Seam stiffness").
//
// The energy: for consecutive seam vertices a, b, c (b a seam vertex between two sewn edges of its panels),
// w c_rod |x_a - 2 x_b + x_c|^2, the discrete rod energy k kappa^2 l with
// kappa = |x_a - 2 x_b + x_c| / l^2, so c_rod = k / l^3 (l the mean rest edge length). It is quadratic: a
// constant Hessian 2 c_rod w w^T (x) I_3, w = (1, -2, 1), which couples only consecutive seam vertices (the
// factorization barely grows). On a smooth seam the force it exerts is a fourth difference, about
// k l / R^3 per vertex for a seam of radius of curvature R: nothing next to the pressure loads.
// The stiffness is relative to the structure: k = beta p R^4, R the radius of the sphere with the outer
// panels' area, so a balloon and a parade float of the same shape behave alike (InflateOptions).
// The weight w is 1 where the seam runs smoothly in its panels and fades to 0 at a corner (seamRodWeight): a
// corner of a panel's outline is meant as a corner of the seam (the pillow's corners, a seam's end at a
// junction, the gores' poles), and a rod there would round it off.
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "simulate/sewn_pattern.hpp"

namespace billow {

struct SeamRods {
  std::vector<std::array<int, 3>> triples;  // simulation vertices a, b, c
  std::vector<double> weights;              // w of each triple, in [0, 1]
  std::vector<std::vector<int>> panels;     // of each triple: the panels whose outline runs a, b, c (w is judged there)
  double coefficient = 0;                   // c_rod [N/m]

  bool empty() const { return triples.empty() || !(coefficient > 0); }
  double energy(const Eigen::Ref<const Eigen::MatrixXd>& x) const;
  // grad (3 #V) += dE/dx.
  void addGradient(const Eigen::Ref<const Eigen::MatrixXd>& x, Eigen::VectorXd& grad) const;
  // The constant Hessian, entry by entry: visit(row, col, value) for every (row, col) of the full 3 #V
  // square matrix (both triangles; repeated entries add up).
  template <class Visit>
  void forEachHessianEntry(Visit visit) const {
    static constexpr double w[3] = {1, -2, 1};
    for (size_t r = 0; r < triples.size(); ++r) {
      const auto& t = triples[r];
      const double c = 2 * coefficient * weights[r];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          for (int i = 0; i < 3; ++i) visit(3 * t[a] + i, 3 * t[b] + i, c * w[a] * w[b]);
    }
  }
};

// c_rod = beta p R^4 / l^3 for this mesh (R, l: see above); 0 when beta <= 0.
double seamRodCoefficient(const SewnMesh& mesh, double pressure, double beta);
// The same from the outer panels' rest area (R^2 = area / 4 pi) and the mean rest edge length l.
double seamRodCoefficient(double outerArea, double meanEdgeLength, double pressure, double beta);

// The weight of a rod whose middle vertex turns by `turn` radians in its panel at rest: 1 up to 30 degrees, 0
// from 60 on, a smoothstep between; its derivative in *dWeight. Why a fade and not a cut-off: the pattern
// optimizer moves the outlines, and a rod switched on or off as a corner passes a threshold made the
// inflated shape jump, so the optimizer's rods and the cut panels' own parted (bench/README.md).
double seamRodWeight(double turn, double* dWeight = nullptr);

// The rods of every seam of the mesh with the given coefficient: one triple for every seam vertex between two
// sewn edges of its panels (once, not once per panel), weighted by its largest turn in any of its panels
// (seamRodWeight; 0 at corners). A seam shared by three panels (an internal panel sewn into a seam) carries
// rods like any other: without them its crease crimped, and Newton chattered there (sphere3-internal at 20k
// triangles: 103 iterations, 25 with them).
SeamRods makeSeamRods(const SewnMesh& mesh, double coefficient);

}  // namespace billow
