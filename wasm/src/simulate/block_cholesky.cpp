// Multifrontal supernodal Cholesky on 3x3 vertex blocks; see block_cholesky.hpp.
#include "simulate/block_cholesky.hpp"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace billow {
namespace {

using Graph = std::vector<std::vector<int>>;

// Nested dissection by coordinate bisection: split the vertex set at the median of its widest coordinate,
// take the vertices of the upper half that touch the lower half as the separator, order both halves
// recursively and the separator last. On a surface mesh with n vertices the separators have O(sqrt n)
// vertices, which bounds the fill by O(n log n) (George 1973; Lipton, Rose and Tarjan 1979).
class Dissection {
 public:
  Dissection(const Graph& g, const Eigen::MatrixXd& p) : g_(g), p_(p), side_(g.size(), 0), stamp_(g.size(), 0) {}

  void order(std::vector<int> set, std::vector<int>& out) {
    if (set.size() <= 8) {
      out.insert(out.end(), set.begin(), set.end());
      return;
    }
    Eigen::RowVector3d lo = p_.row(set[0]), hi = lo;
    for (int v : set) lo = lo.cwiseMin(p_.row(v)), hi = hi.cwiseMax(p_.row(v));
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const size_t half = set.size() / 2;
    std::nth_element(set.begin(), set.begin() + half, set.end(),
                     [&](int a, int b) { return p_(a, axis) < p_(b, axis); });
    const int mark = ++counter_;
    for (size_t i = 0; i < set.size(); ++i) stamp_[set[i]] = mark, side_[set[i]] = i < half ? 0 : 1;
    std::vector<int> a(set.begin(), set.begin() + half), b, separator;
    for (size_t i = half; i < set.size(); ++i) {
      const int v = set[i];
      bool touches = false;
      for (int u : g_[v]) touches = touches || (stamp_[u] == mark && side_[u] == 0);
      (touches ? separator : b).push_back(v);
    }
    if (a.empty() || b.size() + a.size() == 0) {
      out.insert(out.end(), set.begin(), set.end());
      return;
    }
    order(std::move(a), out);
    order(std::move(b), out);
    out.insert(out.end(), separator.begin(), separator.end());
  }

