// Interior of a panel with its boundary fixed: one Laplacian solve (Skouras et al. 2014, Sec. 5.2), then a
// check for flipped triangles and a local repair when the boundary is not convex.
#pragma once
#include <Eigen/SparseCholesky>
#include <memory>
#include <vector>

#include "flatten/boundary_energy.hpp"
#include "mesh/tri_mesh.hpp"

namespace billow {

enum class LaplacianWeights {
  Cotangent,  // from the 3D segment; exact on a developable segment; clamped from below to stay positive
  Uniform,    // Tutte: flip-free whenever the boundary polygon is convex
};

// The Laplace equation on a segment's interior with its boundary fixed (Dirichlet): the system of each weighting
// is assembled and factorized once (a sparse SPD system, SimplicialLDLT) and kept for every solve that follows (the
// conformal angle shift, then each placement of the interior: cotangent, uniform, and again for each more convex
// boundary). On a scanned target's 90k-vertex segment one factorization takes half a second.
class InteriorLaplacian {
 public:
  // clamp: cotangent weights below clamp * (mean weight) are raised to it, so every weight is positive.
  InteriorLaplacian(const TriMesh& segment, const std::vector<char>& isBoundary, double clamp);

  // uv (#V by 2) with the rows of the boundary vertices given; the others are overwritten by the solution.
  void solve(LaplacianWeights weights, Points2& uv);

  // How much of the segment's Gaussian curvature each boundary vertex's angle takes when the segment is laid
  // flat conformally with its boundary lengths kept (scale factor u = 0 on the boundary; Sawhney and Crane 2017,
  // "Boundary First Flattening"): u_I solves A_II u_I = Omega_I (A the clamped cotangent Laplacian; Omega the
  // interior angle defects), and the boundary angle sums become theta_j + (A_BI u_I)_j. The shifts sum to the
  // total interior angle defect, so the flat turning angles then sum to 2 pi. #V entries, 0 away from the boundary.
  Eigen::VectorXd conformalAngleShift();

 private:
  struct System {
    Eigen::SparseMatrix<double> W;                            // edge weights w_ij, #V by #V
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;  // of A_II
  };
  System& system(LaplacianWeights weights);

  const TriMesh& segment_;
  const std::vector<char>& isBoundary_;
  double clamp_;
  std::vector<int> index_;  // interior vertex -> row of A_II, -1 on the boundary
  int interior_ = 0;
  std::unique_ptr<System> cotangent_, uniform_;
};

// Whether triangle f's 2D signed area is not positive (CW or degenerate): flipped on the panel.
bool isFlipped(const Triangles& F, const Points2& uv, int f);

// The boundary of a disk's triangles as next[a] = b for each boundary edge a -> b (the triangle on its left), -1
// inside.
std::vector<int> boundaryNext(const Triangles& F, int numVertices);

// Whether triangle f is flipped and so folds the panel over itself. A flipped triangle whose corners are all on the
// boundary, one of its edges a boundary edge, does not: no interior move can turn it, and it lies outside the
// outline, where the flat boundary turns the other way than the target's one triangle there (a corner sharper than
// Eq. 14's angles keep, as at a figure's armpit); the panel cut from the outline covers it without a fold.
bool foldsPanel(const Triangles& F, const Points2& uv, const std::vector<int>& next, int f);
int countFolds(const Triangles& F, const Points2& uv, const std::vector<int>& next);

// Repair of flipped triangles with the boundary fixed: sweeps over the interior vertices near flipped triangles
// (more rings each few sweeps), each moved to where the smallest signed area of its triangles is largest (a
// small LP); a move never lowers that smallest area. Returns the folds left (countFolds: a flipped triangle with
// three boundary corners lies outside the outline and cannot be moved with the boundary fixed). next: boundaryNext's.
int untangle(const Triangles& F, const std::vector<int>& next, int sweeps, Points2& uv);

}  // namespace billow
