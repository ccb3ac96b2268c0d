// Checks of flat panels shared by the pattern tests (builder, internal panels, remeshing).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "pattern/pattern.hpp"

namespace billow::test {

// Signed area of triangle t of a panel (positive: counter-clockwise).
inline double signedArea(const Panel& p, int t) {
  const Eigen::Vector2d a = p.vertices.row(p.triangles(t, 0)), b = p.vertices.row(p.triangles(t, 1)),
                        c = p.vertices.row(p.triangles(t, 2));
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

inline double panelArea(const Panel& p) {
  double a = 0;
  for (int t = 0; t < p.triangles.rows(); ++t) a += signedArea(p, t);
  return a;
}

// All panels' flat area.
inline double patternArea(const Pattern& pattern) {
  double a = 0;
  for (const Panel& p : pattern.panels) a += panelArea(p);
  return a;
}

// A disk (Euler characteristic 1, no edge in more than two triangles) whose boundary edges run through
// exactly its first `boundaryVertices` rows.
inline void expectDisk(const Panel& p, int boundaryVertices, const std::string& what = "") {
  std::map<std::pair<int, int>, int> edges;
  for (int t = 0; t < p.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = p.triangles(t, k), b = p.triangles(t, (k + 1) % 3);
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  int boundary = 0;
  std::set<int> onBoundary;
  for (const auto& [e, n] : edges) {
    EXPECT_LE(n, 2) << what;
    if (n == 1) ++boundary, onBoundary.insert(e.first), onBoundary.insert(e.second);
  }
  EXPECT_EQ(static_cast<long>(p.vertices.rows()) - static_cast<long>(edges.size()) + p.triangles.rows(), 1) << what;
  EXPECT_EQ(boundary, boundaryVertices) << what;
  EXPECT_EQ(static_cast<int>(onBoundary.size()), boundaryVertices) << what;
  if (!onBoundary.empty()) {
    EXPECT_EQ(*onBoundary.rbegin(), boundaryVertices - 1) << what << ": boundary rows first";
  }
}

}  // namespace billow::test
