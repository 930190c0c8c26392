#pragma once
// The envelope picture (seed 001, Fig. 7): the tube in the horizontal plane (east
// across, north up), the mine boxes, the GPS fixes and, for simulated missions,
// the true track and mines.

#include <string>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/tube_domains.h"

namespace gesmi::io {

struct EnvelopePicture {
  const TubeDomains* domains = nullptr;
  const Mission* mission = nullptr;  // for the truth and the GPS fixes (local boxes)
  std::vector<Vec3I> fix_boxes;      // GPS boxes in the local frame
  std::string title;
};

void write_envelope_png(const EnvelopePicture& picture, const std::string& path);

}  // namespace gesmi::io
