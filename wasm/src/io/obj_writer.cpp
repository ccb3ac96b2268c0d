#include "io/obj_writer.hpp"

#include <cstdio>

namespace billow {

std::string writeObj(const Vertices& V, const Triangles& F, const std::string& comment) {
  std::string s = comment.empty() ? "" : "# " + comment + "\n";
  char line[128];
  for (int v = 0; v < V.rows(); ++v) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", V(v, 0), V(v, 1), V(v, 2));
    s += line;
  }
  for (int f = 0; f < F.rows(); ++f) {
    std::snprintf(line, sizeof line, "f %d %d %d\n", F(f, 0) + 1, F(f, 1) + 1, F(f, 2) + 1);
    s += line;
  }
  return s;
}

}  // namespace billow
