#pragma once
// Recursive SIVIA (seed 000, Table 1; seed 004, Table 1): bisects the prior boxes
// and classifies sub-boxes with an inclusion test T(P) in {false, true, unknown}.
// CLASSIFY keeps two children with the same verdict merged in their father, so a
// region proved inside (or undetermined down to epsilon) is stored as one box.
//
// The test is any callable IBool(const Box&) or IBool(const Box&, int depth); the
// depth form lets a test keep state per recursion level that children inherit from
// their father (seed 003's visibility vectors). An optional contractor (any
// Contractor) narrows each box before it is tested. A contracted box is no longer
// the exact half of its father, so it is stored as soon as it is classified
// instead of being merged upwards.
//
// Memory: one scratch box per recursion level, reused; the only growing storage is
// the two pavings.
//
// Depth: a box is bisected only when the midpoint of its widest side lies strictly
// inside it (detail::can_bisect); otherwise it is kept as a boundary box and counted
// in SiviaReport::boxes_unsplittable, whatever epsilon asks. Halving a double interval
// that way ends after at most about 2100 steps (52 bits of mantissa and 2046 binades),
// so the recursion is at most about 2100 levels per dimension deep.

#include <algorithm>
#include <chrono>
#include <concepts>
#include <span>
#include <vector>

#include "solver/ctc/ctc.h"
#include "solver/interval/interval_bool.h"
#include "solver/setinv/sivia_options.h"

namespace gesmi {

/// The contractor that does nothing: SIVIA without contraction.
struct CtcNone {
  void contract(Box&) const {}
};

template <class T>
concept DepthBoxTest = requires(T& t, const Box& box, int depth) {
  { t(box, depth) } -> std::convertible_to<IBool>;
};
template <class T>
concept PlainBoxTest = requires(T& t, const Box& box) {
  { t(box) } -> std::convertible_to<IBool>;
};
template <class T>
concept BoxTest = DepthBoxTest<T> || PlainBoxTest<T>;

namespace detail {

/// Index of the dimension to bisect: the widest after scaling; its scaled width.
std::pair<std::size_t, double> widest_dimension(std::span<const Interval> box, const std::vector<double>& scale);
/// Whether bisecting the box's widest dimension makes progress: its midpoint lies
/// strictly between its bounds. Two adjacent doubles have no double between them,
/// so below that width "halving" returns the box itself and would recurse forever.
bool can_bisect(std::span<const Interval> box, const std::vector<double>& scale);
/// A prior with its periodic dimension cut to one period.
Box wrap_prior(const Box& prior, const SiviaOptions& options);

template <class Test, class Ctc>
class SiviaRun {
 public:
  SiviaRun(Test& test, const Ctc& ctc, const SiviaOptions& options)
      : test_(test), ctc_(ctc), options_(options), start_(std::chrono::steady_clock::now()) {}

  SiviaResult run(std::span<const Box> priors) {
    for (const Box& prior : priors) {
      if (prior.empty()) continue;
      if (result_.inner.dim() == 0) result_.inner = result_.boundary = Paving(prior.size());
      level(0) = wrap_prior(prior, options_);
      const Verdict v = classify(0);
      if (v == Verdict::inside) result_.inner.add(level(0));
      if (v == Verdict::boundary) result_.boundary.add(level(0));
    }
    result_.report.seconds = elapsed();
    return std::move(result_);
  }

 private:
  // A box is outside, inside, undetermined, or already stored (seed's "empty set").
  enum class Verdict { outside, inside, boundary, stored };
  static constexpr bool kContracts = !std::same_as<Ctc, CtcNone>;

  Box& level(int depth) {
    const auto d = static_cast<std::size_t>(depth);
    if (boxes_.size() <= d) boxes_.resize(d + 1);
    if constexpr (kContracts)
      if (before_.size() <= d) before_.resize(d + 1);
    return boxes_[d];
  }

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  void account_visit(int depth) {
    SiviaReport& r = result_.report;
    ++r.boxes_visited;
    r.max_depth = std::max(r.max_depth, depth);
    if (r.boxes_visited >= options_.max_boxes) r.box_limit_hit = true;
    if ((r.boxes_visited & 1023u) == 0 && elapsed() > options_.max_seconds) r.time_limit_hit = true;
    if (options_.progress && r.boxes_visited % options_.progress_every == 0)
      options_.progress({r.boxes_visited, result_.inner.size(), result_.boundary.size(), elapsed()});
  }

