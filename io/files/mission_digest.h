#pragma once
// Fingerprints of a mission's inputs (hex digests of the result format's kind:
// XXH3-128 today, SHA-256 in results of formats 2 to 5), stored in every result so that
// a warm rerun can prove it starts from a result of the same mission. Three parts:
// navigation (nav arrays, half-widths, GPS fixes, origin, mine count), bounds (the
// sensor model) and the mark table (of its first `marks` rows).

#include <cstddef>
#include <string>

#include "io/digest/digest.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

std::string navigation_digest(const Mission& mission, DigestKind kind);
std::string bounds_digest(const SensorModel& model, DigestKind kind);
std::string marks_digest(const Mission& mission, std::size_t marks, DigestKind kind);

}  // namespace gesmi::io
