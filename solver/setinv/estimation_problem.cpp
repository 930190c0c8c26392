#include "solver/setinv/estimation_problem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "solver/setinv/datum_tests.h"
#include "solver/setinv/outliers/gomne.h"
#include "solver/setinv/outliers/outlier_refinement.h"
#include "solver/setinv/point_math.h"

namespace gesmi {
namespace {


struct GaussianDensity {
  std::vector<double> t;
  std::size_t output_count() const { return t.size(); }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    for (std::size_t i = 0; i < t.size(); ++i)
      y[i] = exp(-sqr(T(t[i]) - p[0]) / (T(2.0) * p[1])) / sqrt(T(2.0 * std::numbers::pi) * p[1]);
  }
};

/// The run's limits, shared by every level's SIVIA and refinement (as GOMNE shares
/// its own between its SIVIA calls).
class Budget {
 public:
  Budget(std::size_t max_boxes, double max_seconds)
      : max_boxes_(max_boxes), max_seconds_(max_seconds), start_(std::chrono::steady_clock::now()) {}
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  std::size_t used() const { return used_; }
  void spend(std::size_t boxes) { used_ += boxes; }
  bool out_of_boxes() const { return used_ >= max_boxes_; }
  bool out_of_time() const { return elapsed() >= max_seconds_; }
  // At least one box and a millisecond: SIVIA and the refinement take no zero limits.
  std::size_t remaining_boxes() const { return out_of_boxes() ? 1 : max_boxes_ - used_; }
  double remaining_seconds() const { return std::max(1e-3, max_seconds_ - elapsed()); }

 private:
  std::size_t max_boxes_;
  double max_seconds_;
  std::chrono::steady_clock::time_point start_;
  std::size_t used_ = 0;
};

}  // namespace

bool EstimationLevel::proved_nonempty() const {
  for (const OutlierSetPaving& s : sets)
    if (!s.inner.empty()) return true;
  return false;
}

std::size_t EstimationResult::boxes_examined() const {
  std::size_t n = 0;
  for (const EstimationLevel& level : levels) n += level.boxes_examined;
  return n;
}

bool EstimationResult::box_limit_hit() const {
  return std::any_of(levels.begin(), levels.end(), [](const EstimationLevel& l) { return l.box_limit_hit; });
}

bool EstimationResult::time_limit_hit() const {
  return std::any_of(levels.begin(), levels.end(), [](const EstimationLevel& l) { return l.time_limit_hit; });
}

std::optional<int> EstimationResult::q_star() const {
  std::optional<int> q;
  for (const EstimationLevel& level : levels)
    if (level.proved_nonempty() && (!q || level.q < *q)) q = level.q;
  return q;
}

std::string EstimationProblem::validate() const {
  if (t.empty() || t.size() != data.size()) return "need one datum per abscissa";
  if (t.size() > kMaxData) return "at most " + std::to_string(kMaxData) + " data";
  if (prior.size() != 2) return "the Gaussian density has 2 parameters";
  for (const Interval& x : prior)
    if (x.is_empty() || !x.is_bounded()) return "the prior box must be bounded and non-empty";
  if (!(epsilon > 0.0)) return "epsilon must be positive";
  if (max_boxes == 0 || max_boxes > kMaxBoxesCeiling || !(max_seconds > 0.0))
    return "max_boxes must be between 1 and " + std::to_string(kMaxBoxesCeiling) + ", max_seconds positive";
  for (int q : levels)
    if (q < 0 || q > static_cast<int>(t.size())) return "levels must be between 0 and the number of data";
  return {};
}

double model_output(const EstimationProblem& problem, std::size_t i, std::span<const double> p) {
  const double t = problem.t[i];
  return std::exp(-sqr(t - p[0]) / (2.0 * p[1])) / std::sqrt(2.0 * std::numbers::pi * p[1]);
}

EstimationResult estimate(const EstimationProblem& problem,
                          const std::function<void(const EstimationProgress&)>& progress) {
  Budget budget(problem.max_boxes, problem.max_seconds);
  ImageInBox<GaussianDensity> data(GaussianDensity{problem.t}, problem.data);
  EstimationResult result;
  for (std::size_t index = 0; index < problem.levels.size(); ++index) {
    const auto level_start = std::chrono::steady_clock::now();
    EstimationLevel level;
    level.q = problem.levels[index];
    EstimationProgress where{index, problem.levels.size(), level.q, budget.used()};
    if (progress) progress(where);
    // Once the run is out of boxes or time, a level examines its prior box alone and
    // keeps it whole: it still encloses j^{-1}(q). The level then names the limit that
    // ended the run, not the one box it was given.
    const bool out_of_boxes = budget.out_of_boxes(), out_of_time = budget.out_of_time();
    const bool exhausted = out_of_boxes || out_of_time;
    SiviaOptions options;
    options.epsilon = problem.epsilon;
    options.max_boxes = exhausted ? 1 : budget.remaining_boxes();
    options.max_seconds = budget.remaining_seconds();
    if (progress)
      options.progress = [&](const SiviaProgress& p) {
        where.boxes_examined = budget.used() + p.boxes_visited;
        progress(where);
      };
    const SiviaResult s = sivia_q(data, level.q, std::span<const Box>(&problem.prior, 1), options);
    budget.spend(s.report.boxes_visited);
    OutlierRefinementOptions refine;
    refine.q = level.q;
    refine.epsilon = problem.epsilon;
    refine.max_boxes = exhausted ? 1 : budget.remaining_boxes();
    refine.max_seconds = budget.remaining_seconds();
    const OutlierPaving refined = refine_by_outliers(data, s, refine);
    budget.spend(refined.boxes_evaluated);
    OutlierPartition partition = partition_by_outlier_set(refined);
    level.sets = sets_of_size(partition, static_cast<std::size_t>(level.q));
    level.unresolved = std::move(partition.unresolved);
    level.boxes_examined = s.report.boxes_visited + refined.boxes_evaluated;
    level.box_limit_hit = exhausted ? out_of_boxes : s.report.box_limit_hit || refined.box_limit_hit;
    level.time_limit_hit = exhausted ? out_of_time : s.report.time_limit_hit || refined.time_limit_hit;
    level.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - level_start).count();
    result.levels.push_back(std::move(level));
  }
  result.seconds = budget.elapsed();
  return result;
}

}  // namespace gesmi
