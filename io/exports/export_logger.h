#pragma once
// `gesmi export --format logger`: a mission written the way a vehicle's logger
// exports it, to exercise and demonstrate the real-log import (docs/formats.md,
// "Logger exports"). In one folder:
//   log.csv        semicolon-separated, ISO 8601 times, angles in degrees, columns in
//                  another order with extra ones; the attitude on every row, the DVL
//                  and altitude every `dvl_every` rows (none inside `dvl_gap`), the
//                  depth every `depth_every` rows; an absent reading is an empty field
//                  (NaN inside the gap)
//   map.yaml       its column map
//   gps.nmea       the fixes as NMEA 0183 RMC + GGA pairs
//   marks.csv      the mark table with ISO 8601 times, and marks_map.yaml
//   model.yaml     the sensor model; truth.csv (on the DVL rows) and truth_mines.csv
//                  when the mission has them
//   import-command.txt  the `gesmi import nav` that reads it all back
// Times are written to the microsecond (fixes to the millisecond), latitudes and
// longitudes to 1e-7 minute (0.2 mm); truth.csv holds the times the import will read.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "solver/mission/mission.h"

namespace gesmi::io {

struct LoggerExportOptions {
  std::int64_t epoch = 0;         // UTC seconds of t = 0 (the mission's own when it has one)
  std::size_t dvl_every = 2;      // DVL and altitude on every dvl_every-th sample
  std::size_t depth_every = 10;   // depth on every depth_every-th sample
  std::optional<std::pair<double, double>> dvl_gap;  // no DVL reading in [from, to] s
};

/// `source` names the mission in errors (a mission with per-sample half-widths is
/// refused: the log cannot carry them).
void export_mission_logger(const Mission& mission, const std::string& source, const std::string& folder,
                           const LoggerExportOptions& options);

/// "hhmmss.sss" and the checksummed sentence "$<body>*HH" of NMEA 0183.
std::string nmea_sentence(const std::string& body);

}  // namespace gesmi::io
