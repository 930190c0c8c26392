#pragma once
// Outward steps on doubles: the building block of gesmi's rounding.
//
// Every +, -, *, / and sqrt is computed at round-to-nearest (IEEE 754 rounds them
// correctly, so the error is at most half an ulp) and the bound is then moved one
// representable number outward unless the rounding error is known to point inward.
// That encloses the real result without touching the global floating-point
// environment. See docs/intervals.md.

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace gesmi {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// Smallest double strictly greater than x (x itself for +inf and NaN).
constexpr double next_up(double x) {
  if (!(x < kInf)) return x;  // +inf stays, NaN stays
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  auto bits = std::bit_cast<std::int64_t>(x);
  bits += (bits >= 0) ? 1 : -1;
  return std::bit_cast<double>(bits);
}

/// Largest double strictly smaller than x (x itself for -inf and NaN).
constexpr double next_down(double x) { return -next_up(-x); }

/// `steps` outward moves: used for libm results, whose error is a few ulps.
constexpr double step_up(double x, int steps) {
  // Away from zero and infinity, `steps` moves are one integer addition on the bits
  // (the doubles of one sign are ordered like their bit patterns).
  if (steps >= 0 && steps < 1024 && ((x > 0x1p-1000 && x < 0x1p1000) || (x < -0x1p-1000 && x > -0x1p1000))) {
    auto bits = std::bit_cast<std::int64_t>(x);
    bits += (bits >= 0) ? steps : -steps;
    return std::bit_cast<double>(bits);
  }
  for (int i = 0; i < steps; ++i) x = next_up(x);
  return x;
}
constexpr double step_down(double x, int steps) { return -step_up(-x, steps); }

/// Outward steps applied to libm results (exp, log, sin, cos, tan, atan, atan2, and
/// asin, acos in the reverse operators). The glibc manual ("Known Maximum Errors in
/// Math Functions", x86_64, double, round-to-nearest) lists at most 1 ulp for each.
/// An error of k ulp is covered by 2k steps (a step is half an ulp just below a
/// power of two), so 4 steps cover 2 ulp: twice the documented maximum, because
/// that table records errors found by testing, not proven bounds. docs/intervals.md.
inline constexpr int kLibmSteps = 4;

// Directed basic operations. Each computes the round-to-nearest result r and the
// sign of the error of that rounding, and steps r outward only when the error
// points outward: the result is the correctly rounded-down (or up) value, never
// more than one ulp from r. Exact results such as 0 + 0 stay exact, which keeps
// sign information (y = x^2 >= 0).
//  - + and -: TwoSum gives the exact error.
//  - *, / and sqrt: an fma computes the error term (a*b - r, a - r*b, x - r*r)
//    exactly and rounds it once. Rounding keeps the sign: a negative error too
//    small to represent becomes -0, and an exactly zero one is +0 (IEEE 754
//    section 6.3). So std::signbit of the fma result says "the error is < 0"
//    exactly, also for subnormal results; each test below is phrased that way.

/// Exact error of r = RN(a + b): a + b = r + e (Knuth's TwoSum; needs no overflow).
inline double two_sum_error(double a, double b, double r) {
  const double bb = r - a;
  return (a - (r - bb)) + (b - bb);
}

// r moved one double up (direction +1) or down (-1) when `step`, else r itself; r is
// finite, and nonzero when `step` (a sum that rounds to zero is exact). Branch-free:
// whether the error points outward is data, and a mispredicted branch on it cost more
// than the sum (measured: the frame margins' loops, docs/performance.md).
inline double step_finite_if(double r, bool step, std::int64_t direction) {
  const auto bits = std::bit_cast<std::int64_t>(r);
  const std::int64_t up = (bits >> 63) | 1;  // the bits' move up: +1 for r >= 0, -1 below (as next_up)
  return std::bit_cast<double>(bits + (direction * up & -static_cast<std::int64_t>(step)));
}

inline double add_down(double a, double b) {
  const double r = a + b;
  if (!std::isfinite(r)) return r == kInf && std::isfinite(a) && std::isfinite(b) ? std::numeric_limits<double>::max() : r;
  return step_finite_if(r, !(two_sum_error(a, b, r) >= 0.0), -1);  // (next_down(r) when stepping)
}
inline double add_up(double a, double b) {
  const double r = a + b;
  if (!std::isfinite(r)) return r == -kInf && std::isfinite(a) && std::isfinite(b) ? -std::numeric_limits<double>::max() : r;
  return step_finite_if(r, !(two_sum_error(a, b, r) <= 0.0), 1);  // (next_up(r) when stepping)
}
inline double sub_down(double a, double b) { return add_down(a, -b); }
inline double sub_up(double a, double b) { return add_up(a, -b); }

/// Product with the interval convention 0 * inf = 0 (bounds are limits).
inline double mul_down(double a, double b) {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double r = a * b;
  if (!std::isfinite(r)) return r == kInf && std::isfinite(a) && std::isfinite(b) ? std::numeric_limits<double>::max() : r;
  if (r == 0.0) return std::signbit(r) ? -std::numeric_limits<double>::denorm_min() : 0.0;  // underflow
  return std::signbit(std::fma(a, b, -r)) ? next_down(r) : r;  // a*b < r
}
inline double mul_up(double a, double b) { return -mul_down(-a, b); }

/// Quotient with the limit convention x / inf = 0 (never called with b = 0).
inline double div_down(double a, double b) {
  if (a == 0.0) return 0.0;
  if (std::isinf(b)) return std::isinf(a) ? std::numeric_limits<double>::quiet_NaN() : 0.0;
  if (b < 0.0) {  // same quotient with b > 0, so that the test below reads one way
    a = -a;
    b = -b;
  }
  const double r = a / b;
  if (!std::isfinite(r)) return r == kInf && std::isfinite(a) ? std::numeric_limits<double>::max() : r;
  if (r == 0.0) return std::signbit(r) ? -std::numeric_limits<double>::denorm_min() : 0.0;  // underflow
  return std::signbit(std::fma(-r, b, a)) ? next_down(r) : r;  // a - r*b < 0, i.e. a/b < r
}
inline double div_up(double a, double b) { return -div_down(-a, b); }

/// Square roots of x >= 0.
inline double sqrt_down(double x) {
  const double r = std::sqrt(x);
  if (r == 0.0 || std::isinf(r)) return r;
  return std::signbit(std::fma(-r, r, x)) ? next_down(r) : r;  // x - r*r < 0
}
inline double sqrt_up(double x) {
  const double r = std::sqrt(x);
  if (r == 0.0 || std::isinf(r)) return r;
  return std::signbit(std::fma(r, r, -x)) ? next_up(r) : r;  // r*r - x < 0
}

/// x^n for x >= 0 and n >= 0, rounded down or up: binary powering where every
/// product is rounded the same way, which is sound because all factors are >= 0.
inline double pow_down(double x, int n) {
  double result = 1.0;
  for (double base = x; n > 0; n >>= 1) {
    if (n & 1) result = mul_down(result, base);
    if (n > 1) base = mul_down(base, base);
  }
  return result;
}
inline double pow_up(double x, int n) {
  double result = 1.0;
  for (double base = x; n > 0; n >>= 1) {
    if (n & 1) result = mul_up(result, base);
    if (n > 1) base = mul_up(base, base);
  }
  return result;
}

}  // namespace gesmi
