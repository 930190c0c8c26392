#include "solver/tube/chain_sweep.h"

#include <algorithm>

namespace gesmi {

namespace {

// Largest narrowing of a bound from old to now (NaN from inf - inf ignored).
double shrink_of(const Interval& old, const Interval& now) {
  return std::max(0.0, std::max(now.lo() - old.lo(), old.hi() - now.hi()));
}

}  // namespace

SweepResult chain_forward_portable(std::span<Interval> x, std::span<const Interval> v) {
  SweepResult result;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const Interval old = x[k + 1];
    if (!x[k + 1].intersect_with(x[k] + v[k])) {
      result.first_empty = k + 1;
      result.max_shrink = kInf;
      break;
    }
    result.max_shrink = std::max(result.max_shrink, shrink_of(old, x[k + 1]));
  }
  return result;
}

SweepResult chain_backward_portable(std::span<Interval> x, std::span<Interval> v) {
  SweepResult result;
  for (std::size_t k = x.size() - 1; k-- > 0;) {
    const Interval old = x[k];
    if (!x[k].intersect_with(x[k + 1] - v[k]) || !v[k].intersect_with(x[k + 1] - x[k])) {
      result.first_empty = k;
      result.max_shrink = kInf;
      break;
    }
    result.max_shrink = std::max(result.max_shrink, shrink_of(old, x[k]));
  }
  return result;
}

}  // namespace gesmi
