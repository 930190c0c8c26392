#pragma once
// The inputs no other input can contradict. A wrong mark or fix is found only where the
// other data determine what it measures too (seed 001, section VII): a mine that one
// mark alone can be, or the position of the mission's only GPS fix, rests on that input
// alone, and a wrong one moves its enclosure with no inconsistency to show it. An
// outlier-tolerant solve (--max-outliers) still encloses the truth then.

#include <cstddef>
#include <vector>

#include "solver/solve/mission_solution.h"

namespace gesmi {

struct UncheckedInputs {
  /// Mines that exactly one mark can be (by its candidates), in increasing order, and
  /// that mark's row for each.
  std::vector<int> mines;
  std::vector<std::size_t> marks;
  /// The GPS rows nothing else checks: the only fix of a mission that has one.
  std::vector<std::size_t> gps_fixes;
  bool empty() const { return mines.empty() && gps_fixes.empty(); }
};

UncheckedInputs unchecked_inputs(const MissionSolution& solution);

}  // namespace gesmi
