#pragma once
// The warm rerun of solve_mission: the previous solution's domains are valid for a
// network that only gained marks (constraints only remove solutions), so the
// propagation starts from them at the added marks.

#include <string>

#include "solver/network/incremental_solver.h"
#include "solver/solve/mission_solution.h"

namespace gesmi::detail {

/// Why the added marks of `network` need a cold rerun, or empty: they name a mine no
/// mark named before, which changes the symmetry breaking among unlabelled mines.
std::string added_marks_problem(const Mission& mission, const MissionNetwork& network, const MissionSolution& previous);

/// Domains to start from, and the network indices of the added detections, once
/// added_marks_problem() found none.
struct WarmDomains {
  TubeDomains domains;
  std::vector<std::size_t> added;
};
/// `spent`: null, or `previous` itself when the caller gave it up (solve_mission's
/// MissionSolution&& overload): its increments are then moved into the domains instead
/// of copied (the rest of it stays: the waterfall compares the tube and mines with it).
WarmDomains warm_domains(const MissionNetwork& network, const MissionSolution& previous,
                         MissionSolution* spent = nullptr);

}  // namespace gesmi::detail
