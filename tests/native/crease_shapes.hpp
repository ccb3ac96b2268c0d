// Closed shapes with sharp creases along their mesh edges, for the crease finder and the layouts along creases: a
// polygon extruded (a box, a drum, a star prism), its front and back faces triangulated in rings about a centre.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "mesh/tri_mesh.hpp"

namespace billow::test {

// The outline's points moved inward by `inset` along their mitred normals (the polygon offset of its sides).
inline std::vector<Eigen::Vector2d> insetOutline(const std::vector<Eigen::Vector2d>& outline, double inset) {
  const size_t n = outline.size();
  std::vector<Eigen::Vector2d> out;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = (outline[i] - outline[(i + n - 1) % n]).normalized(),
                          b = (outline[(i + 1) % n] - outline[i]).normalized();
    const Eigen::Vector2d na(a.y(), -a.x()), nb(b.y(), -b.x());  // outward, the outline counterclockwise
    const Eigen::Vector2d miter = (na + nb).normalized();
    out.push_back(outline[i] - inset / miter.dot(nb) * miter);
  }
  return out;
}

// The outline (counterclockwise in x, y, star-shaped about the origin) extruded from z = -depth / 2 to depth / 2, with
// `rings` rings on each face and `layers` layers of quads on the side. With a bevel, the rim between each face and the
// side is rounded to a quarter circle of that radius in `bevelSegments` strips of quads, as a modeller's bevel makes
// it.
inline TriMesh extrudedOutline(const std::vector<Eigen::Vector2d>& outline, double depth, int rings, int layers,
                               double bevel = 0, int bevelSegments = 0) {
  const int n = int(outline.size());
  std::vector<Eigen::Vector3d> V;
  std::vector<Eigen::Vector3i> F;
  const std::vector<Eigen::Vector2d> faceOutline = bevel > 0 ? insetOutline(outline, bevel) : outline;
  // ring[k][i]: the vertex of ring k (1..rings, scaled k / rings) at outline point i, on a face at height z.
  const auto face = [&](double z, bool up) {
    const int center = int(V.size());
    V.emplace_back(0, 0, z);
    std::vector<std::vector<int>> ring(size_t(rings) + 1);
    for (int k = 1; k <= rings; ++k)
      for (int i = 0; i < n; ++i) {
        ring[size_t(k)].push_back(int(V.size()));
        V.emplace_back(faceOutline[size_t(i)].x() * k / rings, faceOutline[size_t(i)].y() * k / rings, z);
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
  const auto ringAt = [&](const std::vector<Eigen::Vector2d>& points, double z) {
    std::vector<int> r;
    for (int i = 0; i < n; ++i) {
      r.push_back(int(V.size()));
      V.emplace_back(points[size_t(i)].x(), points[size_t(i)].y(), z);
    }
    return r;
  };
  // The side's rings from the bottom face's rim to the top face's, through the bevels' quarter circles.
  const int segments = bevel > 0 ? bevelSegments : 0;
  const double wall = depth / 2 - (segments > 0 ? bevel : 0);
  std::vector<std::vector<int>> side{bottom};
  for (int j = segments - 1; j >= 0; --j) {
    const double t = M_PI / 2 * j / segments;
    side.push_back(ringAt(insetOutline(outline, bevel * (1 - std::cos(t))), -wall - bevel * std::sin(t)));
  }
  for (int l = segments > 0 ? 0 : 1; l < layers + (segments > 0 ? 1 : 0); ++l)
    if (segments == 0 || l > 0) side.push_back(ringAt(outline, -wall + 2 * wall * l / layers));
  for (int j = 1; j < segments; ++j) {
    const double t = M_PI / 2 * j / segments;
    side.push_back(ringAt(insetOutline(outline, bevel * (1 - std::cos(t))), wall + bevel * std::sin(t)));
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
