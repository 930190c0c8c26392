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

Interval pow_nonnegative_exponent(const Interval& x, int n) {
  if (n == 0) return Interval(1.0);
  if (n == 1) return x;
  if (n % 2 == 0) {
    const double m = x.mig(), M = x.mag();
    return Interval::from_bounds(pow_down(m, n), pow_up(M, n));
  }
  // Odd power: increasing, and odd in x.
  const double lo = x.lo() >= 0.0 ? pow_down(x.lo(), n) : -pow_up(-x.lo(), n);
  const double hi = x.hi() >= 0.0 ? pow_up(x.hi(), n) : -pow_down(-x.hi(), n);
  return Interval::from_bounds(lo, hi);
}

// Sign of the derivative of sin (or cos) just inside [a, b] at the end point x:
// +1 rising, -1 falling. The derivative (cos, or -sin) of a double is never 0,
// except -sin(0) for cos, where the side decides: cos falls right of 0.
// libm's sign is right because its error is below one ulp of a non-zero value.
int slope_sign(double x, bool cosine, bool left_end) {
  if (cosine && x == 0.0) return left_end ? -1 : 1;
  const double d = cosine ? -std::sin(x) : std::cos(x);
  return d > 0.0 ? 1 : -1;
}

// Range of sin (or cos, with `cosine`) over [a, b], finite bounds, b - a < 2pi.
// Rising at a and falling at b means exactly one maximum inside, and the converse
// a minimum (the derivative's zeros are pi apart, so a width below 2pi holds at
// most two of them and a sign change means exactly one); equal trends mean
// monotonic when b - a < pi, and both extrema inside otherwise.
Interval periodic_range(double a, double b, bool cosine) {
  const auto f = [cosine](double x) { return cosine ? std::cos(x) : std::sin(x); };
  const double fa = f(a), fb = f(b);
  // sin(0) = 0 and cos(0) = 1 are exact (C Annex F); other values are widened.
  const auto down = [](double x, double fx) { return x == 0.0 ? fx : libm_down(fx); };
  const auto up = [](double x, double fx) { return x == 0.0 ? fx : libm_up(fx); };
  double lo = std::min(down(a, fa), down(b, fb));
  double hi = std::max(up(a, fa), up(b, fb));
  const int sa = slope_sign(a, cosine, true), sb = slope_sign(b, cosine, false);
  const bool surely_below_pi = sub_up(b, a) <= Interval::pi().lo();
  if (sa > 0 && sb < 0) hi = 1.0;
  if (sa < 0 && sb > 0) lo = -1.0;
  if (sa == sb && !surely_below_pi) {
    lo = -1.0;  // same trend over pi or more: both extrema are inside
    hi = 1.0;
  }
  return Interval::from_bounds(std::max(lo, -1.0), std::min(hi, 1.0));
}

Interval sin_or_cos(const Interval& x, bool cosine) {
  if (x.is_empty()) return Interval::empty();
  // periodic_range needs a width surely below 2pi: sub_up bounds the exact width.
  if (!x.is_bounded() || sub_up(x.hi(), x.lo()) > Interval::two_pi().lo()) return Interval(-1.0, 1.0);
  if (x.is_degenerate() && x.lo() == 0.0) return Interval(cosine ? 1.0 : 0.0);
  return periodic_range(x.lo(), x.hi(), cosine);
}

// 1 / v^m for v >= 0, rounded down or up. Two enclosures, 1 / v^m and (1/v)^m,
// each stay tight where the other over- or underflows (v = 1e300, m = 2 gives
// about 1e-600, not 1/DBL_MAX); the tighter bound is kept.
double recip_pow_down(double v, int m) {
  if (v == kInf) return 0.0;
  if (v == 0.0) return kInf;
  const double p = pow_up(v, m);
  return std::max(p == kInf ? 0.0 : div_down(1.0, p), pow_down(div_down(1.0, v), m));
}
double recip_pow_up(double v, int m) {
  if (v == 0.0) return kInf;
  const double p = pow_down(v, m);
  return std::min(p == 0.0 ? kInf : div_up(1.0, p), pow_up(div_up(1.0, v), m));
}

