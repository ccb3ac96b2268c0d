// Plane sections of the target: the closed loops where a plane cuts it, made into seams of surface points. The
// suggested seam layouts (suggest/seam_layouts.hpp) are made of them, as the project's hand-made layouts are
// (the app's section seam tool, web/src/app/section.js, lays one loop a click by the same rule).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/surface_point.hpp"

namespace billow {

struct SectionPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit
  double offset = 0;                                  // the plane is {p . normal = offset}
};

// A loop point: on a mesh edge, kept in the face the walk crossed to reach it (so two neighbouring points share
// that face, which the next point names).
struct SectionPoint {
  SurfacePoint at;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};
using SectionLoop = std::vector<SectionPoint>;

// The loops where the plane {p . normal = offset} cuts the closed mesh, each in walking order; a vertex on the
// plane counts as a hair on its positive side.
std::vector<SectionLoop> planeSection(const TriMesh& mesh, const Eigen::Vector3d& normal, double offset);

double loopLength(const SectionLoop& loop);

// The loops where a field given at the mesh's vertices (linear over each triangle, zero at no vertex) is zero, as
// planeSection's.
std::vector<SectionLoop> zeroLoops(const TriMesh& mesh, const Eigen::VectorXd& values);

// The control points of the seam a loop makes: at equal arc length about `spacing` apart [mesh units], 12 to 160
// of them (the section tool's counts: the shortest paths between them follow the section); with `corners`, also
// where the loop strays from the chord between two of them by more than a tenth of their spacing (an outline's
// sharp turns, as the app's Outline tool keeps them).
std::vector<SurfacePoint> sectionSeamPoints(const TriMesh& mesh, const SectionLoop& loop, double spacing,
                                            bool corners = false);

// The control points of an open piece of a loop (its points in order, first to last): both ends and points at
// equal arc length between them, about `spacing` apart; with `corners`, also its turns, as sectionSeamPoints keeps
// them.
std::vector<SurfacePoint> sectionPathPoints(const TriMesh& mesh, const SectionLoop& path, double spacing,
                                            bool corners = false);

}  // namespace billow
