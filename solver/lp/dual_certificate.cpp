#include "solver/lp/dual_certificate.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/interval/interval.h"
#include "solver/interval/rounding.h"

namespace gesmi {
namespace {

// lambda_i, or 0 where it is not finite or its sign would meet an infinite bound of the row.
double usable_multiplier(double lambda, double lower, double upper) {
  if (!std::isfinite(lambda)) return 0.0;
  if (lambda > 0.0 && lower == -INFINITY) return 0.0;
  if (lambda < 0.0 && upper == INFINITY) return 0.0;
  return lambda;
}

// Bounds lower <= upper, neither NaN, lower < +infinity, upper > -infinity.
bool bounds_usable(double lower, double upper) { return lower <= upper && lower < INFINITY && upper > -INFINITY; }

// The program and the multipliers (the objectives are checked by DualCertificate::lower_bound).
void check(const LinearProgram& lp, std::span<const double> multipliers) {
  const auto fail = [](const char* why) { throw std::invalid_argument(std::string("certified_lower_bound: ") + why); };
  const std::size_t m = lp.rows(), n = lp.columns;
  if (multipliers.size() != m || lp.row_start.size() != m + 1 || lp.row_upper.size() != m ||
      lp.column_lower.size() != n || lp.column_upper.size() != n || lp.row_start.back() != lp.column.size() ||
      lp.value.size() != lp.column.size())
    fail("sizes differ from the linear program's");
  for (std::size_t k = 0; k < lp.column.size(); ++k)
    if (lp.column[k] >= lp.columns || !std::isfinite(lp.value[k])) fail("a coefficient is not finite or out of range");
  for (std::size_t i = 0; i < lp.rows(); ++i)
    if (!bounds_usable(lp.row_lower[i], lp.row_upper[i])) fail("a row's bounds are not an interval");
  for (std::size_t j = 0; j < lp.columns; ++j)
    if (!bounds_usable(lp.column_lower[j], lp.column_upper[j])) fail("a column's bounds are not an interval");
}

}  // namespace

DualCertificate::DualCertificate(const LinearProgram& lp, std::span<const double> multipliers,
                                 std::span<const std::size_t> varying)
    : lp_(lp), varying_(varying.begin(), varying.end()) {
  check(lp, multipliers);
  // d = c - A^T lambda, each component enclosed; c is zero outside the varying columns.
  std::vector<Interval> reduced(lp.columns, Interval(0.0));
  for (std::size_t i = 0; i < lp.rows(); ++i) {
    const double lambda = usable_multiplier(multipliers[i], lp.row_lower[i], lp.row_upper[i]);
    if (lambda == 0.0) continue;
    for (std::size_t k = lp.row_start[i]; k < lp.row_start[i + 1]; ++k)
      reduced[lp.column[k]] = reduced[lp.column[k]] - Interval(lp.value[k]) * Interval(lambda);
    fixed_ = add_down(fixed_, (Interval(lambda) * Interval(lp.row_lower[i], lp.row_upper[i])).lo());
  }
  std::vector<bool> is_varying(lp.columns, false);
  for (const std::size_t j : varying_) {
    if (j >= lp.columns || is_varying[j])
      throw std::invalid_argument("DualCertificate: a varying column is out of range or repeated");
    is_varying[j] = true;
    transposed_.push_back(reduced[j]);
  }
  for (std::size_t j = 0; j < lp.columns; ++j)
    if (!is_varying[j]) fixed_ = add_down(fixed_, (reduced[j] * Interval(lp.column_lower[j], lp.column_upper[j])).lo());
}

double DualCertificate::lower_bound(std::span<const double> objective) const {
  if (objective.size() != varying_.size())
    throw std::invalid_argument("DualCertificate: one coefficient per varying column");
  double bound = fixed_;
  for (std::size_t v = 0; v < varying_.size(); ++v) {
    if (!std::isfinite(objective[v]))
      throw std::invalid_argument("DualCertificate: an objective coefficient is not finite");
    const std::size_t j = varying_[v];
    bound = add_down(
        bound, ((Interval(objective[v]) + transposed_[v]) * Interval(lp_.column_lower[j], lp_.column_upper[j])).lo());
  }
  return bound;  // (terms are finite or -infinity: no NaN)
}

double certified_lower_bound(const LinearProgram& lp, std::span<const double> objective,
                             std::span<const double> multipliers) {
  std::vector<std::size_t> every(lp.columns);
  for (std::size_t j = 0; j < lp.columns; ++j) every[j] = j;
  return DualCertificate(lp, multipliers, every).lower_bound(objective);
}

bool certifies_empty(const LinearProgram& lp, std::span<const double> multipliers) {
  const std::vector<double> zero(lp.columns, 0.0);
  return certified_lower_bound(lp, zero, multipliers) > 0.0;
}

}  // namespace gesmi
