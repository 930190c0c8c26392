#pragma once
// Components of S_q that each mean one hypothesis: one outlier set, one connected
// piece (seed 004, Lemma 3 and Proposition 2; seed 002, section 4).
//
// Two boxes that merely touch may hold different outlier sets: P_O and P_O' can
// meet along a border where a datum changes side, and for q > q* the sets of size q
// border those of size q - 1. So on the refined enclosure (outlier_refinement.h):
// - a box where one set fits ("determined") joins the touching boxes where the same
//   single set fits;
// - boxes where several sets fit (still undetermined at epsilon: "ambiguous") join
//   the touching ambiguous boxes with which they share a possible set, into clusters;
// - a cluster joins the one determined component it touches with a set it may hold.
//   A cluster touching two or more such components, or none, is a hypothesis of its
//   own: it is the gap between hypotheses that the accuracy epsilon could not
//   resolve, and it holds several outlier sets (outlier_sets.h names what they agree on).

#include <vector>

#include "solver/setinv/components.h"
#include "solver/setinv/outliers/outlier_refinement.h"

namespace gesmi {

/// Components over refined.inner and refined.boundary, largest first.
std::vector<PavingComponent> hypothesis_components(const OutlierPaving& refined, const ComponentOptions& options = {});

}  // namespace gesmi
