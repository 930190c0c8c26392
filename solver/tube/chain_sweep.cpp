#include "solver/tube/chain_sweep.h"

namespace gesmi {

SweepResult chain_forward_portable(std::span<Interval> x, std::span<const Interval> v) {
  SweepResult result;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    if (!x[k + 1].intersect_with(x[k] + v[k])) {
      result.first_empty = k + 1;
      break;
    }
  }
  return result;
}

SweepResult chain_backward_portable(std::span<Interval> x, std::span<Interval> v) {
  SweepResult result;
  for (std::size_t k = x.size() - 1; k-- > 0;) {
    if (!x[k].intersect_with(x[k + 1] - v[k]) || !v[k].intersect_with(x[k + 1] - x[k])) {
      result.first_empty = k;
      break;
    }
  }
  return result;
}

}  // namespace gesmi
