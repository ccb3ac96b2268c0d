// Initial flattening of a segment into a panel (Skouras et al. 2014, Sec. 5.2): the boundary by Newton's
// method on Eq. 14 (after Wang 2008, length-preserved free boundary), the interior by one Laplacian solve
// with the boundary fixed, then a rigid placement (centred, principal axis along x, CCW triangles).
// Eq. 14's angle targets theta_j carry the segment's Gaussian curvature: a closed flat polygon turns by 2 pi
// while the 3D boundary turns by 2 pi - K, so the lengths can only be kept if the angles absorb K; they
// absorb it where a conformal map with the boundary lengths kept would (Sawhney and Crane 2017).
#pragma once
#include <string>
#include <vector>

#include "flatten/flatten_boundary.hpp"
#include "flatten/interior_map.hpp"
#include "mesh/tri_mesh.hpp"

namespace billow {

struct FlattenOptions {
  BoundaryNewtonOptions newton;  // Eq. 14: at most 50 Newton iterations, stop at max |grad| < 1e-9
  // Interior: cotangent weights (exact on developable segments) or uniform (Tutte). When the cotangent
  // solve flips a triangle, the uniform one is tried; when both flip (non-convex boundary), a local repair;
  // when that fails too, the boundary's turns are blended toward a circle's (its lengths kept) and all is
  // tried again, up to a convex boundary, where the uniform solve cannot flip a triangle (Tutte).
  // Eq. 14's angle targets theta_j: with the segment's Gaussian curvature moved to the boundary as a conformal
  // map with the boundary lengths kept would (interior_map.hpp), or the 3D angle sums with the curvature
  // defect spread along the boundary (flatten_boundary.hpp).
  bool conformalAngles = true;
  LaplacianWeights weights = LaplacianWeights::Cotangent;
  double cotangentClamp = 1e-3;      // cotangent weights below this fraction of the mean weight are raised to it
  int untangleSweeps = 200;          // sweeps of the local flip repair (0: report flips, do not repair)
  int sweepsBeforeBlending = 30;     // repair sweeps before the boundary's turns are blended toward a circle's
  bool placeOnPrincipalAxis = true;  // centre the panel at the origin, its longest axis along x
};

struct FlattenResult {
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> uv;  // #V by 2, same vertex order as the segment
  std::vector<int> boundary;          // the boundary loop (segment vertex ids), CCW on the panel
  double maxBoundaryLengthError = 0;  // max over boundary edges of |L - l| / l (panel vs segment)
  double areaRatio = 0;               // panel area / segment area
  int flippedTriangles = 0;           // triangles that fold the panel (foldsPanel; 0 unless reported)
  int newtonIterations = 0;           // Eq. 14 Newton iterations, all attempts
  double boundaryEnergy = 0;          // E_fl at the result
  double convexBlend = 0;             // how far the boundary's turns were blended toward a circle's (0: Eq. 14)
  std::string interior;  // "cotangent", "uniform", "uniform+repair", "...+convex": how the interior was placed
};

// segment: a disk-topology piece of the target (one boundary loop, CCW triangles seen from outside).
// The panel's triangles (segment.F on uv) are CCW. Throws billow::Error ("flatten.not-disk",
// "flatten.non-manifold", ...) when the segment cannot be unrolled.
FlattenResult flattenSegment(const TriMesh& segment, const FlattenOptions& options = {});

}  // namespace billow
