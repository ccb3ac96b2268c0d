// Disjoint sets over 0..n-1 with path halving; a union keeps the smaller root, so every set is named by
// its smallest member (callers rely on that for a stable order).
#pragma once
#include <algorithm>
#include <numeric>
#include <vector>

namespace billow {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n = 0) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace billow
