// The mission network on the tiny synthetic mission of tests/support: soundness
// against the truth, usefulness of the marks, precise inconsistency reports.

#include "solver/network/mission_solver.h"

#include <gtest/gtest.h>

#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

using test::make_tiny_mission;
using test::TinyErrors;
using test::TinyMission;

struct Solved {
  TubeDomains domains;
  SolverReport report;
};

Solved solve_mission(const TinyMission& t, SolverOptions options = {}) {
  const MissionNetwork net = build_network(t.mission, t.mission.model, t.fixes);
  Solved s{initial_domains(t.mission, t.mission.model, net), {}};
  s.report = solve(net, s.domains, options);
  return s;
}

void expect_truth_inside(const TinyMission& t, const TubeDomains& d) {
  const Mission& m = t.mission;
  int outside = 0;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const bool in = d.px[k].contains(m.truth_x[k]) && d.py[k].contains(m.truth_y[k]) && d.pz[k].contains(m.truth_z[k]);
    if (!in && outside++ < 5) ADD_FAILURE() << "truth outside the tube at k = " << k;
  }
  EXPECT_EQ(outside, 0);
  for (int i = 0; i < m.mine_count; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(d.mines[static_cast<std::size_t>(i)][c].contains(m.truth_mines[static_cast<std::size_t>(3 * i + c)]))
          << "mine " << i << " axis " << c;
}

TEST(MissionSolver, TinyMissionHasTwoDetections) {
  const TinyMission t = make_tiny_mission(1, TinyErrors::uniform);
  EXPECT_EQ(t.mission.mark_count(), 2u);
}

TEST(MissionSolver, TruthStaysInsideTheTubeAndTheMineBox) {
  for (const TinyErrors errors : {TinyErrors::uniform, TinyErrors::worst_case}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << (errors == TinyErrors::uniform ? " uniform" : " worst"));
      const TinyMission t = make_tiny_mission(seed, errors);
      const Solved s = solve_mission(t);
      ASSERT_TRUE(s.report.consistent()) << s.report.inconsistency->message;
      EXPECT_TRUE(s.report.converged);
      expect_truth_inside(t, s.domains);
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
  const Solved a = solve_mission(with_marks), b = solve_mission(without);
  ASSERT_TRUE(a.report.consistent());
  ASSERT_TRUE(b.report.consistent());
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
  const Solved s = solve_mission(t);
  ASSERT_FALSE(s.report.consistent());
  const Inconsistency& inc = *s.report.inconsistency;
  EXPECT_EQ(inc.kind, Inconsistency::Kind::detection);
  EXPECT_EQ(inc.source, 1u);
  EXPECT_NE(inc.message.find("detection 1"), std::string::npos) << inc.message;
}

TEST(MissionSolver, ReportsAnUnreachableGpsFix) {
  TinyMission t = make_tiny_mission(6, TinyErrors::uniform);
  t.mission.mark_time.clear();
  t.mission.mark_mine.clear();
  t.mission.mark_range.clear();
  t.mission.mark_side.clear();
  t.fixes[1].box[0] = t.fixes[1].box[0] + Interval(500.0);  // 500 m north of the truth
  const Solved s = solve_mission(t);
  ASSERT_FALSE(s.report.consistent());
  EXPECT_EQ(s.report.inconsistency->kind, Inconsistency::Kind::evolution);
  EXPECT_NE(s.report.inconsistency->message.find("GPS fix 1"), std::string::npos) << s.report.inconsistency->message;
  EXPECT_NE(s.report.inconsistency->message.find("GPS fix 0"), std::string::npos) << s.report.inconsistency->message;
}

TEST(MissionSolver, ValidatesItsOptions) {
  SolverOptions o;
  EXPECT_TRUE(o.validate().empty());
  o.max_sweeps = 0;
  EXPECT_FALSE(o.validate().empty());
  o.max_sweeps = 3;
  o.tolerance = -1.0;
  EXPECT_FALSE(o.validate().empty());
}

}  // namespace
}  // namespace gesmi
