#include "solver/solve/unchecked_inputs.h"

namespace gesmi {

UncheckedInputs unchecked_inputs(const MissionSolution& s) {
  UncheckedInputs out;
  const std::size_t rows = std::min(s.candidates.size(), s.mark_count());
  for (int i = 0; i < s.mine_count; ++i) {
    std::size_t count = 0, row = 0;
    for (std::size_t j = 0; j < rows && count < 2; ++j)
      if (s.candidates[j] >> i & 1) {
        ++count;
        row = j;
      }
    if (count == 1) {
      out.mines.push_back(i);
      out.marks.push_back(row);
    }
  }
  if (s.gps_outlier.size() == 1) out.gps_fixes.push_back(0);
  return out;
}

}  // namespace gesmi
