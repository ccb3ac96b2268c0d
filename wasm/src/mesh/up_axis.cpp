#include "mesh/up_axis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace billow {

bool parseUpAxis(std::string_view text, UpAxis& out) {
  if (text.size() != 2 || (text[0] != '+' && text[0] != '-') || text[1] < 'x' || text[1] > 'z') return false;
  out.axis = text[1] - 'x';
  out.sign = text[0] == '+' ? 1 : -1;
  return true;
}

std::string toString(const UpAxis& up) { return std::string(up.sign > 0 ? "+" : "-") + char('x' + up.axis); }

Eigen::Matrix3d upFrame(const UpAxis& up) {
  Eigen::Matrix3d r;
  const double s = up.sign;
  // Rows: the up frame's x, y and z in the target's coordinates. Y up keeps x (z follows as x cross y);
  // X up turns a quarter about z, keeping z.
  if (up.axis == 1)
    r << 1, 0, 0, 0, s, 0, 0, 0, s;
  else if (up.axis == 2)
    r << 1, 0, 0, 0, 0, s, 0, -s, 0;
  else
    r << 0, -s, 0, s, 0, 0, 0, 0, 1;
  return r;
}

namespace {

constexpr double kFloorBand = 0.02;  // a vertex touches the floor when this close to it, as a share of the extent
constexpr double kStands = 0.005;    // the centroid lies this far inside the footprint, as a share of the diagonal

using Point = Eigen::Vector2d;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// The convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Point> convexHull(std::vector<Point> p) {
  std::sort(p.begin(), p.end(),
            [](const Point& a, const Point& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  if (p.size() < 3) return p;
  std::vector<Point> hull;
  const auto chain = [&](auto begin, auto end) {
    const size_t start = hull.size();
    for (auto q = begin; q != end; ++q) {
      while (hull.size() >= start + 2 && cross(hull[hull.size() - 2], hull.back(), *q) <= 0) hull.pop_back();
      hull.push_back(*q);
    }
    hull.pop_back();
  };
  chain(p.begin(), p.end());
  chain(p.rbegin(), p.rend());
  return hull;
}

// Signed distance from c to the boundary of a counter-clockwise convex polygon: positive inside.
double depthInside(const std::vector<Point>& hull, const Point& c) {
  if (hull.size() < 3) return -std::numeric_limits<double>::infinity();
  double depth = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < hull.size(); ++i) {
    const Point& a = hull[i];
    const Point& b = hull[(i + 1) % hull.size()];
    depth = std::min(depth, cross(a, b, c) / (b - a).norm());
  }
  return depth;
}

// How firmly the shape stands with its own axis `axis` (1 y, 2 z) up.
double standing(const TriMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                const Eigen::Vector3d& centroid, int axis) {
  const int u = 0, v = axis == 1 ? 2 : 1;  // the floor's axes
  const double floor = lo[axis] + kFloorBand * (hi[axis] - lo[axis]);
  std::vector<Point> touching;
  for (int i = 0; i < mesh.V.rows(); ++i)
    if (mesh.V(i, axis) <= floor) touching.emplace_back(mesh.V(i, u), mesh.V(i, v));
  const double depth = depthInside(convexHull(std::move(touching)), Point(centroid[u], centroid[v])) / (hi - lo).norm();
  return std::isfinite(depth) ? depth : -1;  // no footprint (a point or a line touches the floor): it tips over
}

}  // namespace

UpGuess guessUp(const TriMesh& mesh) {
  UpGuess guess;
  if (mesh.V.rows() == 0) return guess;
  const Eigen::Vector3d lo = mesh.V.colwise().minCoeff().transpose(), hi = mesh.V.colwise().maxCoeff().transpose();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double area = 0;
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const double w = 0.5 * (b - a).cross(c - a).norm();
    area += w, centroid += w * (a + b + c) / 3;
  }
  if (!(area > 0)) return guess;
  centroid /= area;
  guess.standsY = standing(mesh, lo, hi, centroid, 1);
  guess.standsZ = standing(mesh, lo, hi, centroid, 2);
  if (guess.standsY <= kStands && guess.standsZ > kStands) guess.up = UpAxis{2, 1};
  return guess;
}

}  // namespace billow
