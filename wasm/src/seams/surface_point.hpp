// Points on the target surface (paper Sec. 3.2: seam control points are picked on the target).
// A SurfacePoint is a face and barycentric coordinates, as geometry-central's SurfacePoint; seams keep
// their anchors in this form so they survive any later remeshing of the simulation mesh.
// SurfaceProjector answers "which surface point is closest to this 3D point" with an AABB tree built
// once per target (it runs while the mouse moves, so it must stay well under a millisecond).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mesh/tri_mesh.hpp"

namespace billow {

struct SurfacePoint {
  int face = -1;                                   // row of F
  Eigen::Vector3d bary = Eigen::Vector3d::Zero();  // weights of F(face, 0..2), summing to 1
};

// The 3D position of p on mesh.
Eigen::Vector3d position(const TriMesh& mesh, const SurfacePoint& p);

// The closest point to q on triangle (a, b, c), as barycentric weights of a, b, c.
Eigen::Vector3d closestPointBarycentric(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c);

// Bounding-volume hierarchy over the triangles of one target; build once, query many times.
class SurfaceProjector {
 public:
  explicit SurfaceProjector(const TriMesh& mesh);
  // The surface point closest to q (ties: the lowest face index, so that no hint or search order changes the
  // answer). distance, when given, receives |q - position|. hintFace, when a face of the mesh, is measured first,
  // so the search starts from a bound (a point near its last answer); the answer is the same either way.
  SurfacePoint project(const Eigen::Vector3d& q, double* distance = nullptr, int hintFace = -1) const;
  // The faces within `radius` of q (appended to out, in tree order).
  void facesWithin(const Eigen::Vector3d& q, double radius, std::vector<int>& out) const;
  // Of these faces, the point closest to q, as project answers when they hold its answer (ties alike).
  SurfacePoint closestAmong(const std::vector<int>& faces, const Eigen::Vector3d& q) const;

 private:
  struct Node {
    Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
    int left = -1, right = -1;  // children, or -1 for a leaf
    int begin = 0, end = 0;     // range in order_ (leaves)
  };
  int build(int begin, int end, std::vector<Eigen::Vector3d>& centers);
  // The closest point to q on face f, kept in best when nearer than best2 (ties: the lower face index).
  void measure(int f, const Eigen::Vector3d& q, SurfacePoint& best, double& best2) const;
  const TriMesh& mesh_;
  std::vector<int> order_;  // triangle ids, grouped by leaf
  std::vector<Node> nodes_;
};

}  // namespace billow
