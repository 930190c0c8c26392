// Soundness of the per-sample and per-step sensor boxes (solver/network/
// sensor_boxes.h) against adversarial true signals built independently
// (tests/support/bounded_rate_mission.h): piecewise-linear attitudes, speeds and
// altitude whose rates reach the model's bounds, sitting at the ends of the
// sample boxes and making the largest excursion the rates allow between samples;
// headings that wrap at +-pi; irregular steps from 13 ms to 3 s. Claims checked:
//  - the sample boxes hold the truth at the samples;
//  - the step boxes (attitude as sines and cosines, body velocity, altitude, world
//    velocity R v) hold the truth at every instant of the step (41 instants plus
//    every knot of the signals, where the excursions peak);
//  - step_increment holds the true displacement, the integral of R v over the
//    step, computed in long double with a rigorous error bound.
// Removing the between-sample widening (rate * dt / 2) fails every claim but the
// first; the test also checks that the adversary reaches the widened bounds.

#include "solver/network/sensors/sensor_boxes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "tests/support/bounded_rate_mission.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::BoundedRateMission;
using test::BoundedRateOptions;
using test::kDisplacementError;

using test::holds;
bool holds_with_margin(const Interval& box, long double v, long double error) {
  return box.lo() <= v - error && v + error <= box.hi();
}

std::string describe(const char* what, std::size_t k, long double t, const Interval& box, long double v) {
  char b[256];
  std::snprintf(b, sizeof b, "%s at step %zu, t = %.6Lf: [%.17g, %.17g] misses %.17Lg", what, k, t, box.lo(), box.hi(),
                v);
  return b;
}

struct Failures {
  int count = 0;
  std::string first;
  void add(const std::string& what) {
    if (count++ == 0) first = what;
  }
};

// The missions of the test: headings held near 0, near pi/2, drifting across
// +-pi from both sides, and a model with faster rates (wider excursions, which
// take the attitude boxes past the Taylor form's 0.05 rad into the general sin/cos).
// The truths have kinks inside steps (tents at the largest rate), so their jerk is
// unbounded: they test the rate-hull step model, whose only assumption is the rates
// (trapezoid_step_test.cpp tests the trapezoid with truths of bounded jerk).
std::vector<BoundedRateMission> missions() {
  std::vector<BoundedRateMission> all;
  std::uint64_t seed = 0x5e45;
  for (const double heading : {0.0, std::numbers::pi / 2, std::numbers::pi - 0.02, -std::numbers::pi + 0.01, -1.0}) {
    BoundedRateOptions options;
    options.model.step_model = StepModel::rate_hull;
    options.initial_heading = heading;
    all.push_back(test::make_bounded_rate_mission(seed++, options));
  }
  BoundedRateOptions fast;
  fast.model.step_model = StepModel::rate_hull;
  fast.model.max_attitude_rate = 0.5;
  fast.model.max_acceleration = 1.0;
  fast.initial_heading = std::numbers::pi - 0.05;
  all.push_back(test::make_bounded_rate_mission(seed++, fast));
  // A steep floor (slope 0.1) under a robot that hardly moves sideways: the
  // altitude's rate bound |v| (1 + slope) is then what the adversary reaches.
  BoundedRateOptions steep;
  steep.model.step_model = StepModel::rate_hull;
  steep.model.mine_depth_band = 7.5;
  steep.lateral_speed = 0.01;
  all.push_back(test::make_bounded_rate_mission(seed++, steep));
  return all;
}

const std::vector<BoundedRateMission>& cached_missions() {
  static const std::vector<BoundedRateMission> all = missions();
  return all;
}

// Instants of step k where the truth is checked: 41 evenly spaced and every knot.
std::vector<long double> instants(const test::TrueMotion& truth, long double t0, long double t1) {
  std::vector<long double> ts;
  for (int i = 0; i <= 40; ++i) ts.push_back(t0 + (t1 - t0) * i / 40.0L);
  for (const long double knot : truth.knots)
    if (knot > t0 && knot < t1) ts.push_back(knot);
  return ts;
}

TEST(SensorBoxesSoundness, SampleBoxesHoldTheTruthAtTheSamples) {
  Failures f;
  for (const BoundedRateMission& b : cached_missions()) {
    const Mission& m = b.mission;
    const SensorBoxes boxes(m, m.model);
    for (std::size_t k = 0; k < m.size(); ++k) {
      const long double t = m.time[k];
      const SensorBoxes::SampleBoxes s = boxes.sample(k);
      const long double heading = b.truth.heading.at(t);
      // The heading box is around the wrapped reading: compare the truth's
      // representative nearest to it.
      const long double h = heading - 2.0L * std::numbers::pi_v<long double> *
                                          std::round((heading - m.heading[k]) / (2.0L * std::numbers::pi_v<long double>));
      if (!holds(s.roll, b.truth.roll.at(t))) f.add(describe("roll", k, t, s.roll, b.truth.roll.at(t)));
      if (!holds(s.pitch, b.truth.pitch.at(t))) f.add(describe("pitch", k, t, s.pitch, b.truth.pitch.at(t)));
      if (!holds(s.heading, h)) f.add(describe("heading", k, t, s.heading, h));
      const long double v[3] = {b.truth.vx.at(t), b.truth.vy.at(t), b.truth.vz.at(t)};
      for (int i = 0; i < 3; ++i)
        if (!holds(s.velocity[i], v[i])) f.add(describe("velocity", k, t, s.velocity[i], v[i]));
      if (!holds(boxes.altitude(k), b.truth.altitude.at(t)))
        f.add(describe("altitude", k, t, boxes.altitude(k), b.truth.altitude.at(t)));
    }
  }
  EXPECT_EQ(f.count, 0) << f.first;
}

