// Constrained Delaunay triangulation (CDT) of a planar straight-line graph, for remeshing panels (Sec. 5.3;
// the paper used Shewchuk's Triangle, which we replace). Incremental insertion with walking point location
// (points inserted in Hilbert order), Lawson flips on exact predicates, segments recovered by flipping the
// edges they cross (Sloan 1993), then the region is picked by constraint-crossing parity from the outside.
#pragma once
#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "util/vec2.hpp"

namespace billow {

using Segments = Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor>;  // S  #S by 2, indices into P

// A planar straight-line graph. Segments must enclose the region to mesh: a triangle is kept when every
// path to the outside crosses an odd number of segments (so nested loops alternate inside/outside, and a
// dangling segment inside the region changes nothing). With no segments the convex hull is meshed.
// Each hole seed removes the segment-bounded component that contains it.
struct Pslg {
  Points2 points;
  Segments segments;
  Points2 holes;
};

struct CdtResult {
  Points2 points;                 // input points first (duplicates merged), then Steiner points
  Triangles triangles;            // F  #F by 3, counter-clockwise
  Segments segments;              // constrained edges of the result (input segments, split where needed)
  std::vector<int> inputToPoint;  // input point i -> row of points (duplicates share a row)
};

// The triangulation as a mutable structure, for refinement. Vertices 0..2 are a bounding triangle.
class Cdt {
 public:
  struct Tri {
    std::array<int, 3> v;   // counter-clockwise
    std::array<int, 3> n;   // n[i]: triangle across edge i = (v[i+1], v[i+2]), -1 on the bounding triangle
    std::array<bool, 3> c;  // c[i]: edge i is a constraint
    bool inside = false;    // in the meshed region
  };

  explicit Cdt(const Pslg& pslg);

  int numVertices() const { return static_cast<int>(pts_.size()); }
  int numTriangles() const { return static_cast<int>(tris_.size()); }
  const Eigen::Vector2d& point(int v) const { return pts_[v]; }
  const Tri& tri(int t) const { return tris_[t]; }
  bool isBounding(int v) const { return v < 3; }
  int inputVertex(int i) const { return inputToVertex_[i]; }
  int numInputPoints() const { return static_cast<int>(inputToVertex_.size()); }
  int triangleOf(int v) const { return vertTri_[v]; }  // one triangle incident to v

  // Where p is: a triangle containing it (closed), and whether p is a vertex / on an edge of it.
  struct Location {
    int tri = -1;
    int vertex = -1;  // local index of the vertex equal to p, or -1
    int edge = -1;    // local index of the edge containing p in its interior, or -1
  };
  Location locate(const Eigen::Vector2d& p, int hint = -1) const;

  // Inserts p (Delaunay restored by flips, constraints respected; a point on a constraint splits it).
  // Returns the vertex (an existing one if p coincides with it).
  int insertPoint(const Eigen::Vector2d& p, int hint = -1);
  // Splits edge `edge` of triangle t at p (p on or numerically next to the edge); keeps its constraint flag.
  int splitEdge(int t, int edge, const Eigen::Vector2d& p);
  // Makes (a, b) a chain of constrained edges (inserting crossing points with other constraints).
  void insertSegment(int a, int b);

  // Triangle with directed edge a -> b and that edge's local index, or {-1, -1}.
  std::pair<int, int> findEdge(int a, int b) const;
  // Triangles around vertex v (counter-clockwise, v not a bounding vertex).
  void trianglesAround(int v, std::vector<int>& out) const;

  CdtResult result() const;  // the kept region, bounding vertices dropped

 private:
  int addVertex(const Eigen::Vector2d& p);
  void setTri(int t, int a, int b, int c, int na, int nb, int nc, bool ca, bool cb, bool cc, bool inside);
  void relink(int t, int edge);  // make the neighbor across edge point back at t
  void flip(int t, int edge);
  void legalizeAround(int v, std::vector<std::pair<int, int>>& stack);
  void legalizeEdges(std::vector<std::pair<int, int>> edges);
  void markConstrained(int a, int b);
  int insertInTriangle(int t, const Eigen::Vector2d& p);
  void recoverSegmentFlips(int a, int c, const std::vector<std::pair<int, int>>& crossed);
  void classify(const Points2& holes);

  std::vector<Eigen::Vector2d> pts_;
  std::vector<Tri> tris_;
  std::vector<int> vertTri_;
  std::vector<int> inputToVertex_;
  mutable unsigned rng_ = 12345u;
  int lastTri_ = 0;
};

// One-shot CDT of a PSLG.
CdtResult triangulate(const Pslg& pslg);

}  // namespace billow
