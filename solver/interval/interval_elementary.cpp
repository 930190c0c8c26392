// Elementary functions of intervals: pow, exp, log, sin, cos, tan, atan, atan2.
//
// libm results are widened by kLibmSteps outward steps, except for the values that
// C's Annex F requires to be exact (exp(0) = 1, log(1) = 0, sin(0) = 0, ...), and
// clamped to the function's range. Branches of periodic functions are decided from
// the signs of derivatives computed by the same libm (see docs/intervals.md).

#include <cmath>

#include "solver/interval/interval.h"

namespace gesmi {
namespace {

double libm_down(double y) { return step_down(y, kLibmSteps); }
double libm_up(double y) { return step_up(y, kLibmSteps); }

// x^n for x >= 0 and n >= 1 by binary powering, every product rounded the same way.
double pow_positive(double x, int n, bool up) {
  double result = 1.0;
  double base = x;
  while (n > 0) {
    if (n & 1) result = up ? mul_up(result, base) : mul_down(result, base);
    n >>= 1;
    if (n > 0) base = up ? mul_up(base, base) : mul_down(base, base);
  }
  return result;
}

Interval pow_nonnegative_exponent(const Interval& x, int n) {
  if (n == 0) return Interval(1.0);
  if (n == 1) return x;
  if (n % 2 == 0) {
    const double m = x.mig(), M = x.mag();
    return Interval::from_bounds(pow_positive(m, n, false), pow_positive(M, n, true));
  }
  // Odd power: increasing, and odd in x.
  const auto odd_bound = [n](double v, bool up) {
    if (v >= 0.0) return pow_positive(v, n, up);
    return -pow_positive(-v, n, !up);
  };
  return Interval::from_bounds(odd_bound(x.lo(), false), odd_bound(x.hi(), true));
}

// Sign of a libm value used to decide monotonicity: +1, -1, or 0 when unsure.
int reliable_sign(double v) {
  if (v > 0.0) return 1;
  if (v < 0.0) return -1;
  return 0;
}

// Range of sin (or cos, with `cosine`) over [a, b], finite bounds, b - a < 2pi.
// f rises at an end point where its derivative is positive. Over a width below
// 2pi, rising at a and falling at b means exactly one maximum inside, and the
// converse a minimum; equal trends mean monotonic (width < pi) or both extrema.
Interval periodic_range(double a, double b, bool cosine) {
  const auto f = [cosine](double x) { return cosine ? std::cos(x) : std::sin(x); };
  const auto df = [cosine](double x) { return cosine ? -std::sin(x) : std::cos(x); };
  const int sa = reliable_sign(df(a));
  const int sb = reliable_sign(df(b));
  const double fa = f(a), fb = f(b);
  double lo = libm_down(std::min(fa, fb));
  double hi = libm_up(std::max(fa, fb));
  const double w_up = sub_up(b, a), w_down = sub_down(b, a);
  const bool surely_below_pi = w_up < Interval::pi().lo();
  const bool surely_above_pi = w_down > Interval::pi().hi();
  const bool maybe_max = (sa >= 0 && sb <= 0) || (sa == 0 || sb == 0);
  const bool maybe_min = (sa <= 0 && sb >= 0) || (sa == 0 || sb == 0);
  const bool same_trend_possible = (sa == sb) || sa == 0 || sb == 0;
  if (maybe_max) hi = 1.0;
  if (maybe_min) lo = -1.0;
  if (same_trend_possible && !surely_below_pi) {
    // Same trend at both ends with a width of pi or more: both extrema are inside.
    // With an unsure width the hull of both cases is taken.
    (void)surely_above_pi;
    lo = -1.0;
    hi = 1.0;
  }
  return Interval::from_bounds(std::max(lo, -1.0), std::min(hi, 1.0));
}

Interval sin_or_cos(const Interval& x, bool cosine) {
  if (x.is_empty()) return Interval::empty();
  if (!x.is_bounded() || sub_down(x.hi(), x.lo()) >= Interval::two_pi().hi()) return Interval(-1.0, 1.0);
  if (x.is_degenerate() && x.lo() == 0.0) return Interval(cosine ? 1.0 : 0.0);
  return periodic_range(x.lo(), x.hi(), cosine);
}

}  // namespace

Interval pow(const Interval& x, int n) {
  if (x.is_empty()) return Interval::empty();
  if (n >= 0) return pow_nonnegative_exponent(x, n);
  // x^-n = 1 / x^n; the division handles the zero cases as IEEE 1788 pown does.
  // n = INT_MIN has no positive counterpart: x^INT_MIN = (x^(INT_MIN/2))^2.
  if (n == std::numeric_limits<int>::min()) return sqr(pow(x, n / 2));
  const Interval xn = pow_nonnegative_exponent(x, -n);
  return Interval(1.0) / xn;
}

Interval exp(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const auto down = [](double v) {
    if (v == -kInf) return 0.0;
    if (v == 0.0) return 1.0;
    return std::max(0.0, libm_down(std::exp(v)));
  };
  const auto up = [](double v) {
    if (v == -kInf) return 0.0;
    if (v == 0.0) return 1.0;
    return libm_up(std::exp(v));
  };
  return Interval::from_bounds(down(x.lo()), up(x.hi()));
}

Interval log(const Interval& x) {
  if (x.is_empty() || x.hi() <= 0.0) return Interval::empty();
  const auto down = [](double v) {
    if (v <= 0.0) return -kInf;
    if (v == 1.0) return 0.0;
    return libm_down(std::log(v));
  };
  const auto up = [](double v) {
    if (v == kInf) return kInf;
    if (v == 1.0) return 0.0;
    return libm_up(std::log(v));
  };
  return Interval::from_bounds(down(x.lo()), up(x.hi()));
}

Interval sin(const Interval& x) { return sin_or_cos(x, false); }
Interval cos(const Interval& x) { return sin_or_cos(x, true); }

Interval tan(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  if (!x.is_bounded() || sub_up(x.hi(), x.lo()) >= Interval::pi().lo()) return Interval::entire();
  if (x.is_degenerate() && x.lo() == 0.0) return Interval(0.0);
  // Width below pi: at most one pole, and a pole lies inside exactly when cos
  // changes sign between the end points.
  const int ca = reliable_sign(std::cos(x.lo()));
  const int cb = reliable_sign(std::cos(x.hi()));
  if (ca == 0 || cb == 0 || ca != cb) return Interval::entire();
  const double lo = x.lo() == 0.0 ? 0.0 : libm_down(std::tan(x.lo()));
  const double hi = x.hi() == 0.0 ? 0.0 : libm_up(std::tan(x.hi()));
  return Interval::from_bounds(lo, hi);
}

Interval atan(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const Interval half_pi = Interval::half_pi();
  const auto down = [&](double v) {
    if (v == 0.0) return 0.0;
    if (v == -kInf) return -half_pi.hi();
    return std::max(-half_pi.hi(), libm_down(std::atan(v)));
  };
  const auto up = [&](double v) {
    if (v == 0.0) return 0.0;
    if (v == kInf) return half_pi.hi();
    return std::min(half_pi.hi(), libm_up(std::atan(v)));
  };
  return Interval::from_bounds(down(x.lo()), up(x.hi()));
}

namespace {

// atan2 over a box that does not meet the cut {y = 0, x <= 0} except from above
// (y >= +0 there): the angle is continuous, and the extreme angles of a box seen
// from outside it are reached at its corners.
Interval atan2_from_corners(double yl, double yh, double xl, double xh) {
  const double pi_hi = Interval::pi().hi();
  double lo = kInf, hi = -kInf;
  const auto add_corner = [&](double y, double x) {
    if (y == 0.0) y = 0.0;  // +0: the upper side of the cut
    const double v = std::atan2(y, x);
    const bool exact = (v == 0.0);  // atan2(+0, x > 0) and atan2(y, +inf) are exactly 0
    lo = std::min(lo, exact ? v : libm_down(v));
    hi = std::max(hi, exact ? v : libm_up(v));
  };
  add_corner(yl, xl);
  add_corner(yl, xh);
  add_corner(yh, xl);
  add_corner(yh, xh);
  return Interval::from_bounds(std::max(lo, -pi_hi), std::min(hi, pi_hi));
}

}  // namespace

Interval atan2(const Interval& y, const Interval& x) {
  if (y.is_empty() || x.is_empty()) return Interval::empty();
  const double yl = y.lo(), yh = y.hi(), xl = x.lo(), xh = x.hi();
  const Interval pi = Interval::pi(), half_pi = Interval::half_pi();
  const Interval full = Interval::from_bounds(-pi.hi(), pi.hi());
  if (yl > 0.0 || yh < 0.0 || xl > 0.0) return atan2_from_corners(yl, yh, xl, xh);
  // Here y contains 0 and x reaches 0 or below.
  if (xh < 0.0) {  // box on the left, across or touching the cut
    if (yl < 0.0) return full;
    return atan2_from_corners(0.0, yh, xl, xh);
  }
  // The box contains the origin, which is excluded from the domain.
  if (yl == 0.0 && yh == 0.0) {
    if (xl == 0.0 && xh == 0.0) return Interval::empty();
    if (xl < 0.0 && xh > 0.0) return Interval::from_bounds(0.0, pi.hi());
    if (xl < 0.0) return pi;
    return Interval(0.0);
  }
  if (yl == 0.0) {  // upper half plane, y > 0 part non-empty
    const double lo = xh > 0.0 ? 0.0 : half_pi.lo();
    const double hi = xl < 0.0 ? pi.hi() : half_pi.hi();
    return Interval::from_bounds(lo, hi);
  }
  if (yh == 0.0) {  // lower half plane
    if (xl < 0.0) return full;
    return Interval::from_bounds(-half_pi.hi(), xh > 0.0 ? 0.0 : -half_pi.lo());
  }
  // y strictly around 0.
  if (xl < 0.0) return full;
  return Interval::from_bounds(-half_pi.hi(), half_pi.hi());  // x = [0, xh]
}

}  // namespace gesmi
