#include "simulate/gauss_seidel.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "simulate/enclosed_volume.hpp"
#include "simulate/membrane_energy.hpp"
#include "simulate/seam_rods.hpp"
#include "util/clock.hpp"

namespace billow {

GaussSeidelReport gaussSeidelSweeps(const SewnMesh& mesh, const Material& material, double pressure,
                                    const InflateOptions& options, Vertices& x, int sweeps, double threshold,
                                    bool measure) {
  const auto start = Clock::now();
  GaussSeidelReport report;
  const int n = mesh.numVertices, F = mesh.numTriangles();
  if (x.rows() != n || n == 0) return report;
  const MembraneMaterial membrane = membraneMaterial(material, options);
  const std::shared_ptr<const SeamRods> rods = seamRodsFor(mesh, pressure, options);
  // The triangles and rod triples around each vertex, with the vertex's corner in each.
  std::vector<int> triangleStart(n + 1, 0), triangleOf, cornerOf;
  for (int f = 0; f < F; ++f)
    for (int k = 0; k < 3; ++k) ++triangleStart[mesh.triangles(f, k) + 1];
  for (int v = 0; v < n; ++v) triangleStart[v + 1] += triangleStart[v];
  triangleOf.resize(triangleStart[n]);
  cornerOf.resize(triangleStart[n]);
  {
    std::vector<int> fill(triangleStart.begin(), triangleStart.end() - 1);
    for (int f = 0; f < F; ++f)
      for (int k = 0; k < 3; ++k) {
        const int slot = fill[mesh.triangles(f, k)]++;
        triangleOf[slot] = f;
        cornerOf[slot] = k;
      }
  }
  std::vector<std::vector<std::pair<int, int>>> rodsAt(n);  // (triple, position in it)
  if (!rods->empty())
    for (size_t r = 0; r < rods->triples.size(); ++r)
      for (int k = 0; k < 3; ++k) rodsAt[rods->triples[r][k]].emplace_back(static_cast<int>(r), k);
  static constexpr double w[3] = {1, -2, 1};
  const double forceScale = std::max(pressure * mesh.meanEdgeLength * mesh.meanEdgeLength, 1e-300);
  const double stiffnessUnit = pressure * mesh.meanEdgeLength;  // the shift unit of InflationSolver

  auto rodVector = [&](int r) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) d += w[k] * x.row(rods->triples[r][k]).transpose();
    return d;
  };
  // Pi restricted to the terms that involve vertex v.
  auto starEnergy = [&](int v) {
    double e = 0;
    for (int s = triangleStart[v]; s < triangleStart[v + 1]; ++s) {
      const int f = triangleOf[s];
      const Eigen::Vector3d a = x.row(mesh.triangles(f, 0)), b = x.row(mesh.triangles(f, 1)),
                            c = x.row(mesh.triangles(f, 2));
      e += membraneElementEnergy(mesh.rest[f], a, b, c, membrane);
      if (mesh.outer[f]) e -= pressure * triangleVolume(a, b, c);
    }
    for (const auto& [r, k] : rodsAt[v]) e += rods->coefficient * rodVector(r).squaredNorm();
    return e;
  };
  ElementOptions elementOptions;
  // The force on v (g), its 3x3 stiffness (H, when asked) and starEnergy(v), summed over its star.
  auto vertexTerms = [&](int v, Eigen::Vector3d& g, Eigen::Matrix3d* H) {
    Eigen::Vector3d ga, gv;
    Eigen::Matrix3d ha;
    g.setZero();
    if (H) H->setZero();
    double e = 0;
    for (int s = triangleStart[v]; s < triangleStart[v + 1]; ++s) {
      const int f = triangleOf[s], k = cornerOf[s];
      const Eigen::Vector3d a = x.row(mesh.triangles(f, 0)), b = x.row(mesh.triangles(f, 1)),
                            c = x.row(mesh.triangles(f, 2));
      e += membraneElementCorner(mesh.rest[f], a, b, c, membrane, k, elementOptions, &ga, H ? &ha : nullptr);
      g += ga;
      if (H) *H += ha;
      // The volume is linear in each vertex: no diagonal block in its Hessian.
      if (mesh.outer[f]) {
        e -= pressure * triangleVolume(a, b, c);
        const Eigen::Vector3d& p = k == 0 ? b : k == 1 ? c : a;
        const Eigen::Vector3d& q = k == 0 ? c : k == 1 ? a : b;
        gv = p.cross(q) / 6.0;  // dV/dx_k (enclosed_volume.hpp)
        g -= pressure * gv;
      }
    }
    for (const auto& [r, k] : rodsAt[v]) {
      const Eigen::Vector3d rod = rodVector(r);
      e += rods->coefficient * rod.squaredNorm();
      g += 2 * rods->coefficient * w[k] * rod;
      if (H) H->diagonal().array() += 2 * rods->coefficient * w[k] * w[k];
    }
    return e;
  };
  auto largestForce = [&]() {
    double largest = 0;
    Eigen::Vector3d g;
    for (int v = 0; v < n; ++v) {
      vertexTerms(v, g, nullptr);
      largest = std::max(largest, g.lpNorm<Eigen::Infinity>() / forceScale);
    }
    return largest;
  };
  if (sweeps <= 0) return report;
  if (measure) report.residualBefore = largestForce();
  // A vertex is visited again only when it or a vertex whose terms involve it (a neighbour in a triangle or a
  // rod) moved since its last visit: otherwise its force and stiffness are what they were, and so would be
  // the outcome.
  std::vector<char> active(n, 1), next(n, 0);
  auto wake = [&](int v) {
    next[v] = 1;
    for (int s = triangleStart[v]; s < triangleStart[v + 1]; ++s)
      for (int k = 0; k < 3; ++k) next[mesh.triangles(triangleOf[s], k)] = 1;
    for (const auto& [r, k] : rodsAt[v])
      for (int u : rods->triples[r]) next[u] = 1;
  };
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (int v = 0; v < n; ++v) {
      if (!active[v]) continue;
      Eigen::Vector3d g;
      Eigen::Matrix3d H;
      const double e0 = vertexTerms(v, g, &H);
      const double residual = g.lpNorm<Eigen::Infinity>() / forceScale;
      if (!(residual >= threshold)) continue;  // small, or not finite
      // The projected membrane block is positive semi-definite; a small shift makes it definite where the star
      // is slack.
      H.diagonal().array() += 1e-3 * stiffnessUnit;
      const Eigen::Vector3d d = -H.ldlt().solve(g);
      const double slope = g.dot(d);
      if (!d.allFinite() || !(slope < 0)) continue;
      const Eigen::Vector3d x0 = x.row(v).transpose();
      bool moved = false;
      for (double alpha = 1; alpha > 1e-3 && !moved; alpha *= 0.5) {
        x.row(v) = (x0 + alpha * d).transpose();
        const double e = starEnergy(v);
        moved = std::isfinite(e) && e <= e0 + 1e-4 * alpha * slope;
      }
      if (moved) {
        ++report.moves;
        wake(v);
      } else {
        x.row(v) = x0.transpose();
      }
    }
    active.swap(next);
    std::fill(next.begin(), next.end(), 0);
    ++report.sweeps;
  }
  if (measure) report.residualAfter = largestForce();
  report.ms = msSince(start);
  return report;
}

}  // namespace billow
