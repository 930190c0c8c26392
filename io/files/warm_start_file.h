#pragma once
// A result file used to warm-start a solve of a mission: read (its digests checked
// on the way, result_file.h), then proven to come from the same navigation data and
// sensor bounds with only marks added; FormatError naming the file and what differs
// otherwise.

#include <string>

#include "solver/mission/mission.h"
#include "solver/solve/mission_solution.h"

namespace gesmi::io {

/// `navigation` is navigation_digest(mission) of today's result format when the caller
/// has it already (a solve stores it in its result): each input is hashed once (twice
/// for a result of an earlier format, whose digests are SHA-256).
MissionSolution read_warm_start(const std::string& path, const Mission& mission, std::string navigation);
MissionSolution read_warm_start(const std::string& path, const Mission& mission);

}  // namespace gesmi::io
