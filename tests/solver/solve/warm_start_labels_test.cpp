// A warm rerun keeps the earlier domains only when the added marks leave the mines the
// earlier marks may belong to unchanged (the symmetry breaking among unlabelled mines,
// mission_network.h). allowed_mines_of_marks() computes those sets from the mark table
// alone; the oracle is build_network() itself on the same marks.

#include <gtest/gtest.h>

#include <random>

#include "solver/network/mission_network.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace gesmi {
namespace {

Mission small_mission(std::uint64_t seed) {
  SimulationOptions o;
  o.seed = seed;
  o.duration = 1500.0;
  return simulate_mission(o);
}

TEST(WarmStartLabels, AllowedSetsFromTheMarkTableEqualTheNetworks) {
  std::mt19937_64 random(5);
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    Mission m = small_mission(seed);
    ASSERT_GE(m.mark_count(), 4u);
    // Unknown mines here and there, and equal times, so that order and labels matter.
    for (std::size_t j = 0; j < m.mark_count(); ++j)
      if (random() % 2) m.mark_mine[j] = -1;
    m.mark_time[1] = m.mark_time[0];
    for (const std::size_t rows : {m.mark_count(), m.mark_count() / 2}) {
      Mission first = m;
      for (auto* v : {&first.mark_time, &first.mark_range}) v->resize(rows);
      for (auto* v : {&first.mark_mine, &first.mark_side}) v->resize(rows);
      const MissionNetwork first_net = build_network(first, first.model, gps_fixes(first));
      const std::vector<std::uint64_t> allowed = allowed_mines_of_marks(m, rows);
      ASSERT_EQ(allowed.size(), rows);
      for (const Detection& d : first_net.detections) EXPECT_EQ(allowed[d.mark], d.allowed) << "seed " << seed;
    }
  }
}

TEST(WarmStartLabels, AnAddedMarkNamingAMineNoMarkNamedFallsBackToAColdSolve) {
  Mission m = small_mission(4);
  ASSERT_GE(m.mark_count(), 2u);
  const std::int32_t mine = m.mark_mine[0];
  for (auto& j : m.mark_mine) j = -1;  // the operator named no mine
  const MissionSolution first = solve_mission(m);
  ASSERT_TRUE(first.report.consistent);
  // The same echo marked again, now naming its mine.
  m.mark_time.push_back(m.mark_time[0]);
  m.mark_range.push_back(m.mark_range[0]);
  m.mark_side.push_back(m.mark_side[0]);
  m.mark_mine.push_back(mine);
  SolveOptions warm;
  warm.warm_from = &first;
  const MissionSolution second = solve_mission(m, warm);
  EXPECT_EQ(second.report.mode, SolveMode::cold);
  EXPECT_EQ(second.report.cold_fallback.value_or(""), "the added marks name a mine no mark named before");
  EXPECT_TRUE(second.report.consistent);
  // The last echo marked again without naming a mine: the earlier marks keep their
  // sets (it comes after all of them), so the rerun stays warm.
  const std::size_t last = m.mark_count() - 2;
  m.mark_time.back() = m.mark_time[last];
  m.mark_range.back() = m.mark_range[last];
  m.mark_side.back() = m.mark_side[last];
  m.mark_mine.back() = -1;
  const MissionSolution third = solve_mission(m, warm);
  EXPECT_EQ(third.report.mode, SolveMode::warm) << third.report.cold_fallback.value_or("");
}

}  // namespace
}  // namespace gesmi
