// The simulator's drifting errors (--errors drifting): each sensor's error is
// 0.99 x bound x sin(2 pi t / T + phase), T in [600 s, 2400 s]. Checked on the two
// channels whose truth the mission stores (depth and altitude): always inside the
// bound, sweeping nearly the whole bound over the mission, and changing by no more
// than the fastest period allows per step; marks and fixes inside their bounds; the
// interval solver still encloses the truth (the errors are inside the bounds).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "solver/sim/simulator.h"
#include "solver/sim/survey_plan.h"
#include "solver/solve/solve_mission.h"
#include "tests/support/truth_checks.h"

namespace gesmi {
namespace {

Mission simulate(std::uint64_t seed, double duration) {
  SimulationOptions o;
  o.seed = seed;
  o.errors = SimulatedErrors::drifting;
  o.duration = duration;
  return simulate_mission(o);
}

// Error over its bound at each sample (the bound as the simulator draws it: the
// largest error that keeps the truth inside reading +- the model's bound).
struct Channels {
  std::vector<double> depth, altitude;
};
Channels normalised_errors(const Mission& m) {
  Channels c;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const double z = m.truth_z[k];
    const double depth_bound = (m.model.depth_absolute + m.model.depth_relative * std::fabs(z)) / (1.0 + m.model.depth_relative);
    c.depth.push_back((m.depth[k] - z) / depth_bound);
    const double altitude = sea_floor_depth(m.truth_x[k], m.truth_y[k]) - z;
    c.altitude.push_back((m.altitude[k] - altitude) / m.model.altitude);
  }
  return c;
}

TEST(DriftingErrors, NameRoundTrips) {
  SimulatedErrors e = SimulatedErrors::uniform;
  ASSERT_TRUE(parse_simulated_errors("drifting", e));
  EXPECT_EQ(e, SimulatedErrors::drifting);
  EXPECT_STREQ(simulated_errors_name(SimulatedErrors::drifting), "drifting");
}

TEST(DriftingErrors, StayInsideTheBoundsAndVarySlowly) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    const Mission m = simulate(seed, 5999.4);
    const Channels c = normalised_errors(m);
    // Fastest change of 0.99 sin(2 pi t / T) over a 0.1 s step with T >= 600 s.
    const double max_step = 0.99 * 2.0 * std::numbers::pi * 0.1 / 600.0 + 1e-9;
    for (const std::vector<double>* e : {&c.depth, &c.altitude}) {
      double lo = 1.0, hi = -1.0, largest_step = 0.0;
      for (std::size_t k = 0; k < e->size(); ++k) {
        ASSERT_LE(std::fabs((*e)[k]), 0.99 + 1e-9) << "sample " << k;
        lo = std::min(lo, (*e)[k]);
        hi = std::max(hi, (*e)[k]);
        if (k > 0) largest_step = std::max(largest_step, std::fabs((*e)[k] - (*e)[k - 1]));
      }
      // At least 2.5 periods in 6000 s: both ends of the bound are reached, so the
      // error is not a constant bias.
      EXPECT_GT(hi, 0.97);
      EXPECT_LT(lo, -0.97);
      EXPECT_LE(largest_step, max_step);
      EXPECT_GT(largest_step, 0.2 * max_step);  // it does move
    }
    EXPECT_NE(c.depth[0], c.altitude[0]);  // a phase per sensor
    for (std::size_t j = 0; j < m.mark_count(); ++j) {
      const auto k = static_cast<std::size_t>(std::lround(m.mark_time[j] * 10.0));
      const int i = m.mark_mine[j];
      const double dx = m.truth_x[k] - m.truth_mines[3 * i], dy = m.truth_y[k] - m.truth_mines[3 * i + 1],
                   dz = m.truth_z[k] - m.truth_mines[3 * i + 2];
      EXPECT_LE(std::fabs(std::sqrt(dx * dx + dy * dy + dz * dz) - m.mark_range[j]), m.model.mark_range) << "mark " << j;
    }
    for (std::size_t f = 0; f < m.gps_time.size(); ++f) {
      const auto k = static_cast<std::size_t>(std::lround(m.gps_time[f] * 10.0));
      EXPECT_LE(std::fabs(m.gps_north[f] - m.truth_x[k]), 0.99 * m.model.gps_metres + 1e-9);
      EXPECT_LE(std::fabs(m.gps_east[f] - m.truth_y[k]), 0.99 * m.model.gps_metres + 1e-9);
    }
  }
}

TEST(DriftingErrors, IsDeterministicForASeed) {
  const Mission a = simulate(5, 600.0), b = simulate(5, 600.0), c = simulate(6, 600.0);
  EXPECT_EQ(a.heading, b.heading);
  EXPECT_NE(a.heading, c.heading);
}

TEST(DriftingErrors, TheIntervalSolverStillEnclosesTheTruth) {
  const Mission m = simulate(1, 1800.0);
  ASSERT_GE(m.mark_count(), 1u);
  const MissionSolution s = solve_mission(m);
  ASSERT_TRUE(s.report.consistent) << s.report.message;
  EXPECT_TRUE(test::truth_inside(m, s.domains));
}

}  // namespace
}  // namespace gesmi
