#include "mesh/up_axis.hpp"

namespace billow {

bool parseUpAxis(std::string_view text, UpAxis& out) {
  if (text.size() != 2 || (text[0] != '+' && text[0] != '-') || text[1] < 'x' || text[1] > 'z') return false;
  out.axis = text[1] - 'x';
  out.sign = text[0] == '+' ? 1 : -1;
  return true;
}

std::string toString(const UpAxis& up) { return std::string(up.sign > 0 ? "+" : "-") + char('x' + up.axis); }

Eigen::Matrix3d upFrame(const UpAxis& up) {
  Eigen::Matrix3d r;
  const double s = up.sign;
  // Rows: the up frame's x, y and z in the target's coordinates. Y up keeps x (z follows as x cross y);
  // X up turns a quarter about z, keeping z.
  if (up.axis == 1)
    r << 1, 0, 0, 0, s, 0, 0, 0, s;
  else if (up.axis == 2)
    r << 1, 0, 0, 0, 0, s, 0, -s, 0;
  else
    r << 0, -s, 0, s, 0, 0, 0, 0, 1;
  return r;
}

}  // namespace billow
