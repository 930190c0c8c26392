#pragma once
// The `gesmi import` pipelines: read the text files named on the command line,
// check each against the others (GPS and marks inside the navigation's time span,
// marks against the sonar range and the mine count), and assemble a validated
// Mission with its GPS fixes in the local frame. Errors are FormatError naming the
// file, the line, the field and the reason.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/imports/import_gesmi_txt.h"
#include "io/imports/nav_grid.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

enum class GpsFormat { detect, csv, nmea };

/// Optional inputs shared by the importers (empty path: not given).
struct ImportInputs {
  std::string config;       // sensor model YAML (io/files/sensor_model_yaml.h) over the defaults
  std::string map;          // column map of the navigation log (column_map.h); empty: the exact-header CSV
  std::string gps;          // GPS CSV or NMEA log
  GpsFormat gps_format = GpsFormat::detect;
  std::optional<std::int64_t> gps_date;  // days since 1970 of an NMEA log's first fix, when it has no RMC
  std::string marks;        // marks CSV
  std::string marks_map;    // column map of the marks file; empty: the exact-header CSV
  std::optional<std::int64_t> epoch;  // UTC seconds of t = 0 for a log in seconds (--epoch)
  std::string truth;        // truth.csv (simulated missions)
  std::string truth_mines;  // truth_mines.csv
  std::optional<GeoOrigin> origin;  // default: the first GPS fix (nav), the Redermor start fix (gesmi-txt)
  std::optional<int> mines;         // default: the rows of truth_mines, else 0
};

/// What an import did that the user should hear of: one line each (skipped sentences,
/// the grid, channels bridged or enclosed: Mission::half_widths.fill), and the GPS fixes
/// it could not use, each a warning.
struct ImportNotes {
  std::vector<std::string> lines;
  std::vector<UnusedFix> unused_fixes;
};

/// `gesmi import nav`: a navigation CSV and the optional inputs. A logger's export
/// (inputs.map) spans its first to its last reading or GPS fix (nav_grid.h).
Mission import_nav(const std::string& nav_csv, const ImportInputs& inputs, ImportNotes* notes = nullptr);

/// `gesmi import gesmi-txt`: a GESMI text log; inputs.gps and the truth files are
/// not used (the log carries its own positions).
Mission import_gesmi_txt(const std::string& path, GesmiXy xy, const ImportInputs& inputs);

/// `gesmi import marks`: replaces the mission's mark table by a marks CSV (read
/// through `map` when not empty). `mines`, when given, sets the number of mines first
/// (it must match /truth/mines if any).
void import_marks(Mission& mission, const std::string& marks_csv, std::optional<int> mines, const std::string& map = {});

}  // namespace gesmi::io
