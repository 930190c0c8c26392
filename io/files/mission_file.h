#pragma once
// The HDF5 mission file (docs/formats.md): navigation, GPS fixes, mark table,
// origin, sensor model and, for simulated missions, the truth. read_mission()
// validates everything and names file, dataset, row, field and reason on error.

#include <optional>
#include <string>

#include "solver/mission/mission.h"

namespace gesmi::io {

/// Whether read_mission() reads the simulated truth (/truth), which only commands that
/// compare with it or write the mission again need.
enum class TruthReading { read, skip };

/// Reads and validates a mission; fills the GPS fixes in the local frame.
Mission read_mission(const std::string& path, TruthReading truth = TruthReading::read);
/// Reads the simulated truth (if any) into a mission read with TruthReading::skip from
/// the same file: a command whose peak memory is its computation reads the truth after
/// it (gesmi kalman). Checks its shape against the mission's (FormatError naming the
/// dataset); the mission is unchanged then.
void read_mission_truth(const std::string& path, Mission& mission);
/// Writes a mission atomically (temporary name, then rename).
void write_mission(const Mission& mission, const std::string& path);

/// The validation read_mission() applies, for missions built in memory (importers,
/// simulator): throws FormatError prefixed with `source`.
void validate_mission(const Mission& mission, const std::string& source);

/// `--config`: merges the sensor model YAML at `path` over the mission's model, then
/// change_model(); returns its notice.
std::optional<std::string> merge_model_config(Mission& mission, const std::string& path);

/// Replaces the mission's model (a --config, a key set from Python): refuses a change
/// that per-sample half-widths would ignore, or the step model 'sample' across a gap;
/// adds back the import's unit-conversion margin to a bound it replaces; recomputes what
/// derives from the model (the fixes' boxes in the local frame). FormatError naming
/// `source`; the mission is unchanged then. A change of the GPS bounds of a mission
/// whose fixes carry their own half-widths sets Mission::gps_model_floor (each fix's box
/// becomes the larger of the two) and returns a one-line notice saying so.
std::optional<std::string> change_model(Mission& mission, SensorModel model, const std::string& source);

}  // namespace gesmi::io
