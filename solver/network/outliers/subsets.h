#pragma once
// Enumerating the removal sets of an outlier search: every subset of size q of a
// list of constraint ids, in lexicographic order, each handed over sorted.

#include <cstddef>
#include <vector>

namespace gesmi {

/// Calls visit(subset) on every q-element subset of ids (ids sorted ascending).
template <class Visit>
void for_each_subset(const std::vector<std::size_t>& ids, std::size_t q, Visit visit) {
  const std::size_t n = ids.size();
  if (q > n) return;
  std::vector<std::size_t> at(q), subset(q);
  for (std::size_t i = 0; i < q; ++i) at[i] = i;
  while (true) {
    for (std::size_t i = 0; i < q; ++i) subset[i] = ids[at[i]];
    visit(static_cast<const std::vector<std::size_t>&>(subset));
    std::size_t i = q;
    while (i > 0 && at[i - 1] == n - q + i - 1) --i;
    if (i == 0) return;
    ++at[i - 1];
    for (std::size_t j = i; j < q; ++j) at[j] = at[j - 1] + 1;
  }
}

}  // namespace gesmi
