#pragma once
// The readings' check of step_regimes.h (docs/model.md, "The readings' check"): what
// the readings prove about the motion between samples, gathered in one pass over the
// world velocity boxes, then judged against the bounds of each step's regime.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "solver/interval/interval.h"
#include "solver/mission/mission.h"
#include "solver/network/sensors/sensor_kernel.h"
#include "solver/network/sensors/step_regimes.h"

namespace gesmi {

/// Intervals as two arrays of bounds.
struct IntervalArray {
  std::vector<double> lo, hi;
  explicit IntervalArray(std::size_t n) : lo(n), hi(n) {}
  void set(std::size_t k, const Interval& x) {
    lo[k] = x.lo();
    hi[k] = x.hi();
  }
  Interval at(std::size_t k) const { return Interval::from_bounds(lo[k], hi[k]); }
};

/// A result of a few operations in plain double arithmetic, moved outward by this: a
/// relative 8 units in the last place of the largest magnitude involved plus the smallest
/// normal number cover the roundings to nearest.
inline double outward(double largest) {
  return 8.0 * std::numeric_limits<double>::epsilon() * largest + std::numeric_limits<double>::min();
}

/// dt [-v, v] for step k, outward: the increment of a step bounded by the speed v alone.
Interval speed_step(const Mission& mission, std::size_t k, double v);

/// What the readings show.
struct ReadingsEvidence {
  /// Somewhere between samples centre - span and centre + span, |d²(R v)/dt²| >= least
  /// (> max_jerk).
  struct Jerk {
    std::size_t centre, span;
    double least;
  };
  /// At this sample, |R v| >= sqrt(least_squared) (> max_speed).
  struct Speed {
    std::size_t sample;
    double least_squared;
  };
  std::vector<Jerk> jerks;
  std::vector<Speed> speeds;
  /// Steps whose readings break max_acceleration or max_attitude_rate.
  std::vector<std::size_t> rate_steps;
  /// Each step's vertical increment under the regimes the evidence was gathered with.
  IntervalArray dz;
  explicit ReadingsEvidence(std::size_t steps) : dz(steps) {}
};

/// One pass over the mission's world velocity boxes (frameless, widened by the zone's
/// turn and scale: they hold R v in the local frame at every sample).
ReadingsEvidence gather_evidence(const Mission& mission, const SensorModel& model, const StepRegimes& regimes);

/// Sets StepRegimes::kFallback in `flags` on the steps whose bounds under the surface
/// flags of `surface` the evidence contradicts: a jerk beyond the largest bound of the
/// steps of its window, or (submerged) a rate beyond the rate hull's.
void flag_contradicted(const ReadingsEvidence& evidence, const SensorModel& model, const StepRegimes& surface,
                       std::vector<std::uint8_t>& flags);

/// Counts in `report` the samples whose speed exceeds their regime's bound.
void report_speeds(const ReadingsEvidence& evidence, const Mission& mission, const SensorModel& model,
                   const StepRegimes& surface, StepRegimeReport& report);

}  // namespace gesmi
