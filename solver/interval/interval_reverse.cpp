// Reverse operators. Each one states the relation it inverts; soundness comes from
// computing every candidate set with the outward-rounded forward operations.

#include "solver/interval/interval_reverse.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace gesmi {
namespace {

// Sets every argument empty and reports it, so a failed contraction is never partial.
bool fail(Interval& a) {
  a = Interval::empty();
  return false;
}
bool fail(Interval& a, Interval& b) {
  a = b = Interval::empty();
  return false;
}

bool narrow(Interval& x, const Interval& by) { return x.intersect_with(by); }

// Ordinals of non-negative doubles: consecutive doubles have consecutive ordinals.
std::int64_t ordinal(double x) { return std::bit_cast<std::int64_t>(x); }
double from_ordinal(std::int64_t i) { return std::bit_cast<double>(i); }

// The smallest double r >= 0 with pred(r), for pred monotone (false, then true)
// and true at +inf. Gallops away from the guess, then bisects the ordinals.
template <class Pred>
double smallest_with(double guess, Pred pred) {
  std::int64_t lo = 0, hi = ordinal(kInf);  // pred(hi) holds; every r below lo fails
  const std::int64_t g = ordinal(std::clamp(guess, 0.0, kInf));
  std::int64_t step = 1;
  if (pred(from_ordinal(g))) {
    hi = g;
    while (hi > 0) {
      const std::int64_t probe = std::max<std::int64_t>(0, hi - step);
      if (!pred(from_ordinal(probe))) {
        lo = probe + 1;
        break;
      }
      hi = probe;
      step *= 2;
    }
  } else {
    lo = g + 1;
    while (lo < hi) {
      const std::int64_t probe = std::min(hi, lo + step);
      if (pred(from_ordinal(probe))) {
        hi = probe;
        break;
      }
      lo = probe + 1;
      step *= 2;
    }
  }
  while (lo < hi) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    if (pred(from_ordinal(mid))) hi = mid;
    else lo = mid + 1;
  }
  return from_ordinal(hi);
}

// Lower and upper n-th roots of v >= 0: the largest r with r^n <= v and the
// smallest with r^n >= v, where r^n is bounded by directed powers, so that
// root_down(v)^n <= v <= root_up(v)^n holds for the exact powers.
double root_down(double v, int n) {
  if (v == 0.0 || v == kInf || n == 1) return v;
  if (n == 2) return sqrt_down(v);
  const double first_above = smallest_with(std::pow(v, 1.0 / n), [&](double r) { return pow_up(r, n) > v; });
  return next_down(first_above);
}
double root_up(double v, int n) {
  if (v == 0.0 || v == kInf || n == 1) return v;
  if (n == 2) return sqrt_up(v);
  return smallest_with(std::pow(v, 1.0 / n), [&](double r) { return pow_down(r, n) >= v; });
}
// {x >= 0 : x^n in c}, for c with c >= 0 (n >= 1).
Interval positive_root(const Interval& c, int n) {
  if (c.is_empty()) return c;
  return Interval::from_bounds(root_down(c.lo(), n), root_up(c.hi(), n));
}
// {x > 0 : x^-n in c}, for c >= 0 (n >= 1): x = 1 / root(c), computed through the
// root first so that tiny c (whose reciprocal overflows) keeps a tight bound.
Interval positive_inverse_root(const Interval& c, int n) {
  if (c.is_empty() || c.hi() == 0.0) return Interval::empty();  // x^-n is never 0
  const double r_lo = root_down(c.lo(), n), r_hi = root_up(c.hi(), n);
  const double lo = r_hi == kInf ? 0.0 : div_down(1.0, r_hi);
  const double hi = r_lo == 0.0 ? kInf : div_up(1.0, r_lo);
  return Interval::from_bounds(lo, hi);
}

// Hull of the points of x inside the union of the periodic pieces
// [alpha_j + k period, beta_j + k period], k integer. The pieces are given as
// enclosures of their end points, so the union of the computed pieces contains
// the true solution set and the result is a sound contraction of x.
struct PeriodicPiece {
  Interval alpha, beta;
};

