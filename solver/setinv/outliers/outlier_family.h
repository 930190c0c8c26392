#pragma once
// The outlier sets possible on a box. On a box P, each datum is certainly
// inconsistent (F), certainly consistent, or undetermined (U). Every point p of P
// then has F ⊆ phi(p) ⊆ F ∪ U, where phi(p) is the set of data inconsistent with p
// (seed 004, section IV). Points of S_q have |phi(p)| <= q, and when every S_k with
// k < q_lower was proved empty, |phi(p)| >= q_lower. The family of P is the sets
// allowed by these bounds: {F ∪ V : V ⊆ U, q_lower <= |F ∪ V| <= q}.

#include <cstddef>
#include <span>
#include <vector>

#include "solver/interval/interval_bool.h"

namespace gesmi {

/// A set of data, as sorted indices.
using OutlierSet = std::vector<std::size_t>;

class OutlierFamily {
 public:
  OutlierFamily() = default;
  /// From the data tests on a box (empty IBools count as inconsistent, as in
  /// count_data) and the bounds on the number of outliers.
  OutlierFamily(std::span<const IBool> values, int q_lower, int q);

  const OutlierSet& certain() const { return certain_; }
  const OutlierSet& undetermined() const { return undetermined_; }
  /// No set fits: the box holds no point of S_q with at least q_lower outliers.
  bool empty() const { return min_extra() > max_extra(); }
  /// Exactly one set fits (every point of S_q in the box has that phi).
  bool single() const;
  /// The one set when single().
  OutlierSet single_set() const;
  /// Datum i is in every set of the family / in none.
  bool always_outlier(std::size_t i) const;
  bool never_outlier(std::size_t i) const;
  bool contains(const OutlierSet& set) const;
  /// Some set belongs to both families.
  bool intersects(const OutlierFamily& other) const;
  /// Number of sets, saturated at `cap + 1`.
  std::size_t count(std::size_t cap) const;
  /// The sets, or nothing (and false) when there are more than `cap`.
  bool enumerate(std::size_t cap, std::vector<OutlierSet>& out) const;

 private:
  // Sizes of V ⊆ U allowed: [min_extra, max_extra].
  int min_extra() const;
  int max_extra() const;

  OutlierSet certain_;
  OutlierSet undetermined_;
  int q_lower_ = 0;
  int q_ = 0;
};

}  // namespace gesmi
