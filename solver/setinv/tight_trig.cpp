#include "solver/setinv/tight_trig.h"

#include <cmath>

namespace gesmi {
namespace {

// Could some point offset + n * step (n integer) lie in x? step and offset are
// enclosures; x is bounded with width below two steps.
bool may_hold_multiple(const Interval& x, const Interval& offset, const Interval& step) {
  const double first = std::floor((x.lo() - offset.hi()) / step.hi()) - 1.0;
  for (double n = first; n <= first + 4.0; n += 1.0) {
    // Cheap rejection in doubles with a generous margin, exact check otherwise.
    const double t = offset.mid() + n * step.mid(), margin = 1e-9 * (1.0 + std::abs(t));
    if (t + margin < x.lo() || t - margin > x.hi()) continue;
    if ((offset + Interval(n) * step).intersects(x)) return true;
  }
  return false;
}

}  // namespace

Interval tight_cos(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  if (!x.is_bounded() || x.width() >= Interval::two_pi().lo()) return Interval(-1.0, 1.0);
  const double ca = std::cos(x.lo()), cb = std::cos(x.hi());
  double lo = step_down(std::min(ca, cb), kLibmSteps), hi = step_up(std::max(ca, cb), kLibmSteps);
  if (may_hold_multiple(x, Interval(0.0), Interval::two_pi())) hi = 1.0;       // maxima at 2 pi n
  if (may_hold_multiple(x, Interval::pi(), Interval::two_pi())) lo = -1.0;     // minima at pi + 2 pi n
  return Interval(std::max(lo, -1.0), std::min(hi, 1.0));
}

Interval tight_sin(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  if (!x.is_bounded() || x.width() >= Interval::two_pi().lo()) return Interval(-1.0, 1.0);
  const double sa = std::sin(x.lo()), sb = std::sin(x.hi());
  double lo = step_down(std::min(sa, sb), kLibmSteps), hi = step_up(std::max(sa, sb), kLibmSteps);
  if (may_hold_multiple(x, Interval::half_pi(), Interval::two_pi())) hi = 1.0;              // pi/2 + 2 pi n
  if (may_hold_multiple(x, -Interval::half_pi(), Interval::two_pi())) lo = -1.0;            // -pi/2 + 2 pi n
  return Interval(std::max(lo, -1.0), std::min(hi, 1.0));
}

}  // namespace gesmi
