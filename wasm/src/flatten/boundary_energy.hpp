// Boundary flattening energy, Eq. 14 of Skouras et al. 2014 "Designing Inflatable Structures" (after
// Wang 2008, "Computing length-preserved free boundary for quasi-developable mesh segmentation"):
//   E_fl(Q) = sum_j (1/l_j) (L_j(Q) - l_j)^2 + lbar_j (Theta_j(Q) - theta_j)^2
// with L_j the length of polygon edge j (Q_j -> Q_j+1), Theta_j the interior angle of the polygon at Q_j,
// lbar_j the mean of the 3D lengths of the two edges at vertex j, and l_j, theta_j measured on the target.
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "flatten/segment_boundary.hpp"
#include "util/vec2.hpp"

namespace billow {

// Interior angle at each vertex of a closed polygon, in [0, 2 pi): pi minus the signed turning angle,
// so a CCW convex polygon has angles below pi and sum (n - 2) pi.
Eigen::VectorXd polygonAngles(const Points2& Q);

// E_fl at Q (#b by 2). When given, grad (2 #b, ordered x0 y0 x1 y1 ...) and hess (2 #b by 2 #b, symmetric,
// exact, possibly indefinite) are overwritten.
double boundaryEnergy(const Points2& Q, const BoundaryTargets& targets, Eigen::VectorXd* grad = nullptr,
                      Eigen::SparseMatrix<double>* hess = nullptr);

}  // namespace billow
