#pragma once
// The q-relaxed set S_q of seed 004 on a mission network: every trajectory and mine
// position consistent with all the data but some q of the removable constraints.
// Its enclosure is the hull, over every removal set R of exactly q ids (removing
// fewer only shrinks the set), of the solution without R.
//
// Each removal set is solved on the reduced network (reduced_network.h): a
// relaxation, so its domains at the event samples enclose those of the full network
// without R. Between two events only the evolution chain and the sensor priors act,
// so the tube on every sample is rebuilt as the hull over removal sets of the chain
// projection between their event boxes. The lower bound at a sample depends only on
// the lower bounds at the two events around it (and the upper on the upper), so the
// hull needs only the removal sets on the Pareto frontier of those pairs: a few
// chain sweeps per segment instead of one full solve per removal set.

#include <cstddef>
#include <vector>

#include "solver/network/mission_solver.h"

namespace gesmi {

struct RelaxedStats {
  std::size_t removal_sets = 0;     // sets of q ids examined
  std::size_t consistent_sets = 0;  // those whose reduced network stayed consistent
};

/// sensor: sensor_domains() of the mission; removable: the constraint ids that may
/// be removed (detection index j, or detections.size() + anchor index), sorted.
/// domains receives the enclosure of S_q (tube, increments, mines, candidates);
/// consistent_sets is 0 when no removal set of size q is consistent.
RelaxedStats relaxed_enclosure(const MissionNetwork& network, const TubeDomains& sensor,
                               const std::vector<std::size_t>& removable, std::size_t q, const SolverOptions& options,
                               TubeDomains& domains);

}  // namespace gesmi
