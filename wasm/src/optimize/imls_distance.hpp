// Signed distance to the target by implicit moving least squares (Skouras et al. 2014, Eq. 9, as fixed in
// DESIGN.md "Pattern optimization"):
//     d(x) = sum_k n_k . (x - c_k) phi_k(x) / sum_k phi_k(x),   phi_k(x) = (1 - |x - c_k|^2 / h^2)^4,
// c_k the target vertices, n_k their area-weighted unit normals, h = supportScale x mean target edge length.
// Kernel neighbours come from a dense uniform grid of cell size h (coarser for a very long, thin target)
// over the target's bounding box, the kernels stored contiguously cell by cell: 27 cells per query, read
// as 9 runs of kernels.
// Curvature bias: with point normals, Eq. 9 on a surface of radius R reads about -E[rho^2] / (2R) (the
// neighbours c_k fall below the tangent plane), ~0.8 % of R at h = 2 edges on a 1280-triangle sphere. With
// correctBias the numerator uses n_k . (x - c_k) - b_k, b_k the uncorrected d(c_k): d then vanishes at
// the target vertices to second order, which is what the optimizer should aim at.
// Fallback outside the kernels' support: the signed Euclidean distance +-|x - p| to the closest target
// point p (SurfaceProjector), signed by the side of p's pseudo-normal: its face's normal inside the face, the two
// faces' sum on an edge, the angle-weighted normal at a vertex (Baerentzen and Aanaes 2005). Then the sign is
// right wherever p lies on a closed surface, and the same whichever face the search names for an edge or a vertex
// (one face's side can be wrong there, at a sharp ridge or tip). Between the two, a C1 blend by smoothstep(sum phi /
// blendThreshold), so d and its gradient stay continuous for the optimizer's line search.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/surface_point.hpp"

namespace billow {

struct ImlsOptions {
  double supportScale = 2.0;     // h = supportScale x mean target edge length (the paper: twice)
  double blendThreshold = 0.05;  // sum phi below which the closest-point fallback is blended in
  bool correctBias = true;       // subtract each kernel's own bias b_k (see above)
};

// The target faces that can be closest to any point within `reach` of `center`: those within d + 2 reach of it, d
// its own closest distance (a point q within reach has a face within d + reach, and every face that close to q lies
// within d + 2 reach of the center). One per moving point, so that its next fallback searches a few faces instead
// of the tree: the pattern optimizer asks for the same vertices at every evaluation, mostly moved a hair.
struct ClosestFaceCache {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double reach = -1;  // < 0: empty
  std::vector<int> faces;
};

class ImlsDistance {
 public:
  // target: closed, outward-oriented triangle mesh [m]. Copied (the projector needs a stable address).
  explicit ImlsDistance(const TriMesh& target, const ImlsOptions& options = {});
  ~ImlsDistance();

  // Signed distance d(x) [m], positive outside; grad receives dd/dx when given. cache, when given, holds the
  // fallback's candidate faces for points near the last one asked about with it (and is renewed when x lies
  // beyond its reach): the same d, found faster.
  double distance(const Eigen::Vector3d& x, Eigen::Vector3d* grad = nullptr, ClosestFaceCache* cache = nullptr) const;

  // The IMLS part alone (no fallback): false when no kernel reaches x. weightSum = sum phi_k(x) and, when
  // given, weightSumGrad its gradient (for the blend). Gradients are only accumulated when grad or
  // weightSumGrad is given; d is the same either way.
  bool imls(const Eigen::Vector3d& x, double* d, Eigen::Vector3d* grad, double* weightSum,
            Eigen::Vector3d* weightSumGrad = nullptr) const;
  // The fallback alone: +-|x - p|, p the closest target point, signed by the side of its pseudo-normal.
  double fallback(const Eigen::Vector3d& x, Eigen::Vector3d* grad, ClosestFaceCache* cache = nullptr) const;

  // Unsigned distance to the closest target point [m] (progress figures). face, when given, is the target face to
  // measure first (the answer for a point near this one), and receives this answer's: the same distance, found sooner.
  double closestDistance(const Eigen::Vector3d& x, int* face = nullptr) const;

  double supportRadius() const { return h_; }
  const TriMesh& target() const { return *target_; }
  const Vertices& vertexNormals() const { return normals_; }

 private:
  template <bool Gradient>
  double accumulate(const Eigen::Vector3d& x, double& N, Eigen::Vector3d& gN, Eigen::Vector3d& gD) const;
  std::unique_ptr<TriMesh> target_;
  std::unique_ptr<SurfaceProjector> projector_;
  Vertices normals_;  // #V by 3, unit, area-weighted
  Vertices faceNormals_;
  Vertices angleNormals_;        // #V by 3: angle-weighted sums of the face normals around each vertex
  std::vector<int> faceAcross_;  // 3 per face: the face across the edge opposite corner k (-1: none)
  double h_ = 0, blend_ = 0.05;
  // The grid: cell (i, j, k) of size cell_ from origin_ holds kernels cellStart_[c] .. cellStart_[c + 1] - 1,
  // c = (i dims_[1] + j) dims_[2] + k, so a column's cells k0..k1 are one contiguous run. Kernels in cell
  // order, within a cell by vertex id: the sums run (and round) as in a plain loop over the 27 cells.
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double cell_ = 0;
  int dims_[3] = {0, 0, 0};
  std::vector<int> cellStart_;
  std::vector<Eigen::Vector3d> kernelPos_, kernelNormal_;  // c_k, n_k
  std::vector<double> kernelBias_;                         // b_k, zero when !correctBias
};

}  // namespace billow
