#pragma once
// Truths of bounded jerk with their displacements in closed form (long double), and
// missions read from them with errors that lean against the step models: shared by
// the step model's and the heading frame's tests.

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "solver/mission/mission.h"

namespace gesmi::test {

// One body-frame velocity component v(t) = base + amplitude sin(omega t + phase),
// whose second derivative is at most amplitude omega² in magnitude.
struct Wave {
  long double base, amplitude, omega, phase;
  long double at(long double t) const { return base + amplitude * std::sin(omega * t + phase); }
  long double second_derivative(long double t) const { return -amplitude * omega * omega * std::sin(omega * t + phase); }
  long double integral(long double t0, long double t1) const {
    return base * (t1 - t0) - amplitude / omega * (std::cos(omega * t1 + phase) - std::cos(omega * t0 + phase));
  }
};

// A level robot (roll = pitch = 0) on a constant heading with waving body speeds:
// w = R(psi) v, and |w_north''|, |w_east''| <= |vx''| + |vy''|, |w_down''| = |vz''|.
struct SmoothTruth {
  long double heading;
  Wave vx, vy, vz;
  // The world displacement over [t0, t1], exactly.
  std::array<long double, 3> displacement(long double t0, long double t1) const {
    const long double x = vx.integral(t0, t1), y = vy.integral(t0, t1), z = vz.integral(t0, t1);
    const long double c = std::cos(heading), s = std::sin(heading);
    return {c * x - s * y, s * x + c * y, z};
  }
  long double jerk_bound() const {
    const auto peak = [](const Wave& w) { return w.amplitude * w.omega * w.omega; };
    return std::max(peak(vx) + peak(vy), peak(vz));
  }
};

/// Readings at the samples of an irregular grid (steps of 0.05 to 0.3 s), each DVL
/// error at 99 % of its bound with the sign of the coming curvature (the boxes lean
/// against the trapezoid's error); the heading reads truth.heading + heading_error.
Mission mission_of(const SmoothTruth& truth, const SensorModel& model, std::size_t samples, std::uint64_t seed,
                   double heading_error = 0.0);

/// Four headings, curvatures 0.6 J (vx), 0.3 J (vy), 0.9 J (vz) for J = 1 m/s³.
std::vector<SmoothTruth> truths();

/// The default model with that step model and jerk, and rates far above the truths'
/// (so that the rate hull does not decide).
SensorModel model_with(StepModel step, double jerk);

}  // namespace gesmi::test
