#pragma once
// Adversarial true signals for the soundness tests of the per-step enclosures
// (solver/network/sensors/sensor_boxes, time_location), built independently of gesmi's
// simulator and sensor code. Every quantity is piecewise linear in time; its rate
// never exceeds the model's bound (max_attitude_rate, max_acceleration, and for the
// altitude |v| (1 + slope)), and at every sample it lies in the box the model
// allows around the reading. The adversary puts the truth at an end of the
// sample box (reading +- bound) and, between two samples, goes out at the largest
// allowed rate and comes back (a "tent"), so the step boxes are reached; headings
// are unwrapped truths whose readings wrap at +-pi; time steps are irregular.
//
// Everything is pulled inside its bound by a relative 1e-9 (rates and sample
// errors), far more than the error of evaluating the truth in long double (1e-19),
// so a feasible value is never reported outside by the oracle's own rounding.
//
// The true displacement over [t0, t1] is the integral of R(phi, theta, psi) v,
// computed in long double with the Gauss-Legendre 4-point rule on sub-pieces of at
// most 10 ms between the signals' knots (the integrand is smooth there). Its
// error is below 1e-20 m per step for rates up to 1 rad/s and 1 m/s^2: the rule's
// error is h^9 (4!)^4 / (9 (8!)^3) |f^(8)| = 5.6e-10 h^9 |f^(8)| with h <= 0.01 s,
// and |f^(8)| <= 6 ((3 rho)^8 |v| + 8 (3 rho)^7 |a|) < 5e5 for |v| <= 10 m/s.
// kDisplacementError = 1e-12 m is therefore a generous rigorous bound.

#include <cstdint>
#include <vector>

#include "solver/mission/mission.h"

namespace gesmi::test {

inline constexpr long double kDisplacementError = 1e-12L;  // m

/// A piecewise-linear signal: value at any time by linear interpolation of knots.
struct Track {
  std::vector<long double> t, x;  // knots, t increasing
  long double at(long double time) const;
};

struct TrueMotion {
  Track roll, pitch, heading;  // rad (heading unwrapped)
  Track vx, vy, vz;            // m/s, body frame
  Track altitude;              // m
  /// Every knot time of every track (sorted, unique).
  std::vector<long double> knots;

  /// R(t) v(t) in the world frame (long double, independent of solver/model).
  void world_velocity(long double time, long double out[3]) const;
  /// Integral of R v over [t0, t1] (error below kDisplacementError).
  void displacement(long double t0, long double t1, long double out[3]) const;
};

struct BoundedRateMission {
  Mission mission;      // readings on an irregular grid, model = the given one
  TrueMotion truth;
  std::vector<long double> px, py, pz;  // true position at the samples (p(0) = 0)
};

struct BoundedRateOptions {
  std::size_t samples = 400;
  double initial_heading = 0.0;  // rad
  double lateral_speed = 0.3;    // m/s: |vy|, |vz| stay below (vx in [0.5, 2.5])
  SensorModel model;
};

BoundedRateMission make_bounded_rate_mission(std::uint64_t seed, const BoundedRateOptions& options);

}  // namespace gesmi::test
