#include "solver/network/sensors/sensor_boxes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "solver/network/sensors/step_model.h"

namespace gesmi {

const StepRegimes SensorBoxes::kSubmerged{};

Interval SensorBoxes::reading(const std::vector<double>& values, const std::vector<double>& half_widths,
                              std::size_t k, double model_bound) const {
  const double bound = half_widths.empty() ? model_bound : half_widths[k];
  return Interval::around(values[k], bound);
}

Interval SensorBoxes::roll(std::size_t k) const { return reading(m_.roll, m_.half_widths.roll, k, model_.roll); }
Interval SensorBoxes::pitch(std::size_t k) const { return reading(m_.pitch, m_.half_widths.pitch, k, model_.pitch); }
Interval SensorBoxes::heading(std::size_t k) const {
  // The gyrocompass measures from true north, which turns against the local frame
  // across the mission area (meridian convergence): widen by that angle.
  const Interval h = reading(m_.heading, m_.half_widths.heading, k, model_.heading);
  const double margin = frame_.heading.at(k);
  return margin == 0.0 ? h : h.inflated(margin);
}

Vec3I SensorBoxes::velocity(std::size_t k) const {
  // v ± (a |v| + b) per component (or the sample's own half-width), rounded up, plus
  // what the depth and the local tangent frame do to distances (frame_scale()) times
  // the box's largest |vx| + |vy| + |vz| on every component, since the frame's
  // distortion turns a velocity's error off its own axis (docs/model.md, "The local
  // frame's scale").
  const std::vector<double>* readings[3] = {&m_.vx, &m_.vy, &m_.vz};
  const std::vector<double>* widths[3] = {&m_.half_widths.vx, &m_.half_widths.vy, &m_.half_widths.vz};
  double reading[3], own[3], largest = 0.0;
  for (int i = 0; i < 3; ++i) {
    reading[i] = (*readings[i])[k];
    const double v = std::fabs(reading[i]);
    own[i] = widths[i]->empty() ? dvl_bound(model_, v) : (*widths[i])[k];
    largest = add_up(largest, add_up(v, own[i]));
  }
  const double frame = mul_up(frame_scale(k), largest);
  return Vec3I(Interval::around(reading[0], add_up(own[0], frame)), Interval::around(reading[1], add_up(own[1], frame)),
               Interval::around(reading[2], add_up(own[2], frame)));
}

double SensorBoxes::frame_scale(std::size_t k) const { return add_up(m_.depth_scale_margin, frame_.scale.at(k)); }

Interval SensorBoxes::depth(std::size_t k) const {
  const double bound = depth_bound(model_, m_.depth[k]);
  return reading(m_.depth, m_.half_widths.depth, k, bound);
}

Interval SensorBoxes::altitude(std::size_t k) const {
  return reading(m_.altitude, m_.half_widths.altitude, k, model_.altitude);
}

Interval SensorBoxes::widen_over_step(const Interval& a, const Interval& b, double rate, std::size_t k) const {
  return widen(a, b, excursion(rate, k));
}

double SensorBoxes::excursion(double rate, std::size_t k) const {
  return mul_up(rate, mul_up(0.5, sub_up(m_.time[k + 1], m_.time[k])));
}

Interval SensorBoxes::widen(const Interval& a, const Interval& b, double excursion) {
  return hull(a, b).inflated(excursion);
}

SensorBoxes::SampleBoxes SensorBoxes::sample(std::size_t k) const {
  SampleBoxes s{roll(k), pitch(k), heading(k), velocity(k), {}};
  if (model_.step_model != StepModel::rate_hull)
    s.world_velocity = body_to_world(make_attitude(s.roll, s.pitch, s.heading), s.velocity);
  return s;
}

Interval SensorBoxes::step_duration(std::size_t k) const { return Interval(m_.time[k + 1]) - Interval(m_.time[k]); }

Attitude<Interval> SensorBoxes::step_attitude(const SampleBoxes& a, const SampleBoxes& b, std::size_t k) const {
  const double e = excursion(model_.max_attitude_rate, k);
  return make_attitude(widen(a.roll, b.roll, e), widen(a.pitch, b.pitch, e), widen(a.heading, next_heading(b, k), e));
}

Interval SensorBoxes::next_heading(const SampleBoxes& b, std::size_t k) const {
  // 2 pi turns change neither sine nor cosine.
  const double turns = std::round((m_.heading[k] - m_.heading[k + 1]) / (2.0 * std::numbers::pi));
  return turns == 0.0 ? b.heading : b.heading + Interval(turns) * Interval::two_pi();
}

Vec3I SensorBoxes::speed_box(std::size_t k) const {
  const double v = regimes_->speed(model_, k);
  return Vec3I(Interval(-v, v), Interval(-v, v), Interval(-v, v));
}

Vec3I SensorBoxes::speed_increment(std::size_t k, StepTurn* turn) const {
  // |w| <= v at every instant, in any frame: no turn of the heading moves this box, but
  // the sensitivities must still bound the integrals of |w_north| and |w_east|.
  const Interval dt = step_duration(k);
  const Vec3I v = speed_box(k);
  if (turn) *turn = {mul_up(dt.hi(), v[0].hi()), mul_up(dt.hi(), v[1].hi()), std::nullopt};
  return Vec3I(dt * v[0], dt * v[1], dt * v[2]);
}

Attitude<Interval> SensorBoxes::any_attitude() {
  const Interval pi = Interval::pi(), half_pi = Interval::half_pi();
  const Interval circle(-pi.hi(), pi.hi());
  return make_attitude(circle, Interval(-half_pi.hi(), half_pi.hi()), circle);
}

Vec3I SensorBoxes::step_velocity(const SampleBoxes& a, const SampleBoxes& b, std::size_t k) const {
  const double e = excursion(model_.max_acceleration, k);
  return Vec3I(widen(a.velocity[0], b.velocity[0], e), widen(a.velocity[1], b.velocity[1], e),
               widen(a.velocity[2], b.velocity[2], e));
}

Vec3I SensorBoxes::rate_hull_increment(const SampleBoxes& a, const SampleBoxes& b, std::size_t k,
                                       StepTurn* turn) const {
  // Mean value theorem for integrals: the integral over [t_k, t_k+1] of a function
  // whose values stay in the (convex) box B is in (t_k+1 - t_k) B.
  const Interval dt = step_duration(k);
  const Vec3I w = body_to_world(step_attitude(a, b, k), step_velocity(a, b, k));
  if (turn) *turn = {mul_up(dt.hi(), w[0].mag()), mul_up(dt.hi(), w[1].mag()), std::nullopt};
  return Vec3I(dt * w[0], dt * w[1], dt * w[2]);
}

Vec3I SensorBoxes::step_increment(const SampleBoxes& a, const SampleBoxes& b, std::size_t k, StepTurn* turn) const {
  const Interval dt = step_duration(k);
  // Steps whose jerk bound the readings contradict, and those of the models that rest on
  // the rates where the rates may not hold, keep the speed bound alone.
  if (regimes_->fallback(k) || (!rates_hold(k) && model_.step_model != StepModel::trapezoid))
    return speed_increment(k, turn);
  switch (model_.step_model) {
    case StepModel::rate_hull:
      return rate_hull_increment(a, b, k, turn);
    case StepModel::sample:
      if (turn) *turn = {mul_up(dt.hi(), a.world_velocity[0].mag()), mul_up(dt.hi(), a.world_velocity[1].mag()), std::nullopt};
      return Vec3I(dt * a.world_velocity[0], dt * a.world_velocity[1], dt * a.world_velocity[2]);
    case StepModel::trapezoid:
      break;
  }
  // Trapezoid rule with its remainder (step_model.h), per component, with w(t_k) in
  // sample k's box R v.
  const Interval half = dt / Interval(2.0);
  const Interval remainder = trapezoid_remainder(dt, regimes_->jerk(model_, k));
  Vec3I d;
  for (int i = 0; i < 3; ++i) d[i] = half * (a.world_velocity[i] + b.world_velocity[i]) + remainder;
  // A turn moves only the sample values: the remainder bounds w'' in the local frame.
  if (turn)
    *turn = {mul_up(half.hi(), add_up(a.world_velocity[0].mag(), b.world_velocity[0].mag())),
             mul_up(half.hi(), add_up(a.world_velocity[1].mag(), b.world_velocity[1].mag())), std::nullopt};
  // At the surface the waves break the rate bounds: the speed box bounds the step there.
  if (!rates_hold(k)) return intersect_speed(d, k, turn);
  // Intersected with the rate hull, so never wider than it. The hull holds both samples'
  // world velocities widened by at least max_acceleration dt / 2 on every component (a
  // world component of R (v ± e) spans ± e at least: a rotation's rows have an L1 norm
  // >= 1), so the trapezoid's ± J dt² / 12 can only stick out when J dt > 6
  // max_acceleration; elsewhere the second rotation per step is not worth its cost.
  if (trapezoid_takes_rate_hull(model_, dt.hi())) {
    StepTurn hull_turn;
    const Vec3I hull = rate_hull_increment(a, b, k, &hull_turn);
    Vec3I both;
    bool meet = true;
    for (int i = 0; i < 3; ++i) {
      both[i] = intersect(d[i], hull[i]);
      meet = meet && !both[i].is_empty();
    }
    if (!turn) return both;
    // A later turn widens both by the larger of their sensitivities.
    turn->north = std::max(turn->north, hull_turn.north);
    turn->east = std::max(turn->east, hull_turn.east);
    // Boxes that do not meet say the data break the model, unless that turn mends
    // it (frame_margins.h): then the caller gets both.
    if (meet) return both;
    turn->apart_hull = hull;
  }
  return d;
}

Vec3I SensorBoxes::intersect_speed(const Vec3I& trapezoid, std::size_t k, StepTurn* turn) const {
  StepTurn speed_turn;
  const Vec3I speed = speed_increment(k, &speed_turn);
  Vec3I both;
  for (int i = 0; i < 3; ++i) {
    both[i] = intersect(trapezoid[i], speed[i]);
    // Boxes that do not meet: the trapezoid alone, which holds the step (a later turn
    // widens it; the speed box, true in every frame, would not need it).
    if (both[i].is_empty()) return trapezoid;
  }
  if (turn) {
    turn->north = std::max(turn->north, speed_turn.north);
    turn->east = std::max(turn->east, speed_turn.east);
  }
  return both;
}

void SensorBoxes::offsets_between(std::size_t k, const Interval& alpha, const Interval& beta, Vec3I& forward,
                                  Vec3I& backward) const {
  const SampleBoxes a = sample(k), b = sample(k + 1);
  // Over the whole step: the rate-bounded boxes, or where the rates may not hold, the
  // regime's speed bound.
  const Vec3I v = rates_hold(k) ? body_to_world(step_attitude(a, b, k), step_velocity(a, b, k)) : speed_box(k);
  for (int i = 0; i < 3; ++i) {
    forward[i] = alpha * v[i];
    backward[i] = beta * v[i];
  }
  if (regimes_->fallback(k) || (!rates_hold(k) && model_.step_model != StepModel::trapezoid)) return;
  if (model_.step_model == StepModel::rate_hull) return;
  if (model_.step_model == StepModel::sample) {
    for (int i = 0; i < 3; ++i) {
      forward[i] = alpha * a.world_velocity[i];
      backward[i] = beta * a.world_velocity[i];
    }
    return;
  }
  // The integral of the interpolation between the samples plus its error (step_model.h):
  // p(t) - p(k) lies in a (1 - a / (2 dt)) w_k + a^2 / (2 dt) w_k+1 ± J (dt a^2 / 4 - a^3 / 6),
  // and p(k+1) - p(t) in the same with beta and the samples swapped.
  const Interval dt = step_duration(k), two_dt = Interval(2.0) * dt;
  const double jerk = regimes_->jerk(model_, k);
  const auto partial = [&](const Interval& x, const Vec3I& near, const Vec3I& far, const Vec3I& rate_bound, Vec3I& out) {
    const Interval near_weight = x * (Interval(1.0) - x / two_dt);
    const Interval far_weight = sqr(x) / two_dt;
    const Interval error = interpolation_error_integral(dt, x, jerk);
    const Interval spread = Interval(-1.0, 1.0) * Interval(0.0, error.hi());
    for (int i = 0; i < 3; ++i) out[i] = intersect(near_weight * near[i] + far_weight * far[i] + spread, rate_bound[i]);
  };
  partial(alpha, a.world_velocity, b.world_velocity, forward, forward);
  partial(beta, b.world_velocity, a.world_velocity, backward, backward);
}

Attitude<Interval> SensorBoxes::attitude_between(std::size_t k) const {
  if (!rates_hold(k)) return any_attitude();
  if (model_.step_model == StepModel::sample) return make_attitude(roll(k), pitch(k), heading(k));
  return step_attitude(k);
}

Interval SensorBoxes::altitude_between(std::size_t k) const {
  if (model_.step_model == StepModel::sample) return altitude(k);
  return step_altitude(k);
}

Attitude<Interval> SensorBoxes::step_attitude(std::size_t k) const { return step_attitude(sample(k), sample(k + 1), k); }

Vec3I SensorBoxes::step_velocity(std::size_t k) const { return step_velocity(sample(k), sample(k + 1), k); }

Interval SensorBoxes::step_altitude(std::size_t k) const {
  // a = floor depth - p_z changes at most at |v| (1 + slope), with the floor slope
  // bounded by mine_depth_band / sonar_max_range (the model's flat-floor budget).
  double speed = regimes_->speed(model_, k);  // where the rates may not hold
  if (rates_hold(k)) {
    const Vec3I v = step_velocity(k);
    speed = add_up(add_up(v[0].mag(), v[1].mag()), v[2].mag());
  }
  const double slope = div_up(model_.mine_depth_band, model_.sonar_max_range);
  return widen_over_step(altitude(k), altitude(k + 1), mul_up(speed, add_up(1.0, slope)), k);
}

Vec3I SensorBoxes::step_world_velocity(std::size_t k) const {
  return body_to_world(step_attitude(k), step_velocity(k));
}

Vec3I SensorBoxes::step_increment(std::size_t k) const { return step_increment(sample(k), sample(k + 1), k); }

}  // namespace gesmi
