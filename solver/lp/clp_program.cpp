#include "solver/lp/clp_program.h"

#include <cmath>
#include <coin/ClpSimplex.hpp>
#include <coin/CoinPackedMatrix.hpp>
#include <stdexcept>

namespace gesmi {
namespace {

std::vector<double> clp_bounds(const std::vector<double>& bounds) {
  std::vector<double> out(bounds);
  for (double& b : out)
    if (std::isinf(b)) b = b > 0 ? COIN_DBL_MAX : -COIN_DBL_MAX;
  return out;
}

}  // namespace

ClpProgram::ClpProgram(const LinearProgram& lp) : model_(std::make_unique<ClpSimplex>()) {
  std::vector<CoinBigIndex> starts;
  std::vector<int> indices, lengths;
  for (std::size_t i = 0; i <= lp.rows(); ++i) starts.push_back(static_cast<CoinBigIndex>(lp.row_start[i]));
  for (const std::size_t c : lp.column) indices.push_back(static_cast<int>(c));
  for (std::size_t i = 0; i < lp.rows(); ++i) lengths.push_back(static_cast<int>(starts[i + 1] - starts[i]));
  const CoinPackedMatrix matrix(false, static_cast<int>(lp.columns), static_cast<int>(lp.rows()),
                                static_cast<CoinBigIndex>(lp.value.size()), lp.value.data(), indices.data(),
                                starts.data(), lengths.data());
  const std::vector<double> zero(lp.columns, 0.0);
  model_->setLogLevel(0);
  model_->loadProblem(matrix, clp_bounds(lp.column_lower).data(), clp_bounds(lp.column_upper).data(), zero.data(),
                      clp_bounds(lp.row_lower).data(), clp_bounds(lp.row_upper).data());
}

ClpProgram::~ClpProgram() = default;

ClpProgram::Answer ClpProgram::minimize(std::span<const double> objective) {
  if (objective.size() != static_cast<std::size_t>(model_->numberColumns()))
    throw std::invalid_argument("ClpProgram::minimize: one coefficient per column");
  for (std::size_t j = 0; j < objective.size(); ++j) model_->setObjectiveCoefficient(static_cast<int>(j), objective[j]);
  model_->dual();
  const auto rows = static_cast<std::size_t>(model_->numberRows());
  Answer a;
  if (model_->status() == 0) {
    a.status = Status::optimal;
    a.multipliers.assign(model_->dualRowSolution(), model_->dualRowSolution() + rows);
  } else if (model_->status() == 1) {
    a.status = Status::infeasible;
    if (const double* ray = model_->infeasibilityRay()) {
      a.multipliers.assign(ray, ray + rows);
      delete[] ray;
    }
  }
  return a;
}

}  // namespace gesmi
