#pragma once
// GOMNE, the Guaranteed Outlier Minimal Number Estimator (seed 004, Table 2).
//
// SIVIA(q) characterises S_q = {p | j(p) <= q}, j(p) = number of data inconsistent
// with p, with the inclusion function of Proposition 1,
//     J(P) = [sep(F(P), Y), n - incl(F(P), Y)],
// i.e. certain-no count and n minus certain-yes count of the data tests. q is raised
// from 0 until the inner subpaving is non-empty; for each q, epsilon is halved from
// epsilon0 while the result is undetermined, down to epsilon_min (Remark 3). Prior
// constraints g(p) <= 0 enter CLASSIFY as in Remark 4; extra_outliers = n_u asks
// for the one more call SIVIA(j* + n_u) of Remark 2.
//
// Halving epsilon restarts SIVIA on the boundary boxes of the previous call only:
// its inner set was empty, so S_q lies in those boxes, and the result is the same
// enclosure for a fraction of the work.

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "solver/setinv/datum_tests.h"
#include "solver/setinv/sivia.h"

namespace gesmi {

struct GomneOptions {
  double epsilon0 = 0.01;
  double epsilon_min = 1e-4;
  /// Remark 2: characterise S_{j* + extra_outliers} to survive that many undetected outliers.
  int extra_outliers = 0;
  /// Largest q tried; -1 means the number of data.
  int max_outliers = -1;
  /// Bisection, periodic dimension, limits (for the whole run) and progress;
  /// its epsilon is ignored.
  SiviaOptions sivia;

  std::string validate(std::size_t dim) const;
};

/// One call of SIVIA(q) at accuracy epsilon.
struct GomneStep {
  int q = 0;
  double epsilon = 0.0;
  std::size_t inner_boxes = 0;
  std::size_t boundary_boxes = 0;
  std::size_t boxes_visited = 0;
  double seconds = 0.0;
};

struct GomneResult {
  bool found = false;     // some S_q was proved non-empty (q <= max_outliers)
  int q_star = -1;        // first q with a non-empty inner subpaving
  int q_lower = 0;        // every S_q with q < q_lower was proved empty
  int q_used = -1;        // q_star + extra_outliers: the set the pavings enclose
  double epsilon = 0.0;   // accuracy of the final pavings
  /// Remark 3: some S_q stayed undetermined down to epsilon_min (or down to boxes too
  /// narrow for doubles to bisect), so only the outer guarantee S* ⊂ inner ∪ boundary
  /// holds, and j* lies in [q_lower, q_star].
  bool epsilon_min_reached = false;
  bool limit_hit = false; // a box or time limit stopped the run: no emptiness proof
  SiviaResult paving;
  std::vector<GomneStep> steps;
  double seconds = 0.0;
  bool exact() const { return found && q_lower == q_star && !limit_hit; }
};

/// The prior constraint that holds everywhere.
struct NoPriorConstraint {
  IBool operator()(const Box&) const { return true; }
};

/// SIVIA(q)'s inclusion test: J(P) against q, with a prior constraint (Remark 4).
template <DatumTests Data, class Prior>
class OutlierCountTest {
 public:
  OutlierCountTest(Data& data, const Prior& prior, int q)
      : data_(data), prior_(prior), q_(q), values_(data.datum_count(), IBool::maybe()) {}
  IBool operator()(const Box& box, int depth) {
    const IBool g = prior_(box);
    if (g.is_false() || g.is_empty()) return false;
    data_.evaluate(box, depth, values_, q_);
    const DatumCounts c = count_data(values_);
    if (c.no > q_) return false;                                                    // lb(J) > q
    if (static_cast<int>(values_.size()) - c.yes <= q_ && g.is_true()) return true;  // ub(J) <= q
    return IBool::maybe();
  }

