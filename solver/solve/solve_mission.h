#pragma once
// The mission solve, one entry point for every front end (the gesmi command, the
// Python module, a batch driver):
//
//   SolveOptions options;                  // cold
//   options.max_outliers = 2;              // or: tolerate up to 2 wrong marks or fixes
//   options.warm_from = &previous;         // or: rerun after marks were added
//   MissionSolution s = solve_mission(mission, options);
//
// Cold: the sensors' domains and the network's priors, forward-backward sweeps to
// the fixpoint, and on an inconsistency the diagnosis (the single marks or fixes
// whose removal restores consistency). Warm: the previous solution's domains, then a
// work list from the added marks (outlier_solver.h, incremental_solver.h for the
// models). Results are never wrong: an inapplicable warm start is solved cold, and
// says why.

#include <functional>
#include <string>

#include "solver/mission/mission.h"
#include "solver/network/outliers/outlier_solver.h"
#include "solver/solve/mission_solution.h"

namespace gesmi {

struct SolveOptions {
  SolverOptions propagation;  // sweep limit, tolerance, progress hook
  /// >= 0: tolerate up to this many wrong marks or fixes (outlier_solver.h).
  int max_outliers = -1;
  OutlierMode outlier_mode = OutlierMode::relaxed;
  bool trust_gps = false;  // outlier modes: GPS fixes are never outliers
  /// A solution of the same navigation data and bounds with fewer (or the same)
  /// marks; the caller proves "same data" (the result file's digests do).
  const MissionSolution* warm_from = nullptr;
  bool diagnose = true;   // cold inconsistent solves: find the single inputs to blame
  bool waterfall = true;  // compute the reconstructed waterfall
  /// Progress hook, called on the calling thread: the stage being computed ("sensor
  /// enclosures", "waterfall") and the fraction of it done (< 0 when unknown). The
  /// sweeps in between are reported by propagation.on_sweep.
  std::function<void(const char* stage, double fraction)> on_stage;
  /// Empty when usable; otherwise the reason.
  std::string validate() const;
};

MissionSolution solve_mission(const Mission& mission, const SolveOptions& options = {});

/// A warm rerun from `previous`, which the caller gives up (options.warm_from is
/// replaced by it): its increments are moved into the new solution instead of copied (at
/// 10^7 steps 480 MB less memory and one copy less). The result is the same as with
/// options.warm_from = &previous. `previous` is left valid but unspecified.
MissionSolution solve_mission(const Mission& mission, SolveOptions options, MissionSolution&& previous);

/// Why `previous` cannot warm-start a solve of `mission` (another grid, other mines,
/// an inconsistent result, a mark table that changed other than by added rows), or
/// empty when it can.
std::string warm_start_problem(const Mission& mission, const MissionSolution& previous);

}  // namespace gesmi
