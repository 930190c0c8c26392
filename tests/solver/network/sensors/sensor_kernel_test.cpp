// The blocked upward-rounding sensor kernel (solver/network/sensors/sensor_kernel.h):
//  - its world velocity boxes hold R v for every attitude and velocity in the sample's
//    boxes, checked at the 64 corners and at random points with the textbook rotation
//    matrix in long double (tests/support/rotation_long_double.h), independent of the
//    kernel and of euler.h;
//  - its step increments equal SensorBoxes' (the scalar path, tested against closed-form
//    truths in trapezoid_step_test and heading_frame_test) to within rounding: every
//    bound within 1e-13 m + 1e-12 relative, which a dropped second-order term breaks;
//  - frameless_sensor_priors, which takes the kernel for most steps and SensorBoxes for
//    the rest (wide angle boxes, the rate hull's steps), equals the scalar build alike;
//  - the rounding mode is restored.

#include <gtest/gtest.h>

#include <bit>
#include <cfenv>
#include <cstdint>
#include <cmath>
#include <random>

#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_priors.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/network/sensors/sensor_kernel.h"
#include "solver/sim/simulator.h"
#include "tests/support/rotation_long_double.h"

namespace gesmi {
namespace {

Mission simulated(std::uint64_t seed, StepModel step) {
  SimulationOptions o;
  o.seed = seed;
  o.duration = 900.0;
  Mission m = simulate_mission(o);
  m.model.step_model = step;
  m.depth_scale_margin = 1e-3;  // far above io/'s (5e-6 for a floor 30 m deep): its term shows
  return m;
}

// Per-sample half-widths on every angle and DVL axis, a few of them beyond the
// narrow-angle form (0.05 rad), which the kernel leaves to SensorBoxes.
void give_half_widths(Mission& m, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> angle(1e-5, 0.03), speed(1e-4, 0.05);
  auto& h = m.half_widths;
  for (auto* v : {&h.roll, &h.pitch, &h.heading}) {
    v->resize(m.size());
    for (double& x : *v) x = angle(random);
  }
  for (auto* v : {&h.vx, &h.vy, &h.vz}) {
    v->resize(m.size());
    for (double& x : *v) x = speed(random);
  }
  for (std::size_t k = 5; k < m.size(); k += 997) h.heading[k] = 0.2;
  h.depth.assign(m.size(), 0.5);
  h.altitude.assign(m.size(), 0.1);
}

// Bounds within rounding of each other: 1e-13 m plus 1e-12 of the magnitude.
bool within_rounding(double a, double b) { return std::fabs(a - b) <= 1e-13 + 1e-12 * std::fabs(b); }

bool same_to_rounding(const Interval& a, const Interval& b) {
  return within_rounding(a.lo(), b.lo()) && within_rounding(a.hi(), b.hi());
}

struct Comparison {
  int differing = 0, turns_differing = 0;
};

// The priors' increments against a scalar loop over SensorBoxes (no frame margin).
Comparison compare_with_scalar(const Mission& m) {
  const SensorPriors priors = frameless_sensor_priors(m, m.model, StepRegimes{});
  const SensorBoxes boxes(m, m.model, FrameMargins{});
  Comparison c;
  for (std::size_t k = 0; k + 1 < m.size(); ++k) {
    SensorBoxes::StepTurn turn;
    const Vec3I inc = boxes.step_increment(boxes.sample(k), boxes.sample(k + 1), k, &turn);
    c.differing += !same_to_rounding(priors.dx[k], inc[0]) + !same_to_rounding(priors.dy[k], inc[1]) +
                   !same_to_rounding(priors.dz[k], inc[2]);
    // The float sensitivities: at most one float step apart, and never below the scalar.
    const auto near_float = [](float kernel, double scalar) {
      return kernel >= scalar && kernel <= std::nextafter(static_cast<float>(scalar), 1e30f) * (1.0f + 1e-6f);
    };
    c.turns_differing += !near_float(priors.turn_north[k], turn.north) + !near_float(priors.turn_east[k], turn.east);
  }
  return c;
}

TEST(SensorKernel, IncrementsEqualTheScalarPathToWithinRounding) {
  for (const StepModel step : {StepModel::trapezoid, StepModel::sample})
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      const Comparison c = compare_with_scalar(simulated(seed, step));
      EXPECT_EQ(c.differing, 0) << "seed " << seed << " step model " << static_cast<int>(step);
      EXPECT_EQ(c.turns_differing, 0) << "seed " << seed;
    }
}

TEST(SensorKernel, PerSampleHalfWidthsAndWideAnglesEqualTheScalarPath) {
  Mission m = simulated(4, StepModel::trapezoid);
  give_half_widths(m, 4);
  const Comparison c = compare_with_scalar(m);
  EXPECT_EQ(c.differing, 0);
  EXPECT_EQ(c.turns_differing, 0);
  // The wide heading boxes were left to SensorBoxes.
  WorldVelocityBoxes w;
  world_velocity_boxes(m, m.model, 0, m.size(), w);
  EXPECT_EQ(w.skipped.size(), (m.size() - 5 + 996) / 997);
}

TEST(SensorKernel, RateHullStepsAreLeftToTheScalarPath) {
  // max_jerk dt > 6 max_acceleration: the trapezoid is intersected with the rate hull,
  // which only SensorBoxes computes (with the hulls of steps where the two do not meet).
  Mission m = simulated(5, StepModel::trapezoid);
  m.model.max_jerk = 30.0;
  const Comparison c = compare_with_scalar(m);
  EXPECT_EQ(c.differing, 0);
  EXPECT_EQ(c.turns_differing, 0);
  std::vector<Interval> dx(10), dy(10), dz(10);
  std::vector<float> north(10), east(10);
  const std::vector<std::size_t> left =
      kernel_step_increments(m, m.model, 0, 10, StepIncrementArrays{dx.data(), dy.data(), dz.data(), north.data(), east.data()}, StepRegimes{});
  EXPECT_EQ(left.size(), 10u) << "every step of 0.1 s has J dt = 3 > 6 x 0.2";
}

TEST(SensorKernel, WorldVelocityBoxesHoldRotatedVelocitiesOfTheBoxes) {
  Mission m = simulated(6, StepModel::trapezoid);
  give_half_widths(m, 6);
  WorldVelocityBoxes w;
  world_velocity_boxes(m, m.model, 0, m.size(), w);
  std::mt19937_64 random(66);
  std::uniform_real_distribution<long double> unit(-1.0L, 1.0L);
  int outside = 0, checked = 0;
  std::size_t next_skipped = 0;
  for (std::size_t k = 0; k < m.size(); k += 3) {
    while (next_skipped < w.skipped.size() && w.skipped[next_skipped] < k) ++next_skipped;
    if (next_skipped < w.skipped.size() && w.skipped[next_skipped] == k) continue;
    const auto& h = m.half_widths;
    const long double angle[3] = {m.roll[k], m.pitch[k], m.heading[k]};
    const long double angle_width[3] = {h.roll[k], h.pitch[k], h.heading[k]};
    const long double velocity[3] = {m.vx[k], m.vy[k], m.vz[k]};
    // The frame's scale: its margin times the box's largest |vx| + |vy| + |vz| on each axis.
    const long double frame = m.depth_scale_margin * (std::fabs(velocity[0]) + h.vx[k] + std::fabs(velocity[1]) + h.vy[k] +
                                                       std::fabs(velocity[2]) + h.vz[k]);
    const long double velocity_width[3] = {h.vx[k] + frame, h.vy[k] + frame, h.vz[k] + frame};
    // The 64 corners of the sample's box, then 32 random points inside it.
    for (int point = 0; point < 96; ++point) {
      long double a[3], v[3];
      for (int i = 0; i < 3; ++i) {
        const long double sa = point < 64 ? ((point >> i) & 1 ? 1.0L : -1.0L) : unit(random);
        const long double sv = point < 64 ? ((point >> (i + 3)) & 1 ? 1.0L : -1.0L) : unit(random);
        a[i] = angle[i] + sa * angle_width[i];
        v[i] = velocity[i] + sv * velocity_width[i];
      }
      long double world[3];
      test::RotationLd(a[0], a[1], a[2]).to_world(v, world);
      for (int i = 0; i < 3; ++i) {
        ++checked;
        outside += !(-static_cast<long double>(w.neg_lo[i][k]) <= world[i] && world[i] <= w.hi[i][k]);
      }
    }
  }
  EXPECT_GT(checked, 100000);
  EXPECT_EQ(outside, 0);
}

TEST(SensorKernel, RestoresTheRoundingMode) {
  const Mission m = simulated(7, StepModel::trapezoid);
  WorldVelocityBoxes w;
  world_velocity_boxes(m, m.model, 0, 100, w);
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
  frameless_sensor_priors(m, m.model, StepRegimes{});
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// The depth boxes in the upward rounding mode against SensorBoxes::depth (software
// rounding, rounding.h: each bound the correctly rounded one), bit for bit, signs of
// zero included: readings over every magnitude and sign, subnormal and zero, bounds the
// reading cancels exactly, models with a zero term, and per-sample half-widths.
TEST(SensorKernel, DepthBoxesAreSensorBoxesBitForBit) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-1074.0, 1000.0);
  const auto any_double = [&] { return unit(random) * std::exp2(std::floor(exponent(random))); };
  std::vector<double> readings = {0.0, -0.0, 1.5, -1.5, 3.0, 0x1p-1074, -0x1p-1074, 0x1p-1022, 1e300, -1e300};
  for (int i = 0; i < 20000; ++i) readings.push_back(i % 2 ? any_double() : 200.0 * unit(random));
  struct ModelCase {
    double absolute, relative;
  };
  for (const ModelCase c : {ModelCase{1.5, 0.2}, ModelCase{1.5, 0.0}, ModelCase{0.0, 0.2}, ModelCase{0.0, 0.0},
                            ModelCase{0.1, 0x1p-60}, ModelCase{1e-310, 1e-3}}) {
    for (const bool own : {false, true}) {
      SCOPED_TRACE(::testing::Message() << c.absolute << " " << c.relative << (own ? " own half-widths" : ""));
      Mission m;
      m.depth = readings;
      m.time.resize(m.depth.size());
      if (own) {
        m.half_widths.depth.resize(m.depth.size());
        for (std::size_t k = 0; k < m.depth.size(); ++k)  // a third of them the reading's magnitude: exact zeros
          m.half_widths.depth[k] = k % 3 == 0 ? std::fabs(m.depth[k]) : std::fabs(any_double());
      }
      SensorModel model;
      model.depth_absolute = c.absolute;
      model.depth_relative = c.relative;
      std::vector<Interval> kernel(m.size());
      depth_boxes(m, model, kernel.data());
      EXPECT_EQ(std::fegetround(), FE_TONEAREST);
      const SensorBoxes boxes(m, model);
      std::size_t differ = 0;
      for (std::size_t k = 0; k < m.size(); ++k) {
        const Interval scalar = boxes.depth(k);
        if (!same_bits(kernel[k].lo(), scalar.lo()) || !same_bits(kernel[k].hi(), scalar.hi())) {
          if (differ++ < 3)
            ADD_FAILURE() << "sample " << k << ": depth " << m.depth[k] << ": kernel [" << kernel[k].lo() << ", "
                          << kernel[k].hi() << "], SensorBoxes [" << scalar.lo() << ", " << scalar.hi() << "]";
        }
      }
      EXPECT_EQ(differ, 0u);
    }
  }
}

}  // namespace
}  // namespace gesmi
