// The mission network on the tiny synthetic mission of tests/support: soundness
// against the truth, usefulness of the marks, precise inconsistency reports.

#include "solver/network/mission_solver.h"

#include <gtest/gtest.h>

#include "solver/solve/solve_mission.h"
#include "tests/support/tiny_mission.h"
#include "tests/support/truth_checks.h"

namespace gesmi {
namespace {

using test::make_tiny_mission;
using test::TinyErrors;
using test::TinyMission;

TEST(MissionSolver, TinyMissionHasTwoDetections) {
  const TinyMission t = make_tiny_mission(1, TinyErrors::uniform);
  EXPECT_EQ(t.mission.mark_count(), 2u);
}

TEST(MissionSolver, TruthStaysInsideTheTubeAndTheMineBox) {
  for (const TinyErrors errors : {TinyErrors::uniform, TinyErrors::worst_case}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << (errors == TinyErrors::uniform ? " uniform" : " worst"));
      const TinyMission t = make_tiny_mission(seed, errors);
      const MissionSolution s = solve_mission(t.mission);
      ASSERT_TRUE(s.report.consistent) << s.report.message;
      EXPECT_TRUE(s.report.converged);
      EXPECT_TRUE(test::truth_inside(t.mission, s.domains));
    }
  }
}

TEST(MissionSolver, MarksMakeTheTubeNarrowerThanDeadReckoningWithGps) {
  const TinyMission with_marks = make_tiny_mission(4, TinyErrors::uniform);
  TinyMission without = with_marks;
  without.mission.mark_time.clear();
  without.mission.mark_mine.clear();
  without.mission.mark_range.clear();
  without.mission.mark_side.clear();
  const MissionSolution a = solve_mission(with_marks.mission), b = solve_mission(without.mission);
  ASSERT_TRUE(a.report.consistent);
  ASSERT_TRUE(b.report.consistent);
  double sum_a = 0.0, sum_b = 0.0;
  for (std::size_t k = 0; k < a.domains.size(); ++k) {
    EXPECT_LE(a.domains.px[k].width(), b.domains.px[k].width() + 1e-9);
    sum_a += a.domains.px[k].width() + a.domains.py[k].width();
    sum_b += b.domains.px[k].width() + b.domains.py[k].width();
  }
  EXPECT_LT(sum_a, sum_b);
  EXPECT_TRUE(a.domains.mines[0][0].is_bounded());
  EXPECT_LT(a.domains.mines[0][0].width(), 30.0);
  EXPECT_LT(a.domains.mines[0][1].width(), 30.0);
}

TEST(MissionSolver, ReportsAnOutlierDetectionWithItsNumber) {
  TinyMission t = make_tiny_mission(5, TinyErrors::uniform);
  t.mission.mark_range[1] += 25.0;  // far outside the +-1 m bound
  const MissionSolution s = solve_mission(t.mission);
  ASSERT_FALSE(s.report.consistent);
  const Inconsistency& inc = *s.report.inconsistency;
  EXPECT_EQ(inc.kind, Inconsistency::Kind::detection);
  EXPECT_EQ(inc.source, ConstraintRef::mark(1));
  EXPECT_NE(s.report.message.find("detection 1"), std::string::npos) << s.report.message;
}

TEST(MissionSolver, ReportsAnUnreachableGpsFix) {
  TinyMission t = make_tiny_mission(6, TinyErrors::uniform);
  t.mission.mark_time.clear();
  t.mission.mark_mine.clear();
  t.mission.mark_range.clear();
  t.mission.mark_side.clear();
  t.mission.gps_north[1] += 500.0;  // 500 m north of the truth
  const MissionSolution s = solve_mission(t.mission);
  ASSERT_FALSE(s.report.consistent);
  EXPECT_EQ(s.report.inconsistency->kind, Inconsistency::Kind::evolution);
  EXPECT_EQ(s.report.inconsistency->before, ConstraintRef::gps_fix(0));
  EXPECT_EQ(s.report.inconsistency->after, ConstraintRef::gps_fix(1));
  EXPECT_NE(s.report.message.find("GPS fix 1"), std::string::npos) << s.report.message;
  EXPECT_NE(s.report.message.find("GPS fix 0"), std::string::npos) << s.report.message;
}

// Each reason starts with the option it is about, as the gesmi command spells it.
TEST(MissionSolver, ValidatesItsOptions) {
  SolverOptions o;
  EXPECT_TRUE(o.validate().empty());
  for (const int bad : {0, SolverOptions::kMaxSweeps + 1}) {
    o.max_sweeps = bad;
    EXPECT_EQ(o.validate().rfind("max-sweeps: ", 0), 0u) << o.validate();
  }
  o.max_sweeps = SolverOptions::kMaxSweeps;
  EXPECT_TRUE(o.validate().empty());
  o.tolerance = -1.0;
  EXPECT_EQ(o.validate().rfind("tolerance: ", 0), 0u) << o.validate();
}

}  // namespace
}  // namespace gesmi
