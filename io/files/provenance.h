#pragma once
// What every HDF5 file gesmi writes records about how it was made, and the units of its
// datasets (docs/formats.md, "Provenance and units"):
//   root attributes gesmi_version, command_line, created_utc, and CF's `history` and
//   `source`; the group /provenance with, per input file, its absolute path and the
//   SHA-256 of its bytes (the inputs of the open io::OutputSet, each hashed once per process);
//   on every dataset `units` (UDUNITS syntax, as CF writes them; one per column,
//   comma-separated, where columns differ) and `long_name`.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "io/hdf5/h5_file.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

/// The command line of this process (tools/gesmi/main.cpp), recorded in every file it
/// writes; "(gesmi library)" when none was set (the Python module, tests).
void set_command_line(std::span<const std::string> arguments);

/// Writes the provenance attributes and group. `feature_type`: CF's featureType of the
/// file ("trajectory"), or empty.
void write_provenance(H5File& file, std::string_view feature_type = {});

/// The datum of the latitudes and longitudes gesmi reads and writes.
inline constexpr const char* kDatum = "WGS84";

/// The root attributes origin_latitude, origin_longitude (degrees) and datum: the
/// origin of the file's local frame.
void write_origin(H5File& file, const GeoOrigin& origin);

struct DatasetUnits {
  const char* dataset;
  const char* units;
  const char* long_name;
};

/// Sets `units` and `long_name` on each dataset of the table the file has.
void write_units(H5File& file, std::span<const DatasetUnits> table);

/// Sets a time dataset's `units` as CF writes a time axis ("seconds since
/// YYYY-MM-DDThh:mm:ssZ" when the epoch is known, else "s"), its `standard_name` "time"
/// and `long_name`; nothing when the file has no such dataset.
void write_time_units(H5File& file, const std::string& dataset, const std::string& long_name,
                      const std::optional<std::int64_t>& epoch);

}  // namespace gesmi::io
