#include "simulate/seam_rods.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace billow {

double SeamRods::energy(const Eigen::Ref<const Eigen::MatrixXd>& x) const {
  double e = 0;
  for (const auto& t : triples) e += (x.row(t[0]) - 2 * x.row(t[1]) + x.row(t[2])).squaredNorm();
  return coefficient * e;
}

void SeamRods::addGradient(const Eigen::Ref<const Eigen::MatrixXd>& x, Eigen::VectorXd& grad) const {
  for (const auto& t : triples) {
    const Eigen::Vector3d u = (x.row(t[0]) - 2 * x.row(t[1]) + x.row(t[2])).transpose() * (2 * coefficient);
    grad.segment<3>(3 * t[0]) += u;
    grad.segment<3>(3 * t[1]) -= 2 * u;
    grad.segment<3>(3 * t[2]) += u;
  }
}

double seamRodCoefficient(const SewnMesh& mesh, double pressure, double beta) {
  return seamRodCoefficient(mesh.outerArea, mesh.meanEdgeLength, pressure, beta);
}

double seamRodCoefficient(double outerArea, double meanEdgeLength, double pressure, double beta) {
  const double l = meanEdgeLength;
  if (!(beta > 0) || !(l > 0) || !(pressure > 0)) return 0;
  const double R2 = outerArea / (4 * M_PI);
  return beta * pressure * R2 * R2 / (l * l * l);
}

SeamRods makeSeamRods(const SewnMesh& mesh, double coefficient) {
  SeamRods rods;
  rods.coefficient = coefficient;
  if (!(coefficient > 0)) return rods;
  // Boundary edges of each panel (an edge of one triangle of that panel).
  std::map<std::tuple<int, int, int>, int> edgeCount;
  for (int f = 0; f < mesh.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      ++edgeCount[std::make_tuple(mesh.trianglePanel[f], std::min(a, b), std::max(a, b))];
    }
  std::map<std::pair<int, int>, std::vector<int>> neighbours;  // (panel, vertex) -> along the boundary
  std::map<std::pair<int, int>, int> sides;                    // boundary edge -> panels it bounds
  for (const auto& [key, count] : edgeCount) {
    if (count != 1) continue;
    const auto [panel, a, b] = key;
    neighbours[{panel, a}].push_back(b);
    neighbours[{panel, b}].push_back(a);
    ++sides[{a, b}];
  }
  auto sewn = [&](int a, int b) { return sides[{std::min(a, b), std::max(a, b)}] >= 2; };
  std::set<std::pair<int, int>> corners;  // (panel, simulation vertex) at a seam corner (SewnMesh::seamCorner)
  for (size_t p = 0; p + 1 < mesh.panelVertexStart.size(); ++p)
    for (int g = mesh.panelVertexStart[p]; g < mesh.panelVertexStart[p + 1]; ++g)
      if (mesh.seamCorner[g]) corners.insert({int(p), mesh.simVertexOf[g]});
  std::set<std::array<int, 3>> seen;
  for (const auto& [key, ns] : neighbours) {
    const int b = key.second;
    if (ns.size() != 2 || mesh.stitchedCount[b] < 2) continue;
    if (!sewn(ns[0], b) || !sewn(b, ns[1])) continue;  // the end of a seam
    if (corners.count(key)) continue;                  // a corner
    const std::array<int, 3> t{std::min(ns[0], ns[1]), b, std::max(ns[0], ns[1])};
    if (seen.insert(t).second) rods.triples.push_back(t);  // once, not once per panel
  }
  return rods;
}

}  // namespace billow
