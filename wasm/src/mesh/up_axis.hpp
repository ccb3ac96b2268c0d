// Which of a target's own axes points up (the design's target.up, docs/formats.md). Mesh files carry no
// reliable up: a Z-up file (CAD, 3D printing) read Y up lies on its side. The target keeps its own
// coordinates; what is shown and said about it (its height, "near the top") is read in the up frame.
#pragma once
#include <Eigen/Core>
#include <string>
#include <string_view>

#include "mesh/tri_mesh.hpp"

namespace billow {

struct UpAxis {
  int axis = 1;  // the target's own axis that points up: 0 x, 1 y, 2 z
  int sign = 1;  // +1: along it, -1: against it
  bool operator==(const UpAxis& o) const { return axis == o.axis && sign == o.sign; }
  bool operator!=(const UpAxis& o) const { return !(*this == o); }
};

// "+y", "-y", "+z", "-z", "+x" or "-x" (exactly); false for anything else.
bool parseUpAxis(std::string_view text, UpAxis& out);
std::string toString(const UpAxis& up);

// The rotation from the target's own coordinates to the up frame (x right, y up, z towards the viewer, as in
// the app's target pane): a proper rotation, the same as the app's (web/src/app/up-axis.js UP_FRAMES).
Eigen::Matrix3d upFrame(const UpAxis& up);

// The guess when a mesh file is opened. Files are Y up (graphics tools, Billow's examples) or Z up (CAD, 3D printing),
// and nothing in OBJ, STL or PLY says which. A standing shape stands on its bottom: the centroid of its surface (an
// inflatable's mass is its skin) lies inside the footprint of what touches the floor. The guess is Z up only when the
// shape cannot stand on its Y bottom and can on its Z bottom; otherwise (both, neither) Y stays up. The app takes it
// from the validation report (MeshStats::standing), `billow suggest MESH` from there too.
struct UpGuess {
  UpAxis up;  // +y or +z
  // How firmly it stands with its own y / z axis up: how deep its surface centroid lies inside its footprint, over
  // the box diagonal (negative: it tips over).
  double standsY = 0, standsZ = 0;
};
UpGuess guessUp(const TriMesh& mesh);

}  // namespace billow
