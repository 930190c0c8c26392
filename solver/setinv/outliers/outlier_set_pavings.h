#pragma once
// S_q split by outlier set: for each set O that fits some box of the refined
// enclosure (solver/setinv/outliers/outlier_refinement.h), the paving of
//     P_O = {p in S_q : phi(p) = O},
// the poses consistent with exactly the data outside O. Seed 004 draws these sets
// for Example 2 (Figure 1, one panel per q: the sets of size q).
//
// Inner boxes of P_O lie in S_q and O is the only set that fits them, so phi = O at
// every point. Boundary boxes of P_O may hold points of P_O: O is their only set but
// they are not proved inside S_q, or several sets fit them at epsilon (such a box is
// a boundary box of each of its sets). Boxes with more than `max_sets_per_box`
// sets are listed as unresolved instead. The union of every P_O's boxes and the
// unresolved boxes is the refined enclosure.
//
// Hulls are reported as components' are (components.h): on a periodic dimension
// (theta) the shortest arc, so a set straddling the period's cut is not given the
// whole turn.

#include <cstddef>
#include <vector>

#include "solver/setinv/components.h"
#include "solver/setinv/outliers/outlier_refinement.h"

namespace gesmi {

struct OutlierSetPaving {
  OutlierSet outliers;
  Paving inner;
  Paving boundary;
  Box hull;  // of inner and boundary; on the periodic dimension the shortest arc (wrapped_hull)
  double inner_volume() const { return inner.volume(); }
  double outer_volume() const { return inner.volume() + boundary.volume(); }
};

struct OutlierPartition {
  std::vector<OutlierSetPaving> sets;  // sorted by size, then lexicographically
  Paving unresolved;                   // boxes fitting too many sets to list
};

/// `periodic` names the periodic dimension, its period and the window of the hulls
/// (its wrap_tolerance is not used); the default has none.
OutlierPartition partition_by_outlier_set(const OutlierPaving& refined, const ComponentOptions& periodic = {},
                                          std::size_t max_sets_per_box = 64);

/// The sets of exactly `size` outliers (seed 004's j^{-1}(q) for size = q).
std::vector<OutlierSetPaving> sets_of_size(const OutlierPartition& partition, std::size_t size);

}  // namespace gesmi
