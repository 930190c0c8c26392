#pragma once
// The outlier sets of a hypothesis. phi(p) = {i : datum i is inconsistent with p}.
// Proposition 2 of seed 004 says phi is constant on a connected component of
// j^{-1}(q); a component of S_q for q above q* (a fixed q, or Remark 2's extra
// margin), or a piece left ambiguous at epsilon, may hold several sets. So a
// component is read box by box on the refined enclosure (outlier_refinement.h):
// - agreed outliers: data certainly inconsistent in every set that fits any of its
//   boxes, hence outliers in every set the component holds;
// - agreed inliers: data in none of those sets;
// - the sets proved present: the single set of an inner box (phi is that set at every
//   point), or phi at a sampled box centre that lies in S_q (evaluated as a
//   degenerate box, certain unless a datum sits exactly on its bound).
// The list is complete when every set that fits some box was proved present.

#include <algorithm>
#include <cstddef>
#include <set>
#include <vector>

#include "solver/setinv/components.h"
#include "solver/setinv/datum_tests.h"
#include "solver/setinv/outliers/gomne.h"
#include "solver/setinv/outliers/outlier_refinement.h"

namespace gesmi {

struct ComponentOutliers {
  /// The component holds exactly one outlier set, proved present: `outliers` is that set.
  bool determined = false;
  /// Agreed outliers: outliers in every set the component may hold.
  OutlierSet outliers;
  /// Agreed inliers: outliers in no set the component may hold. Data in neither list
  /// are ambiguous.
  OutlierSet agreed_inliers;
  /// Sets proved present, by size then lexicographically.
  std::vector<OutlierSet> sets;
  /// `sets` holds every set that fits the component's boxes; false: a sample.
  bool sets_complete = false;
  /// Number of sets that fit the component's boxes, saturated at max_sets + 1.
  std::size_t possible_sets = 0;
  /// A point where a set of `sets` was read (degenerate box); empty when none.
  Box point;
};

template <DatumTests Data, class Prior = NoPriorConstraint>
ComponentOutliers component_outliers(Data& data, const OutlierPaving& refined, const PavingComponent& component, int q,
                                     const Prior& prior = {}, std::size_t max_points = 512, std::size_t max_sets = 64) {
  const std::size_t n = data.datum_count();
  std::vector<std::size_t> boxes;
  for (std::size_t i : component.inner) boxes.push_back(i);
  for (std::size_t i : component.boundary) boxes.push_back(refined.inner.size() + i);
  ComponentOutliers out;
  const auto by_size = [](const OutlierSet& a, const OutlierSet& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; };
  std::set<OutlierSet, decltype(by_size)> possible(by_size), proved(by_size);
  bool overflow = false;
  std::vector<OutlierSet> fitting;
  std::vector<char> always(n, 1), never(n, 1);
  const auto centre = [](std::span<const Interval> b) {
    Box point;
    for (const Interval& x : b) point.emplace_back(x.mid());
    return point;
  };
  for (std::size_t i : boxes) {
    const OutlierFamily& f = refined.families[i];
    for (std::size_t d = 0; d < n; ++d) {
      always[d] = always[d] && f.always_outlier(d);
      never[d] = never[d] && f.never_outlier(d);
    }
    if (!overflow) {
      fitting.clear();
      overflow = !f.enumerate(max_sets, fitting);
      possible.insert(fitting.begin(), fitting.end());
      overflow = overflow || possible.size() > max_sets;
    }
    if (refined.inside(i) && f.single()) {
      if (proved.empty()) out.point = centre(refined.box(i));
      proved.insert(f.single_set());
    }
  }
  for (std::size_t d = 0; d < n; ++d) {
    if (always[d]) out.outliers.push_back(d);
    if (never[d]) out.agreed_inliers.push_back(d);
  }
  // Prove the other sets at box centres, where they may be.
  std::vector<IBool> values(n, IBool::maybe());
  std::size_t tried = 0;
  for (std::size_t i : boxes) {
    if (tried >= max_points || (!overflow && proved.size() == possible.size())) break;
    if (refined.inside(i) && refined.families[i].single()) continue;
    ++tried;
    const Box point = centre(refined.box(i));
    const IBool g = prior(point);
    if (!g.is_true()) continue;
    data.evaluate(point, 0, values, static_cast<int>(n));
    OutlierSet phi;
    bool certain = true;
    for (std::size_t d = 0; d < n; ++d) {
      if (values[d].is_false() || values[d].is_empty()) phi.push_back(d);
      certain = certain && !values[d].is_maybe();
    }
    if (!certain || static_cast<int>(phi.size()) > q) continue;
    if (proved.empty()) out.point = point;
    proved.insert(std::move(phi));
  }
  out.sets.assign(proved.begin(), proved.end());
  out.possible_sets = overflow ? max_sets + 1 : possible.size();
  out.sets_complete = !overflow && proved.size() == possible.size();
  out.determined = out.sets_complete && out.sets.size() == 1;
  return out;
}

}  // namespace gesmi
