// The objective of pattern optimization (Skouras et al. 2014, Sec. 5.1; DESIGN.md "Pattern optimization"):
//   E(x, X) = E_target(x) + E_seam(x) + E_length(X) + E_smooth(X) + E_laplace(X).
// Every term is normalized to the model: residuals in meters are divided by the target's bounding-box
// diagonal D, and sums by the number n of simulation vertices, so a weight of 1 means "one meter of this
// residual costs as much as one meter of distance to the target at an average vertex".
//   E_target  = w_t sum_i (A_i / A_mean) d(x_i)^2 / (n D^2), d the IMLS distance (Eq. 9 squared), A_i the
//               lumped rest area of outer vertex i;
//   E_seam    = w_s sum_j sigma_j |x_j - s_j|^2 / (n D^2) over seam vertices (Eq. 10);
//   E_length  = w_l sum_e (L_a - L_b)^2 / (n D^2) over pairs of stitched boundary edges (Eq. 11);
//   E_smooth  = w_b sum_j |Q_l - 2 Q_j + Q_r|^2 / (n D^2) over non-corner boundary vertices (Eq. 12);
//   E_laplace = w_L sum_j |X_j - mean(X_k, k ~ j)|^2 / (n D^2) over interior vertices (Eq. 13, Tutte).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "optimize/imls_distance.hpp"
#include "pattern/build_pattern.hpp"

namespace billow {

struct OptimizeWeights {
  double target = 1.0;    // E_target
  double seam = 1.0;      // multiplies every seam's sigma_i (the design's seam weight)
  double length = 10.0;   // E_length; the final seam-length projection makes it exact (see PatternOptimizer)
  double smooth = 0.05;   // E_smooth
  double laplace = 0.01;  // E_laplace: only needs to remove the interior sliding null space
};

struct ObjectiveTerms {
  double target = 0, seam = 0, length = 0, smooth = 0, laplace = 0;
  double total() const { return target + seam + length + smooth + laplace; }
};

class PatternObjective {
 public:
  struct SeamVertex {
    int vertex = 0;  // simulation vertex
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    double sigma = 1;
  };
  struct EdgePair {
    int a0 = 0, a1 = 0, b0 = 0, b1 = 0;  // panel-vertex ids (global); edge a0-a1 is sewn to b0-b1
  };

  // seamWeights[s]: sigma of seam s (BuiltPanel::seam ids); missing entries count 1.
  PatternObjective(const ImlsDistance& imls, const BuiltPattern& built, const SewnMesh& mesh,
                   const std::vector<double>& seamWeights, const OptimizeWeights& weights);

  // E_target + E_seam at simulation positions x (#V by 3); grad (3 #V) when given.
  double shapeEnergy(const Vertices& x, Eigen::VectorXd* grad, ObjectiveTerms* terms = nullptr) const;
  // E_length + E_smooth + E_laplace at pattern coordinates X (2 per panel vertex, sewn order).
  double patternEnergy(const Eigen::VectorXd& X, Eigen::VectorXd* grad, ObjectiveTerms* terms = nullptr) const;

  // Max over stitched edge pairs of |L_a - L_b| / ((L_a + L_b) / 2), and the same per piece pair.
  double maxEdgeMismatch(const Eigen::VectorXd& X) const;
  double maxPieceMismatch(const Eigen::VectorXd& X) const;

  double seamWeight(const SeamVertex& s) const { return w_.seam * s.sigma * norm_; }  // of |x_j - s_j|^2
  const ImlsDistance& imls() const { return imls_; }
  const std::vector<EdgePair>& edgePairs() const { return pairs_; }
  const std::vector<SeamVertex>& seamVertices() const { return seams_; }
  const Eigen::VectorXd& targetWeights() const { return targetWeight_; }  // #V, includes 1/(n D^2) and w_t
  double modelSize() const { return D_; }                                 // bounding-box diagonal [m]
  double meanEdgeLength() const { return edge_; }
  int numVertices() const { return n_; }

 private:
  struct Triple {
    int l, j, r;
  };
  struct PiecePair {
    std::vector<int> a, b;  // rows (global ids) of the two pieces, b reversed so a[k] ~ b[k]
  };
  const ImlsDistance& imls_;
  OptimizeWeights w_;
  int n_ = 0;
  double D_ = 1, edge_ = 1, norm_ = 1;  // norm_ = 1 / (n D^2)
  Eigen::VectorXd targetWeight_;
  std::vector<SeamVertex> seams_;
  std::vector<EdgePair> pairs_;
  std::vector<PiecePair> piecePairs_;
  std::vector<Triple> boundary_;
  std::vector<int> interior_, ringStart_, ring_;  // interior vertex -> neighbours ring_[ringStart_[i]..]
};

}  // namespace billow
