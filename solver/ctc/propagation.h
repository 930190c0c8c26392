#pragma once
// Propagation to a fixpoint: applies a list of contractors in turn until no
// domain shrinks by more than a relative tolerance (or a sweep limit is hit).

#include <vector>

#include "solver/ctc/ctc.h"

namespace gesmi {

struct PropagationOptions {
  /// A sweep that shrinks no domain by more than this fraction of its width
  /// (or, for an unbounded domain, leaves it unbounded) ends the loop.
  double relative_tolerance = 1e-12;
  int max_sweeps = 100000;
  /// Empty when the options are usable; otherwise the reason.
  std::string validate() const;
};

struct PropagationReport {
  int sweeps = 0;
  bool converged = false;  // false when max_sweeps stopped the loop
  bool empty = false;      // the box became empty: no solution
};

PropagationReport propagate(const std::vector<CtcAny>& contractors, Box& box, const PropagationOptions& options = {});

/// True when `after` (a contraction of `before`) shrank some component by more than
/// the relative tolerance.
bool shrank_significantly(const Box& before, const Box& after, double relative_tolerance);

}  // namespace gesmi