 private:
  const Graph& g_;
  const Eigen::MatrixXd& p_;
  std::vector<char> side_;
  std::vector<int> stamp_;
  int counter_ = 0;
};

std::vector<int> amdOrder(const Graph& g) {
  const int n = int(g.size());
  std::vector<Eigen::Triplet<double>> trip;
  for (int v = 0; v < n; ++v) {
    trip.emplace_back(v, v, 1.0);
    for (int u : g[v]) trip.emplace_back(u, v, 1.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P;
  Eigen::AMDOrdering<int>()(A, P);
  // Eigen's ordering returns the inverse permutation: P.indices()[new] = old.
  return std::vector<int>(P.indices().data(), P.indices().data() + n);
}

// Dense kernels of the frontal matrices. Eigen 3.4 has no WebAssembly SIMD back end (its products run
// scalar in wasm), so the dominant kernel, the rank update of a front, is written here once with the GCC and
// Clang vector extension: a Packet is two doubles, an SSE2 register in the native x86-64 build and a SIMD128
// register in the wasm build (compiled with -msimd128). Both builds run the same arithmetic in the same order.
typedef double Packet __attribute__((vector_size(16)));

inline Packet load(const double* p) {
  Packet v;
  std::memcpy(&v, p, sizeof v);  // unaligned load
  return v;
}
inline void store(double* p, const Packet& v) { std::memcpy(p, &v, sizeof v); }

// Columns per step of the blocked partial factorization: the rank of each update of the trailing matrix.
constexpr int kBlockColumns = 32;

// Copies the n x b column-major matrix P (leading dimension ld) into groups of 4 rows, zero-padded:
// pack[(g b + p) 4 + r] = P(4 g + r, p). The rank-update kernel then reads both operands sequentially.
void packRowGroups(const double* P, int ld, int n, int b, std::vector<double>& pack) {
  const int groups = (n + 3) / 4;
  pack.assign(size_t(groups) * b * 4, 0.0);
  for (int p = 0; p < b; ++p)
    for (int i = 0; i < n; ++i) pack[(size_t(i / 4) * b + p) * 4 + i % 4] = P[size_t(p) * ld + i];
}

// C -= P P^T on the lower triangle of the n x n matrix C (column-major, leading dimension ld), with P packed
// by packRowGroups(). Blocks of 4 x 4 entries are accumulated in 8 registers over the b columns of P.
void lowerRankUpdate(double* C, int ld, int n, const double* pack, int b) {
  const int groups = (n + 3) / 4;
  for (int gj = 0; gj < groups; ++gj) {
    const double* pb = pack + size_t(gj) * b * 4;
    for (int gi = gj; gi < groups; ++gi) {
      const double* pa = pack + size_t(gi) * b * 4;
      Packet c[2][4] = {};  // c[h][col]: rows 2h, 2h+1 of the block, column col
      for (int p = 0; p < b; ++p) {
        const Packet a0 = load(pa + 4 * p), a1 = load(pa + 4 * p + 2);
        for (int col = 0; col < 4; ++col) {
          const double x = pb[4 * p + col];
          const Packet bc = {x, x};
          c[0][col] += a0 * bc;
          c[1][col] += a1 * bc;
        }
      }
      const int i0 = 4 * gi, j0 = 4 * gj;
      if (gi > gj && i0 + 4 <= n) {
        // Below the diagonal and inside C: all 16 entries exist.
        for (int col = 0; col < 4; ++col) {
          double* dst = C + size_t(j0 + col) * ld + i0;
          store(dst, load(dst) - c[0][col]);
          store(dst + 2, load(dst + 2) - c[1][col]);
        }
      } else {
        // On the diagonal or at the last rows: only entries inside the lower triangle.
        for (int col = 0; col < 4 && j0 + col < n; ++col)
          for (int r = 0; r < 4 && i0 + r < n; ++r)
            if (i0 + r >= j0 + col) C[size_t(j0 + col) * ld + i0 + r] -= c[r / 2][col][r % 2];
      }
    }
  }
}

// Partial Cholesky of the m x m front F (lower triangle, column-major): F11 = L11 L11^T, L21 = F21 L11^-T
// and F22 -= L21 L21^T, where F11 is the leading k x k block. Right-looking by blocks of kBlockColumns
// columns: each block is factorized left-looking (axpy over its rows, which the compiler vectorizes), then
// updates the trailing matrix with lowerRankUpdate(). False on a non-positive pivot; with raisedPivot > 0,
// pivots up to tinyPivot are raised instead (see BlockCholesky::factorize) and counted in `raised`.
bool partialCholesky(double* F, int m, int k, double tinyPivot, double raisedPivot, std::vector<double>& pack,
                     int& raised) {
  for (int J = 0; J < k; J += kBlockColumns) {
    const int b = std::min(kBlockColumns, k - J);
    for (int j = J; j < J + b; ++j) {
      double* cj = F + size_t(j) * m;
      // Four columns per pass over cj, each entry updated in the same order as one column at a time (so the
      // factor is the same to the bit): cj is loaded and stored once per four columns instead of per column.
      int p = J;
      for (; p + 4 <= j; p += 4) {
        const double *c0 = F + size_t(p) * m, *c1 = c0 + m, *c2 = c1 + m, *c3 = c2 + m;
        const double f0 = c0[j], f1 = c1[j], f2 = c2[j], f3 = c3[j];
        const Packet g0 = {f0, f0}, g1 = {f1, f1}, g2 = {f2, f2}, g3 = {f3, f3};
        int i = j;
        for (; i + 2 <= m; i += 2)
          store(cj + i, load(cj + i) - g0 * load(c0 + i) - g1 * load(c1 + i) - g2 * load(c2 + i) - g3 * load(c3 + i));
        for (; i < m; ++i) cj[i] = cj[i] - f0 * c0[i] - f1 * c1[i] - f2 * c2[i] - f3 * c3[i];
      }
      for (; p < j; ++p) {
        const double* cp = F + size_t(p) * m;
        const double f = cp[j];
        for (int i = j; i < m; ++i) cj[i] -= f * cp[i];
      }
      if (raisedPivot > 0 && !(cj[j] > tinyPivot)) {
        cj[j] = std::isfinite(cj[j]) ? std::max(raisedPivot, std::abs(cj[j])) : raisedPivot;
        ++raised;
      }
      if (!(cj[j] > 0)) return false;  // also catches NaN
      const double d = std::sqrt(cj[j]), inv = 1 / d;
      cj[j] = d;
      for (int i = j + 1; i < m; ++i) cj[i] *= inv;
    }
    const int rest = m - J - b;
    if (rest == 0) continue;
    packRowGroups(F + size_t(J) * m + J + b, m, rest, b, pack);
    lowerRankUpdate(F + size_t(J + b) * m + J + b, m, rest, pack.data(), b);
  }
  return true;
}

// The vertex graph of H (3x3 blocks), neighbours sorted.
Graph vertexGraph(const Eigen::SparseMatrix<double>& H) {
  Graph g(H.cols() / 3);
  for (int c = 0; c < H.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(H, c); it; ++it) {
      const int u = int(it.row()) / 3, v = c / 3;
      if (u != v) g[u].push_back(v), g[v].push_back(u);
    }
  for (auto& a : g) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  return g;
}

// perm[new] = old: nested dissection by the vertices' positions, or AMD on the graph.
std::vector<int> fillReducingOrder(const Graph& g, const Eigen::MatrixXd& points, BlockCholesky::Ordering ordering) {
  const int n = int(g.size());
  std::vector<int> perm;
  if (ordering == BlockCholesky::Ordering::NestedDissection && points.rows() == n && points.cols() == 3) {
    std::vector<int> all(n);
    std::iota(all.begin(), all.end(), 0);
    Dissection(g, points).order(std::move(all), perm);
  } else {
    perm = amdOrder(g);
  }
  return perm;
}

// The elimination tree of the ordering perm (Liu's algorithm with path compression), then a postorder, so that
// every subtree and every supernode is a range of consecutive columns: order[new] = old vertex and etree[new] =
// the parent column (-1 at a root), both in the postordered numbering.
void postorderedElimination(const Graph& g, const std::vector<int>& perm, std::vector<int>& order,
                            std::vector<int>& etree) {
  const int n = int(g.size());
  std::vector<int> pinv(n);
  for (int i = 0; i < n; ++i) pinv[perm[i]] = i;
  std::vector<int> parent(n, -1), ancestor(n, -1);
  for (int j = 0; j < n; ++j)
    for (int u : g[perm[j]])
      for (int r = pinv[u], next; r != -1 && r < j; r = next) {
        next = ancestor[r];
        ancestor[r] = j;
        if (next == -1) parent[r] = j;
      }
  std::vector<int> head(n, -1), nextSibling(n, -1);
  for (int j = n - 1; j >= 0; --j)
    if (parent[j] != -1) nextSibling[j] = head[parent[j]], head[parent[j]] = j;
  std::vector<int> post, stack;
  post.reserve(n);
  for (int root = 0; root < n; ++root) {
    if (parent[root] != -1) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int j = stack.back();
      if (head[j] != -1) {
        const int child = head[j];
        head[j] = nextSibling[child];
        stack.push_back(child);
      } else {
        post.push_back(j);
        stack.pop_back();
      }
    }
  }
  std::vector<int> postInv(n);
  for (int k = 0; k < n; ++k) postInv[post[k]] = k;
  order.resize(n);
  etree.resize(n);
  for (int k = 0; k < n; ++k) {
    order[k] = perm[post[k]];
    etree[k] = parent[post[k]] == -1 ? -1 : postInv[parent[post[k]]];
  }
}

// Column counts of L (off-diagonal vertex blocks) by row subtrees: row i of L is the union of the tree paths from
// each lower neighbour j < i up to i.
std::vector<int> columnCounts(const Graph& g, const std::vector<int>& order, const std::vector<int>& pinv,
                              const std::vector<int>& etree) {
  const int n = int(g.size());
  std::vector<int> count(n, 0), mark(n, -1);
  for (int i = 0; i < n; ++i) {
    mark[i] = i;
    for (int u : g[order[i]])
      for (int j = pinv[u]; j < i && mark[j] != i; j = etree[j]) mark[j] = i, ++count[j];
  }
  return count;
}

// The first column of each supernode (and n at the end): fundamental supernodes (j and its parent j+1 with nested
// structure), then relaxed amalgamation, which merges a supernode into its parent when it ends right before it
// (the last child in postorder) and the merged panel stays mostly nonzero: bigger dense blocks run faster than
// the zeros cost. Sizes in vertex blocks.
std::vector<int> amalgamatedSupernodes(const std::vector<int>& etree, const std::vector<int>& count) {
  const int n = int(etree.size());
  std::vector<int> sFirst = {0};
  for (int j = 0; j + 1 < n; ++j)
    if (!(etree[j] == j + 1 && count[j] == count[j + 1] + 1)) sFirst.push_back(j + 1);
  sFirst.push_back(n);
  const int ns0 = int(sFirst.size()) - 1;
  std::vector<int> superOf(n);
  for (int s = 0; s < ns0; ++s)
    for (int j = sFirst[s]; j < sFirst[s + 1]; ++j) superOf[j] = s;
  std::vector<int> cols(ns0), below(ns0), into(ns0, -1), firstCol(ns0);
  std::vector<double> zeros(ns0, 0);
  for (int s = 0; s < ns0; ++s) {
    cols[s] = sFirst[s + 1] - sFirst[s];
    below[s] = count[sFirst[s + 1] - 1];
    firstCol[s] = sFirst[s];
  }
  for (int s = 0; s < ns0; ++s) {
    const int last = sFirst[s + 1] - 1, pc = etree[last];
    if (pc == -1 || pc != last + 1) continue;
    const int p = superOf[pc];
    const double k = cols[s] + cols[p], entries = k * (k + 1) / 2 + k * below[p];
    const double z = zeros[s] + zeros[p] + double(cols[s]) * (cols[p] + below[p] - below[s]);
    const bool merge =
        k <= 4 || (k <= 16 && z < 0.5 * entries) || (k <= 48 && z < 0.15 * entries) || z < 0.03 * entries;
    if (!merge) continue;
    into[s] = p;
    cols[p] = int(k);
    zeros[p] = z;
    firstCol[p] = firstCol[s];
  }
  std::vector<int> first;
  for (int s = 0; s < ns0; ++s)
    if (into[s] == -1) first.push_back(firstCol[s]);
  first.push_back(n);
  return first;
}

}  // namespace

void BlockCholesky::analyze(const Eigen::SparseMatrix<double>& H, const Eigen::MatrixXd& points, Ordering ordering) {
  n_ = int(H.cols() / 3);
  const Graph g = vertexGraph(H);
  // An ordering's elimination: the postordered permutation, its elimination tree, the inverse permutation and
  // the column counts of L, with the sum of squared column lengths (proportional to the multiply-adds).
  struct Elimination {
    std::vector<int> perm, etree, pinv, count;
    double work = 0;
  };
  const auto eliminate = [&](Ordering o) {
    Elimination e;
    postorderedElimination(g, fillReducingOrder(g, points, o), e.perm, e.etree);
    e.pinv.resize(n_);
    for (int i = 0; i < n_; ++i) e.pinv[e.perm[i]] = i;
    e.count = columnCounts(g, e.perm, e.pinv, e.etree);
    for (int c : e.count) e.work += (c + 1.0) * (c + 1.0);
    return e;
  };
  // FewerFlops: nested dissection by coordinate bisection suits round shapes, AMD flat sheets and limbs; each is
  // once per mesh, so both are tried (bench/README.md "Linear solver").
  Elimination chosen = eliminate(ordering == Ordering::FewerFlops ? Ordering::Amd : ordering);
  if (ordering == Ordering::FewerFlops && points.rows() == n_) {
    Elimination bisected = eliminate(Ordering::NestedDissection);
    if (bisected.work <= chosen.work) chosen = std::move(bisected);
  }
  perm_ = std::move(chosen.perm);
  first_ = amalgamatedSupernodes(chosen.etree, chosen.count);
  std::vector<int> superOf(n_);
  for (int s = 0; s + 1 < int(first_.size()); ++s)
    for (int j = first_[s]; j < first_[s + 1]; ++j) superOf[j] = s;
  buildRowStructure(g, chosen.pinv, chosen.etree, superOf);
  buildScatterMap(H, chosen.pinv, superOf);
}

void BlockCholesky::buildRowStructure(const std::vector<std::vector<int>>& g, const std::vector<int>& pinv,
                                      const std::vector<int>& etree, const std::vector<int>& superOf) {
  const int n = n_, ns = int(first_.size()) - 1;
  parent_.assign(ns, -1);
  numChildren_.assign(ns, 0);
  std::vector<std::vector<int>> children(ns);
  for (int s = 0; s < ns; ++s) {
    const int pc = etree[first_[s + 1] - 1];
    if (pc != -1) {
      parent_[s] = superOf[pc];
      ++numChildren_[parent_[s]];
      children[parent_[s]].push_back(s);
    }
  }
  // Each supernode's rows: its columns, then the rows below from H and from the children.
  rowStart_.assign(1, 0);
  rows_.clear();
  relStart_.assign(ns + 1, 0);
  std::vector<int> relOf(ns);  // offset of each child's map in rel_, filled when its parent is built
  rel_.clear();
  std::vector<int> pos(n, -1), seen(n, -1);
  for (int s = 0; s < ns; ++s) {
    const int f = first_[s], l = first_[s + 1];
    std::vector<int> r;
    for (int j = f; j < l; ++j) r.push_back(j), seen[j] = s;
    for (int j = f; j < l; ++j)
      for (int u : g[perm_[j]]) {
        const int i = pinv[u];
        if (i >= l && seen[i] != s) seen[i] = s, r.push_back(i);
      }
    for (int c : children[s])
      for (int k = rowStart_[c] + (first_[c + 1] - first_[c]); k < rowStart_[c + 1]; ++k) {
        const int i = rows_[k];
        if (i >= l && seen[i] != s) seen[i] = s, r.push_back(i);
      }
    std::sort(r.begin() + (l - f), r.end());
    for (size_t k = 0; k < r.size(); ++k) pos[r[k]] = int(k);
    rows_.insert(rows_.end(), r.begin(), r.end());
    rowStart_.push_back(int(rows_.size()));
    for (int c : children[s]) {
      relOf[c] = int(rel_.size());
      for (int k = rowStart_[c] + (first_[c + 1] - first_[c]); k < rowStart_[c + 1]; ++k)
        for (int d = 0; d < 3; ++d) rel_.push_back(3 * pos[rows_[k]] + d);
    }
  }
  // relStart_[s]: where s's map (into its parent) starts.
  for (int s = 0; s < ns; ++s) relStart_[s] = parent_[s] == -1 ? 0 : relOf[s];
}

void BlockCholesky::buildScatterMap(const Eigen::SparseMatrix<double>& H, const std::vector<int>& pinv,
                                    const std::vector<int>& superOf) {
  const int ns = int(first_.size()) - 1;
  // Every stored value of H to its slot in a front (column-major, leading dimension m).
  std::vector<int> owner(H.nonZeros()), slot(H.nonZeros());
  std::vector<int> perSuper(ns + 1, 0);
  for (int c = 0; c < H.outerSize(); ++c)
    for (int k = H.outerIndexPtr()[c]; k < H.outerIndexPtr()[c + 1]; ++k) {
      const int r = H.innerIndexPtr()[k];
      int pr = pinv[r / 3], pc = pinv[c / 3], dr = r % 3, dc = c % 3;
      if (pr < pc) std::swap(pr, pc), std::swap(dr, dc);
      const int s = superOf[pc];
      const int m = 3 * (rowStart_[s + 1] - rowStart_[s]);
      // Rows of s are its own columns (in order) then the sorted rows below; find pr among them.
      const int* rb = rows_.data() + rowStart_[s];
      const int* re = rows_.data() + rowStart_[s + 1];
      const int cs = first_[s + 1] - first_[s];
      const int rowIndex = pr < first_[s + 1] ? pr - first_[s] : int(std::lower_bound(rb + cs, re, pr) - rb);
      const int colIndex = pc - first_[s];
      owner[k] = s;
      slot[k] = (3 * colIndex + dc) * m + 3 * rowIndex + dr;
      ++perSuper[s + 1];
    }
  for (int s = 0; s < ns; ++s) perSuper[s + 1] += perSuper[s];
  scatterStart_ = perSuper;
  scatterFrom_.assign(H.nonZeros(), 0);
  scatterTo_.assign(H.nonZeros(), 0);
  for (int k = 0; k < int(H.nonZeros()); ++k) {
    const int at = perSuper[owner[k]]++;
    scatterFrom_[at] = k;
    scatterTo_[at] = slot[k];
  }
  // The factor's panels and the work space, once.
  panelStart_.assign(ns + 1, 0);
  int maxM = 0;
  for (int s = 0; s < ns; ++s) {
    const int m = 3 * (rowStart_[s + 1] - rowStart_[s]), k = 3 * (first_[s + 1] - first_[s]);
    panelStart_[s + 1] = panelStart_[s] + size_t(m) * k;
    maxM = std::max(maxM, m);
  }
  panels_.assign(panelStart_[ns], 0.0);
  front_.resize(maxM, maxM);
  stack_.clear();
  work_.resize(3 * n_);
}

double BlockCholesky::factorNonZeros() const { return double(panels_.size()); }

double BlockCholesky::factorFlops() const {
  double f = 0;
  for (int s = 0; s + 1 < int(first_.size()); ++s) {
    const double m = 3.0 * (rowStart_[s + 1] - rowStart_[s]), k = 3.0 * (first_[s + 1] - first_[s]), u = m - k;
    f += k * k * k / 6 + k * k * u / 2 + k * u * u / 2;
  }
  return f;
}

bool BlockCholesky::factorize(const Eigen::SparseMatrix<double>& H, double tinyPivot, double raisedPivot) {
  const int ns = numSupernodes();
  const double* values = H.valuePtr();
  raised_ = 0;
  // Update matrices of finished supernodes, in postorder; a parent pops its children's from the top.
  std::vector<size_t> offsets;
  size_t top = 0;
  for (int s = 0; s < ns; ++s) {
    const int m = 3 * (rowStart_[s + 1] - rowStart_[s]), k = 3 * (first_[s + 1] - first_[s]), u = m - k;
    Eigen::Map<Eigen::MatrixXd> F(front_.data(), m, m);
    for (int j = 0; j < m; ++j) F.col(j).tail(m - j).setZero();
    for (int e = scatterStart_[s]; e < scatterStart_[s + 1]; ++e) F.data()[scatterTo_[e]] += values[scatterFrom_[e]];
    // Extend-add the children's update matrices (the last numChildren_ on the stack).
    for (int c = 0; c < numChildren_[s]; ++c) {
      const size_t at = offsets.back();
      offsets.pop_back();
      const double* U = stack_.data() + at;
      // Which child is it? Its map is found through the child's index, recorded next to its matrix.
      const int child = int(U[0]);
      const int uc = 3 * (rowStart_[child + 1] - rowStart_[child] - (first_[child + 1] - first_[child]));
      const int* rel = rel_.data() + relStart_[child];
      for (int j = 0; j < uc; ++j) {
        const double* col = U + 1 + size_t(j) * uc;
        double* dst = F.data() + size_t(rel[j]) * m;
        for (int i = j; i < uc; ++i) dst[rel[i]] += col[i];
      }
      top = at;
    }
    // Dense partial factorization: F11 = L11 L11^T, L21 = F21 L11^-T, update = F22 - L21 L21^T.
    if (!partialCholesky(F.data(), m, k, tinyPivot, raisedPivot, pack_, raised_)) return false;
    Eigen::Map<Eigen::MatrixXd>(panels_.data() + panelStart_[s], m, k) = F.leftCols(k);
    if (parent_[s] != -1) {
      const size_t need = top + 1 + size_t(u) * u;
      if (stack_.size() < need) stack_.resize(std::max(need, stack_.size() * 3 / 2));
      offsets.push_back(top);
      stack_[top] = s;  // the child's index (exact in a double)
      // Its lower triangle only: the extend-add reads no more.
      for (int j = 0; j < u; ++j) {
        const double* from = F.data() + size_t(k + j) * m + k;
        std::copy(from + j, from + u, stack_.data() + top + 1 + size_t(j) * u + j);
      }
      top = need;
    }
  }
  return true;
}

void BlockCholesky::solve(Eigen::VectorXd& b) const {
  const int ns = numSupernodes();
  Eigen::VectorXd& x = work_;
  for (int i = 0; i < n_; ++i) x.segment<3>(3 * i) = b.segment<3>(3 * perm_[i]);
  Eigen::VectorXd t;
  for (int s = 0; s < ns; ++s) {
    const int m = 3 * (rowStart_[s + 1] - rowStart_[s]), k = 3 * (first_[s + 1] - first_[s]), u = m - k;
    Eigen::Map<const Eigen::MatrixXd> L(panels_.data() + panelStart_[s], m, k);
    auto xs = x.segment(3 * first_[s], k);
    L.topRows(k).triangularView<Eigen::Lower>().solveInPlace(xs);
    if (u == 0) continue;
    t.noalias() = L.bottomRows(u) * xs;
    const int* r = rows_.data() + rowStart_[s] + k / 3;
    for (int i = 0; i < u / 3; ++i) x.segment<3>(3 * r[i]) -= t.segment<3>(3 * i);
  }
  for (int s = ns - 1; s >= 0; --s) {
    const int m = 3 * (rowStart_[s + 1] - rowStart_[s]), k = 3 * (first_[s + 1] - first_[s]), u = m - k;
    Eigen::Map<const Eigen::MatrixXd> L(panels_.data() + panelStart_[s], m, k);
    auto xs = x.segment(3 * first_[s], k);
    if (u > 0) {
      t.resize(u);
      const int* r = rows_.data() + rowStart_[s] + k / 3;
      for (int i = 0; i < u / 3; ++i) t.segment<3>(3 * i) = x.segment<3>(3 * r[i]);
      xs.noalias() -= L.bottomRows(u).transpose() * t;
    }
    L.topRows(k).transpose().triangularView<Eigen::Upper>().solveInPlace(xs);
  }
  for (int i = 0; i < n_; ++i) b.segment<3>(3 * perm_[i]) = x.segment<3>(3 * i);
}

}  // namespace billow
