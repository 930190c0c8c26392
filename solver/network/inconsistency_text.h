#pragma once
// The operator's one-line wording of an inconsistency: what emptied a domain,
// where, and which inputs to check. Kept apart from the propagation, which only
// records the facts (Inconsistency).

#include <string>
#include <vector>

#include "solver/network/mission_network.h"
#include "solver/network/mission_solver.h"

namespace gesmi {

/// One line naming the constraint, the time and the inputs (network: the one that
/// was solved, for the marks' and fixes' details).
std::string describe(const Inconsistency& inconsistency, const MissionNetwork& network);

/// "mark 3", "GPS fix 1".
std::string describe(const ConstraintRef& constraint);

/// "; removing mark 23 or GPS fix 1 restores consistency", or, with no single input
/// to blame, "; no single mark or fix explains it (try --max-outliers 2)".
std::string describe_diagnosis(const std::vector<ConstraintRef>& explaining);

}  // namespace gesmi
