// Tightness of the default step model against the paper's own network, propagated in
// plain floating point by tests/support/paper_network (independent of solver/): on
// reference-like missions whose readings were drawn in their bounds, gesmi's sound
// tube (trapezoid steps, outward rounding) must stay within 10 % of the paper's width
// (the step-model goal of docs/model.md), and so must its mine boxes.

#include <gtest/gtest.h>

#include <algorithm>

#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"
#include "tests/support/paper_network.h"

namespace gesmi {
namespace {

TEST(PaperNetworkTightness, TheTrapezoidTubeIsWithinTenPercentOfThePapersPropagation) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    SimulationOptions o;
    o.seed = seed;
    const Mission m = simulate_mission(o);
    const test::PaperTube paper = test::propagate_paper_network(m);
    ASSERT_TRUE(paper.consistent);
    SolveOptions options;
    options.waterfall = false;
    const MissionSolution s = solve_mission(m, options);
    ASSERT_TRUE(s.report.consistent) << s.report.message;
    const double ours = s.domains.max_horizontal_width(), theirs = paper.max_horizontal_width();
    RecordProperty("tube_m_seed_" + std::to_string(seed), std::to_string(ours) + " vs " + std::to_string(theirs));
    EXPECT_LE(ours, 1.10 * theirs) << "gesmi " << ours << " m, the paper's network " << theirs << " m";
    EXPECT_GT(ours, 0.9 * theirs) << "narrower than the paper's own network: suspicious";
    for (std::size_t i = 0; i < s.domains.mines.size(); ++i) {
      const double mine_ours = std::max(s.domains.mines[i][0].width(), s.domains.mines[i][1].width());
      const double mine_theirs = std::max(paper.mine_north_width[i], paper.mine_east_width[i]);
      EXPECT_LE(mine_ours, 1.10 * mine_theirs) << "mine " << i << ": " << mine_ours << " m against " << mine_theirs << " m";
    }
  }
}

}  // namespace
}  // namespace gesmi
