// The limits of `estimate` (estimation_problem.h) on seed 004's Example 2: a box or
// time limit over the whole run is reported by the levels it cut short, and every
// level's boxes still enclose j^{-1}(q), checked against phi computed in plain doubles
// on a grid (gaussian_example.h).

#include "solver/setinv/estimation_problem.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/solver/setinv/gaussian_example.h"

namespace gesmi {
namespace {

using test::gaussian_phi;

EstimationProblem example2(double epsilon) {
  EstimationProblem p;
  for (int i = 1; i <= 6; ++i) p.t.push_back(i);
  p.data = test::gaussian_data();
  p.prior = test::gaussian_frame();
  p.epsilon = epsilon;
  p.levels = {0, 1, 2, 3, 4, 5, 6};
  return p;
}

bool in_paving(const Paving& paving, double p1, double p2) {
  for (std::size_t i = 0; i < paving.size(); ++i)
    if (paving.box(i)[0].contains(p1) && paving.box(i)[1].contains(p2)) return true;
  return false;
}

// Every grid point of the frame with |phi| = q lies in a box of its set at level q, or
// in a box fitting too many sets to list. Returns the points checked.
std::size_t expect_enclosure(const EstimationResult& r, int steps) {
  std::size_t checked = 0;
  for (int i = 0; i <= steps; ++i)
    for (int k = 1; k <= steps; ++k) {
      const double p1 = -2.0 + 10.0 * i / steps, p2 = 3.0 * k / steps;
      const OutlierSet phi = gaussian_phi(p1, p2);
      for (const EstimationLevel& level : r.levels) {
        if (phi.size() != static_cast<std::size_t>(level.q)) continue;
        const auto set = std::find_if(level.sets.begin(), level.sets.end(),
                                      [&](const OutlierSetPaving& s) { return s.outliers == phi; });
        const bool found = (set != level.sets.end() && (in_paving(set->inner, p1, p2) || in_paving(set->boundary, p1, p2))) ||
                           in_paving(level.unresolved, p1, p2);
        EXPECT_TRUE(found) << "q = " << level.q << " at " << p1 << ", " << p2;
        ++checked;
      }
    }
  return checked;
}

TEST(Estimate, WithoutLimitsNoLevelSaysOneWasHit) {
  const EstimationResult r = estimate(example2(0.01));
  ASSERT_EQ(r.levels.size(), 7u);
  EXPECT_FALSE(r.box_limit_hit());
  EXPECT_FALSE(r.time_limit_hit());
  EXPECT_EQ(r.q_star(), 1);  // j^{-1}(0) holds no inner box; j^{-1}(1) is datum 5's set
  EXPECT_GT(expect_enclosure(r, 200), 10'000u);
}

TEST(Estimate, ABoxLimitKeepsEveryLevelAnEnclosureAndSaysSo) {
  EstimationProblem p = example2(0.005);
  p.max_boxes = 3000;  // the run needs about 5 x 10^5 at this epsilon, level 0 alone 1.4 x 10^4
  const EstimationResult r = estimate(p);
  ASSERT_EQ(r.levels.size(), 7u);
  EXPECT_TRUE(r.box_limit_hit());
  EXPECT_FALSE(r.time_limit_hit());
  EXPECT_TRUE(r.levels.back().box_limit_hit);  // past the limit: the prior box, kept whole
  EXPECT_GE(r.boxes_examined(), p.max_boxes);
  // The refinement still evaluates once each box SIVIA kept, and a level past the
  // limit examines its prior box in each step: at most about twice the limit.
  EXPECT_LE(r.boxes_examined(), 2 * p.max_boxes + 2 * r.levels.size());
  EXPECT_GT(expect_enclosure(r, 200), 10'000u);
}

TEST(Estimate, ATimeLimitKeepsEveryLevelAnEnclosureAndSaysSo) {
  EstimationProblem p = example2(1e-9);  // would take far longer than the limit
  p.max_seconds = 0.05;
  const EstimationResult r = estimate(p);
  ASSERT_EQ(r.levels.size(), 7u);
  EXPECT_TRUE(r.time_limit_hit());
  EXPECT_FALSE(r.box_limit_hit());
  EXPECT_TRUE(r.levels.back().time_limit_hit);
  EXPECT_LT(r.seconds, 5.0);  // the limit plus the last 1,024 boxes before each check
  EXPECT_GT(expect_enclosure(r, 60), 1'000u);
}

TEST(Estimate, ProgressNamesEachLevelAndCountsTheRunsBoxes) {
  std::vector<EstimationProgress> calls;
  const EstimationResult r = estimate(example2(0.01), [&](const EstimationProgress& p) { calls.push_back(p); });
  ASSERT_GE(calls.size(), 7u);
  std::vector<int> started;
  for (const EstimationProgress& p : calls) {
    EXPECT_EQ(p.level_count, 7u);
    if (started.empty() || p.level != started.size() - 1) started.push_back(p.q);
    EXPECT_LE(p.boxes_examined, r.boxes_examined());
  }
  EXPECT_EQ(started, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
}

}  // namespace
}  // namespace gesmi
