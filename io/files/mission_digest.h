#pragma once
// Fingerprints of a mission's inputs (SHA-256, hex), stored in every result so that
// a warm rerun can prove it starts from a result of the same mission. Three parts:
// navigation (nav arrays, half-widths, GPS fixes, origin, mine count), bounds (the
// sensor model) and the mark table (of its first `marks` rows).

#include <cstddef>
#include <string>

#include "solver/mission/mission.h"

namespace gesmi::io {

std::string navigation_digest(const Mission& mission);
std::string bounds_digest(const SensorModel& model);
std::string marks_digest(const Mission& mission, std::size_t marks);

}  // namespace gesmi::io
