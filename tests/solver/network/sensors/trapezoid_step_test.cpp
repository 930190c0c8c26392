// The trapezoid step model (SensorModel::step_model, docs/model.md): the displacement
// over a step, and to any time between two samples, encloses the exact integral of
// R v whenever the boxes hold at the sample instants and |d²(R v)/dt²| <= max_jerk;
// the paper's convention (the box of sample k over the whole step) does not.
//
// Truths of bounded jerk built here, with their integrals in closed form (long
// double); the simulator's at-samples missions (readings at the ends of their bounds,
// against the motion of the coming step) for the whole chain.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/network/sensors/sensor_boxes.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"
#include "tests/support/smooth_truth.h"
#include "tests/support/truth_checks.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::SmoothTruth;
using test::mission_of;
using test::model_with;
using test::truths;

using test::holds;

struct Misses {
  int steps = 0, between = 0, checks = 0;
};

Misses check(const SmoothTruth& truth, const Mission& m) {
  const SensorBoxes boxes(m, m.model);
  Misses misses;
  for (std::size_t k = 0; k + 1 < m.size(); ++k) {
    const long double t0 = m.time[k], t1 = m.time[k + 1];
    const Vec3I d = boxes.step_increment(k);
    const auto exact = truth.displacement(t0, t1);
    for (int i = 0; i < 3; ++i) misses.steps += !holds(d[i], exact[static_cast<std::size_t>(i)]);
    for (const double f : {0.1, 0.5, 0.9}) {
      const double t = m.time[k] + f * (m.time[k + 1] - m.time[k]);
      Vec3I forward, backward;
      boxes.offsets_between(k, Interval(t) - Interval(m.time[k]), Interval(m.time[k + 1]) - Interval(t), forward, backward);
      const auto before = truth.displacement(t0, t), after = truth.displacement(t, t1);
      for (int i = 0; i < 3; ++i) {
        misses.between += !holds(forward[i], before[static_cast<std::size_t>(i)]);
        misses.between += !holds(backward[i], after[static_cast<std::size_t>(i)]);
      }
    }
    ++misses.checks;
  }
  return misses;
}

TEST(TrapezoidStep, EnclosesTheDisplacementOfEveryTruthOfBoundedJerk) {
  std::uint64_t seed = 11;
  for (const SmoothTruth& truth : truths()) {
    ASSERT_LE(truth.jerk_bound(), 1.0L);
    const Mission m = mission_of(truth, model_with(StepModel::trapezoid, 1.0), 800, seed++);
    const Misses misses = check(truth, m);
    EXPECT_EQ(misses.steps, 0) << "of " << misses.checks << " steps, heading " << static_cast<double>(truth.heading);
    EXPECT_EQ(misses.between, 0) << "positions between samples";
  }
}

TEST(TrapezoidStep, TheTestCatchesARemainderTooSmall) {
  // Negative control: the same truths with J declared at a third of their jerk.
  int misses = 0;
  std::uint64_t seed = 11;
  for (const SmoothTruth& truth : truths()) misses += check(truth, mission_of(truth, model_with(StepModel::trapezoid, 0.3), 800, seed++)).steps;
  EXPECT_GT(misses, 0);
}

TEST(TrapezoidStep, ThePapersConventionLosesTruthsWhoseBoxesHoldOnlyAtTheSamples) {
  // Expected to fail: the box of sample k does not hold over the step, so dt [R v]_k
  // misses the displacement. This is why the default is not the paper's convention.
  int misses = 0;
  std::uint64_t seed = 11;
  for (const SmoothTruth& truth : truths()) misses += check(truth, mission_of(truth, model_with(StepModel::sample, 1.0), 800, seed++)).steps;
  EXPECT_GT(misses, 100);
}

TEST(TrapezoidStep, NeverWiderThanTheRateHull) {
  // Two regimes: J dt <= 6 max_acceleration, where the trapezoid lies inside the hull
  // without computing it (up to rounding: 1e-12 m); and a hull so tight (J dt > 6
  // max_acceleration) that the intersection is computed and must hold exactly.
  std::uint64_t seed = 21;
  for (const double acceleration : {0.2, 0.005}) {
    for (const SmoothTruth& truth : truths()) {
      Mission m = mission_of(truth, model_with(StepModel::trapezoid, 1.0), 400, seed++);
      m.model.max_acceleration = acceleration;
      m.model.max_attitude_rate = 0.05;
      const SensorBoxes trapezoid(m, m.model);
      SensorModel hull_model = m.model;
      hull_model.step_model = StepModel::rate_hull;
      const SensorBoxes hull(m, hull_model);
      const double slack = acceleration == 0.2 ? 1e-12 : 0.0;
      for (std::size_t k = 0; k + 1 < m.size(); ++k) {
        const Vec3I a = trapezoid.step_increment(k), b = hull.step_increment(k);
        for (int i = 0; i < 3; ++i)
          ASSERT_TRUE(b[i].lo() - slack <= a[i].lo() && a[i].hi() <= b[i].hi() + slack)
              << "step " << k << " axis " << i << ": [" << a[i].lo() << ", " << a[i].hi() << "] against [" << b[i].lo() << ", "
              << b[i].hi() << "]";
      }
    }
  }
}

// The simulator's missions: truth integrated on sub-steps, rates constant over each
// step (so the jerk inside a step is that of the rotation, about 0.01 m/s³).
std::size_t steps_outside(const Mission& m) {
  const TubeDomains d = sensor_domains(m, m.model);
  const std::vector<double>* truth[3] = {&m.truth_x, &m.truth_y, &m.truth_z};
  const std::vector<Interval>* increments[3] = {&d.dx, &d.dy, &d.dz};
  std::size_t outside = 0;
  for (std::size_t k = 0; k + 1 < m.size(); ++k)
    for (int i = 0; i < 3; ++i) outside += !(*increments[i])[k].contains((*truth[i])[k + 1] - (*truth[i])[k]);
  return outside;
}

TEST(TrapezoidStep, SimulatedMissionsStepInsideAndThePapersConventionDoesNot) {
  std::size_t paper_outside = 0;
  for (const SimulatedErrors errors : {SimulatedErrors::uniform, SimulatedErrors::at_samples}) {
    for (const std::uint64_t seed : {61u, 62u, 63u}) {
      SCOPED_TRACE(::testing::Message() << simulated_errors_name(errors) << ", seed " << seed);
      SimulationOptions o;
      o.seed = seed;
      o.duration = 900.0;
      o.errors = errors;
      Mission m = simulate_mission(o);
      for (const StepModel step : {StepModel::trapezoid, StepModel::rate_hull}) {
        m.model.step_model = step;
        EXPECT_EQ(steps_outside(m), 0u);
      }
      m.model.step_model = StepModel::sample;
      if (errors == SimulatedErrors::at_samples) paper_outside += steps_outside(m);
    }
  }
  EXPECT_GT(paper_outside, 1000u) << "the at-samples errors were meant to defeat the paper's convention";
}

TEST(TrapezoidStep, WholeMissionsWithBoxesAtTheSamplesOnlyKeepTheTruth) {
  for (const std::uint64_t seed : {71u, 72u}) {
    SimulationOptions o;
    o.seed = seed;
    o.errors = SimulatedErrors::at_samples;
    const Mission m = simulate_mission(o);
    const MissionSolution s = solve_mission(m);
    ASSERT_TRUE(s.report.consistent) << s.report.message;
    EXPECT_TRUE(test::truth_inside(m, s.domains));
  }
}

}  // namespace
}  // namespace gesmi
