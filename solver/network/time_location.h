#pragma once
// Where a time t (a GPS fix, a sonar mark) falls on the mission's sample grid.
// On a sample, the position there is p(k). Between t_k and t_k+1 it is a point
// q = p(t) with q in p(k) + F and q in p(k+1) - B, where F and B enclose the
// displacements from t_k to t and from t to t_k+1 under the step model
// (SensorBoxes::offsets_between).

#include <cstddef>
#include <span>

#include "solver/interval/box.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

class SensorBoxes;

struct TimeLocation {
  std::size_t k = 0;
  bool on_grid = true;
  Vec3I forward, backward;  // p(t) - p(k) and p(k+1) - p(t) (off grid)

  /// t must lie within [time.front(), time.back()].
  static TimeLocation locate(std::span<const double> time, double t, const SensorBoxes& boxes);
  /// The first sample at or after t: t's own sample on the grid, else the end of t's
  /// step. locate() reads the boxes of that sample and of the one before.
  static std::size_t sample_at_or_after(std::span<const double> time, double t);

  /// The position domain at this time.
  Vec3I position(const TubeDomains& d) const;
  /// Narrows the tube with a contracted position q at this time; false if empty.
  bool narrow(TubeDomains& d, const Vec3I& q) const;
};

}  // namespace gesmi
