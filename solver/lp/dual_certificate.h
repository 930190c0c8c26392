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

#include <span>

#include "solver/lp/linear_program.h"

namespace gesmi {

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