template <std::size_t N>
Interval periodic_hull(const Interval& x, const PeriodicPiece (&pieces)[N], const Interval& period) {
  if (x.is_empty()) return x;
  // Far from 0 the multiples of the period are too coarse to contract anything.
  constexpr double kFar = 0x1p40;
  if (x.lo() < -kFar || x.hi() > kFar) return x;
  double lo = kInf, hi = -kInf;
  const auto visit = [&](double k) {  // the pieces of index k that meet x
    const Interval shift = Interval(k) * period;
    for (const PeriodicPiece& p : pieces) {
      const Interval piece = intersect(Interval((p.alpha + shift).lo(), (p.beta + shift).hi()), x);
      if (piece.is_empty()) continue;
      lo = std::min(lo, piece.lo());
      hi = std::max(hi, piece.hi());
    }
  };
  // Every piece of index k lies in [(k - 1/2) period, (k + 3/4) period] (asin is
  // in [-pi/2, pi/2], acos in [0, pi], atan in [-pi/2, pi/2]), so the indices from
  // floor(lo / period) - 1 to floor(hi / period) + 1 cover x; the quotients are
  // bounded outward, so a floor is at most one off, towards the outside. A wide x
  // is scanned near its two ends only: there are solutions in every period, so
  // its extreme solutions lie within a period of its ends.
  const double k_lo = std::floor((Interval(x.lo()) / period).lo());
  const double k_hi = std::floor((Interval(x.hi()) / period).hi());
  if (k_hi - k_lo <= 4) {
    for (double k = k_lo - 1; k <= k_hi + 1; ++k) visit(k);
  } else {
    for (double k = k_lo - 1; k <= k_lo + 2; ++k) visit(k);
    for (double k = k_hi - 2; k <= k_hi + 1; ++k) visit(k);
  }
  if (lo == kInf) return Interval::empty();  // a wide x always meets the solutions
  return Interval(lo, hi);
}

Interval libm_enclosure(double v) {
  if (v == 0.0) return Interval(0.0);
  return Interval(step_down(v, kLibmSteps), step_up(v, kLibmSteps));
}
Interval asin_enclosure(double c) {
  if (c == 0.0) return Interval(0.0);
  return intersect(libm_enclosure(std::asin(c)), Interval(-Interval::half_pi().hi(), Interval::half_pi().hi()));
}
Interval acos_enclosure(double c) {
  if (c == 1.0) return Interval(0.0);
  return intersect(libm_enclosure(std::acos(c)), Interval(0.0, Interval::pi().hi()));
}
Interval atan_enclosure(double c) {
  if (c == kInf) return Interval::half_pi();
  if (c == -kInf) return -Interval::half_pi();
  return libm_enclosure(std::atan(c));
}

}  // namespace

// ---- arithmetic -------------------------------------------------------------

bool bwd_add(const Interval& y, Interval& x1, Interval& x2) {
  if (!narrow(x1, y - x2) || !narrow(x2, y - x1)) return fail(x1, x2);
  return true;
}

bool bwd_sub(const Interval& y, Interval& x1, Interval& x2) {
  if (!narrow(x1, y + x2) || !narrow(x2, x1 - y)) return fail(x1, x2);
  return true;
}

