#include "io/imports/column_map.h"

#include <cmath>

#include "io/format_error.h"
#include "io/text/message_text.h"
#include "io/text/strict_yaml.h"
#include "io/time/utc_time.h"
#include "solver/model/angles.h"

namespace gesmi::io {
namespace {

constexpr double kKnot = 1852.0 / 3600.0;           // m/s

const std::vector<MapUnit> kAngleUnits = {{"rad", 1.0}, {"deg", kRadiansPerDegree}};
const std::vector<MapUnit> kSpeedUnits = {{"m/s", 1.0}, {"knots", kKnot}};
const std::vector<MapUnit> kLengthUnits = {{"m", 1.0}};

std::string unit_names(const std::vector<MapUnit>& units) {
  std::string out;
  for (std::size_t i = 0; i < units.size(); ++i) out += (i == 0 ? "" : i + 1 == units.size() ? " or " : ", ") + std::string(units[i].name);
  return out;
}

std::string line_of(const std::string& path, const YAML::Node& node) {
  return path + ":" + std::to_string(node.Mark().line + 1);
}

std::string scalar(const std::string& path, const YAML::Node& node, const std::string& what) {
  if (!node.IsScalar()) throw FormatError(line_of(path, node) + ": " + what + ": expected a plain value");
  return node.Scalar();
}

}  // namespace

std::span<const MapFieldSpec> nav_map_schema() {
  static const std::vector<MapFieldSpec> schema = {
      {"roll", kAngleUnits, true},  {"pitch", kAngleUnits, true}, {"heading", kAngleUnits, true},
      {"vx", kSpeedUnits},          {"vy", kSpeedUnits},          {"vz", kSpeedUnits},
      {"altitude", kLengthUnits},   {"depth", kLengthUnits},
  };
  return schema;
}

std::span<const MapFieldSpec> marks_map_schema() {
  static const std::vector<MapFieldSpec> schema = {{"mine", {}}, {"range", kLengthUnits}, {"side", {}}};
  return schema;
}

const MappedColumn* ColumnMap::field(std::string_view name) const {
  const auto found = fields.find(name);
  return found == fields.end() ? nullptr : &found->second;
}

std::string ColumnMap::where(const MappedColumn& c, std::string_view name) const {
  return path + ":" + std::to_string(c.map_line) + ": " + std::string(name) + ".column";
}

ColumnMap read_column_map(const std::string& path, std::span<const MapFieldSpec> schema, bool allow_max_gap) {
  const YAML::Node root = load_strict_yaml_file(path);
  if (!root.IsMap()) throw FormatError(path + ": the map is empty (docs/formats.md shows one)");
  ColumnMap map;
  map.path = path;
  bool has_time = false;
  for (const auto& entry : root) {
    const std::string key = entry.first.Scalar();
    const std::string where = line_of(path, entry.first) + ": " + key;
    const YAML::Node& value = entry.second;
    if (key == "delimiter") {
      map.delimiter = parse_delimiter(scalar(path, value, key));
      if (!map.delimiter)
        throw FormatError(where + ": expected \",\", \";\", tab or whitespace, found " + quoted_input(value.Scalar()));
      continue;
    }
    if (key == "max_gap" && allow_max_gap) {
      const std::string text = scalar(path, value, key);
      double gap = 0.0;
      try {
        gap = value.as<double>();
      } catch (const YAML::Exception&) {
        throw FormatError(where + ": expected a number of seconds, found " + quoted_input(text));
      }
      if (!(gap > 0.0) || !std::isfinite(gap)) throw FormatError(where + ": must be a positive number of seconds");
      map.max_gap = gap;
      continue;
    }
    const MapFieldSpec* spec = nullptr;
    for (const MapFieldSpec& s : schema)
      if (s.name == key) spec = &s;
    if (key != "time" && !spec) {
      std::string known = "time";
      for (const MapFieldSpec& s : schema) known += ", " + std::string(s.name);
      known += allow_max_gap ? ", delimiter, max_gap" : ", delimiter";
      throw FormatError(where + ": unknown key (expected " + known + ")");
    }
    if (!value.IsMap()) throw FormatError(where + ": expected {column: NAME" + std::string(key == "time" ? ", format: ...}" : "}"));
    MappedColumn column;
    column.map_line = entry.first.Mark().line + 1;
    std::optional<std::string> unit, format, timezone;
    for (const auto& item : value) {
      const std::string name = item.first.Scalar();
      const std::string text = scalar(path, item.second, key + "." + name);
      if (name == "column") column.column = text;
      else if (name == "unit" && key != "time") unit = text;
      else if (name == "format" && key == "time") format = text;
      else if (name == "timezone" && key == "time") timezone = text;
      else
        throw FormatError(line_of(path, item.first) + ": " + key + "." + name + ": unknown key (expected column" +
                          (key == "time" ? ", format, timezone)" : ", unit)"));
    }
    if (column.column.empty()) throw FormatError(where + ": the column is missing (" + key + ": {column: NAME})");
    if (key == "time") {
      has_time = true;
      map.time = column;
      if (!format || *format == "seconds") map.time_format = TimeFormat::seconds;
      else if (*format == "epoch") map.time_format = TimeFormat::epoch;
      else if (*format == "iso8601") map.time_format = TimeFormat::iso8601;
      else throw FormatError(where + ".format: expected iso8601, epoch or seconds, found " + quoted_input(*format));
      if (timezone) {
        if (map.time_format != TimeFormat::iso8601) throw FormatError(where + ".timezone: only for format: iso8601");
        map.timezone_seconds = parse_utc_offset(*timezone);
        if (!map.timezone_seconds)
          throw FormatError(where + ".timezone: expected UTC or an offset like +02:00, found " + quoted_input(*timezone));
      }
      continue;
    }
    if (spec->units.empty() && unit) throw FormatError(where + ".unit: " + key + " has no unit");
    if (!spec->units.empty()) {
      if (!unit && spec->unit_required)
        throw FormatError(where + ".unit: missing: say " + unit_names(spec->units) + " (a wrong guess gives nonsense)");
      column.unit = spec->units.front();
      if (unit) {
        bool known = false;
        for (const MapUnit& u : spec->units)
          if (u.name == *unit) {
            column.unit = u;
            known = true;
          }
        if (!known) throw FormatError(where + ".unit: unknown unit " + quoted_input(*unit) + " (expected " + unit_names(spec->units) + ")");
      }
    }
    map.fields.emplace(key, column);
  }
  if (!has_time) throw FormatError(path + ": time: missing (time: {column: NAME, format: iso8601|epoch|seconds})");
  for (const MapFieldSpec& s : schema)
    if (s.required && !map.field(s.name))
      throw FormatError(path + ": " + std::string(s.name) + ": missing (" + std::string(s.name) + ": {column: NAME" +
                        (s.units.empty() ? "" : ", unit: " + unit_names(s.units)) + "})");
  return map;
}

std::vector<int> mapped_columns(const CsvReader& csv, const ColumnMap& map, std::span<const MapFieldSpec> schema) {
  std::vector<int> columns;
  const auto find = [&](const MappedColumn& c, std::string_view name) {
    const int column = csv.column(c.column);
    if (column < 0)
      csv.fail_line("header: no column " + quoted_input(c.column) + " (" + map.where(c, name) + " names it)");
    return column;
  };
  columns.push_back(find(map.time, "time"));
  for (const MapFieldSpec& s : schema) {
    const MappedColumn* c = map.field(s.name);
    columns.push_back(c ? find(*c, s.name) : -1);
  }
  return columns;
}

}  // namespace gesmi::io
