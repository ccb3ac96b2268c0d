// Which of a target's own axes points up (the design's target.up, docs/formats.md). Mesh files carry no
// reliable up: a Z-up file (CAD, 3D printing) read Y up lies on its side. The target keeps its own
// coordinates; what is shown and said about it (its height, "near the top") is read in the up frame.
#pragma once
#include <Eigen/Core>
#include <string>
#include <string_view>

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

}  // namespace billow
