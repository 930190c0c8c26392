// S_q split by outlier set (outlier_set_pavings.h) on seed 004's Example 2 at q = 2:
// the pavings of P_O = {p in S_2 : phi(p) = O}, checked against phi evaluated in
// plain doubles on grids (gaussian_example.h).

#include "solver/setinv/outliers/outlier_set_pavings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <set>

#include "tests/solver/setinv/gaussian_example.h"
#include "solver/model/angles.h"

namespace gesmi {
namespace {

using test::gaussian_phi;

struct PartitionedExample2 {
  ImageInBox<test::GaussianDensity> data{test::GaussianDensity{}, test::gaussian_data()};
  OutlierPaving refined;
  OutlierPartition partition;
  PartitionedExample2() {
    SiviaOptions o;
    o.epsilon = 0.01;
    const SiviaResult sq = sivia_q(data, 2, std::span<const Box>(&test::gaussian_frame(), 1), o);
    OutlierRefinementOptions r;
    r.q = 2;
    r.epsilon = 0.01;
    refined = refine_by_outliers(data, sq, r);
    partition = partition_by_outlier_set(refined);
  }
};

TEST(OutlierSetPavings, InnerBoxesOfASetHaveExactlyThatPhi) {
  const PartitionedExample2 e;
  std::size_t checked = 0;
  for (const OutlierSetPaving& s : e.partition.sets) {
    EXPECT_LE(s.outliers.size(), 2u);
    for (std::size_t b = 0; b < s.inner.size(); ++b)
      for (int i = 0; i <= 4; ++i)
        for (int k = 0; k <= 4; ++k) {
          const auto box = s.inner.box(b);
          const double p1 = box[0].lo() + box[0].width() * i / 4.0, p2 = box[1].lo() + box[1].width() * k / 4.0;
          EXPECT_EQ(gaussian_phi(p1, p2), s.outliers) << p1 << " " << p2;
          ++checked;
        }
  }
  EXPECT_GT(checked, 1000u);
}

TEST(OutlierSetPavings, EveryPointOfS2LiesInThePavingOfItsSet) {
  const PartitionedExample2 e;
  std::set<OutlierSet> on_grid;
  for (int i = 0; i <= 500; ++i)
    for (int k = 0; k < 300; ++k) {
      const double p1 = -2.0 + 0.02 * i, p2 = 0.005 + 0.01 * k;
      const auto phi = gaussian_phi(p1, p2);
      if (phi.size() > 2) continue;
      on_grid.insert(phi);
      const auto it = std::find_if(e.partition.sets.begin(), e.partition.sets.end(),
                                   [&](const OutlierSetPaving& s) { return s.outliers == phi; });
      const bool found = (it != e.partition.sets.end() && (test::in_paving(it->inner, p1, p2) || test::in_paving(it->boundary, p1, p2))) ||
                         test::in_paving(e.partition.unresolved, p1, p2);
      EXPECT_TRUE(found) << p1 << " " << p2;
    }
  // The exactly-2 sets are those of the grid (seed 004's j^{-1}(2)); each is proved
  // present by inner boxes.
  std::set<OutlierSet> exactly_two;
  for (const OutlierSetPaving& s : sets_of_size(e.partition, 2))
    if (!s.inner.empty()) exactly_two.insert(s.outliers);
  std::set<OutlierSet> grid_two;
  for (const OutlierSet& s : on_grid)
    if (s.size() == 2) grid_two.insert(s);
  EXPECT_EQ(grid_two.size(), 4u);
  EXPECT_EQ(exactly_two, grid_two);
}

TEST(OutlierSetPavings, TheUnionOfThePartitionIsTheRefinedEnclosure) {
  const PartitionedExample2 e;
  const auto key = [](std::span<const Interval> b) { return std::vector<double>{b[0].lo(), b[0].hi(), b[1].lo(), b[1].hi()}; };
  std::set<std::vector<double>> refined, partition;
  double volume = 0.0;
  for (std::size_t i = 0; i < e.refined.size(); ++i) refined.insert(key(e.refined.box(i)));
  for (const OutlierSetPaving& s : e.partition.sets)
    for (const Paving* p : {&s.inner, &s.boundary})
      for (std::size_t i = 0; i < p->size(); ++i) partition.insert(key(p->box(i)));
  for (std::size_t i = 0; i < e.partition.unresolved.size(); ++i) partition.insert(key(e.partition.unresolved.box(i)));
  for (const auto& b : partition) volume += (b[1] - b[0]) * (b[3] - b[2]);
  EXPECT_EQ(partition, refined);
  EXPECT_NEAR(volume, e.refined.inner.volume() + e.refined.boundary.volume(), 1e-12);
  // A box is inner for at most one set: the inner pavings do not overlap.
  std::set<std::vector<double>> inner;
  std::size_t inner_count = 0;
  for (const OutlierSetPaving& s : e.partition.sets)
    for (std::size_t i = 0; i < s.inner.size(); ++i, ++inner_count) inner.insert(key(s.inner.box(i)));
  EXPECT_EQ(inner.size(), inner_count);
}

TEST(OutlierSetPavings, HullOfASetAcrossThePeriodIsTheShortArc) {
  // Two boxes of the set {0} (datum 0 certainly fails, datum 1 certainly holds), one
  // ending at 2 pi and one starting at 0: on the circle they are the arc [-0.1, 0.1].
  OutlierPaving refined;
  refined.inner = refined.boundary = Paving(3);
  refined.inner.add(Box{Interval(0.0, 1.0), Interval(2.0, 3.0), Interval(kTwoPi - 0.1, kTwoPi)});
  refined.inner.add(Box{Interval(0.5, 1.5), Interval(2.0, 3.0), Interval(0.0, 0.1)});
  const std::vector<IBool> values{IBool(false), IBool(true)};
  refined.families.assign(2, OutlierFamily(values, 0, 1));
  ComponentOptions wrap;  // as gesmi localize, for a prior theta in [0, 2 pi]
  wrap.periodic_dimension = 2;
  wrap.period = kTwoPi;
  wrap.periodic_origin = 0.0;

  const OutlierPartition p = partition_by_outlier_set(refined, wrap);
  ASSERT_EQ(p.sets.size(), 1u);
  EXPECT_EQ(p.sets[0].outliers, OutlierSet{0});
  EXPECT_EQ(p.sets[0].inner.size(), 2u);
  EXPECT_NEAR(p.sets[0].hull[2].lo(), -0.1, 1e-12);
  EXPECT_NEAR(p.sets[0].hull[2].hi(), 0.1, 1e-12);
  EXPECT_EQ(p.sets[0].hull[0], Interval(0.0, 1.5));  // the other dimensions keep the plain hull
  EXPECT_EQ(p.sets[0].hull[1], Interval(2.0, 3.0));
  // Without a periodic dimension the same boxes span the whole turn.
  EXPECT_EQ(partition_by_outlier_set(refined).sets[0].hull[2], Interval(0.0, kTwoPi));
}

}  // namespace
}  // namespace gesmi
