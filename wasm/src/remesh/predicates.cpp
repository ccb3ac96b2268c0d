// Robust orientation / in-circle predicates: floating-point filter, then exact expansion arithmetic.
// An expansion is a sum of doubles that do not overlap bitwise; its sign is the sign of its largest
// component. Only error-free transformations are used: two-sum (Knuth), two-product (Dekker's split, or
// std::fma when the hardware has it), and "grow"/"scale" of expansions, so the result is exact whatever the
// magnitudes, as long as nothing overflows or underflows.
#include "remesh/predicates.hpp"

#include <atomic>
#include <cfloat>
#include <cmath>
#include <vector>

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "The robust predicates need plain double evaluation (FLT_EVAL_METHOD == 0): no x87 extended precision."
#endif
#if defined(__clang__)
// Dekker's split must not be contracted into a fused multiply-add.
#pragma clang fp contract(off)
#endif

namespace billow {

namespace {

using Expansion = std::vector<double>;

constexpr double kEps = DBL_EPSILON / 2;                        // 2^-53, the unit round-off
constexpr double kOrientBound = (3.0 + 16.0 * kEps) * kEps;     // relative error of the orient2d filter
constexpr double kIncircleBound = (10.0 + 96.0 * kEps) * kEps;  // relative error of the incircle filter
constexpr double kSplitter = 134217729.0;                       // 2^27 + 1

std::atomic<long long> gExactCalls{0};

// x + y == a + b exactly, x = fl(a + b).
inline void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void twoDiff(double a, double b, double& x, double& y) { twoSum(a, -b, x, y); }

// x + y == a * b exactly, x = fl(a * b).
inline void twoProduct(double a, double b, double& x, double& y) {
  x = a * b;
#ifdef FP_FAST_FMA
  y = std::fma(a, b, -x);
#else
  auto split = [](double v, double& hi, double& lo) {
    const double c = kSplitter * v;
    const double big = c - v;
    hi = c - big;
    lo = v - hi;
  };
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
#endif
}

// e + b, components in increasing magnitude, zeros dropped (Shewchuk's GROW-EXPANSION idea).
Expansion grow(const Expansion& e, double b) {
  Expansion h;
  h.reserve(e.size() + 1);
  double q = b;
  for (double ei : e) {
    double sum, err;
    twoSum(q, ei, sum, err);
    if (err != 0.0) h.push_back(err);
    q = sum;
  }
  if (q != 0.0 || h.empty()) h.push_back(q);
  return h;
}

Expansion add(const Expansion& e, const Expansion& f) {
  Expansion h = e;
  for (double fi : f) h = grow(h, fi);
  return h;
}

Expansion negate(Expansion e) {
  for (double& x : e) x = -x;
  return e;
}

// e * b (SCALE-EXPANSION idea; two-sum everywhere so no magnitude ordering is assumed).
Expansion scale(const Expansion& e, double b) {
  Expansion h;
  h.reserve(2 * e.size());
  double q = 0.0;
  bool first = true;
  for (double ei : e) {
    double prod, perr;
    twoProduct(ei, b, prod, perr);
    if (first) {
      q = prod;
      if (perr != 0.0) h.push_back(perr);
      first = false;
      continue;
    }
    double s1, e1;
    twoSum(q, perr, s1, e1);
    if (e1 != 0.0) h.push_back(e1);
    double s2, e2;
    twoSum(prod, s1, s2, e2);
    if (e2 != 0.0) h.push_back(e2);
    q = s2;
  }
  if (q != 0.0 || h.empty()) h.push_back(q);
  return h;
}

Expansion mul(const Expansion& e, const Expansion& f) {
  Expansion h{0.0};
  for (double fi : f) h = add(h, scale(e, fi));
  return h;
}

Expansion diff(double a, double b) {
  double x, y;
  twoDiff(a, b, x, y);
  if (y == 0.0) return {x};
  return {y, x};
}

// The components do not overlap, so the largest one decides the sign.
int sign(const Expansion& e) {
  double best = 0.0;
  for (double x : e)
    if (std::abs(x) > std::abs(best)) best = x;
  return (best > 0.0) - (best < 0.0);
}

int orient2dExact(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Expansion acx = diff(a.x(), c.x()), bcy = diff(b.y(), c.y());
  const Expansion acy = diff(a.y(), c.y()), bcx = diff(b.x(), c.x());
  return sign(add(mul(acx, bcy), negate(mul(acy, bcx))));
}

int incircleExact(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  const Eigen::Vector2d& d) {
  const Expansion adx = diff(a.x(), d.x()), ady = diff(a.y(), d.y());
  const Expansion bdx = diff(b.x(), d.x()), bdy = diff(b.y(), d.y());
  const Expansion cdx = diff(c.x(), d.x()), cdy = diff(c.y(), d.y());
  const Expansion alift = add(mul(adx, adx), mul(ady, ady));
  const Expansion blift = add(mul(bdx, bdx), mul(bdy, bdy));
  const Expansion clift = add(mul(cdx, cdx), mul(cdy, cdy));
  const Expansion bc = add(mul(bdx, cdy), negate(mul(bdy, cdx)));
  const Expansion ca = add(mul(cdx, ady), negate(mul(cdy, adx)));
  const Expansion ab = add(mul(adx, bdy), negate(mul(ady, bdx)));
  return sign(add(add(mul(alift, bc), mul(blift, ca)), mul(clift, ab)));
}

}  // namespace

double orient2dFast(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (a.x() - c.x()) * (b.y() - c.y()) - (a.y() - c.y()) * (b.x() - c.x());
}

double incircleFast(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  return (adx * adx + ady * ady) * (bdx * cdy - bdy * cdx) + (bdx * bdx + bdy * bdy) * (cdx * ady - cdy * adx) +
         (cdx * cdx + cdy * cdy) * (adx * bdy - ady * bdx);
}

int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  const double bound = kOrientBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  gExactCalls.fetch_add(1, std::memory_order_relaxed);
  return orient2dExact(a, b, c);
}

int incircle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * alift +
                           (std::abs(cdxady) + std::abs(adxcdy)) * blift +
                           (std::abs(adxbdy) + std::abs(bdxady)) * clift;
  const double bound = kIncircleBound * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  gExactCalls.fetch_add(1, std::memory_order_relaxed);
  return incircleExact(a, b, c, d);
}

long long exactPredicateCalls() { return gExactCalls.load(std::memory_order_relaxed); }

}  // namespace billow
