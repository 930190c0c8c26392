#pragma once
// Proposition 2 of seed 004: on a connected component of j^{-1}(q) the data treated
// as outliers are the same, so they are read at one point of each component:
// phi(p) = {i : datum i is inconsistent with p}. The point is evaluated as a
// degenerate box, so phi is certain unless a datum lies exactly on its bound.

#include <cstddef>
#include <vector>

#include "solver/setinv/components.h"
#include "solver/setinv/datum_tests.h"
#include "solver/setinv/sivia_options.h"

namespace gesmi {

struct ComponentOutliers {
  /// phi was read with certainty at a point of the component where exactly q data
  /// fail (Proposition 2 applies); false when no such point was found among the
  /// sampled box centres (e.g. an enclosure made of boundary boxes only).
  bool determined = false;
  std::vector<std::size_t> outliers;  // indices of the data considered outliers
  Box point;                          // the point where phi was read (degenerate box)
};

/// Reads phi at the centres of the component's inner boxes first, then of its
/// boundary boxes (at most `max_points` in all).
template <DatumTests Data>
ComponentOutliers component_outliers(Data& data, const SiviaResult& pavings, const PavingComponent& component, int q,
                                     std::size_t max_points = 512) {
  ComponentOutliers best;
  std::vector<IBool> values(data.datum_count(), IBool::maybe());
  std::size_t tried = 0;
  const auto try_box = [&](std::span<const Interval> box) {
    Box point;
    for (const Interval& x : box) point.emplace_back(x.mid());
    data.evaluate(point, 0, values, static_cast<int>(values.size()));
    std::vector<std::size_t> out;
    bool certain = true;
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i].is_false()) out.push_back(i);
      certain = certain && !values[i].is_maybe();
    }
    if (!certain || static_cast<int>(out.size()) > q) return false;
    const bool exact = static_cast<int>(out.size()) == q;
    if (exact || best.point.empty()) best = {exact, std::move(out), std::move(point)};
    return exact;
  };
  for (std::size_t i : component.inner)
    if (tried++ < max_points && try_box(pavings.inner.box(i))) return best;
  for (std::size_t i : component.boundary)
    if (tried++ < max_points && try_box(pavings.boundary.box(i))) return best;
  return best;
}

}  // namespace gesmi
