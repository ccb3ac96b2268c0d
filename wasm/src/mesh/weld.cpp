#include "mesh/weld.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "util/error.hpp"

namespace billow {

namespace {

bool isFiniteRow(const Vertices& P, Eigen::Index i) { return P.row(i).allFinite(); }

// For each row, the first row exactly equal to it (itself when it is the first). Sorting keeps this
// O(n log n) without a hash table per corner; rows with a NaN or infinity stand alone.
std::vector<int> firstEqualRow(const Vertices& P) {
  const int n = static_cast<int>(P.rows());
  std::vector<int> order;
  order.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
    if (isFiniteRow(P, i)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&P](int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (P(a, k) != P(b, k)) return P(a, k) < P(b, k);
    return a < b;
  });
  std::vector<int> first(static_cast<size_t>(n));
  std::iota(first.begin(), first.end(), 0);
  for (size_t k = 1; k < order.size(); ++k)
    if (P.row(order[k]) == P.row(order[k - 1])) first[order[k]] = first[order[k - 1]];
  return first;
}

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  size_t operator()(const Cell& c) const {
    std::uint64_t h = 0;
    for (const std::int64_t x : c) h = (h ^ static_cast<std::uint64_t>(x)) * 0x9E3779B97F4A7C15ull + (h >> 29);
    return static_cast<size_t>(h ^ (h >> 32));
  }
};

// Greedy merge of distinct points within tol, in order: each point joins the earliest kept point within
// tol, or is kept. Cells are 2*tol wide, so on each axis only the own cell and the nearer neighbour can
// hold a point within tol: 8 cells to look at.
class ToleranceGrid {
 public:
  ToleranceGrid(const Eigen::RowVector3d& origin, double tol, Eigen::Index points)
      : origin_(origin), tol_(tol), size_(2 * tol), next_(static_cast<size_t>(points), -1) {}

  int findOrAdd(const Vertices& Q, int q) {
    Cell own{}, side{};
    for (int a = 0; a < 3; ++a) {
      const double u = (Q(q, a) - origin_(a)) / size_;
      const double c = std::floor(u);
      own[a] = static_cast<std::int64_t>(c);
      side[a] = u - c < 0.5 ? -1 : 1;
    }
    int best = -1;
    for (int corner = 0; corner < 8; ++corner) {
      Cell cell = own;
      for (int a = 0; a < 3; ++a)
        if (corner & (1 << a)) cell[a] += side[a];
      const auto it = heads_.find(cell);
      for (int p = it == heads_.end() ? -1 : it->second; p >= 0; p = next_[p])
        if ((best < 0 || p < best) && (Q.row(p) - Q.row(q)).squaredNorm() <= tol_ * tol_) best = p;
    }
    if (best >= 0) return best;
    auto [it, added] = heads_.try_emplace(own, q);
    if (!added) next_[q] = std::exchange(it->second, q);
    return q;
  }

 private:
  Eigen::RowVector3d origin_;
  double tol_, size_;
  std::unordered_map<Cell, int, CellHash> heads_;
  std::vector<int> next_;  // next kept point in the same cell
};

// For each row of Q (distinct points, first-seen order), the earliest row it merges with (itself if kept).
std::vector<int> mergeWithinTolerance(const Vertices& Q, double relativeTolerance) {
  std::vector<int> rep(static_cast<size_t>(Q.rows()));
  std::iota(rep.begin(), rep.end(), 0);
  Eigen::RowVector3d lo = Eigen::RowVector3d::Constant(INFINITY), hi = -lo;
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    if (isFiniteRow(Q, i)) lo = lo.cwiseMin(Q.row(i)), hi = hi.cwiseMax(Q.row(i));
  const double diagonal = (hi - lo).norm();
  const double tol = relativeTolerance * diagonal;
  // Nothing to do without a tolerance; and beyond 1e15 cells per axis the cell indices could overflow.
  if (!(tol > 0) || !std::isfinite(diagonal) || diagonal / tol > 1e15) return rep;
  ToleranceGrid grid(lo, tol, Q.rows());
  for (int q = 0; q < static_cast<int>(Q.rows()); ++q)
    if (isFiniteRow(Q, q)) rep[q] = grid.findOrAdd(Q, q);
  return rep;
}

}  // namespace

TriMesh weld(const Vertices& soup, const WeldOptions& options) {
  if (soup.rows() % 3 != 0)
    throw Error("weld.bad-soup", "A triangle soup needs three corners per triangle, but " +
                                     std::to_string(soup.rows()) + " corners were given.");
  const int n = static_cast<int>(soup.rows());
  const std::vector<int> first = firstEqualRow(soup);
  std::vector<int> distinctOf(static_cast<size_t>(n));  // corner -> row of Q
  Vertices Q(n, 3);
  int distinct = 0;
  for (int c = 0; c < n; ++c) {
    if (first[c] == c)
      Q.row(distinct) = soup.row(c), distinctOf[c] = distinct++;
    else
      distinctOf[c] = distinctOf[first[c]];
  }
  Q.conservativeResize(distinct, 3);
  const std::vector<int> rep = mergeWithinTolerance(Q, options.relativeTolerance);
  std::vector<int> finalOf(static_cast<size_t>(distinct));
  TriMesh mesh;
  mesh.V.resize(distinct, 3);
  int kept = 0;
  for (int q = 0; q < distinct; ++q) {
    if (rep[q] == q)
      mesh.V.row(kept) = Q.row(q), finalOf[q] = kept++;
    else
      finalOf[q] = finalOf[rep[q]];
  }
  mesh.V.conservativeResize(kept, 3);
  mesh.F.resize(n / 3, 3);
  for (int c = 0; c < n; ++c) mesh.F(c / 3, c % 3) = finalOf[distinctOf[c]];
  return mesh;
}

}  // namespace billow
