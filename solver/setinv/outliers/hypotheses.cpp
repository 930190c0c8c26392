#include "solver/setinv/outliers/hypotheses.h"

#include <set>

#include "solver/setinv/detail/union_find.h"

namespace gesmi {

std::vector<PavingComponent> hypothesis_components(const OutlierPaving& refined, const ComponentOptions& options) {
  const std::size_t n = refined.size();
  std::vector<char> single(n);
  std::vector<OutlierSet> set_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    single[i] = refined.families[i].single();
    if (single[i]) set_of[i] = refined.families[i].single_set();
  }
  std::vector<std::pair<std::size_t, std::size_t>> touching;
  for_each_touching_pair(refined.inner, refined.boundary, options,
                         [&](std::size_t a, std::size_t b) { touching.emplace_back(a, b); });
  detail::UnionFind uf(n);
  for (const auto& [a, b] : touching) {
    if (single[a] && single[b] && set_of[a] == set_of[b]) uf.unite(a, b);
    if (!single[a] && !single[b] && refined.families[a].intersects(refined.families[b])) uf.unite(a, b);
  }
  // Determined components each ambiguous cluster touches with a set it may hold.
  std::vector<std::set<std::size_t>> candidates(n);
  for (const auto& [a, b] : touching) {
    if (single[a] == single[b]) continue;
    const std::size_t determined = single[a] ? a : b, ambiguous = single[a] ? b : a;
    if (refined.families[ambiguous].contains(set_of[determined])) candidates[uf.find(ambiguous)].insert(uf.find(determined));
  }
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t root = uf.find(i);
    label[i] = !single[i] && candidates[root].size() == 1 ? *candidates[root].begin() : root;
  }
  return components_from_labels(refined.inner, refined.boundary, label, options);
}

}  // namespace gesmi
