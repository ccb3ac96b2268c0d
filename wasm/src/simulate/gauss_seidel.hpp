// Nonlinear Gauss-Seidel sweeps over a shape before Newton (the smoother of a two-grid method).
//
// Why: the coarse-to-fine start (coarse_start.hpp) carries a coarse equilibrium onto a fine mesh. That shape
// is right at the coarse scale but wrong at the scale of the fine mesh: interpolated triangles are strained
// unevenly, seam rods kink at the coarse seam vertices, and the fine vertices near a pole sit where the coarse
// triangles put them. Forces reach thousands of times the pressure load on a mesh patch (sphere3 at 60k
// triangles: a relative residual of 4.4e3), and the first Newton steps are cut to a few percent by the line
// search while the shift damps them: five factorizations for the first step, six iterations to recover.
// That error is local, and local relaxation removes local error cheaply: each vertex in turn takes a damped
// Newton step on its own three coordinates, the others fixed, with a backtracking line search on the energy
// of its star (membrane, pressure work and seam rods). A sweep costs a few assemblies, far less than one
// factorization, and Newton then starts from forces of tens instead of thousands (bench/README.md
// "The start").
// The pattern optimizer sweeps before each of its equilibrium solves too, to a lower force: a step of the
// panels leaves parts of the sheet slack at the last shape, where a vertex feels only the pressure, about
// 0.4 p l^2 (bench/README.md "Gauss-Seidel sweeps before each equilibrium solve").
#pragma once
#include "simulate/inflate.hpp"

namespace billow {

struct GaussSeidelReport {
  int sweeps = 0;
  int moves = 0;              // accepted vertex steps over all sweeps
  double residualBefore = 0;  // largest relative vertex force before and after (the units of
  double residualAfter = 0;   // InflateOptions::tolerance; no vertex pinned); 0 when no sweeps or not measured
  double ms = 0;
};

// `sweeps` sweeps over the vertices of `mesh` (in index order) with the energy of InflationSolver for these
// options (band, seam rods); vertices whose relative force is below `threshold` stay where they are. Never
// increases Pi; x stays finite. `measure`: fill in residualBefore and residualAfter (a force pass each).
GaussSeidelReport gaussSeidelSweeps(const SewnMesh& mesh, const Material& material, double pressure,
                                    const InflateOptions& options, Vertices& x, int sweeps, double threshold = 1.0,
                                    bool measure = true);

}  // namespace billow
