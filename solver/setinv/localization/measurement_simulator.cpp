#include "solver/setinv/localization/measurement_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "solver/setinv/localization/bearing_model.h"
#include "solver/setinv/localization/range_model.h"

namespace gesmi {
namespace {

bool listed(const std::vector<std::size_t>& list, std::size_t i) {
  return std::find(list.begin(), list.end(), i) != list.end();
}

// A value uniform on [lo, hi) outside the band (centre - margin, centre + margin), or
// none when the band covers it all. While the band leaves at least half of [lo, hi),
// by rejection (the draws the shipped scenarios were simulated with); otherwise
// directly from what is left, so that it always ends.
std::optional<double> draw_outside(std::mt19937& rng, double lo, double hi, double centre, double margin) {
  const double below = std::max(0.0, std::min(hi, centre - margin) - lo);
  const double above = std::max(0.0, hi - std::max(lo, centre + margin));
  const double left = below + above;
  if (!(left > 0.0)) return std::nullopt;
  if (left >= 0.5 * (hi - lo)) {
    std::uniform_real_distribution<double> anywhere(lo, hi);
    double d = anywhere(rng);
    while (std::abs(d - centre) < margin) d = anywhere(rng);
    return d;
  }
  const double u = std::uniform_real_distribution<double>(0.0, left)(rng);
  return u < below ? lo + u : std::max(lo, centre + margin) + (u - below);
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
      // Far from the truth's echo: outside the feasible interval by a margin (any
      // reading when the truth hears nothing). When no reading within range is that
      // far, a no echo is an outlier if the truth's echo lies below M (1 - alpha).
      const double margin = std::isfinite(f) ? 4.0 * alpha * f + 0.2 : 0.0;
      const std::optional<double> d = draw_outside(rng, std::min(0.3, 0.5 * max_range), max_range, f, margin);
      if (d) {
        out.push_back({i, *d});
      } else if (limited && f < max_range * (1.0 - alpha)) {
        out.push_back({i, kNoEcho});
      } else {
        throw std::domain_error("range sensor " + std::to_string(i) + " ('" + sensors[i].name +
                                "'): no reading up to its range " + std::to_string(max_range) +
                                " m is an outlier at the true pose (every one lies within " + std::to_string(margin) +
                                " m of its echo " + std::to_string(f) + " m); leave it out of the outliers");
      }
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
        // On the circle: the arc more than the margin away from the truth's bearing.
        // While it leaves half the circle, by rejection (the shipped scenarios' draws),
        // otherwise directly, so that it always ends.
        const double margin = 10.0 * sensors[k].precision + 0.05, pi = std::numbers::pi;
        if (!(margin < pi))
          throw std::domain_error("bearing " + std::to_string(out.size()) + " (sensor '" + sensors[k].name +
                                  "'): its precision leaves no bearing 10 times it away from the truth's; leave it "
                                  "out of the outliers");
        if (margin <= 0.5 * pi) {
          std::uniform_real_distribution<double> anywhere(-pi, pi);
          do {
            measured = anywhere(rng);
          } while (std::abs(std::remainder(measured - b, 2.0 * pi)) < margin);
        } else {
          measured = b + margin + std::uniform_real_distribution<double>(0.0, 2.0 * (pi - margin))(rng);
        }
      }
      out.push_back({k, std::remainder(measured, 2.0 * std::numbers::pi)});
    }
  }
  return out;
}

}  // namespace gesmi
