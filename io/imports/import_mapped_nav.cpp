#include "io/imports/import_mapped_nav.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "io/format_error.h"
#include "io/imports/nav_channel_index.h"
#include "io/text/csv_number.h"
#include "io/imports/csv_reader.h"
#include "io/imports/time_column.h"
#include "io/text/message_text.h"
#include "solver/interval/rounding.h"

namespace gesmi::io {
namespace {

using namespace nav;  // the channels' indices and names

struct Series {
  ChannelReadings readings;
  std::vector<std::size_t> line;
};

// A unit conversion x -> fl(x fl(f)) is off by at most 2^-51 |x f| (two roundings):
// the margin added to the bound of a converted channel, from its largest value.
double conversion_margin(const std::vector<double>& values) {
  double largest = 0.0;
  for (const double v : values) largest = std::max(largest, std::fabs(v));
  return mul_up(largest, 0x1p-51);
}

// The log's columns as the map places them, and each channel's unit.
struct NavColumns {
  std::vector<int> columns;  // the time's, then the channels'
  double factor[kChannels];

  NavColumns(const CsvReader& csv, const ColumnMap& map) : columns(mapped_columns(csv, map, nav_map_schema())) {
    for (int c = 0; c < kChannels; ++c) factor[c] = map.field(channel_name(c))->unit.factor;
  }
  std::size_t time() const { return static_cast<std::size_t>(columns[0]); }
  std::size_t channel(int c) const { return static_cast<std::size_t>(columns[static_cast<std::size_t>(c) + 1]); }
};

// A row's readings in the solver's units; value[c] is set only where present[c].
struct RowReadings {
  bool present[kChannels];
  double value[kChannels];
};

// The current row's readings into `row`: an empty or NaN cell is no reading, an
// infinite one an error, as is an angle beyond ±90° (a column in degrees mapped as radians).
void read_row(const CsvReader& csv, const NavColumns& columns, const ColumnMap& map, RowReadings& row) {
  for (int c = 0; c < kChannels; ++c) {
    const std::string_view text = csv.text(columns.channel(c));
    row.present[c] = false;
    if (text.empty()) continue;
    const double v = csv.any_number(columns.channel(c));
    if (std::isnan(v)) continue;
    if (std::isinf(v)) csv.fail(columns.channel(c), "is infinite");
    row.present[c] = true;
    row.value[c] = v * columns.factor[c];
  }
  for (const int c : {roll, pitch})
    if (row.present[c] && std::fabs(row.value[c]) > std::numbers::pi / 2)
      csv.fail(columns.channel(c), format_number(row.value[c]) +
                                       " rad is beyond ±90° (is the column in degrees? the map says unit: " +
                                       std::string(map.field(channel_name(c))->unit.name) + ")");
}

// Every row's readings, by channel, with their lines; and the rows with some reading.
struct LogReadings {
  Series series[kChannels];
  std::vector<double> row_time;
  std::vector<std::size_t> row_line;
  std::size_t rows = 0;  // every row, with a reading or not
};

// The log's rows, in time order; at least two with a DVL reading (all three components,
// at increasing times).
LogReadings read_rows(CsvReader& csv, const NavColumns& columns, const ColumnMap& map, TimeColumn& time) {
  LogReadings log;
  std::vector<double> grid;
  std::vector<std::size_t> grid_line;
  double previous_time = -std::numeric_limits<double>::infinity();
  std::size_t previous_line = 0;
  while (csv.next()) {
    ++log.rows;
    const double t = time.read(csv, columns.time());
    if (t < previous_time)
      csv.fail(columns.time(), "goes back in time (" + format_number(t) + " s after " + format_number(previous_time) +
                                   " s on line " + std::to_string(previous_line) + ")");
    previous_time = t;
    previous_line = csv.line();
    RowReadings row;
    read_row(csv, columns, map, row);
    if (std::find(row.present, row.present + kChannels, true) != row.present + kChannels) {
      log.row_time.push_back(t);
      log.row_line.push_back(csv.line());
    }
    if (row.present[vx] || row.present[vy] || row.present[vz]) {
      for (const int c : {vx, vy, vz})
        if (!row.present[c]) csv.fail(columns.channel(c), "missing: a DVL reading needs vx, vy and vz on the same row");
      if (!grid.empty() && !(t > grid.back()))
        csv.fail(columns.time(), "a second DVL reading at " + format_number(t) + " s (line " +
                                     std::to_string(grid_line.back()) + ")");
      grid.push_back(t);
      grid_line.push_back(csv.line());
    }
    for (int c = 0; c < kChannels; ++c)
      if (row.present[c]) {
        log.series[c].readings.time.push_back(t);
        log.series[c].readings.value.push_back(row.value[c]);
        log.series[c].line.push_back(csv.line());
      }
  }
  if (grid.size() < 2)
    csv.fail_line("the log needs at least 2 rows with a DVL reading (vx, vy, vz), found " + std::to_string(grid.size()));
  return log;
}

// out.model: `input_model` with the bound of each channel converted from other units
// widened by its conversion margin, recorded in out.conversion_margins.
void widen_converted_bounds(const SensorModel& input_model, const NavColumns& columns, const LogReadings& log,
                            MappedNavLog& out) {
  SensorModel& model = out.model;
  model = input_model;
  double* angle_bound[3] = {&model.roll, &model.pitch, &model.heading};
  double dvl_margin = 0.0;
  double* angle_margin[3] = {&out.conversion_margins.roll, &out.conversion_margins.pitch, &out.conversion_margins.heading};
  for (const int c : {roll, pitch, heading})
    if (columns.factor[c] != 1.0) {
      *angle_margin[c] = conversion_margin(log.series[c].readings.value);
      *angle_bound[c] = add_up(*angle_bound[c], *angle_margin[c]);
    }
  // The DVL bound is one for the three components: it takes the largest margin.
  for (const int c : {vx, vy, vz})
    if (columns.factor[c] != 1.0) dvl_margin = std::max(dvl_margin, conversion_margin(log.series[c].readings.value));
  model.dvl_absolute = add_up(model.dvl_absolute, dvl_margin);
  out.conversion_margins.dvl = dvl_margin;
}

// The readings into out.series, each with its half-width from out.model; FormatError
// for a channel without any reading.
void take_series(LogReadings& log, const std::string& name, const ColumnMap& map, MappedNavLog& out) {
  NavSeries& s = out.series;
  s.name = name;
  s.row_time = std::move(log.row_time);
  s.row_line = std::move(log.row_line);
  s.rows = log.rows;
  for (int c = 0; c < kChannels; ++c) {
    Series& from = log.series[c];
    if (from.readings.time.empty())
      throw FormatError(name + ": " + channel_name(c) + ": no reading in the file (column " +
                        quoted_input(map.field(channel_name(c))->column) + ")");
    for (const double v : from.readings.value)
      from.readings.half_width.push_back(model_half_width(out.model, static_cast<std::size_t>(c), v));
    s.channel[static_cast<std::size_t>(c)] = std::move(from.readings);
    s.line[static_cast<std::size_t>(c)] = std::move(from.line);
  }
}

}  // namespace

MappedNavLog read_mapped_nav(std::istream& in, const std::string& name, const ColumnMap& map, const SensorModel& input_model,
                             std::optional<std::int64_t> epoch) {
  CsvReader csv(in, name);
  csv.read_any_header(map.delimiter);
  const NavColumns columns(csv, map);

  TimeColumn time(map, epoch, true);
  LogReadings log = read_rows(csv, columns, map, time);

  MappedNavLog out;
  out.epoch = time.epoch();
  widen_converted_bounds(input_model, columns, log, out);
  out.max_gap = map.max_gap.value_or(kDefaultMaxGap);
  out.limit = " beyond the " + format_number(out.max_gap) + " s limit (max_gap in " + map.path + ")";
  take_series(log, name, map, out);
  return out;
}

}  // namespace gesmi::io
