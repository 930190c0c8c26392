// Acceptance of the solver on simulated reference-like missions (several seeds, both
// error modes): the truth is inside the tube at every step and every mine inside its
// box (no tolerance); mine boxes are under 30 m on each horizontal axis; marks make
// the tube narrower than dead reckoning with GPS alone; an injected outlier is
// reported with its detection number. Also the simulator's own invariants.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver/model/euler.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"
#include "tests/support/truth_checks.h"

namespace gesmi {
namespace {


Mission simulate(std::uint64_t seed, SimulatedErrors errors) {
  SimulationOptions o;
  o.seed = seed;
  o.errors = errors;
  return simulate_mission(o);
}

TEST(ReferenceMission, SimulatorHonoursTheDeclaredBounds) {
  const Mission m = simulate(7, SimulatedErrors::uniform);
  ASSERT_EQ(m.size(), 59995u);
  EXPECT_DOUBLE_EQ(m.time.back(), 5999.4);
  EXPECT_GE(m.mark_count(), 12u);
  for (std::size_t k = 0; k < m.size(); ++k) {
    // Depth reading within its bound of the true depth.
    EXPECT_LE(std::fabs(m.depth[k] - m.truth_z[k]), m.model.depth_absolute + m.model.depth_relative * std::fabs(m.depth[k]));
    if (k > 0) {  // speeds of 1 to 2.5 m/s
      const double step = std::hypot(m.truth_x[k] - m.truth_x[k - 1], m.truth_y[k] - m.truth_y[k - 1]);
      EXPECT_GT(step, 0.08);
      EXPECT_LT(step, 0.26);
    }
  }
  // Each mark: the true slant range within the bound, the mine in the sonar plane.
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const auto k = static_cast<std::size_t>(std::lround(m.mark_time[j] * 10.0));
    const int i = m.mark_mine[j];
    const Vec3d mine(m.truth_mines[3 * i], m.truth_mines[3 * i + 1], m.truth_mines[3 * i + 2]);
    const Vec3d p(m.truth_x[k], m.truth_y[k], m.truth_z[k]);
    EXPECT_LE(std::fabs((p - mine).norm() - m.mark_range[j]), m.model.mark_range);
  }
}

TEST(ReferenceMission, IsDeterministicForASeed) {
  const Mission a = simulate(3, SimulatedErrors::uniform), b = simulate(3, SimulatedErrors::uniform);
  EXPECT_EQ(a.heading, b.heading);
  EXPECT_EQ(a.mark_range, b.mark_range);
  const Mission c = simulate(4, SimulatedErrors::uniform);
  EXPECT_NE(a.heading, c.heading);
}

TEST(ReferenceMission, TruthInsideTubeAndMineBoxesUnder30Metres) {
  for (const SimulatedErrors errors : {SimulatedErrors::uniform, SimulatedErrors::worst_case}) {
    for (const std::uint64_t seed : {11u, 12u, 13u}) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << (errors == SimulatedErrors::uniform ? " uniform" : " worst-case"));
      const Mission m = simulate(seed, errors);
      const MissionSolution s = solve_mission(m);
      ASSERT_TRUE(s.report.consistent) << s.report.message;
      EXPECT_TRUE(test::truth_inside(m, s.domains));
      for (int i = 0; i < m.mine_count; ++i) {
        const Vec3I& box = s.domains.mines[static_cast<std::size_t>(i)];
        EXPECT_LT(box[0].width(), 30.0) << "mine " << i;
        EXPECT_LT(box[1].width(), 30.0) << "mine " << i;
      }
    }
  }
}

TEST(ReferenceMission, MarksNarrowTheTubeBelowDeadReckoningWithGps) {
  Mission m = simulate(21, SimulatedErrors::uniform);
  const MissionSolution with_marks = solve_mission(m);
  m.mark_time.clear();
  m.mark_mine.clear();
  m.mark_range.clear();
  m.mark_side.clear();
  const MissionSolution without = solve_mission(m);
  ASSERT_TRUE(with_marks.report.consistent);
  ASSERT_TRUE(without.report.consistent);
  EXPECT_LT(with_marks.domains.max_horizontal_width(), 0.8 * without.domains.max_horizontal_width());
}

TEST(ReferenceMission, AnInjectedOutlierIsReportedWithItsDetectionNumber) {
  for (const std::uint64_t seed : {31u, 32u, 33u}) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    SimulationOptions o;
    o.seed = seed;
    o.outliers = 1;
    const Mission m = simulate_mission(o);
    std::size_t corrupted = 0;
    for (std::size_t j = 0; j < m.mark_count(); ++j)
      if (m.truth_marks_outlier[j]) corrupted = j;
    // The diagnosis of the inconsistency: the single marks or fixes whose removal
    // restores consistency. The corrupted mark is one.
    const MissionSolution s = solve_mission(m);
    ASSERT_FALSE(s.report.consistent);
    ASSERT_TRUE(s.report.explained_by.has_value());
    const std::vector<ConstraintRef>& explaining = *s.report.explained_by;
    EXPECT_NE(std::find(explaining.begin(), explaining.end(), ConstraintRef::mark(corrupted)), explaining.end());
    EXPECT_NE(s.report.message.find("removing mark " + std::to_string(corrupted)), std::string::npos) << s.report.message;
  }
}

}  // namespace
}  // namespace gesmi
