#pragma once
// Bounds of a linear function over a linear program's feasible set, certified by Lagrange
// multipliers whatever produced them (an LP solver's duals, a coarse guess, zeros): for
// any multipliers lambda, one per row, and d = c - A^T lambda,
//   c.z = d.z + lambda.(A z) >= sum_j min(d_j l_j, d_j u_j) + sum_i min(lambda_i bl_i, lambda_i bu_i)
// for every feasible z (l, u: the column bounds; bl, bu: the row bounds). Every term is
// enclosed in interval arithmetic, so the bound holds with the rounding of its own
// computation: an LP solver's answer is only a hint, never part of the guarantee.
//
// A multiplier that would multiply an infinite row bound by its sign is taken as 0 (any
// multipliers are valid, and that one would only give -infinity).

#include <cstddef>
#include <span>
#include <vector>

#include "solver/interval/interval.h"
#include "solver/lp/linear_program.h"

namespace gesmi {

/// One set of multipliers prepared for many objectives that are zero outside the same
/// few `varying` columns: the rows' terms and the other columns' terms are summed once,
/// and each objective then costs a term per varying column (the structured relaxation
/// bounds every sample of a segment with the multipliers of a nearby one). The program
/// must outlive this object; it is checked as certified_lower_bound checks it.
class DualCertificate {
 public:
  DualCertificate(const LinearProgram& lp, std::span<const double> multipliers, std::span<const std::size_t> varying);
  /// A lower bound of objective . z, objective[v] the coefficient of column varying[v].
  double lower_bound(std::span<const double> objective) const;

 private:
  const LinearProgram& lp_;
  std::vector<std::size_t> varying_;
  std::vector<Interval> transposed_;  // -(A^T lambda)_j of each varying column
  double fixed_ = 0.0;                // the rows' and the other columns' terms, rounded down
};

/// A lower bound of objective . z over the feasible set of `lp` (-infinity when the
/// multipliers leave it unbounded). std::invalid_argument when the program is malformed:
/// sizes that differ, a coefficient or objective entry that is not finite, bounds that
/// are not an interval.
double certified_lower_bound(const LinearProgram& lp, std::span<const double> objective,
                             std::span<const double> multipliers);

/// Whether the multipliers prove the feasible set empty: the certified lower bound of
/// 0 . z is above 0 (a Farkas certificate, as an LP solver's infeasibility ray gives).
bool certifies_empty(const LinearProgram& lp, std::span<const double> multipliers);

}  // namespace gesmi
