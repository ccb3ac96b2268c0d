#include "suggest/thin_handles.hpp"

#include <algorithm>
#include <map>

#include "seams/mesh_topology.hpp"
#include "segment/segmentation.hpp"
#include "suggest/segment_cuts.hpp"

namespace billow {

std::vector<ThinHandle> thinHandles(const TriMesh& target, double maxLengthRatio) {
  const double diagonal = (target.V.colwise().maxCoeff() - target.V.colwise().minCoeff()).norm();
  const MeshTopology topology = buildTopology(target);
  if (target.numVertices() - topology.numEdges() + target.numTriangles() >= 2) return {};  // genus 0
  // With no seams the whole target is one segment, and its cut mesh's vertices are the target's.
  const Segmentation sg = segmentTarget(target, topology, {});
  if (sg.segments.size() != 1) return {};
  std::vector<ThinHandle> out;
  for (const std::vector<int>& loop : loopsAroundHandles(sg, 0)) {
    ThinHandle h;
    for (int v : loop) {
      const SurfacePoint& p = sg.vertexOrigin[size_t(v)];
      int corner = 0;
      p.bary.maxCoeff(&corner);
      h.loop.push_back(target.F(p.face, corner));
    }
    for (size_t i = 0; i < h.loop.size(); ++i)
      h.length += (target.V.row(h.loop[i]) - target.V.row(h.loop[(i + 1) % h.loop.size()])).norm();
    if (h.length < maxLengthRatio * diagonal) out.push_back(std::move(h));
  }
  // Stable: equally thin handles keep the loops' order, the same in native and wasm builds.
  std::stable_sort(out.begin(), out.end(),
                   [](const ThinHandle& a, const ThinHandle& b) { return a.length < b.length; });
  return out;
}

void cutThinHandles(TriMesh& target, const std::vector<ThinHandle>& handles) {
  std::vector<std::vector<int>> facesAt(size_t(target.numVertices()));
  for (int f = 0; f < target.numTriangles(); ++f)
    for (int k = 0; k < 3; ++k) facesAt[size_t(target.F(f, k))].push_back(f);
  std::vector<Eigen::Vector3i> caps;
  int next = target.numVertices();
  for (const ThinHandle& h : handles) {
    const int n = int(h.loop.size());
    if (n < 3) continue;
    // Around each loop vertex v the faces (v, a, b) turn counterclockwise from a to b: those from the edge to the
    // loop's next vertex round to the edge from its last one lie on the loop's left. All found before any is cut.
    std::vector<std::vector<int>> leftFaces(static_cast<size_t>(n));
    std::vector<Eigen::RowVector3d> left(static_cast<size_t>(n)), right(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      const int v = h.loop[size_t(i)], before = h.loop[size_t((i + n - 1) % n)], after = h.loop[size_t((i + 1) % n)];
      std::map<int, int> from;  // a -> face (v, a, b)
      for (int f : facesAt[size_t(v)]) {
        int k = 0;
        while (target.F(f, k) != v) ++k;
        from[target.F(f, (k + 1) % 3)] = f;
      }
      std::vector<int>& faces = leftFaces[size_t(i)];
      for (int a = after; a != before && from.count(a) && faces.size() < facesAt[size_t(v)].size();) {
        const int f = from[a];
        faces.push_back(f);
        int k = 0;
        while (target.F(f, k) != v) ++k;
        a = target.F(f, (k + 2) % 3);
      }
      // Each side's copy drawn back towards its own ring of vertices off the loop.
      Eigen::RowVector3d leftRing = Eigen::RowVector3d::Zero(), rightRing = Eigen::RowVector3d::Zero();
      int leftCount = 0, rightCount = 0;
      for (int f : facesAt[size_t(v)]) {
        const bool isLeft = std::find(faces.begin(), faces.end(), f) != faces.end();
        for (int k = 0; k < 3; ++k) {
          const int u = target.F(f, k);
          if (u == v || std::find(h.loop.begin(), h.loop.end(), u) != h.loop.end()) continue;
          (isLeft ? leftRing : rightRing) += target.V.row(u);
          ++(isLeft ? leftCount : rightCount);
        }
      }
      const Eigen::RowVector3d x = target.V.row(v);
      left[size_t(i)] = leftCount ? Eigen::RowVector3d(x + 0.3 * (leftRing / leftCount - x)) : x;
      right[size_t(i)] = rightCount ? Eigen::RowVector3d(x + 0.3 * (rightRing / rightCount - x)) : x;
    }
    std::vector<int> copy(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      copy[size_t(i)] = next++;
      for (int f : leftFaces[size_t(i)])
        for (int k = 0; k < 3; ++k)
          if (target.F(f, k) == h.loop[size_t(i)]) target.F(f, k) = copy[size_t(i)];
    }
    // Each end closed by a fan around its middle; the left side's faces run along the loop, its cap against it.
    // The new vertices go in at once: the next handle's rings may reach them.
    const int leftCenter = next++, rightCenter = next++;
    target.V.conservativeResize(next, 3);
    Eigen::RowVector3d leftMiddle = Eigen::RowVector3d::Zero(), rightMiddle = Eigen::RowVector3d::Zero();
    for (int i = 0; i < n; ++i) {
      target.V.row(h.loop[size_t(i)]) = right[size_t(i)];
      target.V.row(copy[size_t(i)]) = left[size_t(i)];
      leftMiddle += left[size_t(i)] / n, rightMiddle += right[size_t(i)] / n;
    }
    target.V.row(leftCenter) = leftMiddle, target.V.row(rightCenter) = rightMiddle;
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      caps.emplace_back(copy[size_t(j)], copy[size_t(i)], leftCenter);
      caps.emplace_back(h.loop[size_t(i)], h.loop[size_t(j)], rightCenter);
    }
  }
  const int oldF = target.numTriangles();
  target.F.conservativeResize(oldF + int(caps.size()), 3);
  for (size_t i = 0; i < caps.size(); ++i) target.F.row(oldF + int(i)) = caps[i].transpose();
}

}  // namespace billow
