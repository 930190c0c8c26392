#include "solver/mission/between_readings.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/interval/interval.h"

namespace gesmi {
namespace {

// The box of reading i widened by rate × |t - time_i|, rounded outward.
Interval widened(const ChannelReadings& r, std::size_t i, double t, double rate) {
  const double elapsed = t >= r.time[i] ? sub_up(t, r.time[i]) : sub_up(r.time[i], t);
  return Interval::around(r.value[i], r.half_width[i]).inflated(mul_up(rate, elapsed));
}

}  // namespace

ChannelAtGrid enclose_between_readings(const ChannelReadings& r, std::span<const double> grid, double uniform_rate,
                                       bool angle, std::span<const double> reading_rates) {
  ChannelAtGrid out;
  out.value.resize(grid.size());
  out.half_width.resize(grid.size());
  out.own_reading.assign(grid.size(), 0);
  const std::size_t n = r.time.size();
  std::size_t after = 0;  // first reading at or after the grid time
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const double t = grid[k];
    while (after < n && r.time[after] < t) ++after;
    // The rate between the readings around t (beyond the ends: the end reading's).
    double rate = uniform_rate;
    if (!reading_rates.empty())
      rate = after == 0 ? reading_rates[0]
             : after == n ? reading_rates[n - 1]
                          : std::max(reading_rates[after - 1], reading_rates[after]);
    Interval box;
    if (after < n && r.time[after] == t) {
      out.value[k] = r.value[after];
      out.half_width[k] = r.half_width[after];
      out.own_reading[k] = 1;
      continue;
    }
    if (after == 0) {
      box = widened(r, 0, t, rate);
    } else if (after == n) {
      box = widened(r, n - 1, t, rate);
    } else {
      const std::size_t before = after - 1;
      const Interval from_before = widened(r, before, t, rate);
      Interval from_after = widened(r, after, t, rate);
      // Two headings 2 pi apart are the same reading. The true change between the two
      // readings is at most rate (t_after - t_before), and each reading is off by at
      // most its half-width: when that sum is below 3 (< pi), only the branch of the
      // reading after closest to the one before is within reach. Otherwise several
      // are, and only the narrower one-sided box is kept, alone.
      const bool several_branches =
          angle && add_up(add_up(mul_up(rate, sub_up(r.time[after], r.time[before])), r.half_width[before]),
                          r.half_width[after]) >= 3.0;
      if (several_branches) {
        box = from_before.width() <= from_after.width() ? from_before : from_after;
      } else {
        if (angle) {
          const double turns = std::round((r.value[before] - r.value[after]) / (2.0 * std::numbers::pi));
          if (turns != 0.0) from_after = from_after + Interval(turns) * Interval::two_pi();
        }
        box = intersect(from_before, from_after);
        if (box.is_empty()) {
          out.conflict = ChannelAtGrid::Conflict{k, before, after};
          return out;
        }
      }
    }
    out.value[k] = box.mid();
    out.half_width[k] = box.rad();
  }
  return out;
}

}  // namespace gesmi
