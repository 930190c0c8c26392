// --max-outliers Q on reference-like missions with corrupted marks: whenever at most
// Q marks are wrong, the truth lies in the tube at every sample and every mine in its
// box (fixes trusted, as the simulator never corrupts them).

#include <gtest/gtest.h>

#include "solver/network/outliers/outlier_solver.h"
#include "solver/sim/simulator.h"

namespace gesmi {
namespace {

TEST(OutlierGuarantee, TruthInsideWheneverAtMostQMarksAreWrong) {
  for (const int wrong : {1, 2}) {
    for (const std::uint64_t seed : {51u, 52u, 53u}) {
      SCOPED_TRACE(::testing::Message() << wrong << " wrong marks, seed " << seed);
      SimulationOptions s;
      s.seed = seed;
      s.duration = 3000.0;
      s.outliers = wrong;
      const Mission m = simulate_mission(s);
      const MissionNetwork net = build_network(m, m.model, gps_fixes(m));
      OutlierOptions o;
      o.max_outliers = 2;
      o.trust_fixes = true;
      TubeDomains d;
      const OutlierReport r = solve_with_outliers(net, sensor_domains(m, m.model), d, o);
      ASSERT_TRUE(r.consistent());
      EXPECT_LE(r.minimal_outliers, wrong);
      EXPECT_EQ(r.removal_sets, m.mark_count() * (m.mark_count() - 1) / 2);
      for (std::size_t k = 0; k < m.size(); ++k) {
        ASSERT_TRUE(d.px[k].contains(m.truth_x[k])) << "sample " << k;
        ASSERT_TRUE(d.py[k].contains(m.truth_y[k])) << "sample " << k;
        ASSERT_TRUE(d.pz[k].contains(m.truth_z[k])) << "sample " << k;
      }
      for (std::size_t i = 0; i < d.mines.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c) EXPECT_TRUE(d.mines[i][c].contains(m.truth_mines[3 * i + c])) << "mine " << i;
    }
  }
}

}  // namespace
}  // namespace gesmi