std::pair<Interval, Interval> mul_rev_to_pair(const Interval& b, const Interval& c) {
  const Interval none = Interval::empty();
  if (b.is_empty() || c.is_empty()) return {none, none};
  if (!b.contains(0.0)) return {c / b, none};
  if (c.contains(0.0)) return {Interval::entire(), none};
  if (b.lo() == 0.0 && b.hi() == 0.0) return {none, none};
  const double bl = b.lo(), bh = b.hi();
  if (c.lo() > 0.0) {
    const double cl = c.lo();
    if (bl < 0.0 && bh > 0.0) return {Interval::from_bounds(-kInf, div_up(cl, bl)), Interval::from_bounds(div_down(cl, bh), kInf)};
    if (bl == 0.0) return {Interval::from_bounds(div_down(cl, bh), kInf), none};
    return {Interval::from_bounds(-kInf, div_up(cl, bl)), none};
  }
  const double ch = c.hi();  // c < 0
  if (bl < 0.0 && bh > 0.0) return {Interval::from_bounds(-kInf, div_up(ch, bh)), Interval::from_bounds(div_down(ch, bl), kInf)};
  if (bl == 0.0) return {Interval::from_bounds(-kInf, div_up(ch, bh)), none};
  return {Interval::from_bounds(div_down(ch, bl), kInf), none};
}

Interval mul_rev(const Interval& b, const Interval& c, const Interval& x) {
  const auto [first, second] = mul_rev_to_pair(b, c);
  return hull(intersect(first, x), intersect(second, x));
}

bool bwd_mul(const Interval& y, Interval& x1, Interval& x2) {
  if (!narrow(x1, mul_rev(x2, y, x1)) || !narrow(x2, mul_rev(x1, y, x2))) return fail(x1, x2);
  return true;
}

bool bwd_div(const Interval& y, Interval& x1, Interval& x2) {
  // y = x1 / x2 with x2 != 0, hence x1 = y * x2.
  if (!narrow(x1, y * x2) || !narrow(x2, mul_rev(y, x1, x2))) return fail(x1, x2);
  if (x2.lo() == 0.0 && x2.hi() == 0.0) return fail(x1, x2);
  return true;
}

bool bwd_neg(const Interval& y, Interval& x) {
  if (!narrow(x, -y)) return fail(x);
  return true;
}

// ---- powers and roots ---------------------------------------------------------

Interval sqr_rev(const Interval& c, const Interval& x) { return pow_rev(c, x, 2); }

Interval pow_rev(const Interval& c, const Interval& x, int n) {
  if (c.is_empty() || x.is_empty()) return Interval::empty();
  if (n == 0) return c.contains(1.0) ? x : Interval::empty();
  if (n > 0) {
    if (n % 2 == 0) {
      const Interval root = positive_root(intersect(c, Interval::pos_reals()), n);
      return hull(intersect(root, x), intersect(-root, x));
    }
    const Interval pos = positive_root(intersect(c, Interval::pos_reals()), n);
    const Interval neg = -positive_root(intersect(-c, Interval::pos_reals()), n);
    return hull(intersect(pos, x), intersect(neg, x));
  }
  // x^n = 1 / x^|n| with x != 0. n = INT_MIN: x^n = (x^(n/2))^2.
  if (n == std::numeric_limits<int>::min()) {
    const Interval inner = pow_rev(sqr_rev(c), Interval::entire(), n / 2);
    return intersect(inner, x);
  }
  const int m = -n;
  const Interval pos = positive_inverse_root(intersect(c, Interval::pos_reals()), m);
  if (m % 2 == 0) return hull(intersect(pos, x), intersect(-pos, x));
  const Interval neg = -positive_inverse_root(intersect(-c, Interval::pos_reals()), m);
  return hull(intersect(pos, x), intersect(neg, x));
}

bool bwd_pow(const Interval& y, Interval& x, int n) {
  if (!narrow(x, pow_rev(y, x, n))) return fail(x);
  return true;
}

bool bwd_sqr(const Interval& y, Interval& x) { return bwd_pow(y, x, 2); }

bool bwd_sqrt(const Interval& y, Interval& x) {
  const Interval root = intersect(y, Interval::pos_reals());
  if (!narrow(x, sqr(root)) || !narrow(x, Interval::pos_reals())) return fail(x);
  return true;
}

Interval abs_rev(const Interval& c, const Interval& x) {
  const Interval pos = intersect(c, Interval::pos_reals());
  return hull(intersect(pos, x), intersect(-pos, x));
}

