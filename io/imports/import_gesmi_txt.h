#pragma once
// The whitespace-separated text log of the original GESMI solver and of the Codac
// library's Redermor example (docs/formats.md, "GESMI text log"): rows of 21
// numbers
//   t  roll droll  pitch dpitch  heading dheading  vx dvx  vy dvy  vz dvz
//      depth ddepth  altitude daltitude  x dx  y dy
// (each value followed by its half-width; SI units, angles in radians). Lines
// before the first such row are header lines; after it, every non-blank line must
// be a data row (a shorter row is an error, not a header). A half-width that is NaN
// or infinite is "not given".
//
// gesmi's reading, stated in docs/formats.md:
//  - a given half-width replaces the sensor model's bound for that sample; a sensor
//    with no given half-width at all keeps the model;
//  - x is north and y east, in metres, in a local frame about the origin (as the
//    simulator reads the Codac mine positions: the file does not say);
//  - GesmiXy::fixes: every row whose x and y half-widths are given (finite, and below
//    the local frame's 100 km zone: logs write "unknown" as a huge bound) is a position
//    fix with those bounds (stored as a GPS fix in longitude/latitude about the
//    origin, with per-fix half-widths);
//  - GesmiXy::truth: x, y and the depth reading are the ground truth, as Codac's
//    loader reads them; only the first row's x, y is a fix (when its half-widths are
//    given): the start position.

#include <array>
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "solver/mission/mission.h"

namespace gesmi::io {

/// Columns of a data row after t, each a (value, half-width) pair.
struct GesmiColumn {
  enum : std::size_t { roll, pitch, heading, vx, vy, vz, depth, altitude, x, y, count };
};

struct GesmiTextLog {
  std::vector<double> time;
  std::array<std::vector<double>, GesmiColumn::count> value, half_width;  // half-width NaN when not given
  std::vector<std::size_t> line;                                // source line of each row
};

/// The name of a column ("roll" .. "altitude", "x", "y"): the navigation channel's name
/// (mission.h) for the first eight.
const char* gesmi_column_name(std::size_t column);

/// Reads and checks a GESMI text log; FormatError "name:LINE: field: reason".
GesmiTextLog read_gesmi_txt(std::istream& in, const std::string& name);

/// The sensor model's half-width for one sample of a column (roll..altitude) with
/// reading `value` (gesmi::model_half_width of its channel).
double column_half_width(const SensorModel& model, std::size_t column, double value);

enum class GesmiXy { fixes, truth };

/// The reference mission's start fix: the default origin of a GESMI text log, whose
/// local frame has no stated geodetic origin (the Redermor log starts there).
inline constexpr GeoOrigin kRedermorStartFix{48.212920614, -4.458227931};

/// Builds a mission (no marks, no mines) from a log, the origin of its local frame
/// and the sensor model; `name` prefixes errors.
Mission mission_from_gesmi_txt(GesmiTextLog log, const std::string& name, const GeoOrigin& origin,
                               const SensorModel& model, GesmiXy xy);

}  // namespace gesmi::io
