#pragma once
// A logger's navigation export read through a column map (column_map.h,
// docs/formats.md "Logger exports"): any column order and extra columns, units,
// absolute times, and sensors at their own rates. An empty field, nan or NaN is "no
// reading of this sensor at this time".
//
// The solver's grid is the rows with a DVL reading (vx, vy, vz together). Every other
// channel (roll, pitch, heading, depth, altitude) is enclosed at grid times from its
// own readings (solver/mission/between_readings.h): a channel read on every grid row
// keeps the model's bounds; one read at other times gets per-sample half-widths. A DVL
// gap is a long step, which the step model encloses with the model's rate bounds
// (docs/model.md, "Gaps"). A channel silent longer than the gap limit is an error.

#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "io/imports/column_map.h"
#include "io/imports/import_nav_csv.h"
#include "solver/mission/sensor_model.h"

namespace gesmi::io {

/// Longest time without a reading of any navigation sensor unless the map's
/// `max_gap` says otherwise (s).
inline constexpr double kDefaultMaxGap = 60.0;

struct MappedNavLog {
  NavLog log;                         // on the grid
  std::optional<std::int64_t> epoch;  // UTC seconds of t = 0, from absolute times
  SensorModel model;                  // the model, bounds widened by unit conversion
  Mission::ConversionMargins conversion_margins;  // what the widening added
  std::vector<std::string> notes;     // what the import did, one line each, for the summary
};

/// `model`: the sensor model the bounds come from. `epoch`: t = 0 of a log in seconds
/// (--epoch), or of absolute times when given.
MappedNavLog read_mapped_nav(std::istream& in, const std::string& name, const ColumnMap& map, const SensorModel& model,
                             std::optional<std::int64_t> epoch);

}  // namespace gesmi::io
