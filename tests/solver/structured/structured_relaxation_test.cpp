// The bias-and-noise relaxation (solver/structured/): its small-angle rests against long
// double, and its per-sample bounds on simulated bias-noise missions (solver/sim/
// reading_errors.h), whose errors the simulator draws without the relaxation's algebra:
// the truth inside every sample's bounds at bias shares 0, 0.5, 0.9 and 1, and the bounds
// narrower than the per-sample solve's tube where the share is large.

#include "solver/structured/structured_relaxation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "solver/network/sensors/step_regimes.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"
#include "solver/structured/affine_track.h"

namespace gesmi {
namespace {

TEST(SmallAngleRests, EncloseCosAndSinRemaindersEverywhereWithinTheBound) {
  std::mt19937_64 random(11);
  for (const double bound : {1e-6, 1e-4, 5.27e-3, 0.1, 1.0}) {
    const SmallAngleRests r = small_angle_rests(bound);
    std::uniform_real_distribution<long double> angle(-bound, bound);
    for (int i = 0; i < 20000; ++i) {
      const long double b = i == 0 ? bound : i == 1 ? -bound : angle(random);
      const long double c = cosl(b) - 1.0L, s = sinl(b) - b;
      ASSERT_LE(static_cast<long double>(r.cos_minus_one.lo()), c) << bound << " " << static_cast<double>(b);
      ASSERT_GE(static_cast<long double>(r.cos_minus_one.hi()), c) << bound;
      ASSERT_LE(static_cast<long double>(r.sin_minus_angle.lo()), s) << bound << " " << static_cast<double>(b);
      ASSERT_GE(static_cast<long double>(r.sin_minus_angle.hi()), s) << bound << " " << static_cast<double>(b);
    }
    // Tight: at the bound, within the series' next term (b^4/24, b^5/120) and rounding.
    const long double b = bound, b2 = b * b;
    // (cosl near 1 is exact to about 1e-19 only: long double's epsilon.)
    EXPECT_NEAR(r.cos_minus_one.lo(), cosl(b) - 1.0L, b2 * b2 / 12.0L + 1e-15L * b2 + 4e-19L);
    EXPECT_NEAR(r.sin_minus_angle.lo(), sinl(b) - b, b2 * b2 * b / 60.0L + 1e-15L * b2 * b + 4e-19L * b);
  }
}

TEST(BiasShareSplit, BiasAndNoiseCoverEachBound) {
  const SensorModel model;
  for (const double share : {0.0, 0.3, 0.9, 1.0}) {
    const StructuredErrors e = split_by_bias_share(model, share);
    EXPECT_GE(e.bias_bound[kHeadingBias] + e.noise.heading, model.heading);
    EXPECT_GE(e.bias_bound[kScaleBias] + e.noise.dvl_relative, model.dvl_relative);
    EXPECT_GE(e.bias_bound[kOffsetBias + 2] + e.noise.dvl_absolute, model.dvl_absolute);
    EXPECT_LE(e.noise.heading, (1.0 - share) * model.heading * (1.0 + 1e-12));
  }
  EXPECT_THROW(split_by_bias_share(model, 1.5), std::invalid_argument);
}

Mission bias_noise_mission(std::uint64_t seed, double share) {
  SimulationOptions o;
  o.seed = seed;
  o.errors = SimulatedErrors::bias_noise;
  o.bias_share = share;
  o.duration = 1800.0;
  return simulate_mission(o);
}

double widest(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  double w = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) w = std::max({w, a[k].width(), b[k].width()});
  return w;
}

TEST(StructuredRelaxation, KeepsTheTruthAndNarrowsTheTubeAsTheBiasShareGrows) {
  for (const double share : {0.0, 0.5, 0.9, 1.0}) {
    for (const std::uint64_t seed : {1u, 2u}) {
      SCOPED_TRACE("share " + std::to_string(share) + ", seed " + std::to_string(seed));
      const Mission m = bias_noise_mission(seed, share);
      const MissionSolution tube = solve_mission(m);
      const StepRegimes regimes = classify_steps(m, m.model);
      const StructuredBounds b = relax_structured(m, regimes, split_by_bias_share(m.model, share), tube.domains);
      ASSERT_TRUE(b.consistent);
      for (std::size_t k = 0; k < m.size(); ++k) {
        ASSERT_TRUE(b.north[k].contains(m.truth_x[k])) << k << " " << b.north[k].lo() << " " << m.truth_x[k];
        ASSERT_TRUE(b.east[k].contains(m.truth_y[k])) << k;
        ASSERT_TRUE(tube.domains.px[k].is_superset(b.north[k])) << k;
      }
      double mine_before = 0.0, mine_after = 0.0;
      for (std::size_t i = 0; i < b.mines.size(); ++i)
        for (std::size_t axis = 0; axis < 2; ++axis) {
          const Interval& solved = tube.domains.mines[i][static_cast<int>(axis)];
          ASSERT_TRUE(b.mines[i][axis].contains(m.truth_mines[3 * i + axis])) << "mine " << i << " axis " << axis;
          ASSERT_TRUE(solved.is_superset(b.mines[i][axis]));
          if (!solved.is_bounded()) continue;  // (a mine no mark saw)
          mine_before = std::max(mine_before, solved.width());
          mine_after = std::max(mine_after, b.mines[i][axis].width());
        }
      const double before = widest(tube.domains.px, tube.domains.py), after = widest(b.north, b.east);
      std::printf("share %.1f seed %d: %zu fixes, %zu marks; widest box %.2f -> %.2f m, mine %.2f -> %.2f m; %zu LPs\n",
                  share, static_cast<int>(seed), m.gps_time.size(), m.mark_count(), before, after, mine_before,
                  mine_after, b.linear_programs);
      if (share >= 0.9) {
        EXPECT_LT(after, 0.8 * before);
      }
    }
  }
}

TEST(StructuredRelaxation, RefusesReadingsWithTheirOwnHalfWidths) {
  Mission m = bias_noise_mission(3, 0.5);
  m.half_widths.roll.assign(m.size(), 1e-3);
  EXPECT_FALSE(structured_relaxation_refusal(m).empty());
  const StepRegimes regimes;
  TubeDomains wide;
  wide.px = wide.py = wide.pz = std::vector<Interval>(m.size(), Interval(-1e6, 1e6));
  wide.mines.assign(static_cast<std::size_t>(m.mine_count),
                    Vec3I(Interval(-1e6, 1e6), Interval(-1e6, 1e6), Interval(0, 1e3)));
  EXPECT_THROW(relax_structured(m, regimes, split_by_bias_share(m.model, 0.5), wide), std::invalid_argument);
}

}  // namespace
}  // namespace gesmi
