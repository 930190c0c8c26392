#pragma once
// gesmi::Interval: a closed interval of reals with double bounds, rounded outward.
//
// Invariants (docs/concepts.md):
//  - non-empty: lo <= hi, lo < +inf, hi > -inf; the bounds may be infinite;
//  - empty: the single representation lo = +inf, hi = -inf, so that hull and
//    intersection are plain min/max;
//  - a default-constructed interval is the whole real line, as in IBEX and Codac.
// Every operation returns an interval that contains the exact real result.

#include <algorithm>
#include <cmath>

#include "solver/interval/rounding.h"

namespace gesmi {

class Interval {
 public:
  constexpr Interval() = default;
  constexpr Interval(double x) : lo_(x), hi_(x) {  // NOLINT: a double is a degenerate interval
    if (x != x || x == kInf || x == -kInf) *this = empty();
  }
  /// [lo, hi]; an interval with lo > hi or a NaN bound is empty.
  constexpr Interval(double lo, double hi) : lo_(lo), hi_(hi) {
    if (!(lo <= hi) || lo == kInf || hi == -kInf) *this = empty();
  }

  static constexpr Interval empty() { return from_bounds(kInf, -kInf); }
  static constexpr Interval entire() { return from_bounds(-kInf, kInf); }
  static constexpr Interval pos_reals() { return from_bounds(0.0, kInf); }
  static constexpr Interval neg_reals() { return from_bounds(-kInf, 0.0); }
  /// Enclosures of pi, 2pi and pi/2 (the doubles on each side of the real value).
  static constexpr Interval pi() { return from_bounds(0x1.921fb54442d18p+1, 0x1.921fb54442d19p+1); }
  static constexpr Interval two_pi() { return from_bounds(0x1.921fb54442d18p+2, 0x1.921fb54442d19p+2); }
  static constexpr Interval half_pi() { return from_bounds(0x1.921fb54442d18p+0, 0x1.921fb54442d19p+0); }
  /// The interval x +- r (r >= 0), rounded outward.
  static Interval around(double x, double r) { return Interval(sub_down(x, r), add_up(x, r)); }
  /// This interval widened by r >= 0 on each side, rounded outward.
  Interval inflated(double r) const { return Interval(sub_down(lo_, r), add_up(hi_, r)); }

  constexpr double lo() const { return lo_; }
  constexpr double hi() const { return hi_; }

  constexpr bool is_empty() const { return !(lo_ <= hi_); }
  constexpr bool is_entire() const { return lo_ == -kInf && hi_ == kInf; }
  constexpr bool is_bounded() const { return !is_empty() && lo_ > -kInf && hi_ < kInf; }
  constexpr bool is_degenerate() const { return lo_ == hi_; }
  constexpr bool contains(double x) const { return lo_ <= x && x <= hi_; }
  /// This interval contains every point of y (the empty set is a subset of all).
  constexpr bool is_superset(const Interval& y) const {
    return y.is_empty() || (lo_ <= y.lo_ && y.hi_ <= hi_);
  }
  constexpr bool is_subset(const Interval& y) const { return y.is_superset(*this); }
  constexpr bool is_interior_subset(const Interval& y) const {
    return is_empty() || ((y.lo_ < lo_ || y.lo_ == -kInf) && (hi_ < y.hi_ || y.hi_ == kInf));
  }
  constexpr bool intersects(const Interval& y) const {
    return !is_empty() && !y.is_empty() && lo_ <= y.hi_ && y.lo_ <= hi_;
  }

  /// Width hi - lo rounded up (NaN for the empty interval, as IEEE 1788 wid).
  inline double width() const {
    if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
    return lo_ == hi_ ? 0.0 : sub_up(hi_, lo_);
  }
  /// A point inside the interval, the rounded midpoint when bounded (IEEE 1788 mid).
  constexpr double mid() const {
    if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
    if (is_entire()) return 0.0;
    if (lo_ == -kInf) return -std::numeric_limits<double>::max();
    if (hi_ == kInf) return std::numeric_limits<double>::max();
    const double m = 0.5 * (lo_ + hi_);
    if (m == kInf || m == -kInf) return 0.5 * lo_ + 0.5 * hi_;  // overflow of lo + hi
    return std::clamp(m, lo_, hi_);
  }
  /// Half width rounded up, such that [mid - rad, mid + rad] contains the interval.
  inline double rad() const {
    if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
    if (lo_ == hi_) return 0.0;
    const double m = mid();
    return std::max(sub_up(m, lo_), sub_up(hi_, m));
  }
  /// Smallest and largest magnitude of its points.
  constexpr double mag() const { return is_empty() ? std::numeric_limits<double>::quiet_NaN() : std::max(-lo_, hi_); }
  constexpr double mig() const {
    if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
    if (lo_ >= 0.0) return lo_;
    if (hi_ <= 0.0) return -hi_;
    return 0.0;
  }

