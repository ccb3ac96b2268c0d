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
// The energy: for consecutive seam vertices a, b, c (b an ordinary seam vertex: stitched to exactly one other
// panel, not a corner of its panel), c_rod |x_a - 2 x_b + x_c|^2, the discrete rod energy k kappa^2 l with
// kappa = |x_a - 2 x_b + x_c| / l^2, so c_rod = k / l^3 (l the mean rest edge length). It is quadratic: a
// constant Hessian 2 c_rod w w^T (x) I_3, w = (1, -2, 1), which couples only consecutive seam vertices (the
// factorization barely grows). On a smooth seam the force it exerts is a fourth difference, about
// k l / R^3 per vertex for a seam of radius of curvature R: nothing next to the pressure loads.
// The stiffness is relative to the structure: k = beta p R^4, R the radius of the sphere with the outer
// panels' area, so a balloon and a parade float of the same shape behave alike (InflateOptions).
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "simulate/sewn_pattern.hpp"

namespace billow {

struct SeamRods {
  std::vector<std::array<int, 3>> triples;  // simulation vertices a, b, c
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
    for (const auto& t : triples)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          for (int i = 0; i < 3; ++i) visit(3 * t[a] + i, 3 * t[b] + i, 2 * coefficient * w[a] * w[b]);
  }
};

// c_rod = beta p R^4 / l^3 for this mesh (R, l: see above); 0 when beta <= 0.
double seamRodCoefficient(const SewnMesh& mesh, double pressure, double beta);
// The same from the outer panels' rest area (R^2 = area / 4 pi) and the mean rest edge length l.
double seamRodCoefficient(double outerArea, double meanEdgeLength, double pressure, double beta);

// The rods of every seam of the mesh with the given coefficient. A seam vertex is left out (as the middle of a
// triple) at a seam corner of its panel (SewnMesh::seamCorner: one the pattern marks, else where the seam turns by
// more than 45 degrees in its panel at rest: the pillow's corners, a seam's end at a junction, the gores' poles). A
// seam shared by three panels (an internal panel sewn into a seam) carries rods like any other: without them its crease
// crimped, and Newton chattered there (sphere3-internal at 20k triangles: 103 iterations, 25 with them).
SeamRods makeSeamRods(const SewnMesh& mesh, double coefficient);

}  // namespace billow
