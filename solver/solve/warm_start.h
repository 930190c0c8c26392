#pragma once
// The warm rerun of solve_mission: the previous solution's domains are valid for a
// network that only gained marks (constraints only remove solutions), so the
// propagation starts from them at the added marks.

#include <optional>
#include <string>

#include "solver/network/incremental_solver.h"
#include "solver/solve/mission_solution.h"

namespace gesmi::detail {

/// Domains to start from, and the network indices of the added detections; nullopt
/// with `why` set when the rerun must be cold (the added marks name a mine no mark
/// named before, which changes the symmetry breaking among unlabelled mines).
struct WarmDomains {
  TubeDomains domains;
  std::vector<std::size_t> added;
};
/// `spent`: null, or `previous` itself when the caller gave it up (solve_mission's
/// MissionSolution&& overload): its increments are then moved into the domains instead
/// of copied (the rest of it stays: the waterfall compares the tube and mines with it).
std::optional<WarmDomains> warm_domains(const Mission& mission, const MissionNetwork& network,
                                        const MissionSolution& previous, std::string& why,
                                        MissionSolution* spent = nullptr);

}  // namespace gesmi::detail
