// The inputs nothing else checks (solver/solve/unchecked_inputs.h): the mines that one
// mark alone can be, by the marks' candidates, and the lone GPS fix.

#include "solver/solve/unchecked_inputs.h"

#include <gtest/gtest.h>

namespace gesmi {
namespace {

MissionSolution with_candidates(int mines, std::vector<std::uint64_t> candidates, std::size_t fixes) {
  MissionSolution s;
  s.mine_count = mines;
  s.mark_time.assign(candidates.size(), 0.0);
  s.candidates = std::move(candidates);
  s.gps_outlier.assign(fixes, 0);
  return s;
}

TEST(UncheckedInputs, NameTheMinesOneMarkAloneCanBeAndTheLoneFix) {
  // Mine 0: marks 0 and 1; mine 1: marks 2 and 3 (3 may also be mine 2); mine 2: mark 3
  // alone; mine 3: no mark; mine 4: mark 4 alone.
  const UncheckedInputs u = unchecked_inputs(with_candidates(5, {0b00001, 0b00001, 0b00010, 0b00110, 0b10000}, 1));
  EXPECT_EQ(u.mines, (std::vector<int>{2, 4}));
  EXPECT_EQ(u.marks, (std::vector<std::size_t>{3, 4}));
  EXPECT_EQ(u.gps_fixes, (std::vector<std::size_t>{0}));
  EXPECT_FALSE(u.empty());
}

TEST(UncheckedInputs, TwoMarksPerMineAndTwoFixesCheckEachOther) {
  const UncheckedInputs u = unchecked_inputs(with_candidates(2, {0b01, 0b11, 0b10}, 2));
  EXPECT_TRUE(u.mines.empty());
  EXPECT_TRUE(u.gps_fixes.empty());
  EXPECT_TRUE(u.empty());
  // No fix at all: nothing to check, nothing named.
  EXPECT_TRUE(unchecked_inputs(with_candidates(0, {}, 0)).empty());
}

}  // namespace
}  // namespace gesmi
