#include "solver/mission/mission.h"

#include <stdexcept>

namespace gesmi {

const std::array<NavChannel, 8>& nav_channels() {
  static const std::array<NavChannel, 8> channels = {{
      {"roll", &Mission::roll, &NavHalfWidths::roll},
      {"pitch", &Mission::pitch, &NavHalfWidths::pitch},
      {"heading", &Mission::heading, &NavHalfWidths::heading},
      {"vx", &Mission::vx, &NavHalfWidths::vx},
      {"vy", &Mission::vy, &NavHalfWidths::vy},
      {"vz", &Mission::vz, &NavHalfWidths::vz},
      {"altitude", &Mission::altitude, &NavHalfWidths::altitude},
      {"depth", &Mission::depth, &NavHalfWidths::depth},
  }};
  return channels;
}

const NavChannel& nav_channel(std::string_view name) {
  for (const NavChannel& c : nav_channels())
    if (c.name == name) return c;
  throw std::logic_error("no navigation channel " + std::string(name));
}

}  // namespace gesmi
