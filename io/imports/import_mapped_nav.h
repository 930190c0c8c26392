#pragma once
// A logger's navigation export read through a column map (column_map.h,
// docs/formats.md "Logger exports"): any column order and extra columns, units,
// absolute times, and sensors at their own rates. An empty field, nan or NaN is "no
// reading of this sensor at this time".
//
// This reads each channel at its own times, with the bound of each reading; the
// mission's grid is made from them and the GPS fixes (nav_grid.h). A DVL reading needs
// vx, vy and vz on the same row.

#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "io/imports/column_map.h"
#include "io/imports/import_nav_csv.h"
#include "io/imports/nav_grid.h"
#include "solver/mission/sensor_model.h"

namespace gesmi::io {

struct MappedNavLog {
  NavSeries series;                   // each channel's readings
  std::optional<std::int64_t> epoch;  // UTC seconds of t = 0, from absolute times
  SensorModel model;                  // the model, bounds widened by unit conversion
  Mission::ConversionMargins conversion_margins;  // what the widening added
  double max_gap = kDefaultMaxGap;    // s
  std::string limit;                  // " beyond the 60 s limit (max_gap in MAP)", for messages
};

/// `model`: the sensor model the bounds come from. `epoch`: t = 0 of a log in seconds
/// (--epoch), or of absolute times when given.
MappedNavLog read_mapped_nav(std::istream& in, const std::string& name, const ColumnMap& map, const SensorModel& model,
                             std::optional<std::int64_t> epoch);

}  // namespace gesmi::io
