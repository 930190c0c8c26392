#include "solver/model/euler.h"

namespace gesmi {
namespace {

// libm's sin and cos are within a few ulps (docs/intervals.md): an enclosure of
// the value at a point.
Interval libm_point(double y) { return Interval(step_down(y, kLibmSteps), step_up(y, kLibmSteps)); }

}  // namespace

SinCos<Interval> sin_cos(const Interval& angle) {
  if (angle.is_empty()) return {Interval::empty(), Interval::empty()};
  const double r = angle.rad();
  if (!(r <= 0.05)) return {sin(angle), cos(angle)};
  const double m = angle.mid();
  const Interval s = libm_point(std::sin(m)), c = libm_point(std::cos(m));
  const Interval h(-r, r);                         // x - m
  const Interval remainder = Interval(-0.5, 0.5) * sqr(Interval(r));  // |f''| <= 1
  const Interval unit(-1.0, 1.0);
  return {intersect(s + c * h + remainder, unit), intersect(c - s * h + remainder, unit)};
}

}  // namespace gesmi