// x^-m for m >= 1 (IEEE 1788 pown): decreasing in |x| on each side of 0.
Interval pow_negative_exponent(const Interval& x, int m) {
  if (x.lo() == 0.0 && x.hi() == 0.0) return Interval::empty();
  if (m % 2 == 0) return Interval::from_bounds(recip_pow_down(x.mag(), m), recip_pow_up(x.mig(), m));
  if (x.lo() < 0.0 && x.hi() > 0.0) return Interval::entire();
  if (x.lo() >= 0.0) return Interval::from_bounds(recip_pow_down(x.hi(), m), recip_pow_up(x.lo(), m));
  return Interval::from_bounds(-recip_pow_up(-x.hi(), m), -recip_pow_down(-x.lo(), m));  // x <= 0
}

}  // namespace

Interval pow(const Interval& x, int n) {
  if (x.is_empty()) return Interval::empty();
  if (n >= 0) return pow_nonnegative_exponent(x, n);
  // n = INT_MIN has no positive counterpart: x^INT_MIN = (x^(INT_MIN/2))^2.
  if (n == std::numeric_limits<int>::min()) return sqr(pow(x, n / 2));
  return pow_negative_exponent(x, -n);
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
  if (!x.is_bounded() || sub_up(x.hi(), x.lo()) > Interval::pi().lo()) return Interval::entire();
  if (x.is_degenerate() && x.lo() == 0.0) return Interval(0.0);
  // Width below pi: at most one pole, and a pole lies inside exactly when cos
  // changes sign between the end points (cos of a double is never 0, and libm
  // gets its sign right).
  if ((std::cos(x.lo()) > 0.0) != (std::cos(x.hi()) > 0.0)) return Interval::entire();
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

// Enclosure of the angle of the corner (y, x) of a box, y = 0 meaning +0 (the
// upper side of the cut). Angles on the axes are exact multiples of pi/2, also as
// limits at infinity (atan2(1, +inf) -> 0, atan2(1, -inf) -> pi); the others come
// from libm, widened. An underflowed 0 (atan2(1e-300, 1e300) is 1e-600) is widened.
Interval corner_angle(double y, double x) {
  const Interval pi = Interval::pi(), half_pi = Interval::half_pi();
  const bool finite_y = std::isfinite(y), finite_x = std::isfinite(x);
  if ((y == 0.0 && x > 0.0) || (x == kInf && finite_y)) return Interval(0.0);
  if ((y == 0.0 && x < 0.0) || (x == -kInf && finite_y && y >= 0.0)) return pi;
  if (x == -kInf && finite_y) return -pi;  // y < 0: the limit from below the cut
  if ((x == 0.0 || finite_x) && (x == 0.0 || !finite_y)) return y > 0.0 ? half_pi : -half_pi;
  const double v = std::atan2(y, x);
  return Interval::from_bounds(libm_down(v), libm_up(v));
}

// atan2 over a box that does not meet the cut {y = 0, x <= 0} except from above
// (y >= +0 there): the angle is continuous, and the extreme angles of a box seen
// from outside it are reached at its corners.
Interval atan2_from_corners(double yl, double yh, double xl, double xh) {
  const double pi_hi = Interval::pi().hi();
  double lo = kInf, hi = -kInf;
  const auto add_corner = [&](double y, double x) {
    const Interval a = corner_angle(y == 0.0 ? 0.0 : y, x);
    lo = std::min(lo, a.lo());
    hi = std::max(hi, a.hi());
  };
  add_corner(yl, xl);
  add_corner(yl, xh);
  add_corner(yh, xl);
  add_corner(yh, xh);
  // Clamp to the range the signs allow: y >= 0 gives [0, pi], y < 0 (or y <= 0
  // with x > 0) gives [-pi, 0], x >= 0 gives [-pi/2, pi/2].
  const double half_pi_hi = Interval::half_pi().hi();
  if (yl >= 0.0) lo = std::max(lo, 0.0);
  if (yh < 0.0 || (yh == 0.0 && xl > 0.0)) hi = std::min(hi, 0.0);
  if (xl >= 0.0) {
    lo = std::max(lo, -half_pi_hi);
    hi = std::min(hi, half_pi_hi);
  }
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
