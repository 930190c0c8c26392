#pragma once
// The HDF5 mission file (docs/formats.md): navigation, GPS fixes, mark table,
// origin, sensor model and, for simulated missions, the truth. read_mission()
// validates everything and names file, dataset, row, field and reason on error.

#include <functional>
#include <optional>
#include <span>
#include <string>

#include "io/hdf5/h5_file.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

/// Whether read_mission() reads the simulated truth (/truth), which only commands that
/// compare with it or write the mission again need.
enum class TruthReading { read, skip };

/// Reads and validates a mission; fills the GPS fixes in the local frame.
Mission read_mission(const std::string& path, TruthReading truth = TruthReading::read);
/// A mission file kept open: the mission first, its truth later from the same file,
/// even if the path is replaced meanwhile (gesmi kalman reads the truth after the
/// smoothing, so that its peak memory is the smoothing's).
class MissionReader {
 public:
  /// Opens the file; FormatError if it is missing or not HDF5.
  explicit MissionReader(const std::string& path);
  /// read_mission()'s reading and validation. With TruthReading::skip the truth is still
  /// checked (its positions block by block) but not kept, so that a damaged truth is
  /// refused before any work.
  Mission read(TruthReading truth = TruthReading::read) const;
  /// Reads the truth (if any) into a mission read with TruthReading::skip (std::logic_error
  /// if it holds a truth already), with the checks of read(); FormatError naming the
  /// dataset, the mission then unchanged.
  void read_truth(Mission& mission) const;
  /// read_truth(), but the true positions are not kept (240 MB at 10^7 steps): each
  /// block of rows of /truth/position (north, east, down; row-major), checked, goes to
  /// `positions(first, rows)`, rows first to first + rows.size() / 3 - 1. The positions
  /// are checked first, row by row (read_truth() checks every dataset after reading
  /// them all, so a file with several faults may be refused for another one); on a
  /// FormatError what `positions` received is to be discarded.
  using TruthPositions = std::function<void(std::size_t first, std::span<const double> rows)>;
  void read_truth(Mission& mission, const TruthPositions& positions) const;

 private:
  void read_truth_into(Mission& mission, const TruthPositions* positions) const;

  std::string path_;
  H5File file_;
};
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
