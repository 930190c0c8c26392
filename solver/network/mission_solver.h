#pragma once
// Forward-backward propagation over the mission network to a fixpoint (seed 001,
// section III-D): each sweep runs the evolution chains forward (x, y, z), applies
// the fixes and detections, runs the chains backward (contracting positions and
// increments), and applies the fixes and detections again. It stops when no bound
// of the tube or of a mine box moved by more than the tolerance, or after the
// sweep limit. An empty domain stops it with a precise report.

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "solver/network/constraint_ref.h"
#include "solver/network/mission_network.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

struct SolverOptions {
  static constexpr int kMaxSweeps = 1000000;
  int max_sweeps = 100;
  double tolerance = 1e-3;  // m: largest move of a bound that still counts as progress
  /// Called after each sweep with the sweep number and the largest bound move (m).
  std::function<void(int sweep, double largest_move)> on_sweep;
  /// Empty when usable; otherwise the reason, starting with the option it is about as
  /// the gesmi command spells it ("max-sweeps: must be ...").
  std::string validate() const;
};

/// The first constraint that emptied a domain, with the inputs that feed it, as
/// data; describe() (inconsistency_text.h) words it for the operator.
struct Inconsistency {
  enum class Kind { evolution, fix, detection } kind = Kind::evolution;
  std::size_t step = 0;      // sample index where it happened
  double time = 0.0;         // s
  std::optional<ConstraintRef> source;  // fix and detection: the GPS row or mark row
  // evolution: the chain (0 north, 1 east, 2 down) that dead reckoning could not
  // join, and the nearest fix or detection on each side (none: the start or end).
  int axis = -1;
  std::optional<ConstraintRef> before, after;
  // fix: the fix box. detection: the mine tried (-1 when no candidate mine could
  // explain the mark) and its box. Both: the tube at that time.
  Vec3I fix_box, tube, mine_box;
  int mine = -1;
  /// detection without any possible mine: the distance from the tube to each candidate.
  std::vector<std::pair<int, Interval>> candidate_distances;
};

struct SolverReport {
  int sweeps = 0;
  bool converged = false;
  double last_move = 0.0;  // largest bound move of the last sweep (m)
  std::optional<Inconsistency> inconsistency;
  bool consistent() const { return !inconsistency.has_value(); }
};

SolverReport solve(const MissionNetwork& network, TubeDomains& domains, const SolverOptions& options = {});

}  // namespace gesmi
