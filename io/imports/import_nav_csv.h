#pragma once
// The navigation CSV (docs/formats.md):
//   time,roll,pitch,heading,vx,vy,vz,altitude,depth
// s, rad, rad, rad, m/s (DVL body frame), m, m; time strictly increasing. Optional
// columns after those, any subset in any order: roll_halfwidth, pitch_halfwidth,
// heading_halfwidth, vx_halfwidth, vy_halfwidth, vz_halfwidth, altitude_halfwidth,
// depth_halfwidth (per-sample bounds replacing the sensor model's).

#include <array>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "solver/mission/mission.h"

namespace gesmi::io {

struct NavLog {
  std::vector<double> time, roll, pitch, heading, vx, vy, vz, altitude, depth;
  NavHalfWidths half_widths;  // each empty unless its column was given
  std::vector<std::size_t> line;  // each row's line in the file (read_nav_csv only)
};

/// Reads and validates a navigation CSV; FormatError "name:LINE: field: reason".
/// At least 2 rows.
NavLog read_nav_csv(std::istream& in, const std::string& name);

/// The optional half-width columns and the arrays they fill, in header order.
struct NavHalfWidthColumn {
  std::string_view name;
  std::vector<double> NavHalfWidths::*member;
};
const std::array<NavHalfWidthColumn, 8>& nav_half_width_columns();

}  // namespace gesmi::io
