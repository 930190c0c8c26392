#include "solver/setinv/outliers/outlier_set_pavings.h"

#include <algorithm>
#include <map>

namespace gesmi {
namespace {

Interval periodic_hull(const OutlierSetPaving& s, std::size_t dim, const ComponentOptions& periodic) {
  std::vector<Interval> arcs;
  for (const Paving* p : {&s.inner, &s.boundary})
    for (std::size_t i = 0; i < p->size(); ++i) arcs.push_back(p->box(i)[dim]);
  return wrapped_hull(arcs, periodic.period, periodic.periodic_origin);
}

}  // namespace

OutlierPartition partition_by_outlier_set(const OutlierPaving& refined, const ComponentOptions& periodic,
                                          std::size_t max_sets_per_box) {
  const std::size_t dim = refined.inner.dim();
  const int pd = periodic.periodic_dimension;
  OutlierPartition out;
  out.unresolved = Paving(dim);
  // Ordered by size first, as the seed's panels are.
  const auto by_size = [](const OutlierSet& a, const OutlierSet& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; };
  std::map<OutlierSet, OutlierSetPaving, decltype(by_size)> sets(by_size);
  std::vector<OutlierSet> fitting;
  for (std::size_t i = 0; i < refined.size(); ++i) {
    const OutlierFamily& family = refined.families[i];
    fitting.clear();
    if (!family.enumerate(max_sets_per_box, fitting)) {
      out.unresolved.add(refined.box(i));
      continue;
    }
    const bool inner = refined.inside(i) && family.single();
    for (const OutlierSet& o : fitting) {
      auto [it, added] = sets.try_emplace(o);
      if (added) it->second = {o, Paving(dim), Paving(dim), Box(dim, Interval::empty())};
      OutlierSetPaving& s = it->second;
      (inner ? s.inner : s.boundary).add(refined.box(i));
      for (std::size_t k = 0; k < dim; ++k) s.hull[k] = hull(s.hull[k], refined.box(i)[k]);
    }
  }
  for (auto& [o, s] : sets) {
    if (pd >= 0) s.hull[static_cast<std::size_t>(pd)] = periodic_hull(s, static_cast<std::size_t>(pd), periodic);
    out.sets.push_back(std::move(s));
  }
  return out;
}

std::vector<OutlierSetPaving> sets_of_size(const OutlierPartition& partition, std::size_t size) {
  std::vector<OutlierSetPaving> out;
  for (const OutlierSetPaving& s : partition.sets)
    if (s.outliers.size() == size) out.push_back(s);
  return out;
}

}  // namespace gesmi
