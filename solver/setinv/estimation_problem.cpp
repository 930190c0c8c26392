#include "solver/setinv/estimation_problem.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include "solver/setinv/datum_tests.h"
#include "solver/setinv/gomne.h"
#include "solver/setinv/outlier_refinement.h"

namespace gesmi {
namespace {

double square(double x) { return x * x; }
Interval square(const Interval& x) { return sqr(x); }  // tighter than x * x when x holds 0
using std::exp;
using std::sqrt;

struct GaussianDensity {
  std::vector<double> t;
  std::size_t output_count() const { return t.size(); }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    for (std::size_t i = 0; i < t.size(); ++i)
      y[i] = exp(-square(T(t[i]) - p[0]) / (T(2.0) * p[1])) / sqrt(T(2.0 * std::numbers::pi) * p[1]);
  }
};

}  // namespace

bool EstimationLevel::proved_nonempty() const {
  for (const OutlierSetPaving& s : sets)
    if (!s.inner.empty()) return true;
  return false;
}

std::string EstimationProblem::validate() const {
  if (t.empty() || t.size() != data.size()) return "need one datum per abscissa";
  if (prior.size() != 2) return "the Gaussian density has 2 parameters";
  for (const Interval& x : prior)
    if (x.is_empty() || !x.is_bounded()) return "the prior box must be bounded and non-empty";
  if (!(epsilon > 0.0)) return "epsilon must be positive";
  for (int q : levels)
    if (q < 0 || q > static_cast<int>(t.size())) return "levels must be between 0 and the number of data";
  return {};
}

double model_output(const EstimationProblem& problem, std::size_t i, std::span<const double> p) {
  const double t = problem.t[i];
  return std::exp(-square(t - p[0]) / (2.0 * p[1])) / std::sqrt(2.0 * std::numbers::pi * p[1]);
}

EstimationResult estimate(const EstimationProblem& problem) {
  const auto start = std::chrono::steady_clock::now();
  ImageInBox<GaussianDensity> data(GaussianDensity{problem.t}, problem.data);
  SiviaOptions options;
  options.epsilon = problem.epsilon;
  options.max_boxes = problem.max_boxes;
  EstimationResult result;
  for (int q : problem.levels) {
    const auto level_start = std::chrono::steady_clock::now();
    EstimationLevel level;
    level.q = q;
    const SiviaResult s = sivia_q(data, q, std::span<const Box>(&problem.prior, 1), options);
    OutlierRefinementOptions refine;
    refine.q = q;
    refine.epsilon = problem.epsilon;
    refine.max_boxes = problem.max_boxes;
    const OutlierPaving refined = refine_by_outliers(data, s, refine);
    level.sets = sets_of_size(partition_by_outlier_set(refined), static_cast<std::size_t>(q));
    level.boxes_examined = s.report.boxes_visited + refined.boxes_evaluated;
    level.limit_hit = s.report.limit_hit() || refined.limit_hit;
    level.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - level_start).count();
    result.levels.push_back(std::move(level));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace gesmi
