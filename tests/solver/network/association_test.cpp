// Marks without mine numbers (seed 001, VI-4): a disjunction over the mines that
// drops the impossible ones and never the true one.

#include <gtest/gtest.h>

#include <bit>

#include "solver/solve/solve_mission.h"
#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

TEST(Association, AnUnnumberedMarkOfTheOnlyMineIsDecided) {
  test::TinyMission t = test::make_tiny_mission(2, test::TinyErrors::uniform);
  t.mission.mark_mine = {-1, -1};
  const MissionSolution r = solve_mission(t.mission);
  ASSERT_TRUE(r.report.consistent);
  for (const std::uint64_t c : r.candidates) EXPECT_EQ(c, 1u);
  EXPECT_TRUE(r.domains.mines[0][0].contains(t.mission.truth_mines[0]));
  EXPECT_LT(r.domains.mines[0][0].width(), 30.0);
}

TEST(Association, KeepsBothMinesWhenAnUnseenMineCouldExplainTheMark) {
  test::TinyMission t = test::make_tiny_mission(3, test::TinyErrors::uniform);
  t.mission.mine_count = 2;  // a second mine, never labelled, anywhere
  t.mission.mark_mine = {0, -1};
  const MissionSolution r = solve_mission(t.mission);
  ASSERT_TRUE(r.report.consistent);
  EXPECT_EQ(r.candidates[0], 1u);
  EXPECT_EQ(r.candidates[1], 3u);  // mine 0 (true) or mine 1: undecidable, both kept
}

TEST(Association, DropsAMineThatCannotBeAtThatRange) {
  test::TinyMission t = test::make_tiny_mission(4, test::TinyErrors::uniform);
  // Mine 1 is pinned far away by a labelled mark: the second mark cannot be it.
  t.mission.mine_count = 2;
  t.mission.mark_mine = {1, -1};
  t.mission.mark_range[0] = 70.0;  // consistent only with a mine 70 m away at t0
  const MissionSolution r = solve_mission(t.mission);
  ASSERT_TRUE(r.report.consistent) << r.report.message;
  EXPECT_EQ(std::popcount(r.candidates[1]), 1);
  EXPECT_EQ(r.candidates[1], 1u);  // mine 0: the unseen one, by symmetry breaking
}

}  // namespace
}  // namespace gesmi
