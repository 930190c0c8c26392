#pragma once
// The Kalman smoother baseline (seed 001, section VI and Fig. 9): Euler angles taken
// as exact, the DVL velocity rotated by the measured attitude drives the position,
// depth and GPS fixes are measurements, and each detection is a range measurement
// linearised at the current estimate (plus the sonar-plane and mine-depth relations);
// a mine is initialised at its first detection from the declared side and the sonar
// geometry. The forward pass is an extended Kalman filter in information form over the
// chain of positions with the mines as static states; the backward pass is the
// Rauch-Tung-Striebel smoothing of that filter (arrowhead_chain.h), iterated a few
// times with the range measurements relinearised at the smoothed estimate.
//
// Noise from the interval bounds: a bound b becomes the variance factor * b^2 / 3, the
// variance of a uniform law on [-b, b] (docs/comparison.md).

#include <span>
#include <string>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/mission_network.h"

namespace gesmi {

struct KalmanOptions {
  double noise_factor = 1.0;  // multiplies every variance
  int iterations = 2;         // linearisations of the range measurements
  std::string validate() const;
};

struct KalmanResult {
  std::size_t steps = 0, mines = 0;
  std::vector<double> mean;        // steps x 3, row-major (north, east, down)
  std::vector<double> covariance;  // steps x 3 x 3
  std::vector<double> mine_mean;   // mines x 3 (NaN for a mine never detected)
  std::vector<double> mine_covariance;  // mines x 3 x 3
  int iterations = 0;
};

KalmanResult kalman_smooth(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes,
                           const KalmanOptions& options = {});

/// Fraction of steps whose true position lies within 3 sigma on every axis, and the
/// same for the mines (simulated missions); NaN without truth.
struct Containment {
  double trajectory = 0.0, mines = 0.0;
};
Containment three_sigma_containment(const KalmanResult& result, const Mission& mission);

}  // namespace gesmi
