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
#include <optional>

#include "simulate/sewn_pattern.hpp"

namespace billow {

Vertices sphericalStart(const SewnMesh& mesh);

// Two outer panels sewn to each other all around, mirror images (a foil balloon, a pillow, a flat ring, a
// letter): the second laid onto the first by their stitched outline (least squares, with reflection), then
// each lifted off the other by a dome over its own outline, z = 1/2 sqrt(2 h) with -lap h = 1 inside and h = 0
// on the outline (an ellipse half as high as wide across a strip), as sketch modellers inflate a drawing.
// From the sphere a long pillow needs hundreds of Newton iterations (bench/README.md); from this, about 20-35.
// Nothing when the pattern is not such a pair or its outlines do not match within 10 %.
std::optional<Vertices> foldedStart(const Pattern& pattern, const SewnMesh& mesh);

// The start of a bare pattern at one level: folded when it is such a pair, else the sphere.
Vertices bareStart(const Pattern& pattern, const SewnMesh& mesh);

// Averages the pattern's "inflated" panel-vertex positions onto the simulation vertices.
// Returns an empty matrix when the pattern has none.
Vertices startFromInflated(const Pattern& pattern, const SewnMesh& mesh);

}  // namespace billow
