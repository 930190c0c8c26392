#pragma once
// The GPS CSV (docs/formats.md):
//   time,longitude,latitude[,north_halfwidth,east_halfwidth]
// s, degrees WGS84, and optionally each fix's own bound in metres (replacing the
// sensor model's GPS bounds). Time strictly increasing and inside the mission.

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "io/imports/nav_grid.h"

namespace gesmi::io {

struct GpsLog {
  std::vector<double> time, longitude, latitude;
  std::vector<double> north_halfwidth, east_halfwidth;  // empty unless given
  std::vector<std::size_t> line;                        // source line of each fix
};

/// Reads and validates a GPS CSV whose fixes must lie in [first_time, last_time]
/// (the navigation's span); FormatError "name:LINE: field: reason". May hold no fix.
/// With `unused`, a fix outside the span is left out and listed there instead, with
/// `why` as its reason.
GpsLog read_gps_csv(std::istream& in, const std::string& name, double first_time, double last_time,
                    std::vector<UnusedFix>* unused = nullptr, const std::string& why = {});

}  // namespace gesmi::io
