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
  for (int i = 0; i < steps; ++i) x = next_up(x);
  return x;
}
constexpr double step_down(double x, int steps) {
  for (int i = 0; i < steps; ++i) x = next_down(x);
  return x;
}

/// Outward steps applied to libm results (exp, log, sin, cos, tan, atan, atan2).
/// glibc documents errors of at most 1-2 ulp for these on x86_64 (manual, "Known
/// Maximum Errors in Math Functions"); an error of k ulp is covered by 2k steps
/// (a step is half an ulp just below a power of two), so 4 steps cover 2 ulp.
inline constexpr int kLibmSteps = 4;

// Directed basic operations. Each computes the round-to-nearest result r and the
// exact error of that rounding (TwoSum for + and -, an fma for *, / and sqrt),
// and steps r outward only when the error points outward: the result is the
// correctly rounded-down (or up) value, never more than one ulp from r. Exact
// results such as 0 + 0 stay exact, which keeps sign information (y = x^2 >= 0).

/// Exact error of r = RN(a + b): a + b = r + e (Knuth's TwoSum; needs no overflow).
inline double two_sum_error(double a, double b, double r) {
  const double bb = r - a;
  return (a - (r - bb)) + (b - bb);
}

inline double add_down(double a, double b) {
  const double r = a + b;
  if (!std::isfinite(r)) return r == kInf && std::isfinite(a) && std::isfinite(b) ? std::numeric_limits<double>::max() : r;
  return two_sum_error(a, b, r) < 0.0 ? next_down(r) : r;
}
inline double add_up(double a, double b) {
  const double r = a + b;
  if (!std::isfinite(r)) return r == -kInf && std::isfinite(a) && std::isfinite(b) ? -std::numeric_limits<double>::max() : r;
  return two_sum_error(a, b, r) > 0.0 ? next_up(r) : r;
}
inline double sub_down(double a, double b) { return add_down(a, -b); }
inline double sub_up(double a, double b) { return add_up(a, -b); }

/// Product with the interval convention 0 * inf = 0 (bounds are limits).
inline double mul_down(double a, double b) {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double r = a * b;
  if (!std::isfinite(r)) return r == kInf && std::isfinite(a) && std::isfinite(b) ? std::numeric_limits<double>::max() : r;
  if (r == 0.0) return std::signbit(r) ? -std::numeric_limits<double>::denorm_min() : 0.0;  // underflow
  const double e = std::fma(a, b, -r);  // exact unless the product is subnormal
  if (std::fabs(r) < 0x1p-969) return next_down(r);  // fma error term may be inexact there
  return e < 0.0 ? next_down(r) : r;
}
inline double mul_up(double a, double b) { return -mul_down(-a, b); }

inline double div_down(double a, double b) {
  if (a == 0.0) return 0.0;
  if (std::isinf(b)) return std::isinf(a) ? std::numeric_limits<double>::quiet_NaN() : 0.0;  // limit x / inf = 0
  const double r = a / b;
  if (!std::isfinite(r)) return r == kInf && std::isfinite(a) ? std::numeric_limits<double>::max() : r;
  if (r == 0.0) return std::signbit(r) ? -std::numeric_limits<double>::denorm_min() : 0.0;  // underflow
  if (std::fabs(r) < 0x1p-969 || std::fabs(a) < 0x1p-969) return next_down(r);  // remainder may be inexact
  // a = r b + rem exactly; the true quotient is below r when rem / b < 0.
  const double rem = std::fma(-r, b, a);
  return (rem != 0.0 && (rem < 0.0) != (b < 0.0)) ? next_down(r) : r;
}
inline double div_up(double a, double b) { return -div_down(-a, b); }

inline double sqrt_down(double x) {
  const double r = std::sqrt(x);
  if (r == 0.0 || std::isinf(r) || x < 0x1p-969) return r == 0.0 || std::isinf(r) ? r : next_down(r);
  return std::fma(-r, r, x) < 0.0 ? next_down(r) : r;
}
inline double sqrt_up(double x) {
  const double r = std::sqrt(x);
  if (r == 0.0 || std::isinf(r) || x < 0x1p-969) return r == 0.0 || std::isinf(r) ? r : next_up(r);
  return std::fma(-r, r, x) > 0.0 ? next_up(r) : r;
}

}  // namespace gesmi
