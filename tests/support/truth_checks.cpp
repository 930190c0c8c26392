#include "tests/support/truth_checks.h"

namespace gesmi::test {

::testing::AssertionResult truth_inside(const Mission& m, const TubeDomains& d) {
  std::size_t outside = 0;
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  for (std::size_t k = 0; k < m.size(); ++k) {
    if (d.px[k].contains(m.truth_x[k]) && d.py[k].contains(m.truth_y[k]) && d.pz[k].contains(m.truth_z[k])) continue;
    if (outside++ < 5) failure << "truth outside the tube at sample " << k << "; ";
  }
  for (std::size_t i = 0; i < d.mines.size() && 3 * i + 2 < m.truth_mines.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!d.mines[i][c].contains(m.truth_mines[3 * i + static_cast<std::size_t>(c)])) {
        ++outside;
        failure << "mine " << i << " outside its box on axis " << c << "; ";
      }
  if (outside == 0) return ::testing::AssertionSuccess();
  return failure << outside << " in all";
}

}  // namespace gesmi::test
