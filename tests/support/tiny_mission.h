#pragma once
// A tiny synthetic mission with known truth, independent of gesmi's simulator:
// 300 s at 10 Hz, a northbound leg, a 180° starboard turn, a southbound leg, one
// mine between the legs seen once on each leg, GPS at both ends. The true attitude
// and speed are piecewise linear (rates within the model's bounds) and the true
// position is integrated with a midpoint rule on sub-steps, so it lies in every
// step's enclosure. Readings are truth plus errors strictly inside the bounds.

#include <cstdint>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/mission_network.h"

namespace gesmi::test {

enum class TinyErrors { uniform, worst_case };

struct TinyMission {
  Mission mission;
  std::vector<PositionFix> fixes;  // GPS boxes in the local frame (also in the mission's gps_north/east)
};

TinyMission make_tiny_mission(std::uint64_t seed, TinyErrors errors);

}  // namespace gesmi::test
