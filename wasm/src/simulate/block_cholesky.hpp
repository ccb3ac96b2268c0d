// Sparse Cholesky factorization H = L L^T of a symmetric positive definite matrix made of 3x3 vertex blocks
// (the inflation Hessian), by the multifrontal method on supernodes:
//   analyze():  a fill-reducing ordering of the *vertices* (nested dissection by coordinate bisection, AMD on
//               the vertex graph, or the one of the two with less work), the elimination tree, its postorder,
//               supernodes (chains of columns with nested structure, merged further when few zeros are added)
//               and, for every nonzero of H, its slot in a frontal matrix. Once per mesh.
//   factorize(): per supernode, a dense frontal matrix = entries of H + the children's update matrices
//               (extend-add), a dense partial Cholesky (blocked, with our own SIMD rank-update kernel, see
//               block_cholesky.cpp) and the update matrix for the parent.
//   solve():    forward and backward substitution over the supernodes.
// Why not Eigen's SimplicialLDLT: it is column-by-column scalar code; on these meshes the dense kernels of
// the supernodes run several times faster for the same fill (bench/README.md).
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace billow {

class BlockCholesky {
 public:
  // FewerFlops: whichever of the two needs fewer (judged by the column counts of L).
  enum class Ordering { NestedDissection, Amd, FewerFlops };

  // H: the lower triangle (row >= column) of a 3n x 3n symmetric matrix, compressed column storage. The
  // pattern must be closed under 3x3 vertex blocks' lower parts. points: n x 3 vertex positions for the
  // nested dissection (ignored for Amd). The same pattern must be passed to factorize().
  void analyze(const Eigen::SparseMatrix<double>& H, const Eigen::MatrixXd& points,
               Ordering ordering = Ordering::NestedDissection);
  // False when H is not (numerically) positive definite; the factor is then unusable. With raisedPivot > 0
  // it is a modified Cholesky instead and never fails: every pivot (diagonal entry of the Schur complement)
  // <= tinyPivot is replaced by max(raisedPivot, |pivot|), so the factor is that of H + E with E >= 0
  // diagonal, nonzero only where H is indefinite or singular; raisedPivots() counts them.
  bool factorize(const Eigen::SparseMatrix<double>& H, double tinyPivot = 0, double raisedPivot = 0);
  int raisedPivots() const { return raised_; }
  // Solves H x = b in place.
  void solve(Eigen::VectorXd& b) const;

  bool analyzed() const { return n_ > 0; }
  double factorNonZeros() const;  // entries stored in L (dense supernode panels)
  double factorFlops() const;     // multiply-adds of one factorization
  int numSupernodes() const { return int(first_.size()) - 1; }

 private:
  // analyze()'s last phases: the supernodes' parents, rows and update maps; the scatter map of H into the fronts
  // and the factor's storage. superOf: each new vertex's supernode.
  void buildRowStructure(const std::vector<std::vector<int>>& g, const std::vector<int>& pinv,
                         const std::vector<int>& etree, const std::vector<int>& superOf);
  void buildScatterMap(const Eigen::SparseMatrix<double>& H, const std::vector<int>& pinv,
                       const std::vector<int>& superOf);

  int n_ = 0;                  // vertices
  int raised_ = 0;             // pivots raised by the last factorize()
  std::vector<int> perm_;      // new vertex -> old vertex
  std::vector<int> first_;     // supernode s owns new vertices [first_[s], first_[s+1])
  std::vector<int> rowStart_;  // rows of s (new vertices, own columns first): rows_[rowStart_[s] ..]
  std::vector<int> rows_;
  std::vector<int> parent_;       // supernode parent, -1 at a root
  std::vector<int> numChildren_;  // supernode children (their update matrices lie on top of the stack)
  std::vector<int> relStart_;     // s's update rows as scalar positions in its parent's front: rel_[..]
  std::vector<int> rel_;
  std::vector<int> scatterStart_;  // entries of H landing in s's front: (value index, front position)
  std::vector<int> scatterFrom_, scatterTo_;
  std::vector<size_t> panelStart_;  // L panel of s: m x k column-major, m = 3 #rows, k = 3 #columns
  std::vector<double> panels_;
  std::vector<double> stack_;  // update matrices waiting for their parent
  Eigen::MatrixXd front_;
  std::vector<double> pack_;  // packed columns for the dense rank update
  mutable Eigen::VectorXd work_;
};

}  // namespace billow
