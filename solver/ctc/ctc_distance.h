#pragma once
// Distance constraint z = ||a - b|| in 2-D or 3-D, contracted forward-backward on
// the decomposition d_i = a_i - b_i, s_i = d_i^2, z = sqrt(sum s_i). Works on
// plain references so that it serves both small boxes and the mission arrays.

#include <array>

#include "solver/interval/interval.h"
#include "solver/ctc/ctc.h"
#include "solver/interval/interval_reverse.h"

namespace gesmi {

/// Narrows z, a and b; returns false when the constraint has no solution (the
/// arguments are then left empty).
template <std::size_t D>
bool contract_distance(Interval& z, std::array<Interval*, D> a, std::array<Interval*, D> b) {
  std::array<Interval, D> d, s;
  Interval sum(0.0);
  for (std::size_t i = 0; i < D; ++i) {
    d[i] = *a[i] - *b[i];
    s[i] = sqr(d[i]);
    sum += s[i];
  }
  bool ok = z.intersect_with(sqrt(sum));
  Interval sum_back = sum;
  ok = ok && sum_back.intersect_with(sqr(intersect(z, Interval::pos_reals())));
  // Backward through the sum: each s_i = sum - (the others).
  for (std::size_t i = 0; ok && i < D; ++i) {
    Interval others(0.0);
    for (std::size_t j = 0; j < D; ++j)
      if (j != i) others += s[j];
    ok = s[i].intersect_with(sum_back - others);
  }
  for (std::size_t i = 0; ok && i < D; ++i) ok = bwd_sqr(s[i], d[i]) && bwd_sub(d[i], *a[i], *b[i]);
  if (!ok) {
    z = Interval::empty();
    for (std::size_t i = 0; i < D; ++i) *a[i] = *b[i] = Interval::empty();
  }
  return ok;
}

/// Contractor form over a box: z, a and b are given by their variable indices.
template <std::size_t D>
class CtcDistance {
 public:
  CtcDistance(int z, std::array<int, D> a, std::array<int, D> b) : z_(z), a_(a), b_(b) {}
  void contract(Box& box) const {
    std::array<Interval*, D> a, b;
    for (std::size_t i = 0; i < D; ++i) {
      a[i] = &box[static_cast<std::size_t>(a_[i])];
      b[i] = &box[static_cast<std::size_t>(b_[i])];
    }
    if (!contract_distance<D>(box[static_cast<std::size_t>(z_)], a, b)) set_empty(box);
  }

 private:
  int z_;
  std::array<int, D> a_, b_;
};

}  // namespace gesmi
