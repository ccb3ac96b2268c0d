// Start positions for the equilibrium solver. Flat panels folded onto each other enclose no volume and sit
// exactly at the corner of the relaxed energy (zero stiffness), so Newton cannot start there. Instead the
// sewn outer surface (genus 0 after sewing) is mapped onto a sphere of the same area:
//   1. spectral embedding: the three lowest non-constant eigenvectors of the uniform graph Laplacian
//      (inverse subspace iteration, one sparse factorization), rows normalized onto the unit sphere;
//   2. projected Laplacian relaxation (x_i <- normalize(mean of neighbours), re-centred) until no triangle
//      faces inwards, which untangles the few folds the spectral map leaves;
//   3. scaled to radius sqrt(A / 4 pi) and mirrored if needed so triangles face outwards.
// Vertices of internal panels only are placed by harmonic interpolation (Jacobi) from the outer ones.
#pragma once
#include "simulate/sewn_pattern.hpp"

namespace billow {

Vertices sphericalStart(const SewnMesh& mesh);

// Averages the pattern's "inflated" panel-vertex positions onto the simulation vertices.
// Returns an empty matrix when the pattern has none.
Vertices startFromInflated(const Pattern& pattern, const SewnMesh& mesh);

}  // namespace billow
