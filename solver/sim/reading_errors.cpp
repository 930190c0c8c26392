#include "solver/sim/reading_errors.h"

#include <cmath>

#include "solver/model/angles.h"

namespace gesmi {
namespace {

constexpr double kInside = 0.99;  // errors at most 99 % of their bound

}  // namespace

ReadingErrors::ReadingErrors(RandomSource& rng, const SimulationOptions& options) : rng_(rng), options_(options) {
  for (double& s : signs_) s = rng_.sign();
  // Drawn only in their mode, so the other modes keep their random sequence.
  if (options_.errors == SimulatedErrors::drifting)
    for (int s = 0; s < count; ++s) {
      periods_[s] = rng_.uniform(600.0, 2400.0);
      phases_[s] = rng_.uniform(0.0, kTwoPi);
    }
  if (options_.errors == SimulatedErrors::bias_noise)
    for (double& s : scale_signs_) s = rng_.sign();
}

double ReadingErrors::operator()(Sensor sensor, double bound, double t, double change, double curvature) {
  switch (options_.errors) {
    case SimulatedErrors::corners: return 0.999 * bound * (curvature >= 0.0 ? 1.0 : -1.0);
    case SimulatedErrors::worst_case: return kInside * bound * signs_[sensor];
    case SimulatedErrors::at_samples:
      if (change != 0.0) return -kInside * bound * (change > 0.0 ? 1.0 : -1.0);
      break;
    case SimulatedErrors::drifting: return kInside * bound * std::sin(kTwoPi * t / periods_[sensor] + phases_[sensor]);
    case SimulatedErrors::bias_noise: return bias_noise(sensor, 0.0, 0.0, bound, t);
    case SimulatedErrors::uniform: break;
  }
  return kInside * bound * rng_.uniform(-1.0, 1.0);
}

double ReadingErrors::scaled(Sensor sensor, double value, double relative, double absolute, double t, double change,
                             double curvature) {
  if (options_.errors == SimulatedErrors::bias_noise)
    return bias_noise(sensor, value, relative / (1.0 + relative), absolute / (1.0 + relative), t);
  return (*this)(sensor, (relative * std::fabs(value) + absolute) / (1.0 + relative), t, change, curvature);
}

double ReadingErrors::drift(double t) const {
  switch (options_.drift) {
    case BiasDrift::none: return 1.0;
    case BiasDrift::ramp: return 1.0 - 2.0 * t / options_.duration;
    case BiasDrift::flip: return t < 0.5 * options_.duration ? 1.0 : -1.0;
  }
  return 1.0;
}

double ReadingErrors::bias_noise(Sensor sensor, double value, double relative, double absolute, double t) {
  const double bound = relative * std::fabs(value) + absolute;
  // The structured channels (heading, DVL, barometer, altitude, mark range) carry a bias;
  // the fixes, roll and pitch independent errors.
  const bool biased = sensor != roll && sensor != pitch && sensor != gps_north && sensor != gps_east;
  if (!biased) return kInside * bound * rng_.uniform(-1.0, 1.0);
  const double share = options_.bias_share;
  // |bias| <= share * bound, |noise| <= (1 - share) * bound: within the bound together.
  const double bias = share * drift(t) * (scale_signs_[sensor] * relative * value + signs_[sensor] * absolute);
  return kInside * (bias + (1.0 - share) * bound * rng_.uniform(-1.0, 1.0));
}

}  // namespace gesmi
