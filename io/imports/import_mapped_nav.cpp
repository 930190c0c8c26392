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
#include "solver/mission/between_readings.h"

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

std::string seconds_text(double s) { return format_number(std::round(s * 1000.0) / 1000.0) + " s"; }

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
  std::vector<double> grid;
  std::vector<std::size_t> grid_line;
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

  // Gaps: the longest time without a reading, inside the grid's span and at its ends.
  const double max_gap = map.max_gap.value_or(kDefaultMaxGap);
  const std::string limit = " beyond the " + format_number(max_gap) + " s limit (max_gap in " + map.path + ")";
  for (int c = 0; c < kChannels; ++c) {
    const std::string_view channel = nav_map_schema()[static_cast<std::size_t>(c)].name;
    const Series& s = series[c];
    if (s.readings.time.empty())
      throw FormatError(name + ": " + std::string(channel) + ": no reading in the file (column " +
                        quoted_input(map.field(channel)->column) + ")");
    const auto fail_gap = [&](std::size_t line, double from, double to) {
      throw FormatError(name + ":" + std::to_string(line) + ": " + std::string(channel) + ": no reading for " +
                        seconds_text(to - from) + " (from " + seconds_text(from) + " to " + seconds_text(to) + "),"  + limit);
    };
    if (s.readings.time.front() - grid.front() > max_gap) fail_gap(s.line.front(), grid.front(), s.readings.time.front());
    if (grid.back() - s.readings.time.back() > max_gap) fail_gap(s.line.back(), s.readings.time.back(), grid.back());
    for (std::size_t i = 1; i < s.readings.time.size(); ++i)
      if (s.readings.time[i] - s.readings.time[i - 1] > max_gap) fail_gap(s.line[i], s.readings.time[i - 1], s.readings.time[i]);
  }

  NavLog& log = out.log;
  log.time = grid;
  log.vx = std::move(series[vx].readings.value);
  log.vy = std::move(series[vy].readings.value);
  log.vz = std::move(series[vz].readings.value);
  struct Enclosed {
    Channel channel;
    std::vector<double> NavLog::*values;
    std::vector<double> NavHalfWidths::*half_widths;
    double rate;
  };
  const Enclosed enclosed[] = {
      {roll, &NavLog::roll, &NavHalfWidths::roll, model.max_attitude_rate},
      {pitch, &NavLog::pitch, &NavHalfWidths::pitch, model.max_attitude_rate},
      {heading, &NavLog::heading, &NavHalfWidths::heading, model.max_attitude_rate},
      {altitude, &NavLog::altitude, &NavHalfWidths::altitude, model.max_altitude_rate},
      {depth, &NavLog::depth, &NavHalfWidths::depth, model.max_depth_rate},
  };
  std::string between;
  for (const Enclosed& e : enclosed) {
    Series& s = series[e.channel];
    // Each reading's half-width as the solver computes it from the model (SensorBoxes).
    for (const double v : s.readings.value)
      s.readings.half_width.push_back(e.channel == depth ? depth_bound(model, v)
                                      : e.channel == altitude ? model.altitude
                                                              : *angle_bound[e.channel]);
    ChannelAtGrid at = enclose_between_readings(s.readings, grid, e.rate, e.channel == heading);
    const std::string_view channel = nav_map_schema()[e.channel].name;
    if (at.conflict)
      throw FormatError(name + ":" + std::to_string(s.line[at.conflict->after]) + ": " + std::string(channel) + ": the readings at " +
                        format_number(s.readings.time[at.conflict->before]) + " s (line " + std::to_string(s.line[at.conflict->before]) +
                        ") and " + format_number(s.readings.time[at.conflict->after]) +
                        " s differ by more than the sensor bounds and the model's rate bound allow (check the readings or the bounds in --config)");
    const std::size_t own = static_cast<std::size_t>(std::count(at.own_reading.begin(), at.own_reading.end(), 1));
    log.*e.values = std::move(at.value);
    // A channel read on every grid row keeps the model's bounds (no half-widths).
    if (own < grid.size()) {
      log.half_widths.*e.half_widths = std::move(at.half_width);
      between += (between.empty() ? "" : ", ") + std::string(channel) + " at " + std::to_string(grid.size() - own);
    }
  }
  double longest = 0.0;
  std::size_t longest_at = 0;
  for (std::size_t k = 1; k < grid.size(); ++k)
    if (grid[k] - grid[k - 1] > longest) {
      longest = grid[k] - grid[k - 1];
      longest_at = k;
    }
  // The paper's sample convention holds sample k's box over its whole step: across a
  // DVL gap that is far from true (docs/model.md, "Gaps").
  if (const auto gap = longest_gap(grid); gap && model.step_model == StepModel::sample)
    throw FormatError(name + ":" + std::to_string(grid_line[*gap + 1]) + ": vx: a DVL gap of " +
                      seconds_text(grid[*gap + 1] - grid[*gap]) + " (from line " + std::to_string(grid_line[*gap]) +
                      "), which the step model 'sample' cannot cross soundly: use trapezoid or rate-hull (step_model in --config)");
  out.notes.push_back("grid: the " + std::to_string(grid.size()) + " rows with a DVL reading, of " + std::to_string(rows) +
                      "; longest step " + seconds_text(longest) + " (lines " + std::to_string(grid_line[longest_at - 1]) + "-" +
                      std::to_string(grid_line[longest_at]) + ")");
  if (!between.empty()) out.notes.push_back("enclosed between readings (grid samples without their own reading): " + between);
  return out;
}

}  // namespace gesmi::io