  /// Intersection in place; returns false when it became empty.
  constexpr bool intersect_with(const Interval& y) {
    *this = from_bounds(std::max(lo_, y.lo_), std::min(hi_, y.hi_));
    if (lo_ > hi_) *this = empty();
    return !is_empty();
  }

  constexpr Interval operator-() const { return is_empty() ? empty() : from_bounds(-hi_, -lo_); }
  inline Interval& operator+=(const Interval& y);
  inline Interval& operator-=(const Interval& y);
  inline Interval& operator*=(const Interval& y);
  inline Interval& operator/=(const Interval& y);

  /// Builds an interval from bounds already known to satisfy the invariants.
  static constexpr Interval from_bounds(double lo, double hi) {
    Interval r;
    r.lo_ = lo;
    r.hi_ = hi;
    return r;
  }

 private:
  double lo_ = -kInf;
  double hi_ = kInf;
};

/// Exact equality of the sets.
constexpr bool operator==(const Interval& x, const Interval& y) {
  return (x.is_empty() && y.is_empty()) || (x.lo() == y.lo() && x.hi() == y.hi());
}

// Order relations of IEEE 1788 (all true when both are empty, see each comment).
/// Every point of x is <= every point of y (true when either is empty).
constexpr bool precedes(const Interval& x, const Interval& y) {
  return x.is_empty() || y.is_empty() || x.hi() <= y.lo();
}
/// Every point of x is < every point of y (true when either is empty).
constexpr bool strictly_precedes(const Interval& x, const Interval& y) {
  return x.is_empty() || y.is_empty() || x.hi() < y.lo();
}
/// x.lo <= y.lo and x.hi <= y.hi (1788 "less"); an empty set is only related to itself.
constexpr bool weakly_less(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return x.is_empty() && y.is_empty();
  return x.lo() <= y.lo() && x.hi() <= y.hi();
}
/// As weakly_less with strict comparisons, where -inf < -inf and +inf < +inf count as true.
constexpr bool strictly_less(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return x.is_empty() && y.is_empty();
  return (x.lo() < y.lo() || (x.lo() == -kInf && y.lo() == -kInf)) && (x.hi() < y.hi() || (x.hi() == kInf && y.hi() == kInf));
}

constexpr Interval intersect(const Interval& x, const Interval& y) {
  Interval r = x;
  r.intersect_with(y);
  return r;
}
constexpr Interval hull(const Interval& x, const Interval& y) {
  return Interval::from_bounds(std::min(x.lo(), y.lo()), std::max(x.hi(), y.hi()));
}
constexpr Interval hull(const Interval& x, double y) { return hull(x, Interval(y)); }

// ---- arithmetic -------------------------------------------------------------

inline Interval operator+(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  return Interval::from_bounds(add_down(x.lo(), y.lo()), add_up(x.hi(), y.hi()));
}
inline Interval operator-(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  return Interval::from_bounds(sub_down(x.lo(), y.hi()), sub_up(x.hi(), y.lo()));
}

inline Interval operator*(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  const double a = x.lo(), b = x.hi(), c = y.lo(), d = y.hi();
  if (a >= 0.0) {
    if (c >= 0.0) return Interval::from_bounds(mul_down(a, c), mul_up(b, d));
    if (d <= 0.0) return Interval::from_bounds(mul_down(b, c), mul_up(a, d));
    return Interval::from_bounds(mul_down(b, c), mul_up(b, d));
  }
  if (b <= 0.0) {
    if (c >= 0.0) return Interval::from_bounds(mul_down(a, d), mul_up(b, c));
    if (d <= 0.0) return Interval::from_bounds(mul_down(b, d), mul_up(a, c));
    return Interval::from_bounds(mul_down(a, d), mul_up(a, c));
  }
  if (c >= 0.0) return Interval::from_bounds(mul_down(a, d), mul_up(b, d));
  if (d <= 0.0) return Interval::from_bounds(mul_down(b, c), mul_up(a, c));
  return Interval::from_bounds(std::min(mul_down(a, d), mul_down(b, c)), std::max(mul_up(a, c), mul_up(b, d)));
}

/// Division, IEEE 1788 semantics: the hull of {x/y : y != 0}; empty when y = [0,0].
inline Interval operator/(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty() || (y.lo() == 0.0 && y.hi() == 0.0)) return Interval::empty();
  const double a = x.lo(), b = x.hi(), c = y.lo(), d = y.hi();
  const bool x_zero = (a == 0.0 && b == 0.0);
  if (c > 0.0) {
    if (a >= 0.0) return Interval::from_bounds(div_down(a, d), div_up(b, c));
    if (b <= 0.0) return Interval::from_bounds(div_down(a, c), div_up(b, d));
    return Interval::from_bounds(div_down(a, c), div_up(b, c));
  }
  if (d < 0.0) {
    if (a >= 0.0) return Interval::from_bounds(div_down(b, d), div_up(a, c));
    if (b <= 0.0) return Interval::from_bounds(div_down(b, c), div_up(a, d));
    return Interval::from_bounds(div_down(b, d), div_up(a, d));
  }
  if (x_zero) return Interval(0.0);
  if (c == 0.0) {  // y = [0, d], d > 0
    if (a >= 0.0) return Interval::from_bounds(div_down(a, d), kInf);
    if (b <= 0.0) return Interval::from_bounds(-kInf, div_up(b, d));
    return Interval::entire();
  }
  if (d == 0.0) {  // y = [c, 0], c < 0
    if (a >= 0.0) return Interval::from_bounds(-kInf, div_up(a, c));
    if (b <= 0.0) return Interval::from_bounds(div_down(b, c), kInf);
    return Interval::entire();
  }
  return Interval::entire();  // 0 strictly inside y
}

