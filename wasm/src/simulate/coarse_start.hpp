// A coarse-to-fine start for a bare pattern (one without start positions). Newton from the spherical start
// (initial_shape.hpp) needs more iterations the finer the mesh (the Mylar balloon: 29 at 0.7k triangles, 55
// at 15k, 121 at 60k), while from a shape that is already right at a coarser scale it needs about 15 to 20 at
// any size. So a large pattern is first coarsened (the same panels, meshed about 6 times coarser and sewn
// at a subset of the same seam vertices), the coarse pattern is inflated (itself started the same way), and
// its shape is carried onto the fine panels.
//
// Coarsening keeps every seam consistent: each of a panel's boundary loops is split at key simulation vertices
// (corners, and junctions: where a boundary changes partner or meets panels its edges do not join, as at
// the ends of free edges), and each piece between two keys keeps every stride-th vertex, decided once per
// simulation vertex, so the panels on both sides of a seam keep the same vertices and are stitched there.
// The interior is remeshed (meshPanel). Prolongation locates each fine panel vertex in its coarse
// panel (barycentric) and interpolates the coarse inflated positions, curved by Phong tessellation with the
// coarse outer surface's vertex normals (a flat interpolation starts Newton with every fine triangle flat,
// and costs a few shifted iterations more). The prolongated shape then gets Gauss-Seidel sweeps (gauss_seidel.hpp): it
// is right at the coarse scale only, and Newton from it needed twice as many iterations.
#pragma once
#include <optional>

#include "simulate/inflate.hpp"

namespace billow {

// The coarse pattern, or nothing when a panel has no outline to remesh (its boundary touches itself, or it is
// in pieces; an outline with holes, as a ring's, is remeshed with them), a loop would keep fewer than 3
// boundary vertices, or meshing fails. `h`: target edge length of the coarse panels [m].
std::optional<Pattern> coarsenPattern(const Pattern& pattern, const SewnMesh& mesh, double h);

// Positions of `fine`'s simulation vertices interpolated from the coarse pattern's inflated positions `x`.
// `fine` and `coarse` have the same panels (coarse from coarsenPattern).
Vertices prolongate(const Pattern& coarse, const SewnMesh& coarseMesh, const Vertices& x, const Pattern& fine,
                    const SewnMesh& fineMesh);

struct StartReport {
  int levels = 0;           // coarse patterns inflated (0: spherical or given start)
  int coarseTriangles = 0;  // triangles of the coarsest
  int coarseIterations = 0;
  double coarseMs = 0;  // time spent on coarsening, coarse solves, prolongation and Gauss-Seidel sweeps
  double gaussSeidelMs = 0;
  double residualProlongated = 0;  // the fine level's relative force residual before and after the Gauss-Seidel sweeps
  double residualAfterGaussSeidel = 0;
};

// The start positions for inflating `pattern`: its own start positions when it has them (the optimizer's
// target shape), else the coarse-to-fine start when it has at least options.coarseStartTriangles triangles
// (and coarsening works and the coarse solve does not fail), else bareStart (initial_shape.hpp; the coarsest
// level starts there too).
Vertices startPositions(const Pattern& pattern, const SewnMesh& mesh, const InflateOptions& options = {},
                        StartReport* report = nullptr);

}  // namespace billow
