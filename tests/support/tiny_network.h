#pragma once
// The tiny mission with its network and its sensors' domains: the inputs of the
// network-level solvers (outlier search, relaxed enclosure), for tests that call
// them below solve_mission.

#include <vector>

#include "solver/network/mission_network.h"
#include "tests/support/tiny_mission.h"

namespace gesmi::test {

struct TinyNetwork {
  TinyMission tiny;
  MissionNetwork net;
  TubeDomains sensor;
  explicit TinyNetwork(TinyMission t);
  /// Every constraint id: the detections, then the anchors.
  std::vector<std::size_t> all_ids() const;
};

}  // namespace gesmi::test