  IBool evaluate(const Box& box, int depth) {
    if constexpr (DepthBoxTest<Test>)
      return test_(box, depth);
    else
      return test_(box);
  }

  // Fills level(depth + 1) with the lower (first) or upper half of level(depth).
  void make_child(int depth, std::size_t dim, bool upper) {
    level(depth + 1);  // grow before taking references
    const Box& father = boxes_[static_cast<std::size_t>(depth)];
    Box& child = boxes_[static_cast<std::size_t>(depth) + 1];
    child.assign(father.begin(), father.end());
    const double m = father[dim].mid();
    child[dim] = upper ? Interval(m, father[dim].hi()) : Interval(father[dim].lo(), m);
  }

  Verdict classify(int depth) {
    bool contracted = false;
    if constexpr (kContracts) {
      Box& box = level(depth);
      Box& before = before_[static_cast<std::size_t>(depth)];
      before.assign(box.begin(), box.end());
      ctc_.contract(box);
      if (is_empty(box)) return Verdict::outside;
      contracted = !std::equal(box.begin(), box.end(), before.begin());
      if (contracted) ++result_.report.boxes_contracted;
    }
    account_visit(depth);
    const IBool t = evaluate(level(depth), depth);
    Verdict v;
    if (t.is_true()) {
      v = Verdict::inside;
    } else if (t.is_false() || t.is_empty()) {
      return Verdict::outside;
    } else {
      const auto [dim, width] = widest_dimension(level(depth), options_.scale);
      if (result_.report.limit_hit()) {
        v = Verdict::boundary;
      } else if (width < options_.epsilon) {
        ++result_.report.boxes_at_epsilon;
        v = Verdict::boundary;
      } else if (!can_bisect(level(depth), options_.scale)) {
        ++result_.report.boxes_unsplittable;
        v = Verdict::boundary;
      } else {
        make_child(depth, dim, false);
        const Verdict v1 = classify(depth + 1);
        make_child(depth, dim, true);
        const Verdict v2 = classify(depth + 1);
        if (v1 == v2) {
          v = v1;
        } else {
          store(v2, depth + 1);  // the upper half is still in level(depth + 1)
          if (v1 == Verdict::inside || v1 == Verdict::boundary) {
            make_child(depth, dim, false);
            store(v1, depth + 1);
          }
          v = Verdict::stored;
        }
      }
    }
    if (contracted && (v == Verdict::inside || v == Verdict::boundary)) {
      store(v, depth);
      v = Verdict::stored;
    }
    return v;
  }

  void store(Verdict v, int depth) {
    if (v == Verdict::inside) result_.inner.add(boxes_[static_cast<std::size_t>(depth)]);
    if (v == Verdict::boundary) result_.boundary.add(boxes_[static_cast<std::size_t>(depth)]);
  }

  Test& test_;
  const Ctc& ctc_;
  const SiviaOptions& options_;
  std::chrono::steady_clock::time_point start_;
  std::vector<Box> boxes_;   // scratch box per recursion level
  std::vector<Box> before_;  // copy before contraction, per level
  SiviaResult result_;
};

}  // namespace detail

/// The smallest epsilon that bisection can reach everywhere in the priors: twice the
/// spacing of doubles at each dimension's largest magnitude, times its scale, for the
/// widest dimension. A smaller epsilon is met nowhere near that magnitude: boxes
/// there end as unsplittable boundary boxes (detail::can_bisect), after as many boxes
/// as the set has boundary at the spacing of doubles.
double finest_epsilon(std::span<const Box> priors, const std::vector<double>& scale);

/// Inner and boundary subpavings of {p in priors : T(p) = true}. The options must
/// be valid (SiviaOptions::validate) and the priors of one dimension.
template <BoxTest Test, Contractor Ctc = CtcNone>
SiviaResult sivia(Test& test, std::span<const Box> priors, const SiviaOptions& options, const Ctc& ctc = {}) {
  return detail::SiviaRun<Test, Ctc>(test, ctc, options).run(priors);
}

template <BoxTest Test, Contractor Ctc = CtcNone>
SiviaResult sivia(Test& test, const Box& prior, const SiviaOptions& options, const Ctc& ctc = {}) {
  return sivia(test, std::span<const Box>(&prior, 1), options, ctc);
}

}  // namespace gesmi
