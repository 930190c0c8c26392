// A warm rerun copies the cells of the earlier waterfall whose inputs did not change
// (solver/network/waterfall/waterfall.h): its waterfall must be the one a full computation on
// the final domains gives, bit for bit (NaN cells included), and some cells must have
// been worth recomputing (the added marks moved a mine box). A cell whose neighbouring
// step's box moved is recomputed too.

#include <gtest/gtest.h>

#include <algorithm>
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

// The frame margins at a step are taken over its neighbours' position boxes too, so a cell
// whose own box is unchanged but whose neighbour's moved is computed again. Step k + 1's
// box is halved on the side away from the origin where the robot heads away from it
// (the margins at k then come from k + 1's reach), and nothing else changes.
TEST(WarmWaterfall, ANeighboursBoxMovedRecomputesTheCell) {
  SimulationOptions o;
  o.seed = 5;
  o.duration = 2000.0;
  Mission m = simulate_mission(o);
  m.heading_frame_margin = 1e-3;  // as io/ sets it: the margins then depend on the tube
  const MissionSolution first = solve_mission(m);
  ASSERT_TRUE(first.report.consistent);
  const TubeDomains& then = first.domains;
  const auto reach = [&](std::size_t k) {
    const double north = std::max(std::fabs(then.px[k].lo()), std::fabs(then.px[k].hi()));
    const double east = std::max(std::fabs(then.py[k].lo()), std::fabs(then.py[k].hi()));
    return std::hypot(north, east);
  };
  std::size_t tried = 0, changed = 0;
  const Waterfall& w = first.waterfall;
  for (std::size_t c = 0; c < w.cells() && tried < 20; c += 97) {
    const auto k = static_cast<std::size_t>(w.step[c]);
    if (k == 0 || k + 2 >= then.size() || !(reach(k - 1) < reach(k) && reach(k) < reach(k + 1))) continue;
    ++tried;
    TubeDomains now = then;
    for (std::vector<Interval>* axis : {&now.px, &now.py}) {
      Interval& x = (*axis)[k + 1];
      x = std::fabs(x.hi()) > std::fabs(x.lo()) ? Interval(x.lo(), x.mid()) : Interval(x.mid(), x.hi());
    }
    const WaterfallBefore before = waterfall_before(w, then, now);
    const Waterfall full = compute_waterfall(m, m.model, now);
    const Waterfall warm = compute_waterfall(m, m.model, now, &before);
    EXPECT_EQ(warm.step, full.step) << "step " << k;
    EXPECT_EQ(warm.mine, full.mine);
    EXPECT_TRUE(bitwise_equal(warm.lower, full.lower)) << "step " << k;
    EXPECT_TRUE(bitwise_equal(warm.upper, full.upper)) << "step " << k;
    const std::size_t a = w.first_cell_at(k), b = full.first_cell_at(k);
    changed += !(w.lower[a] == full.lower[b] && w.upper[a] == full.upper[b] && w.step[a] == full.step[b]);
  }
  EXPECT_GT(tried, 3u);
  EXPECT_GT(changed, 0u) << "no neighbour's change reached a cell: the test proves nothing";
}

}  // namespace
}  // namespace gesmi
