// Outlier-tolerant solve: the minimal number of outliers, the hypotheses that
// restore consistency, and the truth inside the hull.

#include "solver/network/outliers/outlier_solver.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/support/tiny_network.h"

namespace gesmi {
namespace {

using Problem = test::TinyNetwork;

bool has_hypothesis(const OutlierReport& r, std::vector<std::size_t> h) {
  return std::find(r.hypotheses.begin(), r.hypotheses.end(), h) != r.hypotheses.end();
}

TEST(OutlierSolver, ConsistentDataNeedNoOutlier) {
  const Problem s(test::make_tiny_mission(31, test::TinyErrors::uniform));
  TubeDomains d;
  const OutlierReport r = solve_with_outliers(s.net, s.sensor, d, {2, {}});
  EXPECT_EQ(r.minimal_outliers, 0);
  EXPECT_TRUE(r.hypotheses.empty());
}

TEST(OutlierSolver, OneCorruptedMarkGivesQStarOneAndKeepsTheTruth) {
  test::TinyMission t = test::make_tiny_mission(32, test::TinyErrors::uniform);
  t.mission.mark_range[1] += 25.0;
  const Problem s(t);
  TubeDomains d;
  const OutlierReport r = solve_with_outliers(s.net, s.sensor, d, {2, {}});
  ASSERT_EQ(r.minimal_outliers, 1);
  EXPECT_FALSE(r.first_solve.consistent());
  EXPECT_TRUE(has_hypothesis(r, {1}));
  // With a single mine seen twice, either mark can be the wrong one: nothing is
  // decided, and the hull covers both readings.
  EXPECT_TRUE(has_hypothesis(r, {0}));
  EXPECT_EQ(r.detection_outlier[0] + r.detection_outlier[1], 0);
  const Mission& m = t.mission;
  for (std::size_t k = 0; k < m.size(); ++k) {
    ASSERT_TRUE(d.px[k].contains(m.truth_x[k])) << k;
    ASSERT_TRUE(d.py[k].contains(m.truth_y[k])) << k;
  }
  EXPECT_TRUE(d.mines[0][0].contains(m.truth_mines[0]));
  EXPECT_LT(r.full_solves, r.hypotheses_screened + 1);
}

TEST(OutlierSolver, AFixFarOffIsNamedWhenNothingElseExplainsIt) {
  test::TinyMission t = test::make_tiny_mission(33, test::TinyErrors::uniform);
  t.fixes[1].box[0] = t.fixes[1].box[0] + Interval(400.0);
  const Problem s(t);
  TubeDomains d;
  const OutlierReport r = solve_with_outliers(s.net, s.sensor, d, {1, {}});
  ASSERT_EQ(r.minimal_outliers, 1);
  EXPECT_TRUE(has_hypothesis(r, {s.net.detections.size() + 1}));
}

TEST(OutlierSolver, ReportsWhenMoreOutliersThanAllowed) {
  test::TinyMission t = test::make_tiny_mission(34, test::TinyErrors::uniform);
  t.fixes[0].box[1] = t.fixes[0].box[1] + Interval(300.0);
  t.fixes[1].box[1] = t.fixes[1].box[1] - Interval(300.0);
  const Problem s(t);
  TubeDomains d;
  const OutlierReport r = solve_with_outliers(s.net, s.sensor, d, {0, {}});
  EXPECT_EQ(r.minimal_outliers, -1);
  EXPECT_FALSE(r.consistent());
}

}  // namespace
}  // namespace gesmi
