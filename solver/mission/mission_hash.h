#pragma once
// Fingerprints of a mission's inputs, stored in every result so that a warm rerun
// can prove it starts from a result of the same mission (FNV-1a over the bytes of
// the arrays, hex). Three parts: navigation (nav arrays and GPS fixes), bounds (the
// sensor model) and the mark table (of its first `marks` rows).

#include <cstddef>
#include <string>

#include "solver/mission/mission.h"

namespace gesmi {

std::string navigation_hash(const Mission& mission);
std::string bounds_hash(const SensorModel& model);
std::string marks_hash(const Mission& mission, std::size_t marks);

}  // namespace gesmi
