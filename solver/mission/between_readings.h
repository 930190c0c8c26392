#pragma once
// A sensor read at its own times (depth at 1 Hz, attitude at 20 Hz) enclosed at the
// solver's grid times (docs/model.md, "Readings between samples"). At a grid time
// with its own reading, the reading's box; elsewhere the intersection of the boxes of
// the readings just before and just after, each widened by the largest change the
// model's rate bound allows over the time between (|y(t) - y(t_i)| <= rate |t - t_i|).
// Never interpolation: the enclosure holds every trajectory the bounds allow.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace gesmi {

/// One channel's readings, times non-decreasing, each with its half-width (the
/// sensor bound at that reading).
struct ChannelReadings {
  std::vector<double> time, value, half_width;
};

/// The channel at the grid times: centre and half-width of a box holding the true
/// value (the reading and its own half-width at a grid time that has one), and
/// whether the grid time had a reading of its own.
struct ChannelAtGrid {
  std::vector<double> value, half_width;
  std::vector<unsigned char> own_reading;
  /// Readings (indices) whose widened boxes do not meet: the data break the model.
  struct Conflict {
    std::size_t grid, before, after;
  };
  std::optional<Conflict> conflict;
};

/// `rate`: bound on |dy/dt|. `angle`: y is an angle (the reading after may be taken
/// 2 pi turns away, to the branch closest to the reading before, when the bounds
/// leave only that one). Grid times must be non-decreasing; readings non-empty.
/// `reading_rates` (empty, or one per reading): the bound near each reading instead;
/// between two readings the larger of theirs holds (the depth's rate at the surface).
ChannelAtGrid enclose_between_readings(const ChannelReadings& readings, std::span<const double> grid, double rate,
                                       bool angle, std::span<const double> reading_rates = {});

}  // namespace gesmi
