// The q-relaxed enclosure (--max-outliers Q): it contains the solution of the full
// network without R for every removal set R of size Q (checked against brute force:
// one full solve per R, independent of the reduced network and of the chain
// projection), stays close to that hull, and keeps the truth when more marks are
// wrong than the data reveal, where the minimal-q* enclosure loses it.

#include "solver/network/outliers/relaxed_enclosure.h"

#include <gtest/gtest.h>

#include "solver/network/outliers/outlier_solver.h"
#include "solver/network/outliers/subsets.h"
#include "tests/support/tiny_network.h"

namespace gesmi {
namespace {

using Problem = test::TinyNetwork;

// The oracle: the hull over removal sets of full solves of the network without them.
bool brute_force_hull(const Problem& p, std::size_t q, TubeDomains& hull) {
  bool any = false;
  for_each_subset(p.all_ids(), q, [&](const std::vector<std::size_t>& removed) {
    const MissionNetwork sub = without_constraints(p.net, removed);
    TubeDomains d = p.sensor;
    add_network_priors(d, sub);
    SolverOptions tight;
    tight.tolerance = 0.0;
    tight.max_sweeps = 1000;
    if (!solve(sub, d, tight).consistent()) return;
    if (!any) {
      hull = d;
      any = true;
      return;
    }
    for (std::size_t k = 0; k < d.size(); ++k) {
      hull.px[k] = gesmi::hull(hull.px[k], d.px[k]);
      hull.py[k] = gesmi::hull(hull.py[k], d.py[k]);
      hull.pz[k] = gesmi::hull(hull.pz[k], d.pz[k]);
    }
    for (std::size_t i = 0; i < d.mines.size(); ++i)
      for (int c = 0; c < 3; ++c) hull.mines[i][c] = gesmi::hull(hull.mines[i][c], d.mines[i][c]);
  });
  return any;
}

// Both sides are outward-rounded enclosures of the same set, computed along
// different paths: they may differ at rounding level (seen: 6e-12 m), so containment
// is checked to 1 nm, far below any modelling error.
constexpr double kEndpointRounding = 1e-9;

::testing::AssertionResult encloses(const Interval& outer, const Interval& inner) {
  if (inner.is_empty() ||
      (outer.lo() <= inner.lo() + kEndpointRounding && inner.hi() <= outer.hi() + kEndpointRounding))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "[" << inner.lo() << ", " << inner.hi() << "] not in [" << outer.lo() << ", "
                                       << outer.hi() << "]";
}

void expect_encloses(const TubeDomains& outer, const TubeDomains& inner) {
  ASSERT_EQ(outer.size(), inner.size());
  for (std::size_t k = 0; k < inner.size(); ++k) {
    ASSERT_TRUE(encloses(outer.px[k], inner.px[k])) << "north, sample " << k;
    ASSERT_TRUE(encloses(outer.py[k], inner.py[k])) << "east, sample " << k;
    ASSERT_TRUE(encloses(outer.pz[k], inner.pz[k])) << "down, sample " << k;
  }
  for (std::size_t i = 0; i < inner.mines.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_TRUE(encloses(outer.mines[i][c], inner.mines[i][c])) << "mine " << i << " axis " << c;
}

TEST(RelaxedEnclosure, ContainsEverySolveWithoutQConstraintsAndStaysCloseToTheirHull) {
  for (const std::uint64_t seed : {41u, 42u, 43u}) {
    for (const test::TinyErrors errors : {test::TinyErrors::uniform, test::TinyErrors::worst_case}) {
      const Problem p(test::make_tiny_mission(seed, errors));
      for (const std::size_t q : {1u, 2u}) {
        SCOPED_TRACE(::testing::Message() << "seed " << seed << ", q " << q);
        TubeDomains oracle;
        ASSERT_TRUE(brute_force_hull(p, q, oracle));
        TubeDomains relaxed;
        const RelaxedStats stats = relaxed_enclosure(p.net, p.sensor, p.all_ids(), q, {}, relaxed);
        ASSERT_GT(stats.consistent_sets, 0u);
        expect_encloses(relaxed, oracle);
        // Tightness: the reduced network and the projection lose little (the solver's
        // 1 mm tolerance and the depth priors between events).
        double worst = 0.0;
        for (std::size_t k = 0; k < oracle.size(); ++k)
          if (oracle.px[k].is_bounded() && oracle.py[k].is_bounded())
            worst = std::max({worst, relaxed.px[k].width() - oracle.px[k].width(), relaxed.py[k].width() - oracle.py[k].width()});
        EXPECT_LT(worst, 0.05) << "metres wider than the hull of the full solves";
      }
    }
  }
}

// Two wrong marks that agree with each other, and one right mark of the same mine:
// dropping the right one restores consistency (q* = 1), so the minimal enclosure
// places the mine where the wrong marks say. The relaxed set with Q = 2 keeps the truth.
TEST(RelaxedEnclosure, KeepsTheTruthWhenMoreMarksAreWrongThanTheDataReveal) {
  test::TinyMission t = test::make_tiny_mission(44, test::TinyErrors::uniform);
  Mission& m = t.mission;
  m.mark_range[1] += 25.0;  // wrong
  m.mark_time.push_back(m.mark_time[1]);  // a second wrong mark agreeing with it
  m.mark_mine.push_back(m.mark_mine[1]);
  m.mark_range.push_back(m.mark_range[1]);
  m.mark_side.push_back(m.mark_side[1]);
  const Problem p(t);
  const auto mine_inside = [&](const TubeDomains& d) {
    for (int c = 0; c < 3; ++c)
      if (!d.mines[0][c].contains(m.truth_mines[static_cast<std::size_t>(c)])) return false;
    return true;
  };
  const auto truth_inside = [&](const TubeDomains& d) {
    for (std::size_t k = 0; k < m.size(); ++k)
      if (!d.px[k].contains(m.truth_x[k]) || !d.py[k].contains(m.truth_y[k]) || !d.pz[k].contains(m.truth_z[k])) return false;
    return mine_inside(d);
  };

  OutlierOptions minimal;
  minimal.max_outliers = 2;
  minimal.mode = OutlierMode::minimal;
  minimal.trust_fixes = true;
  TubeDomains conditional;
  const OutlierReport rm = solve_with_outliers(p.net, p.sensor, conditional, minimal);
  ASSERT_EQ(rm.minimal_outliers, 1);
  ASSERT_EQ(rm.hypotheses.size(), 1u);
  EXPECT_EQ(rm.hypotheses[0], (std::vector<std::size_t>{0}));  // the right mark is the one dropped
  EXPECT_FALSE(mine_inside(conditional)) << "the conditional enclosure was expected to lose the mine here";

  OutlierOptions relaxed = minimal;
  relaxed.mode = OutlierMode::relaxed;
  TubeDomains guaranteed;
  const OutlierReport rr = solve_with_outliers(p.net, p.sensor, guaranteed, relaxed);
  EXPECT_EQ(rr.minimal_outliers, 1);  // q* is reported as before
  EXPECT_EQ(rr.removal_sets, 3u);     // {0,1}, {0,2}, {1,2} of the three marks
  EXPECT_TRUE(truth_inside(guaranteed));
}

TEST(RelaxedEnclosure, UntrustedFixesCanAllGoAndThenNothingBoundsTheTube) {
  const Problem p(test::make_tiny_mission(45, test::TinyErrors::uniform));
  OutlierOptions o;
  o.max_outliers = 2;  // two fixes: both may be wrong
  TubeDomains d;
  const OutlierReport r = solve_with_outliers(p.net, p.sensor, d, o);
  ASSERT_TRUE(r.consistent());
  EXPECT_EQ(r.removal_sets, 6u);  // C(4, 2): two marks and two fixes
  EXPECT_FALSE(d.px[0].is_bounded());
  o.trust_fixes = true;
  const OutlierReport trusted = solve_with_outliers(p.net, p.sensor, d, o);
  EXPECT_EQ(trusted.removal_sets, 1u);
  EXPECT_TRUE(d.px[0].is_bounded());
}

}  // namespace
}  // namespace gesmi
