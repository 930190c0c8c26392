#pragma once
// The HDF5 mission file (docs/formats.md): navigation, GPS fixes, mark table,
// origin, sensor model and, for simulated missions, the truth. read_mission()
// validates everything and names file, dataset, row, field and reason on error.

#include <string>

#include "solver/mission/mission.h"

namespace gesmi::io {

/// Whether read_mission() reads the simulated truth (/truth), which only commands that
/// compare with it or write the mission again need.
enum class TruthReading { read, skip };

/// Reads and validates a mission; fills the GPS fixes in the local frame.
Mission read_mission(const std::string& path, TruthReading truth = TruthReading::read);
/// Writes a mission atomically (temporary name, then rename).
void write_mission(const Mission& mission, const std::string& path);

/// The validation read_mission() applies, for missions built in memory (importers,
/// simulator): throws FormatError prefixed with `source`.
void validate_mission(const Mission& mission, const std::string& source);

/// `--config`: merges the sensor model YAML at `path` over the mission's model, then
/// change_model().
void merge_model_config(Mission& mission, const std::string& path);

/// Replaces the mission's model (a --config, a key set from Python): refuses a change
/// that per-sample half-widths would ignore, or the step model 'sample' across a gap;
/// adds back the import's unit-conversion margin to a bound it replaces; recomputes what
/// derives from the model (the fixes' boxes in the local frame). FormatError naming
/// `source`; the mission is unchanged then.
void change_model(Mission& mission, SensorModel model, const std::string& source);

}  // namespace gesmi::io
