#pragma once
// Refines the pavings of S_q until phi, the set of data inconsistent with a point,
// is known on each box: a box is bisected while more than one outlier set fits it
// (solver/setinv/outliers/outlier_family.h) and it is wider than epsilon. Sub-boxes that no
// set fits, or that break the prior constraint (seed 004, Remark 4), hold no point
// of S_q and are dropped, so the result still encloses S_q, box for box inside the
// given pavings.
//
// This is what makes Proposition 2 usable on boxes: where phi is single on a box it
// is the same at every point of S_q in it, and the boxes split by outlier set
// (solver/setinv/outliers/outlier_set_pavings.h, solver/setinv/outliers/hypotheses.h).

#include <chrono>
#include <cstddef>
#include <limits>
#include <vector>

#include "solver/setinv/datum_tests.h"
#include "solver/setinv/outliers/gomne.h"
#include "solver/setinv/outliers/outlier_family.h"
#include "solver/setinv/sivia.h"

namespace gesmi {

struct OutlierRefinementOptions {
  int q = 0;
  /// Every S_k with k < q_lower was proved empty (GOMNE's q_lower; 0 when unknown).
  int q_lower = 0;
  /// Boxes narrower than epsilon (scaled widths) are not bisected.
  double epsilon = 0.01;
  std::vector<double> scale;
  /// Bounds on the boxes evaluated and on the wall time (checked every 1,024 boxes);
  /// past either, boxes are kept unrefined (the result still encloses S_q).
  std::size_t max_boxes = 1'000'000;
  double max_seconds = std::numeric_limits<double>::infinity();
};

/// The refined enclosure of S_q: inner boxes lie in S_q (they came from an inner
/// box, or their test proved it), boundary boxes may hold points of S_q. One
/// family per box, numbered as components.h does: inner boxes first, then boundary.
struct OutlierPaving {
  Paving inner;
  Paving boundary;
  std::vector<OutlierFamily> families;
  std::size_t boxes_evaluated = 0;
  // A limit stopped the refinement: some boxes that could be split were kept as they were.
  bool box_limit_hit = false;
  bool time_limit_hit = false;
  bool limit_hit() const { return box_limit_hit || time_limit_hit; }

  std::size_t size() const { return inner.size() + boundary.size(); }
  bool inside(std::size_t i) const { return i < inner.size(); }
  std::span<const Interval> box(std::size_t i) const { return inside(i) ? inner.box(i) : boundary.box(i - inner.size()); }
};

namespace detail {

template <DatumTests Data, class Prior>
class OutlierRefiner {
 public:
  OutlierRefiner(Data& data, const Prior& prior, const OutlierRefinementOptions& options)
      : data_(data), prior_(prior), options_(options), values_(data.datum_count(), IBool::maybe()),
        start_(std::chrono::steady_clock::now()) {}

  void refine(Box& box, bool known_inside, int depth) {
    const IBool g = known_inside ? IBool(true) : IBool(prior_(box));
    if (g.is_false() || g.is_empty()) return;
    ++result_.boxes_evaluated;
    const bool stopped = limit_reached();  // at every box, so that every 1,024th box checks the time
    data_.evaluate(box, depth, values_, options_.q);
    OutlierFamily family(values_, options_.q_lower, options_.q);
    if (family.empty()) return;
    const DatumCounts c = count_data(values_);
    const bool inside = known_inside || (static_cast<int>(values_.size()) - c.yes <= options_.q && g.is_true());
    const auto [dim, width] = widest_dimension(box, options_.scale);
    const bool splittable = !family.single() && width >= options_.epsilon && can_bisect(box, options_.scale);
    if (!splittable || stopped) {
      if (splittable) {  // kept only because of a limit: say which
        result_.box_limit_hit = result_.box_limit_hit || box_limit_;
        result_.time_limit_hit = result_.time_limit_hit || time_limit_;
      }
      (inside ? result_.inner : result_.boundary).add(box);
      (inside ? inner_families_ : boundary_families_).push_back(std::move(family));
      return;
    }
    const Interval side = box[dim];
    const double m = side.mid();
    box[dim] = Interval(side.lo(), m);
    refine(box, inside, depth + 1);
    box[dim] = Interval(m, side.hi());
    refine(box, inside, depth + 1);
    box[dim] = side;
  }

  OutlierPaving take() {
    result_.families = std::move(inner_families_);
    result_.families.insert(result_.families.end(), boundary_families_.begin(), boundary_families_.end());
    return std::move(result_);
  }
  void start(std::size_t dim) { result_.inner = result_.boundary = Paving(dim); }
  /// Evaluates the hull of all boxes at depth 0, so that evaluators with state per
  /// depth (solver/setinv/datum_tests.h) start each box from what holds on the hull
  /// instead of from nothing: the boxes are then evaluated at depth 1.
  void seed(const Box& hull) { data_.evaluate(hull, 0, values_, static_cast<int>(values_.size())); }

 private:
  // Once a limit is reached it stays reached: the remaining boxes are kept as they are.
  bool limit_reached() {
    if (result_.boxes_evaluated >= options_.max_boxes) box_limit_ = true;
    if ((result_.boxes_evaluated & 1023u) == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > options_.max_seconds)
      time_limit_ = true;
    return box_limit_ || time_limit_;
  }

  Data& data_;
  const Prior& prior_;
  const OutlierRefinementOptions& options_;
  std::vector<IBool> values_;
  std::chrono::steady_clock::time_point start_;
  bool box_limit_ = false, time_limit_ = false;
  OutlierPaving result_;
  std::vector<OutlierFamily> inner_families_, boundary_families_;
};

}  // namespace detail

/// Refines the inner and boundary pavings of S_q (as SIVIA(q) or GOMNE gave them).
template <DatumTests Data, class Prior = NoPriorConstraint>
OutlierPaving refine_by_outliers(Data& data, const SiviaResult& pavings, const OutlierRefinementOptions& options,
                                 const Prior& prior = {}) {
  detail::OutlierRefiner<Data, Prior> refiner(data, prior, options);
  const std::size_t dim = std::max(pavings.inner.dim(), pavings.boundary.dim());
  refiner.start(dim);
  Box hull(dim, Interval::empty());
  for (const auto* paving : {&pavings.inner, &pavings.boundary})
    for (std::size_t i = 0; i < paving->size(); ++i)
      for (std::size_t k = 0; k < dim; ++k) hull[k] = gesmi::hull(hull[k], paving->box(i)[k]);
  if (pavings.inner.empty() && pavings.boundary.empty()) return refiner.take();
  refiner.seed(hull);
  for (const auto* paving : {&pavings.inner, &pavings.boundary})
    for (std::size_t i = 0; i < paving->size(); ++i) {
      Box box = paving->box_copy(i);
      refiner.refine(box, paving == &pavings.inner, 1);
    }
  return refiner.take();
}

}  // namespace gesmi
