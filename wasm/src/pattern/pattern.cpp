#include "pattern/pattern.hpp"

#include <algorithm>

namespace billow {

std::map<std::pair<int, int>, std::pair<int, int>> outlineEdges(const Panel& panel) {
  std::map<std::pair<int, int>, int> count;
  std::map<std::pair<int, int>, std::pair<int, int>> directed;
  for (int t = 0; t < panel.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = panel.triangles(t, k), b = panel.triangles(t, (k + 1) % 3);
      const auto key = std::minmax(a, b);
      ++count[key];
      directed[key] = {a, b};
    }
  std::map<std::pair<int, int>, std::pair<int, int>> out;
  for (const auto& [key, n] : count)
    if (n == 1) out[key] = directed[key];
  return out;
}

std::vector<int> outlineVertices(const Panel& panel) {
  std::vector<char> on(panel.vertices.rows(), 0);
  for (const auto& [key, edge] : outlineEdges(panel)) on[key.first] = on[key.second] = 1;
  std::vector<int> out;
  for (int v = 0; v < int(on.size()); ++v)
    if (on[v]) out.push_back(v);
  return out;
}

long long numTriangles(const Pattern& pattern) {
  long long n = 0;
  for (const Panel& panel : pattern.panels) n += panel.triangles.rows();
  return n;
}

}  // namespace billow
