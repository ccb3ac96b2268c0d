// The objective of pattern optimization (Skouras et al. 2014, Sec. 5.1; DESIGN.md "Pattern optimization"):
//   E(x, X) = E_target(x) + E_seam(x) + E_length(X) + E_smooth(X) + E_laplace(X) (the paper's terms)
//             + E_cover(x) + E_quality(X) + E_gap(X) + E_fair(X) (ours).
// Every term is normalized to the model: residuals in meters are divided by the target's bounding-box
// diagonal D, and sums by the number n of simulation vertices, so a weight of 1 means "one meter of this
// residual costs as much as one meter of distance to the target at an average vertex".
//   E_target  = w_t m sum_i (A_i(X) / A(X)) d(x_i)^2 / (n D^2), d the IMLS distance (Eq. 9 squared), A_i(X)
//               the lumped rest area of outer vertex i in the current pattern X, A(X) their sum, m the number
//               of outer vertices (so uniform areas give w_t sum_i d^2 / (n D^2));
//   E_seam    = w_s sum_j sigma_j |x_j - s_j|^2 / (n D^2) over seam vertices (Eq. 10);
//   E_length  = w_l sum_e (L_a - L_b)^2 / (n D^2) over pairs of stitched boundary edges (Eq. 11);
//   E_smooth  = w_b sum_j |Q_l - 2 Q_j + Q_r|^2 / (n D^2) over non-corner boundary vertices (Eq. 12);
//   E_laplace = w_L sum_j |X_j - mean(X_k, k ~ j)|^2 / (n D^2) over interior vertices (Eq. 13, Tutte).
//   E_cover   = w_c m sum_j (a_j / A_T) |c_j(x) - t_j|^2 / (n D^2) over target vertices t_j (a sample of them on a
//               target finer than the outer surface), a_j their lumped areas, A_T their sum, c_j the closest point
//               of the outer surface (ours: E_target sees only the inflated shape's points, so a part of the
//               target the shape leaves out costs it nothing; docs/architecture.md "Distance to target, both
//               ways"). Its gradient reaches x through c_j's barycentric weights (the envelope theorem).
//               Robust: |c_j - t_j|^2 enters through rho(d) = tau^2 d^2 / (d^2 + tau^2), tau = coverReach D
//               (OptimizeWeights::coverReach), so target points far from the shape saturate instead of pulling;
//               longer where c_j lies on a seam in the coarse phase (coverReachAtSeams).
//   E_quality = w_q l^2 sum_t (A0_t / A0_mean) (|J_t|^2 / (2 det J_t) - 1) / (n D^2) over rest triangles, J_t
//               the 2D map from triangle t of the flattened pattern to the current one, l the mean edge length
//               (ours, not the paper's: where the paper remeshes when elements degenerate, Sec. 5.3, this
//               barrier keeps them from degenerating; zero for rotations and uniform scalings, infinite at a
//               collapse, about w_q l^2 eps^2 / 2 per triangle for a small distortion eps).
//   E_gap     = w_g l^2 sum_(v,e) b(d(v, e) / h_v) / (n D^2) over each outline vertex v and edge e of the same
//               outline not ending at v, d their distance, b(s) = -(s - 1)^2 ln s for s < 1 and 0 beyond (the
//               barrier of IPC, Li et al. 2020; ours), h_v = min(l, v's distance to the nearest such edge in the
//               flattened pattern): a panel whose outline crosses itself cannot be cut, and where the optimizer
//               refused such steps it stopped at a thin tip of the outline; the barrier turns the steps along it.
//   E_fair    = w_f sum_j (c_j-1 - 2 c_j + c_j+1)^2 / m over the vertices j of each outline without a corner (one
//               closed seam around a flat-cut panel), c_j = theta_j(X) - theta_j(X0) the change of the outline's
//               turning angle at vertex j since the pattern X0 the objective was made for, m their count (ours): a
//               change of turning that alternates from vertex to vertex (a spike, a slit or a needle a vertex or two
//               wide) costs, a bulge spread along the outline hardly does. Unheld, the round balloon's rim gathered
//               into teeth and other outlines grew needles, which no maker cuts (bench/README.md "Teeth that are
//               left").
// Why E_target weighs by the *current* areas: it is then a quadrature of the surface integral of d^2, which
// does not change (to the order of the discretization) when pattern vertices slide within a panel together
// with their inflated positions. With weights fixed at the flattened pattern, sliding vertices into regions
// where the inflated shape is close to the target lowers E_target without changing the shape: the optimizer
// did exactly that, collapsing rest triangles until the fold check stopped every step (bench/README.md).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "optimize/imls_distance.hpp"
#include "pattern/build_pattern.hpp"

