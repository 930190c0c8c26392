#pragma once
// Warm-started rerun (seed 001, end of section V: "the operator can be seen as a
// contractor"): the domains of an earlier solve stay valid when detections are
// added, because constraints only remove solutions. Propagation starts at the new
// detections and spreads along the chains and through the mines only while domains
// keep shrinking: a work list, not full sweeps.

#include <cstdint>
#include <span>
#include <vector>

#include "solver/network/mission_solver.h"

namespace gesmi {

struct IncrementalReport {
  SolverReport solver;         // consistency and the inconsistency if any
  std::size_t work_items = 0;  // detections and fixes applied
  std::size_t samples_touched = 0;  // sum of the lengths of the spreads
};

/// Sets the candidate mines of the detections that an earlier solve already had
/// (its candidates by mark row: the mark table only grew, so rows keep their
/// index) and returns the network indices of the new detections.
std::vector<std::size_t> carry_candidates(const MissionNetwork& network, TubeDomains& domains,
                                          std::span<const std::uint64_t> previous_by_mark);

/// domains: the contracted domains of the same network without the detections
/// `added` (indices into network.detections), with their candidates initialised.
IncrementalReport propagate_from(const MissionNetwork& network, TubeDomains& domains,
                                 std::span<const std::size_t> added, const SolverOptions& options = {});

}  // namespace gesmi
