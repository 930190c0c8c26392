#pragma once
// The academic example of seed 001 (sections II-B and III-D): a 2-D robot starts at
// x(0) = (0, 0), moves by x(k+1) = x(k) + v(k) for k = 0..3, measures its distance
// z(k) = ||x(k) - m|| to an unknown seamark m at k = 1, 2, 3, and gets a GPS fix of
// x(4) at the end. Every measured quantity a has the domain [a* - d, a* + 2d] around
// its true value a* (d = inf: unmeasured), the rest is unbounded.

#include <array>

#include "solver/ctc/propagation.h"
#include "solver/interval/interval.h"

namespace gesmi {

struct Paper2dDeltas {
  double v = 1.0;  // velocity (input) error coefficient
  double z = 1.0;  // range error coefficient
  double x = kInf; // final GPS error coefficient
  /// Empty when usable: every delta is >= 0 (inf allowed); otherwise the reason.
  std::string validate() const;
};

using Interval2 = std::array<Interval, 2>;

struct Paper2dDomains {
  std::array<Interval2, 5> x;  // x(0) .. x(4)
  std::array<Interval2, 4> v;  // v(0) .. v(3)
  Interval2 m;
  std::array<Interval, 3> z;   // z(1) .. z(3)
};

/// The true configuration of the paper (Remark 1, equation (4)).
struct Paper2dTruth {
  std::array<std::array<double, 2>, 5> x{{{0, 0}, {40, 10}, {100, 60}, {0, 90}, {0, 0}}};
  std::array<std::array<double, 2>, 4> v{{{40, 10}, {60, 50}, {-100, 30}, {0, -90}}};
  std::array<double, 2> m{40, 60};
  std::array<double, 3> z{50, 60, 50};
};

/// Prior domains [a* - d, a* + 2d] built from the truth, rounded outward.
Paper2dDomains paper2d_prior(const Paper2dDeltas& deltas, const Paper2dTruth& truth = {});

struct Paper2dResult {
  Paper2dDomains domains;
  PropagationReport report;
};

/// Contracts the prior domains to the fixpoint of the forward-backward contractors
/// of equations (5): x(k+1) = x(k) + v(k) per component, z(k) = ||x(k) - m||.
Paper2dResult solve_paper2d(const Paper2dDomains& prior, const PropagationOptions& options = {});

}  // namespace gesmi
