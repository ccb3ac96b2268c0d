// The plane's vectors, for panels (flat, z = 0) and the 2D steps of flattening, meshing and export.
#pragma once
#include <Eigen/Dense>

namespace billow {

using Vec2 = Eigen::Vector2d;
using Points2 = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;  // #points by 2

// The z of a x b: > 0 when b turns counterclockwise from a.
inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Area of a closed polygon (#points by 2), positive when it runs counterclockwise.
inline double signedArea(const Points2& polygon) {
  double a = 0;
  for (Eigen::Index i = 0, n = polygon.rows(); i < n; ++i) {
    const Eigen::Index j = (i + 1) % n;
    a += polygon(i, 0) * polygon(j, 1) - polygon(i, 1) * polygon(j, 0);
  }
  return 0.5 * a;
}

}  // namespace billow
