// Closed shapes with sharp creases along their mesh edges, for the crease finder and the layouts along creases: a
// polygon extruded (a box, a drum, a star prism), its front and back faces triangulated in rings about a centre.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "mesh/tri_mesh.hpp"

namespace billow::test {

// The outline (counterclockwise in x, y, star-shaped about the origin) extruded from z = -depth / 2 to depth / 2, with
// `rings` rings on each face and `layers` layers of quads on the side.
inline TriMesh extrudedOutline(const std::vector<Eigen::Vector2d>& outline, double depth, int rings, int layers) {
  const int n = int(outline.size());
  std::vector<Eigen::Vector3d> V;
  std::vector<Eigen::Vector3i> F;
  // ring[k][i]: the vertex of ring k (1..rings, scaled k / rings) at outline point i, on a face at height z.
  const auto face = [&](double z, bool up) {
    const int center = int(V.size());
    V.emplace_back(0, 0, z);
    std::vector<std::vector<int>> ring(size_t(rings) + 1);
    for (int k = 1; k <= rings; ++k)
      for (int i = 0; i < n; ++i) {
        ring[size_t(k)].push_back(int(V.size()));
        V.emplace_back(outline[size_t(i)].x() * k / rings, outline[size_t(i)].y() * k / rings, z);
      }
    const auto tri = [&](int a, int b, int c) {
      F.push_back(up ? Eigen::Vector3i(a, b, c) : Eigen::Vector3i(a, c, b));
    };
    for (int i = 0; i < n; ++i) tri(center, ring[1][size_t(i)], ring[1][size_t((i + 1) % n)]);
    for (int k = 1; k < rings; ++k)
      for (int i = 0; i < n; ++i) {
        const int a = ring[size_t(k)][size_t(i)], b = ring[size_t(k)][size_t((i + 1) % n)],
                  c = ring[size_t(k) + 1][size_t(i)], d = ring[size_t(k) + 1][size_t((i + 1) % n)];
        tri(a, c, d), tri(a, d, b);
      }
    return ring[size_t(rings)];
  };
  const std::vector<int> top = face(depth / 2, true), bottom = face(-depth / 2, false);
  std::vector<std::vector<int>> side{bottom};
  for (int l = 1; l < layers; ++l) {
    std::vector<int> r;
    for (int i = 0; i < n; ++i) {
      r.push_back(int(V.size()));
      V.emplace_back(outline[size_t(i)].x(), outline[size_t(i)].y(), -depth / 2 + depth * l / layers);
    }
    side.push_back(r);
  }
  side.push_back(top);
  for (size_t l = 0; l + 1 < side.size(); ++l)
    for (int i = 0; i < n; ++i) {
      const int a = side[l][size_t(i)], b = side[l][size_t((i + 1) % n)], c = side[l + 1][size_t(i)],
                d = side[l + 1][size_t((i + 1) % n)];
      F.emplace_back(a, b, d), F.emplace_back(a, d, c);
    }
  TriMesh m;
  m.V.resize(Eigen::Index(V.size()), 3), m.F.resize(Eigen::Index(F.size()), 3);
  for (size_t i = 0; i < V.size(); ++i) m.V.row(Eigen::Index(i)) = V[i].transpose();
  for (size_t i = 0; i < F.size(); ++i) m.F.row(Eigen::Index(i)) = F[i].transpose();
  return m;
}

// Points along a closed polygon, `perSide` on each side (its corners among them).
inline std::vector<Eigen::Vector2d> polygonOutline(const std::vector<Eigen::Vector2d>& corners, int perSide) {
  std::vector<Eigen::Vector2d> out;
  for (size_t c = 0; c < corners.size(); ++c)
    for (int k = 0; k < perSide; ++k)
      out.push_back(corners[c] + (corners[(c + 1) % corners.size()] - corners[c]) * double(k) / perSide);
  return out;
}

// A box of w x h x d: the rectangle's outline extruded.
inline TriMesh boxShape(double w, double h, double d) {
  return extrudedOutline(polygonOutline({{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}}, 12), d, 8,
                         6);
}

// A drum (a round cushion): a circle of radius r extruded to height d.
inline TriMesh drumShape(double r, double d) {
  std::vector<Eigen::Vector2d> circle;
  for (int i = 0; i < 64; ++i) circle.emplace_back(r * std::cos(2 * M_PI * i / 64), r * std::sin(2 * M_PI * i / 64));
  return extrudedOutline(circle, d, 10, 8);
}

// A five-pointed star cushion (tips at radius r, notches at 0.45 r), d thick.
inline TriMesh starShape(double r, double d) {
  std::vector<Eigen::Vector2d> corners;
  for (int k = 0; k < 10; ++k) {
    const double radius = k % 2 == 0 ? r : 0.45 * r, angle = M_PI / 2 + M_PI * k / 5;
    corners.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  return extrudedOutline(polygonOutline(corners, 8), d, 10, 3);
}

}  // namespace billow::test
