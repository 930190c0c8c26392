#pragma once
// Column maps (docs/formats.md, "Logger exports"): a YAML file that says, for each
// field gesmi needs, which column of a logger's CSV export holds it and in which unit,
// plus the delimiter and how times are written:
//
//   delimiter: ";"                                  # optional: detected from the header
//   time:     {column: timestamp, format: iso8601}  # iso8601, epoch or seconds
//   heading:  {column: hdg, unit: deg}
//
// A schema lists the fields a kind of file has (navigation, marks) with their units.

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/imports/csv_reader.h"

namespace gesmi::io {

enum class TimeFormat { seconds, epoch, iso8601 };

/// A unit a field accepts, and the factor that takes it to gesmi's (SI, radians).
struct MapUnit {
  std::string_view name;
  double factor;
};

/// One field of a schema. `units` empty: the field has no unit (a mine number, a side).
/// `unit_required`: the map must say it (angles: a silent default would let degrees
/// through as radians).
struct MapFieldSpec {
  std::string_view name;
  std::vector<MapUnit> units;
  bool unit_required = false;
  bool required = true;
};

/// What a map says of one field.
struct MappedColumn {
  std::string column;
  MapUnit unit{"", 1.0};
  std::size_t map_line = 0;  // where the map names it
};

struct ColumnMap {
  std::string path;
  std::optional<Delimiter> delimiter;   // nullopt: detect from the header
  MappedColumn time;
  TimeFormat time_format = TimeFormat::seconds;
  std::optional<int> timezone_seconds;  // offset of ISO 8601 times written without one
  std::map<std::string, MappedColumn, std::less<>> fields;
  std::optional<double> max_gap;        // s, navigation maps only

  const MappedColumn* field(std::string_view name) const;
  /// "MAP:LINE: name.column" for messages.
  std::string where(const MappedColumn& c, std::string_view name) const;
};

/// The navigation fields: roll, pitch, heading (deg or rad, unit required), vx, vy, vz
/// (m/s or knots), altitude, depth (m).
std::span<const MapFieldSpec> nav_map_schema();
/// The mark table's fields: mine, range (m), side.
std::span<const MapFieldSpec> marks_map_schema();

/// Reads a map against a schema (`time` is always required; `allow_max_gap` for
/// navigation maps). FormatError "MAP:LINE: field: reason".
ColumnMap read_column_map(const std::string& path, std::span<const MapFieldSpec> schema, bool allow_max_gap);

/// The header column of every mapped field (time first, then the schema's order;
/// -1 for an optional field the map leaves out); a column the file lacks is an error
/// naming the file's header and the map's line.
std::vector<int> mapped_columns(const CsvReader& csv, const ColumnMap& map, std::span<const MapFieldSpec> schema);

}  // namespace gesmi::io
