#include "io/obj_writer.hpp"

#include <algorithm>
#include <cstdio>

namespace billow {

std::string writeObj(const Vertices& V, const Triangles& F, const std::string& comment) {
  std::string s;
  // Every line of the comment is a comment line: a line break in it must not start an element.
  for (size_t from = 0; from < comment.size();) {
    const size_t to = std::min(comment.find('\n', from), comment.size());
    s += "# " + comment.substr(from, to - from) + "\n";
    from = to + 1;
  }
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