namespace billow {

struct OptimizeWeights {
  double target = 1.0;  // E_target
  double cover = 1.0;   // E_cover
  // E_cover's kernel scale tau, a fraction of the target's diagonal D: each target point costs
  // rho(d) = tau^2 d^2 / (d^2 + tau^2) (Geman-McClure), about d^2 near the shape and at most tau^2 far from it,
  // so a part of the target the shape cannot reach does not pull it (a small loop's lens on a sphere). The
  // "left out" threshold of uncoveredRegions: what the figures call left out is what stops pulling (the
  // scales tried: bench/README.md).
  double coverReach = 0.06;
  // E_cover's reach where a sample's closest point on the shape lies on the seams, blended to coverReach over
  // kCoverSeamBand inside the panels (0: coverReach everywhere). The coarse phase's (OptimizeRemeshing).
  double coverReachAtSeams = 0;
  double seam = 1.0;     // multiplies every seam's sigma_i (the design's seam weight)
  double length = 10.0;  // E_length; the final seam-length projection makes it exact (see PatternOptimizer)
  double smooth = 2.0;   // E_smooth: weaker lets the outlines zig-zag (bench/README.md)
  // E_smooth's weight is smooth x slidingSmooth along a sliding seam (sigma x seam below slidingBelow), which
  // nothing else holds (OptimizeSliding::seamWeight sets both).
  double slidingSmooth = 1.0;
  double slidingBelow = 0;
  double fair = 0.001;    // E_fair: the weights tried, bench/README.md "Teeth that are left, and E_fair"
  double laplace = 0.01;  // E_laplace: only needs to remove the interior sliding null space
  double quality = 0.01;  // E_quality
  double gap = 1.0;       // E_gap
};

// The weights that ask of a mesh of `ratio` times the design's edge length what `w` asks of the design's mesh (the
// coarse first phase): E_smooth and E_seam sum over outline and seam vertices divided by the count of all vertices,
// where E_target and E_cover are means, so against them E_seam grows as the ratio and E_smooth as its fourth power (a
// fair outline's second differences also grow as the edge length squared); E_fair as E_smooth. Unscaled, the coarse
// phase smoothed outlines the fine mesh then meshed anew instead of following the target (bench/README.md "The coarse
// first phase").
OptimizeWeights weightsAtEdgeLength(OptimizeWeights w, double ratio);

struct ObjectiveTerms {
  double target = 0, cover = 0, seam = 0, length = 0, smooth = 0, laplace = 0, quality = 0, gap = 0, fair = 0;
  double total() const { return target + cover + seam + length + smooth + laplace + quality + gap + fair; }
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

  // E_cover's terms at x: per target sample its closest point c on the outer surface, the outer triangle and
  // barycentric weights of c there, the target point t and the weight w of |c - t|^2.
  struct CoverPoint {
    Eigen::Vector3d closest, target, bary;
    int triangle = -1;  // of the outer surface (OuterTriangle order)
    double weight = 0;
    double tau2 = 0;  // the sample's kernel scale squared (of its tracked triangle: trackCover)
  };
  // E_cover's kernel of scale^2 tau2 at squared distance d2: rho(d) (the cost, in length^2) and rho'(d) / (2 d) (the
  // IRLS weight of d^2: the gradient is weight * 2 * irls * (c - t), and the rigid alignment's Gauss-Newton rows use
  // it).
  static double coverKernel(double d2, double tau2, double* irls);
  // The closest points are tracked, not searched for: each sample walks from its triangle at the last tracked
  // shape to the nearest of the triangles around it, so an evaluation needs no search tree and gives the same
  // energy for the same x between two trackCover calls (the line search compares them).
  void coverPoints(const Vertices& x, std::vector<CoverPoint>& out) const;
  // Each sample's closest triangle on shape x, searched for over the whole outer surface: at every accepted shape
  // (a cache: the energy it gives is that of x either way).
  void trackCover(const Vertices& x) const;

  // E_target + E_cover + E_seam at simulation positions x (#V by 3) and pattern coordinates X; gradx (3 #V) and gradX
  // (dE/dX at fixed x, through E_target's area weights; 2 per panel vertex) when given.
  double shapeEnergy(const Vertices& x, const Eigen::VectorXd& X, Eigen::VectorXd* gradx,
                     Eigen::VectorXd* gradX = nullptr, ObjectiveTerms* terms = nullptr) const;
  // E_target + E_cover + E_seam as weighted squared residuals, sum_k weight_k r_k^2, each residual's gradient in x
  // given per vertex (at most three): the Gauss-Newton matrix 2 sum_k weight_k (dr_k/dx)(dr_k/dx)^T of the shape
  // terms, as the rigid alignment linearizes them (E_cover point-to-plane, its kernel by its IRLS weight).
  struct ResidualRow {
    int count = 0;
    int vertex[3] = {0, 0, 0};
    Eigen::Vector3d grad[3] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    double weight = 0;
  };
  void residualRows(const Vertices& x, const Eigen::VectorXd& X, std::vector<ResidualRow>& rows) const;
  // E_length + E_smooth + E_laplace + E_quality + E_gap at pattern coordinates X (2 per panel vertex, sewn order);
  // E_quality is +inf when a rest triangle is folded or degenerate, E_gap when an outline touches itself.
  double patternEnergy(const Eigen::VectorXd& X, Eigen::VectorXd* grad, ObjectiveTerms* terms = nullptr) const;

