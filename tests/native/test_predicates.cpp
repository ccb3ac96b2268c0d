// Robust predicates: exact signs on near-degenerate inputs where plain floating point is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "remesh/predicates.hpp"

using namespace billow;
using Eigen::Vector2d;

namespace {

__extension__ typedef __int128 Int128;

// Exact orient2d for points whose coordinates are integer multiples of 2^-shift (|value| < 2^62 after scaling).
int orientExactScaled(const Vector2d& a, const Vector2d& b, const Vector2d& c, int shift) {
  auto s = [&](double x) { return static_cast<Int128>(static_cast<long long>(std::ldexp(x, shift))); };
  const Int128 det = (s(a.x()) - s(c.x())) * (s(b.y()) - s(c.y())) - (s(a.y()) - s(c.y())) * (s(b.x()) - s(c.x()));
  return (det > 0) - (det < 0);
}

}  // namespace

// Kettner et al.'s classic failure case: p near (0.5, 0.5) on a 2^-53 grid, q = (12, 12), r = (24, 24).
TEST(Predicates, Orient2dMatchesExactOnNearCollinearGrid) {
  const Vector2d q(12, 12), r(24, 24);
  const double ulp = std::ldexp(1.0, -53);
  int naiveWrong = 0, checked = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) {
      const Vector2d p(0.5 + i * ulp, 0.5 + j * ulp);
      const int exact = orientExactScaled(p, q, r, 53);
      EXPECT_EQ(orient2d(p, q, r), exact) << i << " " << j;
      EXPECT_EQ(orient2d(q, r, p), exact);
      EXPECT_EQ(orient2d(r, q, p), -exact);
      const double naive = orient2dFast(p, q, r);
      if (((naive > 0) - (naive < 0)) != exact) ++naiveWrong;
      ++checked;
    }
  // The test input is hard: plain floating point gets many of these wrong.
  EXPECT_GT(naiveWrong, checked / 10);
}

TEST(Predicates, Orient2dOnLongLineWithTinyPerturbations) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    // Points on the line y = 0.75 x (coordinates that are exact multiples of 2^-40), nudged by +-1 unit.
    const long long ia = static_cast<long long>(u(rng) * (1LL << 40)) * 4;
    const long long ib = static_cast<long long>(u(rng) * (1LL << 40)) * 4;
    const long long ic = static_cast<long long>(u(rng) * (1LL << 40)) * 4;
    const int nudge = static_cast<int>(k % 3) - 1;
    const Vector2d a(std::ldexp(double(ia), -40), std::ldexp(double(ia / 4 * 3), -40));
    const Vector2d b(std::ldexp(double(ib), -40), std::ldexp(double(ib / 4 * 3), -40));
    const Vector2d c(std::ldexp(double(ic), -40), std::ldexp(double(ic / 4 * 3 + nudge), -40));
    EXPECT_EQ(orient2d(a, b, c), orientExactScaled(a, b, c, 40));
  }
}

TEST(Predicates, IncircleIsZeroOnCocircularLatticePoints) {
  // All lattice points on the circle x^2 + y^2 = 5^20 (84 of them): exactly cocircular, but the determinant's
  // products (~1e28) are far beyond double precision, so the plain formula is rarely exactly zero.
  const long long r = 9765625, n = r * r;
  std::vector<Vector2d> pts;
  for (long long x = -r; x <= r; ++x) {
    const long long rest = n - x * x;
    auto y = static_cast<long long>(std::llround(std::sqrt(static_cast<double>(rest))));
    while (y * y > rest) --y;
    while ((y + 1) * (y + 1) <= rest) ++y;
    if (y * y != rest) continue;
    pts.emplace_back(double(x), double(y));
    if (y != 0) pts.emplace_back(double(x), double(-y));
  }
  ASSERT_EQ(pts.size(), 84u);
  const double offsets[] = {0.0, 12345.0};
  for (double off : offsets) {
    int naiveNonZero = 0, checked = 0;
    for (std::size_t a = 0; a < pts.size(); a += 5)
      for (std::size_t b = a + 1; b < pts.size(); b += 7)
        for (std::size_t c = b + 1; c < pts.size(); c += 3)
          for (std::size_t d = 0; d < pts.size(); d += 11) {
            if (d == a || d == b || d == c) continue;
            const Vector2d o(off, off);
            EXPECT_EQ(incircle(pts[a] + o, pts[b] + o, pts[c] + o, pts[d] + o), 0);
            if (incircleFast(pts[a] + o, pts[b] + o, pts[c] + o, pts[d] + o) != 0) ++naiveNonZero;
            ++checked;
          }
    EXPECT_GT(naiveNonZero, checked / 4) << "offset " << off;
  }
}

TEST(Predicates, IncircleSeesOneUlpRadialMoves) {
  const double offsets[] = {0.0, 1e6, 1e9};
  for (double off : offsets) {
    const Vector2d a(off + 0, off + 25), b(off - 25, off + 0), c(off + 0, off - 25);  // CCW
    const Vector2d on(off + 25, off + 0);
    const Vector2d out(std::nextafter(on.x(), 1e300), on.y());
    const Vector2d in(std::nextafter(on.x(), -1e300), on.y());
    EXPECT_EQ(incircle(a, b, c, on), 0);
    EXPECT_EQ(incircle(a, b, c, in), 1) << off;
    EXPECT_EQ(incircle(a, b, c, out), -1) << off;
    EXPECT_EQ(incircle(a, c, b, in), -1);  // clockwise flips the sign
    EXPECT_EQ(orient2d(a, b, c), 1);
  }
}

TEST(Predicates, FilterAnswersEasyCasesWithoutExactArithmetic) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  const long long before = exactPredicateCalls();
  for (int k = 0; k < 10000; ++k) {
    const Vector2d a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng)), d(u(rng), u(rng));
    const double o = orient2dFast(a, b, c), ic = incircleFast(a, b, c, d);
    if (std::abs(o) > 1e-9) {
      EXPECT_EQ(orient2d(a, b, c), o > 0 ? 1 : -1);
    }
    if (std::abs(ic) > 1e-9) {
      EXPECT_EQ(incircle(a, b, c, d), ic > 0 ? 1 : -1);
    }
  }
  EXPECT_LT(exactPredicateCalls() - before, 20);
}
