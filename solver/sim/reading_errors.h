#pragma once
// The simulator's reading errors, strictly inside their bounds (simulation_options.h
// names the modes). In the bias-noise mode a reading's error is a bias, the same over
// the mission (or drifting as the options say), at a share F of the bound, plus noise
// within the rest: for the DVL and the barometer, whose bounds are relative plus
// absolute, a scale bias proportional to the value and an offset bias, each with its own
// sign. The GPS fixes and the attitude angles but the heading keep independent errors.

#include "solver/sim/random_source.h"
#include "solver/sim/simulation_options.h"

namespace gesmi {

class ReadingErrors {
 public:
  enum Sensor { roll, pitch, heading, vx, vy, vz, depth, altitude, gps_north, gps_east, mark, count };
  ReadingErrors(RandomSource& rng, const SimulationOptions& options);

  /// An error within `bound` at time t; `change` is how the true value moves over the
  /// coming step (at_samples), `curvature` its second difference at the sample (corners).
  double operator()(Sensor sensor, double bound, double t, double change = 0.0, double curvature = 0.0);
  /// The same for a sensor bounded by relative |reading| + absolute (the DVL, the
  /// barometer): within (relative |value| + absolute) / (1 + relative) of the true value,
  /// which keeps it inside the reading's box. The bias-noise mode splits its bias into a
  /// scale (times the value) and an offset; the other modes take the whole bound.
  double scaled(Sensor sensor, double value, double relative, double absolute, double t, double change,
                double curvature);

 private:
  /// The bias's factor at time t: 1, or its drift (a ramp from 1 to -1 over the mission,
  /// or a flip to -1 at its middle).
  double drift(double t) const;
  double bias_noise(Sensor sensor, double value, double relative, double absolute, double t);

  RandomSource& rng_;
  SimulationOptions options_;
  double signs_[count];
  double scale_signs_[count] = {};
  double periods_[count] = {};
  double phases_[count] = {};
};

}  // namespace gesmi
