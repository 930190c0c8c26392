#include "io/imports/import_mapped_nav.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/format_error.h"
#include "io/imports/csv_number.h"
#include "io/imports/csv_reader.h"
#include "io/imports/time_column.h"
#include "io/text/message_text.h"
#include "solver/interval/rounding.h"

namespace gesmi::io {
namespace {

// Channels in nav_map_schema()'s order.
enum Channel { roll, pitch, heading, vx, vy, vz, altitude, depth, kChannels };

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

}  // namespace

MappedNavLog read_mapped_nav(std::istream& in, const std::string& name, const ColumnMap& map, const SensorModel& input_model,
                             std::optional<std::int64_t> epoch) {
  CsvReader csv(in, name);
  csv.read_any_header(map.delimiter);
  const std::vector<int> columns = mapped_columns(csv, map, nav_map_schema());
  const auto column = [&](int channel) { return static_cast<std::size_t>(columns[static_cast<std::size_t>(channel) + 1]); };
  double factor[kChannels];
  for (int c = 0; c < kChannels; ++c) factor[c] = map.field(nav_map_schema()[static_cast<std::size_t>(c)].name)->unit.factor;

  TimeColumn time(map, epoch, true);
  Series series[kChannels];
  std::vector<double> grid, row_time;
  std::vector<std::size_t> grid_line, row_line;
  double previous_time = -std::numeric_limits<double>::infinity();
  std::size_t previous_line = 0, rows = 0;
  while (csv.next()) {
    ++rows;
    const double t = time.read(csv, static_cast<std::size_t>(columns[0]));
    if (t < previous_time)
      csv.fail(static_cast<std::size_t>(columns[0]), "goes back in time (" + format_number(t) + " s after " +
                                                         format_number(previous_time) + " s on line " + std::to_string(previous_line) + ")");
    previous_time = t;
    previous_line = csv.line();
    bool present[kChannels];
    double value[kChannels];
    for (int c = 0; c < kChannels; ++c) {
      const std::string_view text = csv.text(column(c));
      present[c] = false;
      if (text.empty()) continue;
      const double v = csv.any_number(column(c));
      if (std::isnan(v)) continue;
      if (std::isinf(v)) csv.fail(column(c), "is infinite");
      present[c] = true;
      value[c] = v * factor[c];
    }
    for (const int c : {roll, pitch})
      if (present[c] && std::fabs(value[c]) > std::numbers::pi / 2)
        csv.fail(column(c), format_number(value[c]) + " rad is beyond ±90° (is the column in degrees? the map says unit: " +
                                std::string(map.field(nav_map_schema()[static_cast<std::size_t>(c)].name)->unit.name) + ")");
    if (std::find(present, present + kChannels, true) != present + kChannels) {
      row_time.push_back(t);
      row_line.push_back(csv.line());
    }
    if (present[vx] || present[vy] || present[vz]) {
      for (const int c : {vx, vy, vz})
        if (!present[c]) csv.fail(column(c), "missing: a DVL reading needs vx, vy and vz on the same row");
      if (!grid.empty() && !(t > grid.back()))
        csv.fail(static_cast<std::size_t>(columns[0]), "a second DVL reading at " + format_number(t) + " s (line " +
                                                           std::to_string(grid_line.back()) + ")");
      grid.push_back(t);
      grid_line.push_back(csv.line());
    }
    for (int c = 0; c < kChannels; ++c)
      if (present[c]) {
        series[c].readings.time.push_back(t);
        series[c].readings.value.push_back(value[c]);
        series[c].line.push_back(csv.line());
      }
  }
  if (grid.size() < 2)
    csv.fail_line("the log needs at least 2 rows with a DVL reading (vx, vy, vz), found " + std::to_string(grid.size()));

  MappedNavLog out;
  out.epoch = time.epoch();
  SensorModel& model = out.model;
  model = input_model;
  double* angle_bound[3] = {&model.roll, &model.pitch, &model.heading};
  double dvl_margin = 0.0;
  double* angle_margin[3] = {&out.conversion_margins.roll, &out.conversion_margins.pitch, &out.conversion_margins.heading};
  for (const int c : {roll, pitch, heading})
    if (factor[c] != 1.0) {
      *angle_margin[c] = conversion_margin(series[c].readings.value);
      *angle_bound[c] = add_up(*angle_bound[c], *angle_margin[c]);
    }
  // The DVL bound is one for the three components: it takes the largest margin.
  for (const int c : {vx, vy, vz})
    if (factor[c] != 1.0) dvl_margin = std::max(dvl_margin, conversion_margin(series[c].readings.value));
  model.dvl_absolute = add_up(model.dvl_absolute, dvl_margin);
  out.conversion_margins.dvl = dvl_margin;
  out.max_gap = map.max_gap.value_or(kDefaultMaxGap);
  out.limit = " beyond the " + format_number(out.max_gap) + " s limit (max_gap in " + map.path + ")";

  NavSeries& s = out.series;
  s.name = name;
  s.row_time = std::move(row_time);
  s.row_line = std::move(row_line);
  s.rows = rows;
  for (int c = 0; c < kChannels; ++c) {
    Series& from = series[c];
    if (from.readings.time.empty())
      throw FormatError(name + ": " + std::string(nav_map_schema()[static_cast<std::size_t>(c)].name) +
                        ": no reading in the file (column " +
                        quoted_input(map.field(nav_map_schema()[static_cast<std::size_t>(c)].name)->column) + ")");
    // Each reading's half-width as the solver computes it from the model (SensorBoxes).
    for (const double v : from.readings.value)
      from.readings.half_width.push_back(c == depth      ? depth_bound(model, v)
                                         : c == altitude ? model.altitude
                                         : c >= vx       ? dvl_bound(model, v)
                                                         : *angle_bound[c]);
    s.channel[static_cast<std::size_t>(c)] = std::move(from.readings);
    s.line[static_cast<std::size_t>(c)] = std::move(from.line);
  }
  return out;
}

}  // namespace gesmi::io
