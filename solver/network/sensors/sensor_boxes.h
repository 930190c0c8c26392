#pragma once
// Sensor readings turned into boxes that contain the true values (seed 001, V-B):
// at a sample, the reading ± its bound (the mission's per-sample half-width when
// it gives one, the model's bound otherwise); over a step [t_k, t_k+1], the hull
// of the boxes at both ends widened by rate_bound · dt / 2, the largest excursion
// of a quantity whose rate is bounded. The displacement over a step, and to a time
// between two samples, follows the model's StepModel (docs/model.md).

#include <cstddef>
#include <optional>

#include "solver/interval/box.h"
#include "solver/mission/mission.h"
#include "solver/model/euler.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/step_regimes.h"

namespace gesmi {

/// Whether a trapezoid step of duration at most dt_hi is also intersected with the rate
/// hull (SensorBoxes::step_increment explains why only then it can cut).
inline bool trapezoid_takes_rate_hull(const SensorModel& model, double dt_hi) {
  return model.max_jerk * dt_hi > 6.0 * model.max_acceleration;
}

class SensorBoxes {
 public:
  /// The mission must outlive this object (it reads the mission's arrays), and so must
  /// the frame's per-sample margins. The heading boxes grow by the frame's heading
  /// margin and the DVL boxes by its scale (the mission's zone-wide ones by default).
  /// With `regimes` (which
  /// must outlive this object), each step takes its regime's bounds (step_regimes.h);
  /// without, every step is submerged and unchecked.
  SensorBoxes(const Mission& mission, const SensorModel& model) : SensorBoxes(mission, model, zone_frame(mission)) {}
  SensorBoxes(const Mission& mission, const SensorModel& model, const FrameMargins& frame,
              const StepRegimes* regimes = nullptr)
      : m_(mission), model_(model), frame_(frame), regimes_(regimes ? regimes : &kSubmerged) {}

  Interval roll(std::size_t k) const;
  Interval pitch(std::size_t k) const;
  Interval heading(std::size_t k) const;
  Vec3I velocity(std::size_t k) const;  // DVL, body frame
  Interval depth(std::size_t k) const;
  /// The relative scale error between the surface speed at sample k and the DVL's
  /// (Mission::depth_scale_margin plus the frame's scale margin), rounded up.
  double frame_scale(std::size_t k) const;
  Interval altitude(std::size_t k) const;

  /// Boxes valid over the whole step [t_k, t_k+1] (k + 1 < size).
  Attitude<Interval> step_attitude(std::size_t k) const;
  Vec3I step_velocity(std::size_t k) const;
  Interval step_altitude(std::size_t k) const;
  /// Enclosure of the world-frame velocity R v over the step (bounded rates).
  Vec3I step_world_velocity(std::size_t k) const;
  /// Enclosure of the displacement p(k+1) - p(k) = integral of R v over the step,
  /// under the model's step model.
  Vec3I step_increment(std::size_t k) const;
  /// Enclosures of p(t) - p(k) (forward) and p(k+1) - p(t) (backward) for t between
  /// t_k and t_k+1, alpha = t - t_k and beta = t_k+1 - t, under the step model.
  void offsets_between(std::size_t k, const Interval& alpha, const Interval& beta, Vec3I& forward,
                       Vec3I& backward) const;
  /// The attitude and altitude at a time between t_k and t_k+1 (the step's boxes; the
  /// sample model takes sample k's).
  Attitude<Interval> attitude_between(std::size_t k) const;
  Interval altitude_between(std::size_t k) const;

  /// The boxes of one sample, so that a sweep over the steps builds each once.
  struct SampleBoxes {
    Interval roll, pitch, heading;
    Vec3I velocity;
    Vec3I world_velocity;  // R v from this sample's boxes alone (trapezoid and sample models)
  };
  SampleBoxes sample(std::size_t k) const;
  Attitude<Interval> step_attitude(const SampleBoxes& a, const SampleBoxes& b, std::size_t k) const;
  /// Sample k + 1's heading box b.heading on the turn of sample k's (headings wrap at
  /// +-pi: the representative closest to sample k's reading).
  Interval next_heading(const SampleBoxes& b, std::size_t k) const;
  Vec3I step_velocity(const SampleBoxes& a, const SampleBoxes& b, std::size_t k) const;
  /// Upper bounds of the integrals of |w_north| and |w_east| over a step, as the step
  /// model sees w: what a further turn of the heading widens the increment by
  /// (sensor_priors.h).
  struct StepTurn {
    double north = 0.0, east = 0.0;
    /// Trapezoid steps that also take the rate hull: when the two boxes do not meet,
    /// the increment returned is the trapezoid's alone and this is the hull, which the
    /// turned increment must meet (a turn widens both by the same amount).
    std::optional<Vec3I> apart_hull;
  };
  Vec3I step_increment(const SampleBoxes& a, const SampleBoxes& b, std::size_t k, StepTurn* turn = nullptr) const;
  /// dt times R v over the step's rate-bounded boxes: the rate_hull model.
  Vec3I rate_hull_increment(const SampleBoxes& a, const SampleBoxes& b, std::size_t k, StepTurn* turn = nullptr) const;
  /// dt times the step regime's speed bound on every component: what a step whose other
  /// bounds the readings contradict keeps (step_regimes.h).
  Vec3I speed_increment(std::size_t k, StepTurn* turn = nullptr) const;

  const SensorModel& model() const { return model_; }
  const StepRegimes& regimes() const { return *regimes_; }

 private:
  Interval reading(const std::vector<double>& values, const std::vector<double>& half_widths, std::size_t k,
                   double model_bound) const;
  Interval widen_over_step(const Interval& a, const Interval& b, double rate, std::size_t k) const;
  /// rate * dt / 2 over step k, rounded up.
  double excursion(double rate, std::size_t k) const;
  Interval step_duration(std::size_t k) const;
  static Interval widen(const Interval& a, const Interval& b, double excursion);
  /// Whether the rate hull's premise (max_acceleration, max_attitude_rate) holds over
  /// step k: submerged and not contradicted by the readings.
  bool rates_hold(std::size_t k) const { return !regimes_->special(k); }
  /// [-v, v] on each component, v the speed bound of step k's regime.
  Vec3I speed_box(std::size_t k) const;
  /// The trapezoid's increment of step k intersected with its speed increment; the turn's
  /// sensitivities the larger of both.
  Vec3I intersect_speed(const Vec3I& trapezoid, std::size_t k, StepTurn* turn) const;
  /// The attitude over step k when no rate bounds it: every angle.
  static Attitude<Interval> any_attitude();

  static const StepRegimes kSubmerged;

  const Mission& m_;
  SensorModel model_;
  FrameMargins frame_;
  const StepRegimes* regimes_;
};

}  // namespace gesmi
