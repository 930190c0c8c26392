#include "solver/setinv/components.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "solver/setinv/detail/union_find.h"

namespace gesmi {
namespace {

bool touch_1d(const Interval& a, const Interval& b) { return a.lo() <= b.hi() && b.lo() <= a.hi(); }

bool touch_periodic(const Interval& a, const Interval& b, const ComponentOptions& o) {
  if (touch_1d(a, b)) return true;
  const double p = o.period, tol = o.wrap_tolerance;
  // Shift b by whole periods towards a, then test with the tolerance.
  const double shift = std::round((a.mid() - b.mid()) / p) * p;
  for (double s : {shift - p, shift, shift + p})
    if (a.lo() <= b.hi() + s + tol && b.lo() + s - tol <= a.hi()) return true;
  return false;
}

}  // namespace

Interval wrapped_hull(const std::vector<Interval>& arcs, double period, double origin) {
  // Normalise every arc to start in [origin, origin + period) and repeat the set
  // three periods long; every gap starting in the middle period is then complete,
  // including gaps closed by arcs that overflow the window. The hull is the circle
  // minus the largest gap.
  std::vector<std::pair<double, double>> a;
  for (const Interval& x : arcs) {
    if (x.is_empty()) continue;
    if (x.width() >= period) return Interval(origin, origin + period);
    const double lo = origin + std::fmod(std::fmod(x.lo() - origin, period) + period, period);
    for (int copy = 0; copy < 3; ++copy) a.emplace_back(lo + copy * period, lo + copy * period + (x.hi() - x.lo()));
  }
  if (a.empty()) return Interval::empty();
  std::sort(a.begin(), a.end());
  std::vector<std::pair<double, double>> merged{a.front()};
  for (std::size_t i = 1; i < a.size(); ++i) {
    if (a[i].first <= merged.back().second)
      merged.back().second = std::max(merged.back().second, a[i].second);
    else
      merged.push_back(a[i]);
  }
  double best_gap = 0.0, lo = origin, hi = origin + period;
  for (std::size_t i = 0; i + 1 < merged.size(); ++i) {
    const double end = merged[i].second;
    if (end < origin + period || end >= origin + 2.0 * period) continue;
    const double gap = merged[i + 1].first - end;
    if (gap > best_gap) {
      best_gap = gap;
      lo = merged[i + 1].first;
      hi = end + period;
    }
  }
  if (best_gap <= 0.0) return Interval(origin, origin + period);
  const double shift = std::floor((0.5 * (lo + hi) - origin) / period) * period;
  return Interval(lo - shift, hi - shift);
}

void for_each_touching_pair(const Paving& inner, const Paving& boundary, const ComponentOptions& options,
                            const std::function<void(std::size_t, std::size_t)>& touching,
                            const std::function<bool(std::size_t, std::size_t)>& skip) {
  const std::size_t n_inner = inner.size(), n = n_inner + boundary.size();
  const std::size_t dim = std::max(inner.dim(), boundary.dim());
  const auto box = [&](std::size_t i) { return i < n_inner ? inner.box(i) : boundary.box(i - n_inner); };
  const int pd = options.periodic_dimension;
  // Sweep along the first non-periodic dimension: only boxes overlapping in it can touch.
  const std::size_t sweep = (pd == 0 && dim > 1) ? 1 : 0;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return box(a)[sweep].lo() < box(b)[sweep].lo(); });
  std::vector<std::size_t> active;
  for (std::size_t i : order) {
    const auto bi = box(i);
    std::erase_if(active, [&](std::size_t j) { return box(j)[sweep].hi() < bi[sweep].lo(); });
    for (std::size_t j : active) {
      if (skip && skip(i, j)) continue;
      const auto bj = box(j);
      bool touch = true;
      for (std::size_t k = 0; k < dim && touch; ++k)
        touch = static_cast<int>(k) == pd ? touch_periodic(bi[k], bj[k], options) : touch_1d(bi[k], bj[k]);
      if (touch) touching(std::min(i, j), std::max(i, j));
    }
    active.push_back(i);
  }
}

std::vector<PavingComponent> components_from_labels(const Paving& inner, const Paving& boundary,
                                                    std::span<const std::size_t> label, const ComponentOptions& options) {
  const std::size_t n_inner = inner.size(), n = n_inner + boundary.size();
  const std::size_t dim = std::max(inner.dim(), boundary.dim());
  const auto box = [&](std::size_t i) { return i < n_inner ? inner.box(i) : boundary.box(i - n_inner); };
  const int pd = options.periodic_dimension;
  std::vector<PavingComponent> components;
  std::vector<std::size_t> index_of_label(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = label[i];
    if (index_of_label[r] == n) {
      index_of_label[r] = components.size();
      components.emplace_back();
    }
    PavingComponent& c = components[index_of_label[r]];
    if (i < n_inner) {
      c.inner.push_back(i);
      c.inner_volume += box_volume(box(i));
    } else {
      c.boundary.push_back(i - n_inner);
      c.boundary_volume += box_volume(box(i));
    }
  }
  for (PavingComponent& c : components) {
    c.hull.assign(dim, Interval::empty());
    std::vector<Interval> arcs;
    const auto add = [&](std::span<const Interval> b) {
      for (std::size_t k = 0; k < dim; ++k) c.hull[k] = hull(c.hull[k], b[k]);
      if (pd >= 0) arcs.push_back(b[static_cast<std::size_t>(pd)]);
    };
    for (std::size_t i : c.inner) add(inner.box(i));
    for (std::size_t i : c.boundary) add(boundary.box(i));
    if (pd >= 0) c.hull[static_cast<std::size_t>(pd)] = wrapped_hull(arcs, options.period, options.periodic_origin);
  }
  std::stable_sort(components.begin(), components.end(), [](const PavingComponent& a, const PavingComponent& b) {
    const double va = a.inner_volume + a.boundary_volume, vb = b.inner_volume + b.boundary_volume;
    if (va != vb) return va > vb;
    return a.inner.size() > b.inner.size();
  });
  return components;
}

std::vector<PavingComponent> connected_components(const Paving& inner, const Paving& boundary,
                                                  const ComponentOptions& options) {
  const std::size_t n = inner.size() + boundary.size();
  detail::UnionFind uf(n);
  for_each_touching_pair(
      inner, boundary, options, [&](std::size_t a, std::size_t b) { uf.unite(a, b); },
      [&](std::size_t a, std::size_t b) { return uf.find(a) == uf.find(b); });  // joined already: skip the test
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i) label[i] = uf.find(i);
  return components_from_labels(inner, boundary, label, options);
}

}  // namespace gesmi
