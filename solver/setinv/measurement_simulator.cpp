#include "solver/setinv/measurement_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "solver/setinv/bearing_model.h"
#include "solver/setinv/range_model.h"

namespace gesmi {
namespace {

bool listed(const std::vector<std::size_t>& list, std::size_t i) {
  return std::find(list.begin(), list.end(), i) != list.end();
}

}  // namespace

std::vector<RangeMeasurement> simulate_ranges(const LocalizationMap& map, const std::vector<RangeSensor>& sensors,
                                              const Pose<double>& truth, const MeasurementSimulationOptions& options) {
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<RangeMeasurement> out;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const double f = simulated_range(truth, sensors[i], std::span<const Segment>(map.walls));
    const double alpha = sensors[i].precision;
    const bool limited = sensors[i].has_max_range();
    const double max_range = limited ? sensors[i].max_range : options.max_range;
    if (listed(options.range_outliers, i)) {
      // Far from the truth's echo: outside the feasible interval by a margin.
      std::uniform_real_distribution<double> anywhere(std::min(0.3, 0.5 * max_range), max_range);
      double d = anywhere(rng);
      while (std::isfinite(f) && std::abs(d - f) < 4.0 * alpha * f + 0.2) d = anywhere(rng);
      out.push_back({i, d});
      continue;
    }
    if (!limited && !(f <= max_range)) continue;  // without the option: nothing beyond
    const double d = std::isfinite(f) ? f / (1.0 + options.error_fraction * alpha * unit(rng)) : kNoEcho;
    out.push_back({i, !limited || d <= max_range ? d : kNoEcho});  // a reading beyond max_range: no echo
  }
  return out;
}

std::vector<BearingMeasurement> simulate_bearings(const LocalizationMap& map, const std::vector<BearingSensor>& sensors,
                                                  const Pose<double>& truth, const MeasurementSimulationOptions& options) {
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<BearingMeasurement> out;
  const double c = std::cos(truth.theta), s = std::sin(truth.theta);
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const Vec2T<double> at = robot_to_world(truth, c, s, sensors[k].x, sensors[k].y);
    for (const LandmarkPoint& l : map.landmarks) {
      if (!landmark_visible(at, l, std::span<const Segment>(map.walls))) continue;
      const double b = landmark_bearing(at, truth.theta + sensors[k].heading, l);
      double measured = b + options.error_fraction * sensors[k].precision * unit(rng);
      if (listed(options.bearing_outliers, out.size())) {
        std::uniform_real_distribution<double> anywhere(-std::numbers::pi, std::numbers::pi);
        do {
          measured = anywhere(rng);
        } while (std::abs(std::remainder(measured - b, 2.0 * std::numbers::pi)) < 10.0 * sensors[k].precision + 0.05);
      }
      out.push_back({k, std::remainder(measured, 2.0 * std::numbers::pi)});
    }
  }
  return out;
}

}  // namespace gesmi
