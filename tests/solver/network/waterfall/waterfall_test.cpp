// The reconstructed waterfall contains every detection (time, range) of the truth
// and is empty where the mine cannot be on the sonar plane.

#include "solver/network/waterfall/waterfall.h"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/model/euler.h"
#include "solver/network/mission_solver.h"
#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

TEST(Waterfall, ContainsTheTrueRangeWheneverTheMineCrossesTheSonarPlane) {
  const test::TinyMission t = test::make_tiny_mission(3, test::TinyErrors::uniform);
  const Mission& m = t.mission;
  const MissionNetwork net = build_network(m, m.model, t.fixes);
  TubeDomains d = initial_domains(m, m.model, net);
  ASSERT_TRUE(solve(net, d).consistent());
  const Waterfall w = compute_waterfall(m, m.model, d);
  ASSERT_EQ(w.steps, m.size());
  ASSERT_EQ(w.mines, 1u);
  // Every detection of the table lies in a feasible zone at its range.
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const auto k = static_cast<std::size_t>(std::lround(m.mark_time[j] / 0.1));
    ASSERT_TRUE(w.feasible(k, 0)) << "mark " << j;
    const Vec3d q(m.truth_x[k], m.truth_y[k], m.truth_z[k]);
    const Vec3d mine(m.truth_mines[0], m.truth_mines[1], m.truth_mines[2]);
    const double range = (q - mine).norm();
    EXPECT_LE(w.lo(k, 0), range);
    EXPECT_GE(w.hi(k, 0), range);
  }
  // Far from the crossings the mine cannot be on the sonar plane.
  std::size_t feasible = 0;
  for (std::size_t k = 0; k < w.steps; ++k) feasible += w.feasible(k, 0);
  EXPECT_GT(feasible, 0u);
  EXPECT_LT(feasible, w.steps / 4);
}

}  // namespace
}  // namespace gesmi
