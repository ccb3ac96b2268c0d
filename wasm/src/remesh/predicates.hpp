// Robust geometric predicates for the remesher (Sec. 5.3): orientation and in-circle tests whose signs are
// exact. A floating-point filter with a forward error bound (the classic bounds of Shewchuk, "Adaptive
// precision floating-point arithmetic and fast robust geometric predicates", 1997) answers almost every
// call; near-degenerate inputs fall back to exact evaluation with floating-point expansions (sums of
// non-overlapping doubles, Dekker/Knuth two-sum and two-product), written here from the published ideas.
// Requires IEEE-754 double arithmetic with round-to-nearest and no extended precision (x86-64 SSE2, wasm):
// a compile-time check rejects FLT_EVAL_METHOD != 0, and a fused multiply-add is only used as std::fma.
#pragma once
#include <Eigen/Core>

namespace billow {

// Sign of the signed area of (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear. Exact.
int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

// +1 if d lies strictly inside the circle through a, b, c (a, b, c counter-clockwise), -1 outside, 0 on it.
// For clockwise a, b, c the sign flips. Exact.
int incircle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d);

// Plain floating-point determinants (no guarantee): for tests and for non-critical quality decisions.
double orient2dFast(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);
double incircleFast(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d);

// How many calls needed the exact fallback since program start (diagnostics and tests).
long long exactPredicateCalls();

}  // namespace billow
