#include "solver/model/euler.h"

namespace gesmi {
namespace {

// libm's sin and cos are within a few ulps (docs/intervals.md): an enclosure of
// the value at a point.
Interval libm_point(double y) { return Interval(step_down(y, kLibmSteps), step_up(y, kLibmSteps)); }

}  // namespace

std::optional<NarrowAngle> narrow_angle(const Interval& angle) {
  if (angle.is_empty()) return std::nullopt;
  const double r = angle.rad();
  if (!(r <= 0.05)) return std::nullopt;
  const double m = angle.mid();
  return NarrowAngle{r, libm_point(std::sin(m)), libm_point(std::cos(m))};
}

SinCos<Interval> sin_cos(const Interval& angle) {
  if (angle.is_empty()) return {Interval::empty(), Interval::empty()};
  const std::optional<NarrowAngle> narrow = narrow_angle(angle);
  if (!narrow) return {sin(angle), cos(angle)};
  // For x = m + h, |h| <= r: sin x in sin m + cos(m) [-r, r] + [-r^2/2, r^2/2] (|sin''| <= 1),
  // so the enclosure of sin m widened by |cos m| r + r^2/2 (rounded up), and the same
  // for cos with |sin m|.
  const double r = narrow->radius;
  const Interval &s = narrow->sin_mid, &c = narrow->cos_mid;
  const double quadratic = mul_up(0.5, mul_up(r, r));
  const double sin_spread = add_up(mul_up(c.mag(), r), quadratic);
  const double cos_spread = add_up(mul_up(s.mag(), r), quadratic);
  const auto widened = [](const Interval& x, double spread) {
    return Interval::from_bounds(std::max(-1.0, sub_down(x.lo(), spread)), std::min(1.0, add_up(x.hi(), spread)));
  };
  return {widened(s, sin_spread), widened(c, cos_spread)};
}

}  // namespace gesmi
