#pragma once
// Which bounds hold over each step (docs/model.md, "Regimes: the surface, and the
// readings' check").
//
// A step is in the surface regime when its possible depths reach the surface layer
// (the lowest depths at its two samples that the barometer's boxes and the depth chain
// allow, with the shallowest point between them at the surface speed) or a GPS fix
// falls in it (fixes are taken at the surface): it takes
// surface_max_jerk, and its displacement is also held by surface_max_speed. Elsewhere
// it is submerged: max_jerk, and the rate hull (max_acceleration, max_attitude_rate).
//
// The readings check the jerk bound they rest on. For a twice differentiable w, the
// second divided difference over three times is w''(xi) for some xi between them, so
// with the world velocity boxes of samples k - m, k, k + m it lies in an interval that
// must meet [-J, J]. Where it does not (for spans of m = 1, 4 and 16 samples), the
// data contradict J somewhere in that window, and its steps fall back to the bound that
// needs no jerk: the displacement over dt is within dt times the regime's speed bound.
// The long submerged steps whose trapezoid takes the rate hull (max_jerk dt > 6
// max_acceleration) are checked the same way against the rates that hull rests on.
// A check can only find what the readings' error bounds do not hide: docs/guarantees.md.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "solver/mission/mission.h"

namespace gesmi {

/// What the readings contradict, for the report (SolveReport::regimes).
struct StepRegimeReport {
  std::size_t surface_steps = 0;
  /// Steps whose bounds the readings contradict, bounded by the speed alone.
  std::size_t fallback_steps = 0;
  /// Start times (s) of the first runs of such steps, at most kShownTimes.
  std::vector<double> fallback_times;
  /// Samples whose DVL and attitude boxes hold no velocity within the regime's speed
  /// bound: that bound (max_speed or surface_max_speed) is contradicted there, so the
  /// fallback's premise does not hold at those samples.
  std::size_t speed_exceeded = 0;
  std::vector<double> speed_exceeded_times;
  static constexpr std::size_t kShownTimes = 5;
};

class StepRegimes {
 public:
  static constexpr std::uint8_t kSurface = 1, kFallback = 2;

  /// Every step submerged, nothing contradicted (a mission the caller did not check).
  StepRegimes() = default;
  /// Flags per step (kSurface, kFallback), one per step of the mission.
  explicit StepRegimes(std::vector<std::uint8_t> flags) : flags_(std::move(flags)) {}

  bool surface(std::size_t k) const { return !flags_.empty() && (flags_[k] & kSurface) != 0; }
  bool fallback(std::size_t k) const { return !flags_.empty() && (flags_[k] & kFallback) != 0; }
  /// Whether step k takes bounds other than the submerged jerk model's.
  bool special(std::size_t k) const { return !flags_.empty() && flags_[k] != 0; }
  double jerk(const SensorModel& model, std::size_t k) const {
    return surface(k) ? model.surface_max_jerk : model.max_jerk;
  }
  double speed(const SensorModel& model, std::size_t k) const {
    return surface(k) ? model.surface_max_speed : model.max_speed;
  }
  /// The largest speed bound a fall-back step rests on: 0 when no step falls back.
  double largest_speed(const SensorModel& model) const;
  const StepRegimeReport& report() const { return report_; }
  void set_report(StepRegimeReport report) { report_ = std::move(report); }
  std::size_t steps() const { return flags_.size(); }

 private:
  std::vector<std::uint8_t> flags_;
  StepRegimeReport report_;
};

/// The regimes of the mission's steps under `model`, and the readings' check. Reads
/// every DVL, attitude and depth reading (before a solve releases them).
StepRegimes classify_steps(const Mission& mission, const SensorModel& model);

}  // namespace gesmi
