#include "solver/setinv/outliers/datum_safety.h"

#include <algorithm>

namespace gesmi {

Interval safety_ratio(double inner, double outer, double inner_without, double outer_without) {
  // The volumes are floating-point sums of box volumes (relative error about the
  // number of boxes times 1e-16); a relative 1e-9 margin covers that.
  constexpr double kMargin = 1e-9;
  const double lo = outer_without > 0.0 ? inner / outer_without * (1.0 - kMargin) : 0.0;
  const double hi = inner_without > 0.0 ? outer / inner_without * (1.0 + kMargin) : 1.0;
  return Interval(std::clamp(lo, 0.0, 1.0), std::clamp(hi, 0.0, 1.0));
}

}  // namespace gesmi