bool bwd_abs(const Interval& y, Interval& x) {
  if (!narrow(x, abs_rev(y, x))) return fail(x);
  return true;
}

bool bwd_exp(const Interval& y, Interval& x) {
  if (!narrow(x, log(y))) return fail(x);
  return true;
}

bool bwd_log(const Interval& y, Interval& x) {
  if (!narrow(x, exp(y)) || x.hi() <= 0.0) return fail(x);
  return true;
}

bool bwd_min(const Interval& y, Interval& x1, Interval& x2) {
  // Both arguments are >= y.lo; one of them equals the minimum.
  if (!narrow(x1, Interval(y.lo(), kInf)) || !narrow(x2, Interval(y.lo(), kInf))) return fail(x1, x2);
  if (x2.lo() > y.hi() && !narrow(x1, y)) return fail(x1, x2);
  if (x1.lo() > y.hi() && !narrow(x2, y)) return fail(x1, x2);
  return true;
}

bool bwd_max(const Interval& y, Interval& x1, Interval& x2) {
  Interval n1 = -x1, n2 = -x2;
  if (!bwd_min(-y, n1, n2)) return fail(x1, x2);
  x1 = -n1;
  x2 = -n2;
  return true;
}

// ---- periodic functions -------------------------------------------------------

Interval sin_rev(const Interval& c, const Interval& x) {
  const Interval cc = intersect(c, Interval(-1.0, 1.0));
  if (cc.is_empty() || x.is_empty()) return Interval::empty();
  if (cc.lo() == -1.0 && cc.hi() == 1.0) return x;
  if (x.is_entire()) return x;
  const Interval a1 = asin_enclosure(cc.lo()), a2 = asin_enclosure(cc.hi());
  const Interval pi = Interval::pi();
  const PeriodicPiece pieces[] = {{a1, a2}, {pi - a2, pi - a1}};
  if (x.lo() == -kInf || x.hi() == kInf) {
    // Unbounded on one side: solutions reach that side; contract the finite end.
    const Interval finite_end = x.lo() == -kInf ? Interval(x.hi() - 8.0, x.hi()) : Interval(x.lo(), x.lo() + 8.0);
    const Interval near_end = periodic_hull(intersect(finite_end, x), pieces, Interval::two_pi());
    return x.lo() == -kInf ? Interval(-kInf, near_end.hi()) : Interval(near_end.lo(), kInf);
  }
  return periodic_hull(x, pieces, Interval::two_pi());
}

Interval cos_rev(const Interval& c, const Interval& x) {
  const Interval cc = intersect(c, Interval(-1.0, 1.0));
  if (cc.is_empty() || x.is_empty()) return Interval::empty();
  if (cc.lo() == -1.0 && cc.hi() == 1.0) return x;
  if (x.is_entire()) return x;
  const Interval a1 = acos_enclosure(cc.hi()), a2 = acos_enclosure(cc.lo());  // a1 <= a2
  const PeriodicPiece pieces[] = {{a1, a2}, {-a2, -a1}};
  if (x.lo() == -kInf || x.hi() == kInf) {
    const Interval finite_end = x.lo() == -kInf ? Interval(x.hi() - 8.0, x.hi()) : Interval(x.lo(), x.lo() + 8.0);
    const Interval near_end = periodic_hull(intersect(finite_end, x), pieces, Interval::two_pi());
    return x.lo() == -kInf ? Interval(-kInf, near_end.hi()) : Interval(near_end.lo(), kInf);
  }
  return periodic_hull(x, pieces, Interval::two_pi());
}

Interval tan_rev(const Interval& c, const Interval& x) {
  if (c.is_empty() || x.is_empty()) return Interval::empty();
  if (c.is_entire() || x.is_entire()) return x;
  const PeriodicPiece pieces[] = {{atan_enclosure(c.lo()), atan_enclosure(c.hi())}};
  if (x.lo() == -kInf || x.hi() == kInf) {
    const Interval finite_end = x.lo() == -kInf ? Interval(x.hi() - 4.0, x.hi()) : Interval(x.lo(), x.lo() + 4.0);
    const Interval near_end = periodic_hull(intersect(finite_end, x), pieces, Interval::pi());
    return x.lo() == -kInf ? Interval(-kInf, near_end.hi()) : Interval(near_end.lo(), kInf);
  }
  return periodic_hull(x, pieces, Interval::pi());
}

