#pragma once
// Measurements consistent with a true pose, for scenarios and tests: each range is
// the model's f_i(p*) divided by (1 + u), u uniform in +- error_fraction * alpha, so
// the feasible interval [d (1 - alpha), d (1 + alpha)] holds f_i(p*); each bearing of
// a visible landmark is shifted by at most error_fraction * delta. Chosen data can
// be replaced by outliers: values inconsistent with p* by a margin. A sensor with a
// max_range reports "no echo" when that reading would exceed it (seed 002: d_i starts
// at d_max); one without drops its measurement beyond options.max_range.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "solver/setinv/localization/localization_map.h"

namespace gesmi {

struct MeasurementSimulationOptions {
  std::uint32_t seed = 1;
  double error_fraction = 0.9;           // of each bound, in [0, 1)
  double max_range = 10.0;               // sonars without a max_range of their own report nothing beyond
  std::vector<std::size_t> range_outliers;    // sensor indices whose range is replaced
  std::vector<std::size_t> bearing_outliers;  // measurement indices (in output order) replaced
};

/// In sensor order: one range per sensor that gets an echo within range, and a "no
/// echo" for each other sensor that has a max_range. An outlier sensor whose every
/// reading within range lies near its echo gets a no echo when that is an outlier;
/// otherwise (as for a bearing whose precision leaves no far value) std::domain_error
/// names it: the simulation always ends.
std::vector<RangeMeasurement> simulate_ranges(const LocalizationMap& map, const std::vector<RangeSensor>& sensors,
                                              const Pose<double>& truth, const MeasurementSimulationOptions& options);

/// One bearing per (sensor, visible landmark), in sensor then landmark order.
std::vector<BearingMeasurement> simulate_bearings(const LocalizationMap& map, const std::vector<BearingSensor>& sensors,
                                                  const Pose<double>& truth, const MeasurementSimulationOptions& options);

}  // namespace gesmi
