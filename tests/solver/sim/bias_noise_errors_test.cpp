// The simulator's bias-noise errors (--errors bias-noise, solver/sim/reading_errors.h),
// checked on the channels whose truth the mission stores: the barometer (a scale and an
// offset bias) and the altimeter (an offset bias). With the whole bound a bias, the depth
// error is an exact affine function of the depth and the altitude error a constant;
// with a ramp or a flip, they change as the drift says; with noise, they stay inside
// the bound. The interval solver, whose per-sample model does not know of biases, still
// encloses the truth (the errors are inside the bounds).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "solver/sim/simulator.h"
#include "solver/sim/survey_plan.h"
#include "solver/solve/solve_mission.h"
#include "tests/support/truth_checks.h"

namespace gesmi {
namespace {

Mission simulate(std::uint64_t seed, double share, BiasDrift drift, double duration = 1200.0) {
  SimulationOptions o;
  o.seed = seed;
  o.errors = SimulatedErrors::bias_noise;
  o.bias_share = share;
  o.drift = drift;
  o.duration = duration;
  return simulate_mission(o);
}

struct Errors {
  std::vector<double> depth, depth_bound, altitude;
};
Errors errors_of(const Mission& m) {
  Errors e;
  const double r = m.model.depth_relative;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const double z = m.truth_z[k];
    e.depth.push_back(m.depth[k] - z);
    e.depth_bound.push_back((m.model.depth_absolute + r * std::fabs(z)) / (1.0 + r));
    e.altitude.push_back(m.altitude[k] - (sea_floor_depth(m.truth_x[k], m.truth_y[k]) - z));
  }
  return e;
}

TEST(BiasNoiseErrors, NamesRoundTrip) {
  SimulatedErrors e = SimulatedErrors::uniform;
  ASSERT_TRUE(parse_simulated_errors("bias-noise", e));
  EXPECT_EQ(e, SimulatedErrors::bias_noise);
  for (const BiasDrift d : {BiasDrift::none, BiasDrift::ramp, BiasDrift::flip}) {
    BiasDrift parsed = BiasDrift::none;
    ASSERT_TRUE(parse_bias_drift(bias_drift_name(d), parsed));
    EXPECT_EQ(parsed, d);
  }
  EXPECT_EQ(simulated_errors_names(), "uniform, worst-case, at-samples, drifting, corners or bias-noise");
}

TEST(BiasNoiseErrors, AWholeBiasIsAScaleAndAnOffsetOfTheDepthAndAConstantOfTheAltitude) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const Mission m = simulate(seed, 1.0, BiasDrift::none);
    const Errors e = errors_of(m);
    const double r = m.model.depth_relative;
    const double scale = 0.99 * r / (1.0 + r), offset = 0.99 * m.model.depth_absolute / (1.0 + r);
    // The signs, from two samples of different depths: error = s z + o.
    const std::size_t a = 0, b = static_cast<std::size_t>(std::max_element(m.truth_z.begin(), m.truth_z.end()) - m.truth_z.begin());
    const double s = (e.depth[b] - e.depth[a]) / (m.truth_z[b] - m.truth_z[a]), o = e.depth[a] - s * m.truth_z[a];
    EXPECT_NEAR(std::fabs(s), scale, 1e-9);
    EXPECT_NEAR(std::fabs(o), offset, 1e-9);
    for (std::size_t k = 0; k < m.size(); ++k) {
      ASSERT_NEAR(e.depth[k], s * m.truth_z[k] + o, 1e-9) << k;
      ASSERT_NEAR(std::fabs(e.altitude[k]), 0.99 * m.model.altitude, 1e-9) << k;
      ASSERT_EQ(e.altitude[k] > 0.0, e.altitude[0] > 0.0) << k;
    }
  }
}

TEST(BiasNoiseErrors, ARampGoesToItsOppositeAndAFlipTurnsAtTheMiddle) {
  const Mission ramp = simulate(4, 1.0, BiasDrift::ramp), flip = simulate(4, 1.0, BiasDrift::flip);
  const Errors r = errors_of(ramp), f = errors_of(flip);
  const double bound = 0.99 * ramp.model.altitude, duration = 1200.0;
  for (std::size_t k = 0; k < ramp.size(); ++k) {
    const double t = ramp.time[k];
    ASSERT_NEAR(r.altitude[k], r.altitude[0] * (1.0 - 2.0 * t / duration), 1e-9) << k;
    ASSERT_NEAR(f.altitude[k], t < 0.5 * duration ? f.altitude[0] : -f.altitude[0], 1e-9) << k;
  }
  EXPECT_NEAR(std::fabs(r.altitude[0]), bound, 1e-9);
  EXPECT_NEAR(r.altitude.back(), -r.altitude[0], 1e-9 + 2.0 * bound * 0.1 / duration);
}

TEST(BiasNoiseErrors, WithNoiseTheErrorsStayInsideTheBoundsAroundTheirBias) {
  const Mission m = simulate(5, 0.5, BiasDrift::none);
  const Errors e = errors_of(m);
  double mean = 0.0;
  for (std::size_t k = 0; k < m.size(); ++k) {
    ASSERT_LE(std::fabs(e.depth[k]), 0.99 * e.depth_bound[k] + 1e-12) << k;
    ASSERT_LE(std::fabs(e.altitude[k]), 0.99 * m.model.altitude + 1e-12) << k;
    mean += e.altitude[k] / static_cast<double>(m.size());
  }
  // The bias, half the bound, shows through the noise's mean (12,001 samples of a
  // uniform noise of half-width 0.495 m: the mean's deviation is about 0.0026 m).
  EXPECT_NEAR(std::fabs(mean), 0.99 * 0.5 * m.model.altitude, 0.02);
  for (std::size_t k = 0; k < m.size(); ++k) ASSERT_LE(std::fabs(e.altitude[k] - mean), 0.99 * 0.5 * m.model.altitude + 0.02);
}

TEST(BiasNoiseErrors, TheIntervalSolverStillEnclosesTheTruth) {
  struct Case {
    double share;
    BiasDrift drift;
  };
  for (const Case c : {Case{0.0, BiasDrift::none}, Case{0.5, BiasDrift::none}, Case{0.9, BiasDrift::none},
                       Case{1.0, BiasDrift::none}, Case{0.9, BiasDrift::ramp}, Case{0.9, BiasDrift::flip}}) {
    SCOPED_TRACE(::testing::Message() << "share " << c.share << " drift " << bias_drift_name(c.drift));
    const Mission m = simulate(7, c.share, c.drift, 1800.0);
    ASSERT_GE(m.mark_count(), 1u);
    const MissionSolution s = solve_mission(m);
    ASSERT_TRUE(s.report.consistent) << s.report.message;
    EXPECT_TRUE(test::truth_inside(m, s.domains));
  }
}

}  // namespace
}  // namespace gesmi
