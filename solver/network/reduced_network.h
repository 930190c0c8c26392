#pragma once
// A relaxation of the mission network on its "events" only (the samples where a
// fix or a detection sits): between two consecutive events the chain is replaced
// by the sum of its increments, and the depth prior at an event is the barometer
// tube there. Every constraint of the reduced network is implied by the full one,
// so an inconsistency of the reduced network proves the full one inconsistent:
// used to screen outlier hypotheses in microseconds before any full solve.

#include <vector>

#include "solver/network/mission_network.h"

namespace gesmi {

struct ReducedNetwork {
  std::vector<std::size_t> events;  // the full grid's sample index of each event, increasing
  std::vector<double> time;  // event times (owned: net.time points here)
  MissionNetwork net;
  TubeDomains domains;       // sensor priors on the events (no fixes, no mines yet)
  /// On the full grid: the depth tube and vertical increments from the barometer and
  /// the sensors alone (one forward-backward pass of the depth chain).
  std::vector<Interval> depth, depth_increments;

  ReducedNetwork() = default;
  ReducedNetwork(const ReducedNetwork&) = delete;
  ReducedNetwork& operator=(const ReducedNetwork&) = delete;
};

/// sensor: the full network's sensor domains (sensor_domains()), unchanged.
/// Returns false when the sensors alone are inconsistent (depth against DVL).
bool build_reduced_network(const MissionNetwork& full, const TubeDomains& sensor, ReducedNetwork& reduced);

}  // namespace gesmi
