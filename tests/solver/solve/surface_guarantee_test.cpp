// The truth is kept, or its loss reported, on missions that begin and end at the
// surface in waves and that hold jerk bursts while submerged, with every reading on the
// corner of its box where the step model is weakest (--errors corners). The waves' and
// bursts' motion is the simulator's closed form (solver/sim/extra_motion.h): it does not
// follow the solver's bounds between samples, which is what is tested.

#include <gtest/gtest.h>

#include <string>

#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace gesmi {
namespace {

struct Case {
  const char* name;
  double wave_height, wave_period;
  bool surface_dvl;
  int bursts;
  double burst_jerk;
};

Mission surface_mission(const Case& c, SimulatedErrors errors) {
  SimulationOptions o;
  o.seed = 3;
  o.duration = 900.0;
  o.surface = 90.0;
  o.errors = errors;
  o.wave_height = c.wave_height;
  o.wave_period = c.wave_period;
  o.surface_dvl = c.surface_dvl;
  o.bursts = c.bursts;
  o.burst_jerk = c.burst_jerk;
  return simulate_mission(o);
}

// Samples whose true position is outside the tube, on some axis.
std::size_t samples_outside(const Mission& m, const MissionSolution& s) {
  std::size_t outside = 0;
  for (std::size_t k = 0; k < m.size(); ++k)
    outside += !(s.domains.px[k].contains(m.truth_x[k]) && s.domains.py[k].contains(m.truth_y[k]) &&
                 s.domains.pz[k].contains(m.truth_z[k]));
  return outside;
}

class SurfaceGuarantee : public testing::TestWithParam<Case> {};

TEST_P(SurfaceGuarantee, TheTruthIsKeptOrItsLossReported) {
  for (const SimulatedErrors errors : {SimulatedErrors::corners, SimulatedErrors::uniform}) {
    const Mission m = surface_mission(GetParam(), errors);
    const MissionSolution s = solve_mission(m);
    const std::string label = std::string(GetParam().name) + ", " + simulated_errors_name(errors);
    ASSERT_GT(s.report.regimes.surface_steps, 0u) << label;
    const std::size_t outside = s.report.consistent ? samples_outside(m, s) : 0;
    if (s.report.regimes.fallback_steps == 0 && s.report.consistent) {
      EXPECT_EQ(outside, 0u) << label << ": the truth lost silently";
    }
    EXPECT_EQ(s.report.regimes.speed_exceeded, 0u) << label;
  }
}

TEST_P(SurfaceGuarantee, TheEndsOfTheMissionAreHeldByTheSurfaceFixes) {
  const Mission m = surface_mission(GetParam(), SimulatedErrors::corners);
  const MissionSolution s = solve_mission(m);
  ASSERT_TRUE(s.report.consistent);
  // A fix every second at the surface: at most the fix box (2 × 2.5 m) plus what the
  // surface speed allows over the half second to the nearest fix, on each axis.
  for (const std::size_t k : {std::size_t{0}, m.size() / 20, m.size() - 1 - m.size() / 20, m.size() - 1}) {
    const double allowed = 2.0 * m.model.gps_metres + 2.0 * m.model.surface_max_speed * 0.5 + 1e-6;
    EXPECT_LE(s.domains.px[k].width(), allowed) << GetParam().name << " at sample " << k;
    EXPECT_LE(s.domains.py[k].width(), allowed) << GetParam().name << " at sample " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Waves, SurfaceGuarantee,
    testing::Values(Case{"chop_without_bottom_lock", 0.3, 2.0, false, 0, 0.0},   // about 4.6 m/s³
                    Case{"chop_with_bottom_lock", 0.3, 2.0, true, 0, 0.0},
                    Case{"steep_waves_with_bottom_lock", 1.4, 1.6, true, 0, 0.0},  // about 42 m/s³, 2.7 m/s
                    Case{"ripples_with_bottom_lock", 0.05, 0.5, true, 0, 0.0},    // about 50 m/s³
                    Case{"bursts_of_10", 0.3, 2.0, true, 3, 10.0},
                    Case{"bursts_of_3", 0.0, 6.0, false, 3, 3.0}),
    [](const testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

TEST(SurfaceGuarantee, SubmergedBurstsBeyondTheJerkBoundAreReported) {
  const Mission m = surface_mission(Case{"bursts", 0.0, 6.0, false, 3, 10.0}, SimulatedErrors::corners);
  const MissionSolution s = solve_mission(m);
  ASSERT_GE(s.report.regimes.fallback_times.size(), 1u);
  // Each reported run starts at most 1.6 s (the check's widest span) before a burst.
  const double submerged = m.time.back() - 2.0 * 90.0;
  for (const double t : s.report.regimes.fallback_times) {
    bool near_a_burst = false;
    for (int i = 0; i < 3; ++i) {
      const double start = 90.0 + (i + 1) * submerged / 4.0;
      near_a_burst = near_a_burst || (t >= start - 1.7 && t <= start + 1.0);
    }
    EXPECT_TRUE(near_a_burst) << "a fall-back at t = " << t << " s, far from every burst";
  }
  EXPECT_EQ(samples_outside(m, s), 0u);
}

}  // namespace
}  // namespace gesmi
