// A warm rerun copies the cells of the earlier waterfall whose inputs did not change
// (solver/network/waterfall.h): its waterfall must be the one a full computation on
// the final domains gives, bit for bit (NaN cells included), and some cells must have
// been worth recomputing (the added marks moved a mine box).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace gesmi {
namespace {

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(WarmWaterfall, EqualsAFullComputationOnTheFinalDomains) {
  for (const std::uint64_t seed : {5u, 6u}) {
    SCOPED_TRACE(seed);
    SimulationOptions o;
    o.seed = seed;
    o.duration = 2000.0;
    o.missed = 0.4;
    Mission m = simulate_mission(o);
    m.heading_frame_margin = 1e-3;  // as io/ sets it: the margins then depend on the tube
    ASSERT_GE(m.truth_missed_marks.size(), 3u);
    const MissionSolution first = solve_mission(m);
    ASSERT_TRUE(first.report.consistent);
    // The operator finds the missed marks (their true ranges and mines).
    for (std::size_t i = 0; i + 2 < m.truth_missed_marks.size(); i += 3) {
      m.mark_time.push_back(m.truth_missed_marks[i]);
      m.mark_mine.push_back(static_cast<std::int32_t>(m.truth_missed_marks[i + 1]));
      m.mark_range.push_back(m.truth_missed_marks[i + 2]);
      m.mark_side.push_back(1);
    }
    SolveOptions warm;
    warm.warm_from = &first;
    const MissionSolution second = solve_mission(m, warm);
    ASSERT_EQ(second.report.mode, SolveMode::warm) << second.report.cold_fallback.value_or("");
    const Waterfall full = compute_waterfall(m, m.model, second.domains);
    EXPECT_EQ(second.waterfall.step, full.step);
    EXPECT_EQ(second.waterfall.mine, full.mine);
    EXPECT_TRUE(bitwise_equal(second.waterfall.lower, full.lower));
    EXPECT_TRUE(bitwise_equal(second.waterfall.upper, full.upper));
    EXPECT_FALSE(first.waterfall.step == full.step && bitwise_equal(first.waterfall.lower, full.lower))
        << "nothing changed: the test proves nothing";
  }
}

}  // namespace
}  // namespace gesmi
