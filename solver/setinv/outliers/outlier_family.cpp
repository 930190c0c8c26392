#include "solver/setinv/outliers/outlier_family.h"

#include <algorithm>
#include <iterator>

namespace gesmi {
namespace {

bool has(const OutlierSet& s, std::size_t i) { return std::binary_search(s.begin(), s.end(), i); }

OutlierSet set_union(const OutlierSet& a, const OutlierSet& b) {
  OutlierSet out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace

OutlierFamily::OutlierFamily(std::span<const IBool> values, int q_lower, int q) : q_lower_(q_lower), q_(q) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i].is_false() || values[i].is_empty()) certain_.push_back(i);
    if (values[i].is_maybe()) undetermined_.push_back(i);
  }
}

int OutlierFamily::min_extra() const { return std::max(0, q_lower_ - static_cast<int>(certain_.size())); }
int OutlierFamily::max_extra() const {
  return std::min(static_cast<int>(undetermined_.size()), q_ - static_cast<int>(certain_.size()));
}

bool OutlierFamily::single() const {
  const int lo = min_extra(), hi = max_extra(), u = static_cast<int>(undetermined_.size());
  return lo == hi && (lo == 0 || lo == u);
}

OutlierSet OutlierFamily::single_set() const {
  return min_extra() == 0 ? certain_ : set_union(certain_, undetermined_);
}

bool OutlierFamily::always_outlier(std::size_t i) const {
  // Every allowed V holds i when a V without i is too small: |U| - 1 < min_extra.
  return has(certain_, i) || (has(undetermined_, i) && min_extra() >= static_cast<int>(undetermined_.size()));
}

bool OutlierFamily::never_outlier(std::size_t i) const {
  if (has(certain_, i)) return false;
  return !has(undetermined_, i) || max_extra() <= 0;
}

bool OutlierFamily::contains(const OutlierSet& set) const {
  const int n = static_cast<int>(set.size());
  if (n < q_lower_ || n > q_) return false;
  if (!std::includes(set.begin(), set.end(), certain_.begin(), certain_.end())) return false;
  return std::all_of(set.begin(), set.end(), [&](std::size_t i) { return has(certain_, i) || has(undetermined_, i); });
}

bool OutlierFamily::intersects(const OutlierFamily& other) const {
  if (empty() || other.empty()) return false;
  // A common set O has F1 ∪ F2 ⊆ O ⊆ (F1 ∪ U1) ∩ (F2 ∪ U2), within both size bounds.
  const OutlierSet low = set_union(certain_, other.certain_);
  const OutlierSet a = set_union(certain_, undetermined_), b = set_union(other.certain_, other.undetermined_);
  OutlierSet high;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(high));
  if (!std::includes(high.begin(), high.end(), low.begin(), low.end())) return false;
  const int lo = std::max({static_cast<int>(low.size()), q_lower_, other.q_lower_});
  const int hi = std::min({static_cast<int>(high.size()), q_, other.q_});
  return lo <= hi;
}

std::size_t OutlierFamily::count(std::size_t cap) const {
  const int u = static_cast<int>(undetermined_.size());
  std::size_t total = 0;
  for (int k = min_extra(); k <= max_extra(); ++k) {
    // C(u, k), saturated: the product of the first j factors over j! is C(u, j) exactly.
    std::size_t c = 1;
    for (int j = 1; j <= k && c <= cap; ++j) c = c * static_cast<std::size_t>(u - k + j) / static_cast<std::size_t>(j);
    total += std::min(c, cap + 1);
    if (total > cap) return cap + 1;
  }
  return total;
}

bool OutlierFamily::enumerate(std::size_t cap, std::vector<OutlierSet>& out) const {
  if (count(cap) > cap) return false;
  const int u = static_cast<int>(undetermined_.size());
  for (int k = min_extra(); k <= max_extra(); ++k) {
    std::vector<int> pick(static_cast<std::size_t>(k));
    for (int j = 0; j < k; ++j) pick[static_cast<std::size_t>(j)] = j;
    for (;;) {
      OutlierSet extra;
      for (int j : pick) extra.push_back(undetermined_[static_cast<std::size_t>(j)]);
      out.push_back(set_union(certain_, extra));
      // Next combination in lexicographic order.
      int j = k - 1;
      while (j >= 0 && pick[static_cast<std::size_t>(j)] == u - k + j) --j;
      if (j < 0) break;
      ++pick[static_cast<std::size_t>(j)];
      for (int l = j + 1; l < k; ++l) pick[static_cast<std::size_t>(l)] = pick[static_cast<std::size_t>(l - 1)] + 1;
    }
  }
  return true;
}

}  // namespace gesmi
