#pragma once
// The navigation channels by their place in nav_channels() (solver/mission/mission.h),
// the order nav_map_schema() follows too: indices of the importers' per-channel arrays.

#include <cstddef>
#include <string>

#include "solver/mission/mission.h"

namespace gesmi::io::nav {

enum Channel { roll, pitch, heading, vx, vy, vz, altitude, depth, kChannels };

/// The channel's name: its column in gesmi's navigation CSV and its key in a nav map.
inline std::string channel_name(int channel) {
  return std::string(nav_channels()[static_cast<std::size_t>(channel)].name);
}

}  // namespace gesmi::io::nav
