#pragma once
// The `gesmi import` pipelines: read the text files named on the command line,
// check each against the others (GPS and marks inside the navigation's time span,
// marks against the sonar range and the mine count), and assemble a validated
// Mission with its GPS fixes in the local frame. Errors are FormatError naming the
// file, the line, the field and the reason.

#include <optional>
#include <string>

#include "io/imports/import_gesmi_txt.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

/// Optional inputs shared by the importers (empty path: not given).
struct ImportInputs {
  std::string config;       // sensor model YAML (io/files/sensor_model_yaml.h) over the defaults
  std::string gps;          // GPS CSV
  std::string marks;        // marks CSV
  std::string truth;        // truth.csv (simulated missions)
  std::string truth_mines;  // truth_mines.csv
  std::optional<GeoOrigin> origin;  // default: the first GPS fix (nav), the Redermor start fix (gesmi-txt)
  std::optional<int> mines;         // default: the rows of truth_mines, else 0
};

/// `gesmi import nav`: a navigation CSV and the optional inputs.
Mission import_nav(const std::string& nav_csv, const ImportInputs& inputs);

/// `gesmi import gesmi-txt`: a GESMI text log; inputs.gps and the truth files are
/// not used (the log carries its own positions).
Mission import_gesmi_txt(const std::string& path, GesmiXy xy, const ImportInputs& inputs);

/// `gesmi import marks`: replaces the mission's mark table by a marks CSV. `mines`,
/// when given, sets the number of mines first (it must match /truth/mines if any).
void import_marks(Mission& mission, const std::string& marks_csv, std::optional<int> mines);

}  // namespace gesmi::io
