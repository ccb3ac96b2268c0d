// The target's outline seen from a direction: the seam a foil balloon is made along, two pieces sealed around the
// silhouette (the app's Outline tool lays it by the same rule, web/src/app/section.js outlineLoop), and the
// suggested layouts' front-and-back ones (suggest/seam_layouts.hpp).
#pragma once
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/plane_section.hpp"

namespace billow {

struct Outline {
  SectionLoop loop;                       // the longest loop of the contour: the rim
  std::vector<SectionLoop> holes;         // the others: one per handle the view looks through (a ring face on)
  int movedToBack = 0, movedToFront = 0;  // parts that changed sides to make each side one piece
};

// The contour where the surface turns away from a viewer in direction `towards` (unit, from the target to the
// viewer): the zero set of n . towards over the area-weighted vertex normals, cleaned so that the front and the back
// are each one edge-connected piece without a pinch (a fold, an arm's far side goes with the side around it), so
// the contour is one loop on a shape without handles. None where the shape has no front or back.
std::optional<Outline> outlineSeenFrom(const TriMesh& mesh, const Eigen::Vector3d& towards);

// A shape with a handle seen through it has an outline of several loops, and its front and back are rings, not
// panels. Per hole, two sections along the view, each straight across the hole's line, cut them open into halves:
// one where the ring is narrowest, one opposite it across the hole. One cut alone would leave each ring a C sewn to
// itself across the cut, which flattens badly. A hole gets none where no such cut runs around its ring (across the rim
// and its hole once or twice each, no other hole, along no flat wall: on a statue's legs and base a plane grazes a
// hole or wanders along an edge-on rim); the cuts that open a tube (suggest/seam_layouts.hpp openIntoPanels) open
// those.
std::vector<SectionLoop> acrossHandles(const TriMesh& mesh, const SectionLoop& rim,
                                       const std::vector<SectionLoop>& holes, const Eigen::Vector3d& towards);

// The section loop across `normal` through a point of the surface (`face` holds it; -1: none): the loop that passes
// through that face, else the nearest one. None where the plane misses.
std::optional<SectionLoop> sectionThrough(const TriMesh& mesh, const Eigen::Vector3d& position, int face,
                                          const Eigen::Vector3d& normal);

}  // namespace billow
