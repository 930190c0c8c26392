// Components that mean hypotheses (hypotheses.h): seed 004's Lemma 3 on Example 2 at
// q = 2, checked against phi evaluated in plain doubles on a grid, and the joining
// rules on boxes built by hand.

#include "solver/setinv/outliers/hypotheses.h"

#include <gtest/gtest.h>

#include <set>

#include "solver/setinv/outliers/outlier_sets.h"
#include "tests/solver/setinv/gaussian_example.h"

namespace gesmi {
namespace {

using test::gaussian_phi;

TEST(Hypotheses, ExampleTwoAtQ2HasOneHypothesisPerOutlierSetAsLemma3Requires) {
  ImageInBox<test::GaussianDensity> data(test::GaussianDensity{}, test::gaussian_data());
  SiviaOptions o;
  o.epsilon = 0.01;
  const SiviaResult sq = sivia_q(data, 2, std::span<const Box>(&test::gaussian_frame(), 1), o);
  OutlierRefinementOptions r;
  r.q = 2;
  r.epsilon = 0.01;
  const OutlierPaving refined = refine_by_outliers(data, sq, r);
  const auto hypotheses = hypothesis_components(refined);
  // The sets of exactly two outliers on a grid: Lemma 3 puts each in its own
  // component of j^{-1}(2), so at least that many hypotheses.
  std::set<OutlierSet> grid_two;
  for (int i = 0; i <= 500; ++i)
    for (int k = 0; k < 300; ++k) {
      const auto phi = gaussian_phi(-2.0 + 0.02 * i, 0.005 + 0.01 * k);
      if (phi.size() == 2) grid_two.insert(phi);
    }
  ASSERT_EQ(grid_two.size(), 4u);
  std::set<OutlierSet> determined_two;
  std::size_t determined_hypotheses_of_two = 0;
  std::vector<int> hypothesis_of(refined.size(), -1);
  std::vector<ComponentOutliers> named;
  for (std::size_t h = 0; h < hypotheses.size(); ++h) {
    for (std::size_t i : hypotheses[h].inner) hypothesis_of[i] = static_cast<int>(h);
    for (std::size_t i : hypotheses[h].boundary) hypothesis_of[refined.inner.size() + i] = static_cast<int>(h);
    named.push_back(component_outliers(data, refined, hypotheses[h], 2));
    if (named.back().determined && named.back().outliers.size() == 2) {
      determined_two.insert(named.back().outliers);
      ++determined_hypotheses_of_two;
    }
  }
  EXPECT_GE(determined_hypotheses_of_two, 4u);
  EXPECT_EQ(determined_two, grid_two);
  // A determined hypothesis holds no grid point of S_2 with another phi.
  for (int i = 0; i <= 250; ++i)
    for (int k = 0; k < 150; ++k) {
      const double p1 = -2.0 + 0.04 * i + 0.001, p2 = 0.0105 + 0.02 * k;
      const auto phi = gaussian_phi(p1, p2);
      if (phi.size() > 2) continue;
      for (std::size_t b = 0; b < refined.size(); ++b) {
        const auto box = refined.box(b);
        if (!box[0].contains(p1) || !box[1].contains(p2)) continue;
        const ComponentOutliers& n = named[static_cast<std::size_t>(hypothesis_of[b])];
        if (n.determined) {
          EXPECT_EQ(n.outliers, phi) << p1 << " " << p2;
        }
      }
    }
}

// Boxes built by hand: [a, a+1] x [0, 1] with the given verdicts of two data, q = 1.
OutlierPaving row(const std::vector<std::vector<IBool>>& verdicts) {
  OutlierPaving p;
  p.inner = Paving(2);
  p.boundary = Paving(2);
  for (std::size_t a = 0; a < verdicts.size(); ++a) {
    p.inner.add(Box{Interval(static_cast<double>(a), static_cast<double>(a) + 1.0), Interval(0, 1)});
    p.families.emplace_back(verdicts[a], 0, 1);
  }
  return p;
}

TEST(Hypotheses, TouchingBoxesWithDifferentSetsAreDifferentHypotheses) {
  const IBool yes(true), no(false), maybe = IBool::maybe();
  // {0} | {1}: two hypotheses although the boxes touch.
  EXPECT_EQ(hypothesis_components(row({{no, yes}, {yes, no}})).size(), 2u);
  // {0} | {0}: one.
  EXPECT_EQ(hypothesis_components(row({{no, yes}, {no, yes}})).size(), 1u);
  // {0} | ambiguous {0} or {} : the ambiguous box joins the only hypothesis it may extend.
  EXPECT_EQ(hypothesis_components(row({{no, yes}, {maybe, yes}})).size(), 1u);
  // {0} | ambiguous {0}, {1} or {} | {1}: the ambiguous box is the gap between two
  // hypotheses and stays on its own.
  EXPECT_EQ(hypothesis_components(row({{no, yes}, {maybe, maybe}, {yes, no}})).size(), 3u);
  // {0} | ambiguous {1} or {} : it may not extend {0}, so it stays on its own.
  EXPECT_EQ(hypothesis_components(row({{no, yes}, {yes, maybe}})).size(), 2u);
}

}  // namespace
}  // namespace gesmi