TEST(SensorBoxesSoundness, StepBoxesHoldTheTruthOverTheWholeStep) {
  const auto start = std::chrono::steady_clock::now();
  Failures f;
  std::size_t checks = 0, steps = 0;
  double closest_velocity = 1.0;  // smallest gap between a true speed and its step box, relative to the widening
  for (const BoundedRateMission& b : cached_missions()) {
    const Mission& m = b.mission;
    const SensorBoxes boxes(m, m.model);
    for (std::size_t k = 0; k + 1 < m.size(); ++k, ++steps) {
      const Attitude<Interval> att = boxes.step_attitude(k);
      const Vec3I v = boxes.step_velocity(k);
      const Vec3I w = boxes.step_world_velocity(k);
      const Interval altitude = boxes.step_altitude(k);
      const long double widening = m.model.max_acceleration * (m.time[k + 1] - m.time[k]) / 2.0L;
      // Tightness of the heading: the boxes at both ends are taken on the same
      // turn (headings wrap at +-pi), so the angle box is at most w = 4 b + 2 rate dt
      // wide (two readings ~2 b + rate dt apart, +-b, widened by rate dt / 2 twice),
      // and its sine and cosine spread over at most w + w^2 / 4 (Lipschitz 1, plus
      // the Taylor remainder), not over the whole circle.
      const double angle_width = 4.0 * m.model.heading + 2.0 * m.model.max_attitude_rate * (m.time[k + 1] - m.time[k]);
      const double spread = angle_width + angle_width * angle_width / 4.0 + 1e-9;
      if (!(att.heading.sin.width() <= spread && att.heading.cos.width() <= spread))
        f.add("heading box of step " + std::to_string(k) + " spreads over more than one turn's width");
      for (const long double t : instants(b.truth, m.time[k], m.time[k + 1])) {
        ++checks;
        const std::pair<const SinCos<Interval>*, long double> angles[] = {
            {&att.roll, b.truth.roll.at(t)}, {&att.pitch, b.truth.pitch.at(t)}, {&att.heading, b.truth.heading.at(t)}};
        for (const auto& [sc, angle] : angles) {
          if (!holds(sc->sin, std::sin(angle))) f.add(describe("sin of an angle", k, t, sc->sin, std::sin(angle)));
          if (!holds(sc->cos, std::cos(angle))) f.add(describe("cos of an angle", k, t, sc->cos, std::cos(angle)));
        }
        const long double tv[3] = {b.truth.vx.at(t), b.truth.vy.at(t), b.truth.vz.at(t)};
        long double tw[3];
        b.truth.world_velocity(t, tw);
        for (int i = 0; i < 3; ++i) {
          if (!holds(v[i], tv[i])) f.add(describe("body velocity", k, t, v[i], tv[i]));
          if (!holds(w[i], tw[i])) f.add(describe("world velocity", k, t, w[i], tw[i]));
          const long double gap = std::min(tv[i] - v[i].lo(), v[i].hi() - tv[i]);
          closest_velocity = std::min(closest_velocity, static_cast<double>(gap / widening));
        }
        if (!holds(altitude, b.truth.altitude.at(t))) f.add(describe("altitude", k, t, altitude, b.truth.altitude.at(t)));
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("step boxes: %zu steps, %zu instants, %d failures; closest true speed to its box: %.2g of the widening; "
              "%.2f s\n",
              steps, checks, f.count, closest_velocity, seconds);
  EXPECT_EQ(f.count, 0) << f.first;
  // The adversary really reaches the widened bound (to within 1e-6 of the widening).
  EXPECT_LT(closest_velocity, 1e-6);
}

TEST(SensorBoxesSoundness, StepIncrementHoldsTheTrueDisplacement) {
  Failures f;
  std::size_t steps = 0;
  double tightest = 1.0;  // smallest gap between the true displacement and its box, over the step's dt
  for (const BoundedRateMission& b : cached_missions()) {
    const Mission& m = b.mission;
    const SensorBoxes boxes(m, m.model);
    for (std::size_t k = 0; k + 1 < m.size(); ++k, ++steps) {
      const Vec3I d = boxes.step_increment(k);
      long double truth[3];
      b.truth.displacement(m.time[k], m.time[k + 1], truth);
      for (int i = 0; i < 3; ++i) {
        if (!holds_with_margin(d[i], truth[i], kDisplacementError))
          f.add(describe("increment", k, m.time[k], d[i], truth[i]));
        const long double gap = std::min(truth[i] - d[i].lo(), d[i].hi() - truth[i]);
        tightest = std::min(tightest, static_cast<double>(gap / (m.time[k + 1] - m.time[k])));
      }
    }
  }
  std::printf("step increments: %zu steps, %d failures; tightest gap %.3g m per second of step\n", steps, f.count,
              tightest);
  EXPECT_EQ(f.count, 0) << f.first;
}

}  // namespace
}  // namespace gesmi
