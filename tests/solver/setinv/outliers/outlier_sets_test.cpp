// The outlier sets of a hypothesis (outlier_sets.h) on the 24-sensor belt of seed 004
// with one outlier more than the minimum (q = 8, Remark 2's margin): the names are
// checked against phi evaluated at points by the point form of the range model
// (simulated_range against each measurement's interval).

#include "solver/setinv/outliers/outlier_sets.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "io/localization/localization_scenario.h"
#include "solver/setinv/localization/localization_problem.h"
#include "solver/setinv/localization/range_model.h"
#include "tests/support/paths.h"

namespace gesmi {
namespace {

constexpr std::size_t kS03 = 3;  // sensor S03: consistent at the true pose
const OutlierSet kInjected{2, 5, 9, 13, 16, 20, 22};

OutlierSet phi_at(const LocalizationProblem& p, const Pose<double>& pose) {
  OutlierSet phi;
  for (std::size_t i = 0; i < p.ranges.size(); ++i) {
    const RangeSensor& s = p.range_sensors[p.ranges[i].sensor];
    if (!range_interval(p.ranges[i].range, s.precision).contains(simulated_range(pose, s, std::span<const Segment>(p.map.walls))))
      phi.push_back(i);
  }
  return phi;
}

bool includes(const OutlierSet& big, const OutlierSet& small) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

TEST(OutlierSets, BeltWithOneOutlierMoreNamesOnlyWhatEverySetAgreesOn) {
  LocalizationProblem p = io::read_localization_scenario(test::source_dir() + "/missions/localization/belt24_outliers.yaml");
  p.extra_outliers = 1;
  p.epsilon = 0.004;
  const LocalizationResult r = localize(p);
  ASSERT_EQ(r.q, 8);
  ASSERT_EQ(phi_at(p, *p.truth), kInjected);
  bool some_hypothesis_holds_several_sets = false, truth_found = false;
  std::size_t points_in_s8 = 0;
  for (const LocalizationHypothesis& h : r.hypotheses) {
    const ComponentOutliers& o = h.outliers;
    some_hypothesis_holds_several_sets = some_hypothesis_holds_several_sets || o.sets.size() > 1;
    EXPECT_EQ(o.determined, o.sets_complete && o.sets.size() == 1);
    for (const OutlierSet& s : o.sets) {
      EXPECT_TRUE(includes(s, o.outliers));  // named outliers are in every set listed
      EXPECT_GE(s.size(), 7u);
      EXPECT_LE(s.size(), 8u);
    }
    // S03 holds at the truth: no hypothesis that may hold the true set names it.
    if (h.contains_truth || std::find(o.sets.begin(), o.sets.end(), kInjected) != o.sets.end()) {
      EXPECT_FALSE(std::binary_search(o.outliers.begin(), o.outliers.end(), kS03));
      truth_found = truth_found || h.contains_truth;
    }
    // Points of S_8 in the hypothesis's boxes: every named outlier fails there, every
    // agreed inlier holds, and a determined hypothesis has exactly its set.
    const auto check_box = [&](std::span<const Interval> box) {
      for (int c = 0; c < 27; ++c) {
        const double f[3] = {(c % 3 + 0.5) / 3.0, (c / 3 % 3 + 0.5) / 3.0, (c / 9 + 0.5) / 3.0};
        const Pose<double> at{box[0].lo() + f[0] * box[0].width(), box[1].lo() + f[1] * box[1].width(),
                              box[2].lo() + f[2] * box[2].width()};
        const OutlierSet phi = phi_at(p, at);
        if (phi.size() > 8) continue;
        ++points_in_s8;
        EXPECT_TRUE(includes(phi, o.outliers));
        for (std::size_t i : o.agreed_inliers) EXPECT_FALSE(std::binary_search(phi.begin(), phi.end(), i)) << i;
        if (o.determined) {
          EXPECT_EQ(phi, o.outliers);
        }
        if (o.sets_complete) {
          EXPECT_NE(std::find(o.sets.begin(), o.sets.end(), phi), o.sets.end());
        }
      }
    };
    for (std::size_t i : h.component.inner) check_box(r.paving.inner.box(i));
    for (std::size_t i : h.component.boundary) check_box(r.paving.boundary.box(i));
  }
  EXPECT_TRUE(truth_found);
  // The margin makes S_8 hold several outlier sets in touching regions: the case
  // where a name read at one point went wrong.
  EXPECT_TRUE(some_hypothesis_holds_several_sets);
  EXPECT_GT(points_in_s8, 1000u);
}

}  // namespace
}  // namespace gesmi