/// 1 / x with the conventions of division.
inline Interval recip(const Interval& x) { return Interval(1.0) / x; }

inline Interval& Interval::operator+=(const Interval& y) { return *this = *this + y; }
inline Interval& Interval::operator-=(const Interval& y) { return *this = *this - y; }
inline Interval& Interval::operator*=(const Interval& y) { return *this = *this * y; }
inline Interval& Interval::operator/=(const Interval& y) { return *this = *this / y; }

// Mixed forms with a double are written out so that `2.0 * x` needs no conversion.
inline Interval operator+(const Interval& x, double y) { return x + Interval(y); }
inline Interval operator+(double x, const Interval& y) { return Interval(x) + y; }
inline Interval operator-(const Interval& x, double y) { return x - Interval(y); }
inline Interval operator-(double x, const Interval& y) { return Interval(x) - y; }
inline Interval operator*(const Interval& x, double y) { return x * Interval(y); }
inline Interval operator*(double x, const Interval& y) { return Interval(x) * y; }
inline Interval operator/(const Interval& x, double y) { return x / Interval(y); }
inline Interval operator/(double x, const Interval& y) { return Interval(x) / y; }

inline Interval sqr(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double m = x.mig(), M = x.mag();
  return Interval::from_bounds(std::max(0.0, mul_down(m, m)), mul_up(M, M));
}

inline Interval sqrt(const Interval& x) {
  if (x.is_empty() || x.hi() < 0.0) return Interval::empty();
  const double lo = x.lo() <= 0.0 ? 0.0 : sqrt_down(x.lo());
  return Interval::from_bounds(lo, sqrt_up(x.hi()));
}

constexpr Interval abs(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  return Interval::from_bounds(x.mig(), x.mag());
}
constexpr Interval min(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  return Interval::from_bounds(std::min(x.lo(), y.lo()), std::min(x.hi(), y.hi()));
}
constexpr Interval max(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  return Interval::from_bounds(std::max(x.lo(), y.lo()), std::max(x.hi(), y.hi()));
}

/// Integer power x^n (IEEE 1788 pown): x^0 = [1,1], negative n through 1/x^|n|.
Interval pow(const Interval& x, int n);
Interval exp(const Interval& x);
Interval log(const Interval& x);
Interval sin(const Interval& x);
Interval cos(const Interval& x);
Interval tan(const Interval& x);
Interval atan(const Interval& x);
/// Range of the angle atan2(y, x) over the box y x x minus the origin, in [-pi, pi].
Interval atan2(const Interval& y, const Interval& x);

}  // namespace gesmi