  // Max over stitched edge pairs of |L_a - L_b| / ((L_a + L_b) / 2), and the same per piece pair.
  double maxEdgeMismatch(const Eigen::VectorXd& X) const;
  double maxPieceMismatch(const Eigen::VectorXd& X) const;

  double seamWeight(const SeamVertex& s) const { return w_.seam * s.sigma * norm_; }  // of |x_j - s_j|^2
  const ImlsDistance& imls() const { return imls_; }
  // E_target's signed distance d(x) of simulation vertex i at x, and its gradient when given (ImlsDistance::distance,
  // with the vertex's own candidate faces).
  double targetDistance(int i, const Eigen::Vector3d& x, Eigen::Vector3d* grad) const {
    return imls_.distance(x, grad, &targetCache_[size_t(i)]);
  }
  const std::vector<EdgePair>& edgePairs() const { return pairs_; }
  const std::vector<SeamVertex>& seamVertices() const { return seams_; }
  // E_target's weights of d(x_i)^2 (#V, include w_t / (n D^2)) in pattern X; zero off the outer surface.
  Eigen::VectorXd targetWeights(const Eigen::VectorXd& X) const;
  const Eigen::VectorXd& targetWeights() const { return targetWeight_; }  // in the flattened pattern
  // E_cover's sample of the target's vertices (all of them unless the target has more than twice as many as the
  // outer surface) and their lumped areas [m^2].
  const std::vector<int>& coverVertices() const { return coverVertex_; }
  const Eigen::VectorXd& coverAreas() const { return coverArea_; }
  double modelSize() const { return D_; }  // bounding-box diagonal [m]
  double meanEdgeLength() const { return edge_; }
  int numVertices() const { return n_; }

 private:
  struct Triple {
    int l, j, r;
    double weight = 1;  // relative (OptimizeWeights::slidingSmooth)
  };
  struct OuterTriangle {
    int vertex[3];   // simulation vertices
    int pattern[3];  // panel-vertex ids (global), rows of X
  };
  double restArea(const OuterTriangle& t, const Eigen::VectorXd& X) const;
  struct RestTriangle {
    int pattern[3];         // rows of X
    Eigen::Matrix2d DmInv;  // of the flattened triangle
    double weight = 0;      // w_q l^2 (A0_t / A0_mean) / (n D^2)
  };
  std::vector<RestTriangle> rest_;
  struct PiecePair {
    std::vector<int> a, b;  // rows (global ids) of the two pieces, b reversed so a[k] ~ b[k]
  };
  const ImlsDistance& imls_;
  OptimizeWeights w_;
  int n_ = 0;
  double D_ = 1, edge_ = 1, norm_ = 1;  // norm_ = 1 / (n D^2)
  double targetScale_ = 0;              // w_t m / (n D^2)
  Eigen::VectorXd targetWeight_;
  std::vector<OuterTriangle> outer_;
  std::vector<SeamVertex> seams_;
  std::vector<EdgePair> pairs_;
  std::vector<PiecePair> piecePairs_;
  std::vector<Triple> boundary_;
  std::vector<int> interior_, ringStart_, ring_;  // interior vertex -> neighbours ring_[ringStart_[i]..]
  std::vector<std::vector<int>> outlines_;        // each panel's outline loop (rows of X, in order)
  std::vector<std::vector<double>> gapReach_;     // E_gap's h_v, per outline vertex
  double gapEnergy(const Eigen::VectorXd& X, Eigen::VectorXd* grad) const;
  // E_fair's outlines (those without a corner): which of outlines_, and each vertex's turning angle in the pattern the
  // objective was made for.
  struct FairOutline {
    size_t outline;
    std::vector<double> turn0;
  };
  std::vector<FairOutline> fairOutlines_;
  int fairVertices_ = 0;
  double fairEnergy(const Eigen::VectorXd& X, Eigen::VectorXd* grad) const;
  // E_cover: the target samples (vertex ids of imls_.target()) and their weights (w_c m a_j / (A_T n D^2));
  // outer triangles around each outer triangle (sharing a vertex) for the walk; each sample's tracked triangle.
  std::vector<int> coverVertex_;
  Eigen::VectorXd coverWeight_;
  Eigen::VectorXd coverArea_;  // each sample's lumped area on the target [m^2]
  std::vector<int> aroundStart_, around_;
  mutable std::vector<int> coverTriangle_;
  mutable std::vector<ClosestFaceCache> targetCache_;  // per simulation vertex, for E_target's fallback
  double coverTau2_ = 0;                               // tau^2 of E_cover's kernel inside the panels
  // How near each outer triangle lies to a seam, 1 on it to 0 a band's width inside its panel (empty: coverReachAtSeams
  // unused), and each sample's tau^2 by its tracked triangle, fixed between trackCover calls as the triangle is.
  std::vector<double> seamNearness_;
  mutable std::vector<double> coverTau2Sample_;
};

}  // namespace billow
