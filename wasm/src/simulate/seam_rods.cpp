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

namespace {
// A seam turning by more than 45 degrees in its panel at rest (angleSum: the rest angles of the panel's triangles
// at the vertex) has a corner there.
bool turnsAtCorner(double angleSum) { return std::abs(M_PI - angleSum) > M_PI / 4; }

double cornerAngle(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
}
}  // namespace

std::vector<int> seamCornersByTurn(const Panel& panel) {
  std::vector<double> angle(panel.vertices.rows(), 0.0);
  for (int f = 0; f < panel.triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = panel.triangles(f, k), b = panel.triangles(f, (k + 1) % 3), c = panel.triangles(f, (k + 2) % 3);
      const Eigen::Vector2d pa = panel.vertices.row(a).transpose();
      angle[a] += cornerAngle(Eigen::Vector2d(panel.vertices.row(b).transpose()) - pa,
                              Eigen::Vector2d(panel.vertices.row(c).transpose()) - pa);
    }
  std::vector<int> corners;
  for (int v : outlineVertices(panel))
    if (turnsAtCorner(angle[v])) corners.push_back(v);
  return corners;
}

SeamRods makeSeamRods(const SewnMesh& mesh, double coefficient) {
  SeamRods rods;
  rods.coefficient = coefficient;
  if (!(coefficient > 0)) return rods;
  // Boundary edges of each panel (an edge of one triangle of that panel), and each boundary vertex's rest
  // angle inside its panel.
  std::map<std::tuple<int, int, int>, int> edgeCount;
  std::map<std::pair<int, int>, double> angle;  // (panel, vertex) -> sum of rest corner angles
  for (int f = 0; f < mesh.numTriangles(); ++f) {
    const int panel = mesh.trianglePanel[f];
    const Eigen::Matrix2d Dm = mesh.rest[f].DmInv.inverse();
    const Eigen::Vector2d P[3] = {Eigen::Vector2d::Zero(), Dm.col(0), Dm.col(1)};
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      ++edgeCount[std::make_tuple(panel, std::min(a, b), std::max(a, b))];
      const Eigen::Vector2d u = P[(k + 1) % 3] - P[k], v = P[(k + 2) % 3] - P[k];
      angle[{panel, a}] += cornerAngle(u, v);
    }
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
  // The corners the pattern marks, per (panel, simulation vertex): 1 a corner, 0 not, -1 not marked.
  std::map<std::pair<int, int>, signed char> marked;
  for (size_t p = 0; p + 1 < mesh.panelVertexStart.size() && !mesh.seamCorner.empty(); ++p)
    for (int g = mesh.panelVertexStart[p]; g < mesh.panelVertexStart[p + 1]; ++g)
      if (mesh.seamCorner[g] >= 0) {
        signed char& m = marked.try_emplace({int(p), mesh.simVertexOf[g]}, 0).first->second;
        m = std::max(m, mesh.seamCorner[g]);
      }
  std::set<std::array<int, 3>> seen;
  for (const auto& [key, ns] : neighbours) {
    const int b = key.second;
    if (ns.size() != 2 || mesh.stitchedCount[b] < 2) continue;
    if (!sewn(ns[0], b) || !sewn(b, ns[1])) continue;  // the end of a seam
    const auto mark = marked.find(key);
    if (mark != marked.end() ? mark->second == 1 : turnsAtCorner(angle[key])) continue;  // a corner
    const std::array<int, 3> t{std::min(ns[0], ns[1]), b, std::max(ns[0], ns[1])};
    if (seen.insert(t).second) rods.triples.push_back(t);  // once, not once per panel
  }
  return rods;
}

}  // namespace billow