 private:
  Data& data_;
  const Prior& prior_;
  int q_;
  std::vector<IBool> values_;
};

template <DatumTests Data, class Prior = NoPriorConstraint, Contractor Ctc = CtcNone>
SiviaResult sivia_q(Data& data, int q, std::span<const Box> priors, const SiviaOptions& options,
                    const Prior& prior = {}, const Ctc& ctc = {}) {
  OutlierCountTest<Data, Prior> test(data, prior, q);
  return sivia(test, priors, options, ctc);
}

/// A contractor whose validity depends on the number of outliers allowed: GOMNE
/// asks it for its SIVIA(q) version with `with_outliers(q)`.
template <class C>
concept OutlierAwareContractor = requires(const C& c, int q) {
  { c.with_outliers(q) } -> Contractor;
};

/// Seed 004, Table 2. The contractor, when given, must keep every point of S_q
/// (an OutlierAwareContractor is asked for its version for each q); the default
/// contracts nothing.
template <DatumTests Data, class Prior = NoPriorConstraint, Contractor Ctc = CtcNone>
GomneResult gomne(Data& data, std::span<const Box> priors, const GomneOptions& options, const Prior& prior = {},
                  const Ctc& ctc = {}) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const int n = static_cast<int>(data.datum_count());
  const int q_max = options.max_outliers < 0 ? n : std::min(options.max_outliers, n);
  GomneResult result;
  std::size_t visited = 0;
  const auto run = [&](int q, double epsilon, std::span<const Box> boxes) {
    SiviaOptions o = options.sivia;
    o.epsilon = epsilon;
    o.max_seconds = std::max(1e-3, options.sivia.max_seconds - elapsed());
    o.max_boxes = options.sivia.max_boxes > visited ? options.sivia.max_boxes - visited : 1;
    const auto t0 = Clock::now();
    SiviaResult r = [&] {
      if constexpr (OutlierAwareContractor<Ctc>)
        return sivia_q(data, q, boxes, o, prior, ctc.with_outliers(q));
      else
        return sivia_q(data, q, boxes, o, prior, ctc);
    }();
    visited += r.report.boxes_visited;
    result.steps.push_back({q, epsilon, r.inner.size(), r.boundary.size(), r.report.boxes_visited,
                            std::chrono::duration<double>(Clock::now() - t0).count()});
    result.limit_hit = result.limit_hit || r.report.limit_hit();
    return r;
  };
  for (int q = 0; q <= q_max && !result.found && !result.limit_hit; ++q) {
    double epsilon = options.epsilon0;
    std::vector<Box> boxes(priors.begin(), priors.end());
    for (;;) {
      SiviaResult r = run(q, epsilon, boxes);
      if (!r.inner.empty() || result.limit_hit) {
        result.found = !r.inner.empty();
        result.q_star = q;
        result.epsilon = epsilon;
        result.paving = std::move(r);
        break;
      }
      if (r.boundary.empty()) {  // S_q proved empty
        if (result.q_lower == q) result.q_lower = q + 1;
        break;
      }
      // Remark 3: give up on this q at epsilon_min, or sooner when epsilon stopped no
      // box (every undetermined box was too narrow for doubles to split): halving it
      // would give the same result again.
      if (epsilon / 2.0 < options.epsilon_min || r.report.boxes_at_epsilon == 0) {
        result.epsilon_min_reached = true;
        result.paving = std::move(r);
        result.epsilon = epsilon;
        break;
      }
      epsilon /= 2.0;
      boxes.clear();
      for (std::size_t i = 0; i < r.boundary.size(); ++i) boxes.push_back(r.boundary.box_copy(i));
    }
  }
  result.q_used = result.q_star;
  if (result.found && options.extra_outliers > 0 && !result.limit_hit) {
    result.q_used = std::min(n, result.q_star + options.extra_outliers);
    result.paving = run(result.q_used, result.epsilon, priors);
  }
  result.seconds = elapsed();
  return result;
}

}  // namespace gesmi
