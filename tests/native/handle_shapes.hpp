// Closed shapes with handles, for the loops around handles (segment_cuts.hpp) and the thin handles cut through
// (thin_handles.hpp): a ring, and a slab with two holes.
#pragma once
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "test_support.hpp"

namespace billow::test {

// A ring around z: radius R to the tube's middle, tube radius r.
inline TriMesh ringMesh(double R, double r, int nu = 120, int nv = 40) {
  TriMesh m;
  m.V.resize(nu * nv, 3), m.F.resize(2 * nu * nv, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
      const Eigen::Vector3d radial(std::cos(u), std::sin(u), 0);
      m.V.row(i * nv + j) = R * radial + r * (std::cos(v) * radial + std::sin(v) * Eigen::Vector3d::UnitZ());
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
      m.F.row(2 * a) = Eigen::Vector3i(a, b, c);
      m.F.row(2 * a + 1) = Eigen::Vector3i(a, c, d);
    }
  return m;
}

// A slab of 5 x 3 x 1 cubes without the cubes (1, 1) and (3, 1): two holes through it, genus 2. Each cube face in
// n x n squares.
inline TriMesh twoHoledSlab(int n = 4) {
  const auto solid = [](int i, int j, int k) {
    return i >= 0 && i < 5 && j >= 0 && j < 3 && k == 0 && !(j == 1 && (i == 1 || i == 3));
  };
  std::map<std::array<int, 3>, int> index;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> triangles;
  const auto vertex = [&](const std::array<int, 3>& p) {
    const auto [it, added] = index.emplace(p, int(points.size()));
    if (added) points.push_back(Eigen::Vector3d(p[0], p[1], p[2]) / n);
    return it->second;
  };
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) {
      if (!solid(i, j, 0)) continue;
      const std::array<int, 3> cell{i, j, 0};
      for (int a = 0; a < 3; ++a)
        for (int sign : {-1, 1}) {
          std::array<int, 3> next = cell;
          next[a] += sign;
          if (solid(next[0], next[1], next[2])) continue;
          const int u = (a + 1) % 3, v = (a + 2) % 3;  // u x v = a
          for (int iu = 0; iu < n; ++iu)
            for (int iv = 0; iv < n; ++iv) {
              std::array<int, 4> q;
              const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
              for (int k = 0; k < 4; ++k) {
                std::array<int, 3> p;
                p[a] = (cell[a] + (sign > 0)) * n, p[u] = cell[u] * n + iu + du[k], p[v] = cell[v] * n + iv + dv[k];
                q[size_t(k)] = vertex(p);
              }
              if (sign < 0) std::swap(q[1], q[3]);  // facing -a
              triangles.push_back({q[0], q[1], q[2]});
              triangles.push_back({q[0], q[2], q[3]});
            }
        }
    }
  TriMesh m;
  m.V.resize(int(points.size()), 3), m.F.resize(int(triangles.size()), 3);
  for (size_t k = 0; k < points.size(); ++k) m.V.row(int(k)) = points[k].transpose();
  for (size_t k = 0; k < triangles.size(); ++k) m.F.row(int(k)) = triangles[k].transpose();
  return m;
}

}  // namespace billow::test
