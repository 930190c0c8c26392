// A solve says where its tube leaves the local frame's zone (SolveReport::
// beyond_frame_zone): there the frame's margins are capped at the zone's, which rests on
// the robot having stayed within it. The zone's margins are numbers in the mission, so a
// zone of a few hundred metres makes the simulated survey leave it.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "solver/mission/frame_scale.h"
#include "solver/mission/meridian_convergence.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace gesmi {
namespace {

Mission survey_with_zone(double zone) {
  SimulationOptions o;
  o.seed = 4;
  o.duration = 600.0;
  Mission m = simulate_mission(o);
  m.origin = {48.2, -4.4};
  m.heading_frame_margin = meridian_convergence_within(m.origin.latitude, zone);
  m.frame_scale_margin = frame_scale_within(zone);
  return m;
}

// The farthest any sample's box reaches from the origin.
double farthest_reach(const TubeDomains& d) {
  double farthest = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) farthest = std::max(farthest, std::hypot(d.px[k].mag(), d.py[k].mag()));
  return farthest;
}

TEST(FrameZoneReport, ATubeBeyondTheZoneIsReportedWithItsDistance) {
  const Mission m = survey_with_zone(300.0);
  const MissionSolution s = solve_mission(m);
  ASSERT_TRUE(s.report.consistent) << s.report.message;
  const double farthest = farthest_reach(s.domains);
  ASSERT_GT(farthest, 300.0);  // the scene: the survey leaves the zone
  // Beyond the zone, and no farther than the tube's farthest point plus half a step's travel.
  EXPECT_GT(s.report.beyond_frame_zone, 300.0);
  EXPECT_LE(s.report.beyond_frame_zone, 1.01 * farthest + 10.0);
}

TEST(FrameZoneReport, ATubeWithinTheZoneIsNotReported) {
  const Mission m = survey_with_zone(100000.0);
  const MissionSolution s = solve_mission(m);
  ASSERT_TRUE(s.report.consistent) << s.report.message;
  ASSERT_LT(farthest_reach(s.domains), 50000.0);
  EXPECT_EQ(s.report.beyond_frame_zone, 0.0);
}

TEST(FrameZoneReport, MarginsOverATubeNameTheFarthestCappedDistance) {
  Mission m = survey_with_zone(1000.0);
  TubeDomains tube;
  for (const double r : {100.0, 900.0, 1500.0, 400.0}) {
    m.time.push_back(static_cast<double>(m.time.size()));
    tube.px.push_back(Interval::around(r, 1.0));
    tube.py.push_back(Interval(0.0));
  }
  m.time.erase(m.time.begin(), m.time.end() - 4);
  const FrameMarginValues v = frame_margins_over(m, tube, 1.0);
  EXPECT_GT(v.beyond_zone, 1501.0);  // 1501 m plus half a step at 1 m/s, rounded up
  EXPECT_LT(v.beyond_zone, 1505.0);
  tube.px[2] = Interval::entire();  // unbounded: nothing shows the robot stayed in the zone
  EXPECT_EQ(frame_margins_over(m, tube, 1.0).beyond_zone, std::numeric_limits<double>::infinity());
  tube.px[2] = Interval::around(500.0, 1.0);  // all within
  EXPECT_EQ(frame_margins_over(m, tube, 1.0).beyond_zone, 0.0);
}

}  // namespace
}  // namespace gesmi
