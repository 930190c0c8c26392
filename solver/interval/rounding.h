#pragma once
// Outward steps on doubles: the building block of gesmi's rounding.
//
// Every +, -, *, / and sqrt is computed at round-to-nearest (IEEE 754 rounds them
// correctly, so the error is at most half an ulp) and the bound is then moved one
// representable number outward. That encloses the real result without touching the
// global floating-point environment. See docs/intervals.md.

#include <bit>
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

// Directed basic operations. Exact zeros and infinities are kept exact so that
// sign information (a bound at 0) survives, e.g. [0,1]*[0,1] = [0, 1+ulp].
constexpr double add_down(double a, double b) { return next_down(a + b); }
constexpr double add_up(double a, double b) { return next_up(a + b); }
constexpr double sub_down(double a, double b) { return next_down(a - b); }
constexpr double sub_up(double a, double b) { return next_up(a - b); }

/// Product with the interval convention 0 * inf = 0 (bounds are limits).
constexpr double mul_down(double a, double b) {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double p = a * b;
  return (p == kInf || p == -kInf) && (a == kInf || a == -kInf || b == kInf || b == -kInf)
             ? p
             : next_down(p);
}
constexpr double mul_up(double a, double b) {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double p = a * b;
  return (p == kInf || p == -kInf) && (a == kInf || a == -kInf || b == kInf || b == -kInf)
             ? p
             : next_up(p);
}
constexpr double div_down(double a, double b) {
  if (a == 0.0 || b == kInf || b == -kInf) return a / b == 0.0 ? 0.0 : a / b;
  return next_down(a / b);
}
constexpr double div_up(double a, double b) {
  if (a == 0.0 || b == kInf || b == -kInf) return a / b == 0.0 ? 0.0 : a / b;
  return next_up(a / b);
}

}  // namespace gesmi