bool bwd_sin(const Interval& y, Interval& x) {
  if (!narrow(x, sin_rev(y, x))) return fail(x);
  return true;
}
bool bwd_cos(const Interval& y, Interval& x) {
  if (!narrow(x, cos_rev(y, x))) return fail(x);
  return true;
}
bool bwd_tan(const Interval& y, Interval& x) {
  if (!narrow(x, tan_rev(y, x))) return fail(x);
  return true;
}

bool bwd_atan(const Interval& y, Interval& x) {
  const Interval half_pi = Interval::half_pi();
  const Interval range = intersect(y, Interval(-half_pi.hi(), half_pi.hi()));
  if (range.is_empty()) return fail(x);
  // atan is increasing: x lies between the tangents of the end points of y,
  // unbounded where y reaches +-pi/2.
  const double lo = range.lo() <= -half_pi.lo() ? -kInf : tan(Interval(range.lo())).lo();
  const double hi = range.hi() >= half_pi.lo() ? kInf : tan(Interval(range.hi())).hi();
  if (!narrow(x, Interval(lo, hi))) return fail(x);
  return true;
}

bool bwd_atan2(const Interval& theta, Interval& y, Interval& x) {
  // Split theta by quadrant. In each quadrant the signs of x and y are known and
  // y = x tan(theta) (away from theta = +-pi/2), x = y cot(theta) (away from 0, +-pi).
  const Interval pi = Interval::pi(), half_pi = Interval::half_pi();
  const Interval th = intersect(theta, Interval(-pi.hi(), pi.hi()));
  if (th.is_empty()) return fail(y, x);
  struct Quadrant {
    Interval angles, x_sign, y_sign;
  };
  const Quadrant quadrants[] = {
      {Interval(-pi.hi(), -half_pi.lo()), Interval::neg_reals(), Interval::neg_reals()},
      {Interval(-half_pi.hi(), 0.0), Interval::pos_reals(), Interval::neg_reals()},
      {Interval(0.0, half_pi.hi()), Interval::pos_reals(), Interval::pos_reals()},
      {Interval(half_pi.lo(), pi.hi()), Interval::neg_reals(), Interval::pos_reals()},
  };
  Interval new_y = Interval::empty(), new_x = Interval::empty();
  for (const Quadrant& q : quadrants) {
    const Interval angles = intersect(th, q.angles);
    if (angles.is_empty()) continue;
    Interval qx = intersect(x, q.x_sign), qy = intersect(y, q.y_sign);
    if (qx.is_empty() || qy.is_empty()) continue;
    const bool avoids_vertical = !angles.intersects(half_pi) && !angles.intersects(-half_pi);
    const bool avoids_horizontal = !angles.contains(0.0) && !angles.intersects(pi) && !angles.intersects(-pi);
    if (avoids_vertical) {
      const Interval t = tan(angles);
      if (t.is_bounded()) {
        if (!qy.intersect_with(qx * t)) continue;
        if (!qx.intersect_with(mul_rev(t, qy, qx))) continue;
      }
    }
    if (avoids_horizontal) {
      const Interval cot = cos(angles) / sin(angles);
      if (cot.is_bounded()) {
        if (!qx.intersect_with(qy * cot)) continue;
        if (!qy.intersect_with(mul_rev(cot, qx, qy))) continue;
      }
    }
    if (qx.is_empty() || qy.is_empty()) continue;
    new_x = hull(new_x, qx);
    new_y = hull(new_y, qy);
  }
  if (new_x.is_empty() || new_y.is_empty()) return fail(y, x);
  x = new_x;
  y = new_y;
  return true;
}

}  // namespace gesmi
