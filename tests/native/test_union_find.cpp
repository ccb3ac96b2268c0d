// UnionFind (util/union_find.hpp) on its own: the pattern builder, the sewn mesh and the remesher group
// vertices with it and rely on each set being named by its smallest member, so that names and orders are
// stable; a different root would renumber them without any higher-level test noticing.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "util/union_find.hpp"

using namespace billow;

namespace {

// Connected components of the graph on 0..n-1 with these edges, each labelled by its smallest vertex: a
// plain graph search, independent of the disjoint-set forest.
std::vector<int> componentMinima(int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> adjacent(n);
  for (const auto& [a, b] : edges) adjacent[a].push_back(b), adjacent[b].push_back(a);
  std::vector<int> label(n, -1);
  for (int start = 0; start < n; ++start) {  // ascending starts: the first vertex reached is the smallest
    if (label[start] >= 0) continue;
    std::vector<int> stack{start};
    label[start] = start;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int w : adjacent[v])
        if (label[w] < 0) label[w] = start, stack.push_back(w);
    }
  }
  return label;
}

}  // namespace

TEST(UnionFind, EveryElementStartsAsItsOwnSet) {
  UnionFind sets(5);
  ASSERT_EQ(sets.parent.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(sets.find(i), i);
  EXPECT_TRUE(UnionFind().parent.empty()) << "the default is the empty universe";
}

TEST(UnionFind, AUnionOfTheseSetsIsNamedByItsSmallestMember) {
  // {3, 5} joined with {1}, then {7, 4}: roots 1 and 4, whatever the order of the arguments.
  UnionFind sets(8);
  sets.unite(5, 3);
  EXPECT_EQ(sets.find(5), 3);
  sets.unite(3, 1);
  sets.unite(7, 4);
  for (int i : {1, 3, 5}) EXPECT_EQ(sets.find(i), 1) << i;
  for (int i : {4, 7}) EXPECT_EQ(sets.find(i), 4) << i;
  for (int i : {0, 2, 6}) EXPECT_EQ(sets.find(i), i) << "untouched elements stay alone";
  // Joining two sets through non-root members names the union by the smaller of both minima.
  sets.unite(7, 5);
  for (int i : {1, 3, 4, 5, 7}) EXPECT_EQ(sets.find(i), 1) << i;
}

TEST(UnionFind, UnitingMembersOfOneSetChangesNothing) {
  UnionFind sets(4);
  sets.unite(2, 3);
  sets.unite(1, 2);
  const std::vector<int> before{sets.find(0), sets.find(1), sets.find(2), sets.find(3)};
  sets.unite(3, 1);
  sets.unite(2, 2);
  EXPECT_EQ((std::vector<int>{sets.find(0), sets.find(1), sets.find(2), sets.find(3)}), before);
  EXPECT_EQ(before, (std::vector<int>{0, 1, 1, 1}));
}

TEST(UnionFind, ALongChainUnitedFromItsFarEndHasTheFirstElementAsRootAndFindsHalveItsPath) {
  // Uniting (i + 1, i) from the top down hangs each element under the next smaller one: a chain of depth
  // n - 1. Path halving points every visited element at its grandparent, so one find at least halves the
  // depth of the element found (rounded up): 999 -> 500 -> 250 -> ... -> 1 in eleven finds.
  const int n = 1000;
  UnionFind sets(n);
  for (int i = n - 2; i >= 0; --i) sets.unite(i + 1, i);
  const auto depth = [&](int i) {
    int d = 0;
    for (; sets.parent[i] != i; i = sets.parent[i]) ++d;
    return d;
  };
  ASSERT_EQ(depth(n - 1), n - 1);
  int before = n - 1;
  for (int k = 0; k < 11; ++k) {
    EXPECT_EQ(sets.find(n - 1), 0);
    const int after = depth(n - 1);
    EXPECT_LE(after, (before + 1) / 2) << "find " << k + 1;
    before = after;
  }
  EXPECT_LE(before, 1);
  for (int i = 0; i < n; ++i) EXPECT_EQ(sets.find(i), 0) << i;
}

TEST(UnionFind, RandomUnionsMatchTheComponentsOfAGraphSearch) {
  std::mt19937 rng(23);
  for (int round = 0; round < 20; ++round) {
    const int n = 60;
    std::uniform_int_distribution<int> pick(0, n - 1);
    std::vector<std::pair<int, int>> edges;
    for (int k = 0; k < 40; ++k) edges.emplace_back(pick(rng), pick(rng));
    UnionFind sets(n);
    for (const auto& [a, b] : edges) sets.unite(a, b);
    const std::vector<int> expected = componentMinima(n, edges);
    for (int i = 0; i < n; ++i) EXPECT_EQ(sets.find(i), expected[i]) << "round " << round << ", element " << i;
  }
}
