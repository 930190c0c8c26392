#include "io/imports/nav_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/format_error.h"
#include "io/imports/nav_channel_index.h"
#include "io/text/csv_number.h"
#include "solver/interval/rounding.h"

namespace gesmi::io {
namespace {

using namespace nav;  // the channels' indices and names

// The DVL's channels: bridged by the speed bound where the log has no reading, which
// needs no reading nearby (the others are enclosed by their rate from the nearest one).
bool bridged(int c) { return c == vx || c == vy || c == vz || c == altitude; }

// The navigation log's arrays, in nav_channels() order.
constexpr std::vector<double> NavLog::*kValues[kChannels] = {&NavLog::roll, &NavLog::pitch, &NavLog::heading,
                                                              &NavLog::vx,   &NavLog::vy,    &NavLog::vz,
                                                              &NavLog::altitude, &NavLog::depth};

std::string seconds_text(double s) { return format_number(std::round(s * 1000.0) / 1000.0) + " s"; }

// The DVL's rows, and outside their span the other rows and the fixes' times that lie
// within `usable`.
std::vector<double> grid_times(const NavSeries& s, std::span<const double> fix_times, std::pair<double, double> usable) {
  const std::vector<double>& dvl = s.channel[vx].time;
  std::vector<double> outside;
  const auto take = [&](double t) {
    if ((t < dvl.front() || t > dvl.back()) && t >= usable.first && t <= usable.second) outside.push_back(t);
  };
  for (const double t : s.row_time) take(t);
  for (const double t : fix_times)
    if (t < s.row_time.front() || t > s.row_time.back()) take(t);
  std::sort(outside.begin(), outside.end());
  std::vector<double> grid;
  grid.reserve(dvl.size() + outside.size());
  std::merge(dvl.begin(), dvl.end(), outside.begin(), outside.end(), std::back_inserter(grid));
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

void check_gaps(const NavSeries& s, const std::vector<double>& grid, double max_gap, const std::string& limit) {
  for (int c = 0; c < kChannels; ++c) {
    const ChannelReadings& r = s.channel[static_cast<std::size_t>(c)];
    const std::vector<std::size_t>& line = s.line[static_cast<std::size_t>(c)];
    const auto fail_gap = [&](std::size_t at, double from, double to) {
      throw FormatError(s.name + ":" + std::to_string(at) + ": " + channel_name(c) + ": no reading for " +
                        seconds_text(to - from) + " (from " + seconds_text(from) + " to " + seconds_text(to) + ")," +
                        limit);
    };
    if (!bridged(c)) {
      if (r.time.front() - grid.front() > max_gap) fail_gap(line.front(), grid.front(), r.time.front());
      if (grid.back() - r.time.back() > max_gap) fail_gap(line.back(), r.time.back(), grid.back());
    }
    for (std::size_t i = 1; i < r.time.size(); ++i)
      if (r.time[i] - r.time[i - 1] > max_gap) fail_gap(line[i], r.time[i - 1], r.time[i]);
  }
}

// The DVL on the grid: its readings on its rows, 0 ± surface_max_speed elsewhere. The
// half-widths are written when some sample is bridged or the log gave its own.
void dvl_on_grid(const NavSeries& s, const std::vector<double>& grid, const SensorModel& model, NavLog& log) {
  std::vector<double>* values[3] = {&log.vx, &log.vy, &log.vz};
  std::vector<double>* widths[3] = {&log.half_widths.vx, &log.half_widths.vy, &log.half_widths.vz};
  const std::vector<double>& rows = s.channel[vx].time;
  const bool any_bridged = grid.size() > rows.size();
  for (int i = 0; i < 3; ++i) {
    const ChannelReadings& r = s.channel[static_cast<std::size_t>(vx + i)];
    values[i]->assign(grid.size(), 0.0);
    if (any_bridged || s.given[static_cast<std::size_t>(vx + i)]) widths[i]->assign(grid.size(), model.surface_max_speed);
    std::size_t j = 0;
    for (std::size_t k = 0; k < grid.size() && j < rows.size(); ++k) {
      if (grid[k] != rows[j]) continue;
      (*values[i])[k] = r.value[j];
      if (!widths[i]->empty()) (*widths[i])[k] = r.half_width[j];
      ++j;
    }
  }
  if (!any_bridged) return;
  ChannelFill fill{"surface_max_speed", 0, 0, 0, rows.front(), rows.back()};
  for (const double t : grid) {
    if (t < rows.front()) ++fill.before;
    if (t > rows.back()) ++fill.after;
  }
  for (const int c : {vx, vy, vz}) log.half_widths.fill[static_cast<std::size_t>(c)] = fill;
}

double channel_rate(int c, const SensorModel& model) {
  return c == altitude ? model.max_altitude_rate : c == depth ? model.max_depth_rate : model.max_attitude_rate;
}

std::string rate_name(int c) {
  return c == altitude ? "max_altitude_rate" : c == depth ? "max_depth_rate" : "max_attitude_rate";
}

// A channel enclosed at the grid times from its own readings.
void enclose_on_grid(const NavSeries& s, int c, const std::vector<double>& grid, const SensorModel& model, NavLog& log) {
  const NavChannel& channel = nav_channels()[static_cast<std::size_t>(c)];
  const ChannelReadings& r = s.channel[static_cast<std::size_t>(c)];
  const std::vector<std::size_t>& line = s.line[static_cast<std::size_t>(c)];
  // Within the surface layer the waves move the robot faster than max_depth_rate: there
  // the depth changes at most at the surface speed.
  std::vector<double> rates;
  if (c == depth)
    for (std::size_t i = 0; i < r.time.size(); ++i)
      rates.push_back(sub_down(r.value[i], r.half_width[i]) <= model.surface_layer_depth ? model.surface_max_speed
                                                                                         : model.max_depth_rate);
  ChannelAtGrid at = enclose_between_readings(r, grid, channel_rate(c, model), c == heading, rates);
  if (at.conflict)
    throw FormatError(s.name + ":" + std::to_string(line[at.conflict->after]) + ": " + channel_name(c) +
                      ": the readings at " + format_number(r.time[at.conflict->before]) + " s (line " +
                      std::to_string(line[at.conflict->before]) + ") and " + format_number(r.time[at.conflict->after]) +
                      " s differ by more than the sensor bounds and the model's rate bound allow (check the readings or "
                      "the bounds in --config)");
  // A channel read on every grid row keeps the model's bounds (no half-widths), unless
  // the log gave its own.
  const std::size_t own = static_cast<std::size_t>(std::count(at.own_reading.begin(), at.own_reading.end(), 1));
  if (own < grid.size() || s.given[static_cast<std::size_t>(c)]) log.half_widths.*channel.half_widths = std::move(at.half_width);
  log.*kValues[c] = std::move(at.value);
  if (own == grid.size()) return;
  ChannelFill fill{rate_name(c), 0, 0, 0, r.time.front(), r.time.back()};
  for (std::size_t k = 0; k < grid.size(); ++k) {
    if (at.own_reading[k]) continue;
    ++(grid[k] < r.time.front() ? fill.before : grid[k] > r.time.back() ? fill.after : fill.between);
  }
  log.half_widths.fill[static_cast<std::size_t>(c)] = fill;
}

// The line of the row at time t, or 0 for a fix's time outside every row.
std::size_t line_at(const NavSeries& s, double t) {
  const auto it = std::lower_bound(s.row_time.begin(), s.row_time.end(), t);
  return it != s.row_time.end() && *it == t ? s.row_line[static_cast<std::size_t>(it - s.row_time.begin())] : 0;
}

std::string lines_text(const NavSeries& s, double from, double to) {
  const std::size_t a = line_at(s, from), b = line_at(s, to);
  if (a == 0 || b == 0) return "from " + seconds_text(from) + " to " + seconds_text(to) + ", a fix's time";
  return "lines " + std::to_string(a) + "-" + std::to_string(b);
}

std::string grid_note(const NavSeries& s, const std::vector<double>& grid, const SensorModel& model) {
  std::size_t longest_at = 1;
  for (std::size_t k = 1; k < grid.size(); ++k)
    if (grid[k] - grid[k - 1] > grid[longest_at] - grid[longest_at - 1]) longest_at = k;
  const double longest = grid[longest_at] - grid[longest_at - 1];
  // The paper's sample convention holds sample k's box over its whole step: across a
  // DVL gap that is far from true (docs/model.md, "Gaps").
  if (const auto gap = longest_gap(grid); gap && model.step_model == StepModel::sample)
    throw FormatError(s.name + ":" + std::to_string(line_at(s, grid[*gap + 1])) + ": vx: a DVL gap of " +
                      seconds_text(grid[*gap + 1] - grid[*gap]) + " (from line " + std::to_string(line_at(s, grid[*gap])) +
                      "), which the step model 'sample' cannot cross soundly: use trapezoid or rate-hull (step_model in --config)");
  const std::size_t dvl_rows = s.channel[vx].time.size();
  std::string note = "grid: the " + std::to_string(dvl_rows) + " rows with a DVL reading, of " + std::to_string(s.rows);
  if (grid.size() > dvl_rows)
    note += ", and " + std::to_string(grid.size() - dvl_rows) + " samples before and after them";
  return note + "; longest step " + seconds_text(longest) + " (" + lines_text(s, grid[longest_at - 1], grid[longest_at]) + ")";
}

}  // namespace

NavSeries series_of_rows(NavLog rows, const SensorModel& model, const std::string& name) {
  NavSeries s;
  s.name = name;
  s.rows = rows.time.size();
  for (std::size_t c = 0; c < kChannels; ++c) {
    ChannelReadings& r = s.channel[c];
    r.time = rows.time;
    r.value = std::move(rows.*kValues[c]);
    const std::vector<double>& given = rows.half_widths.*nav_channels()[c].half_widths;
    s.given[c] = !given.empty();
    if (s.given[c]) {
      r.half_width = given;
    } else {
      r.half_width.reserve(r.value.size());
      for (const double v : r.value) r.half_width.push_back(model_half_width(model, c, v));
    }
    s.line[c] = rows.line;
  }
  s.row_time = std::move(rows.time);
  s.row_line = std::move(rows.line);
  return s;
}

std::vector<std::string> fill_lines(const NavHalfWidths& half_widths) {
  std::vector<std::string> out;
  for (const int c : {vx, roll, pitch, heading, altitude, depth}) {
    const ChannelFill& f = half_widths.fill[static_cast<std::size_t>(c)];
    if (f.samples() == 0) continue;
    std::string parts;
    const auto part = [&](std::size_t n, const std::string& where) {
      if (n > 0) parts += (parts.empty() ? "" : ", ") + std::to_string(n) + " " + where;
    };
    part(f.before, "before its first reading (" + seconds_text(f.first_reading) + ")");
    part(f.between, "between its readings");
    part(f.after, "after its last reading (" + seconds_text(f.last_reading) + ")");
    const std::string name = c == vx ? "vx, vy, vz" : channel_name(c);
    const std::string how = c == vx ? "bridged by " : "enclosed by ";
    out.push_back(name + ": " + how + f.key + " at " + std::to_string(f.samples()) + " samples without a reading: " + parts);
  }
  return out;
}

std::string unused_fix_line(const UnusedFix& fix) {
  return fix.where + ": warning: the fix at " + seconds_text(fix.time) + " is not used: " + fix.reason;
}

std::pair<double, double> usable_span(const NavSeries& series, double max_gap) {
  double first = -std::numeric_limits<double>::infinity(), last = std::numeric_limits<double>::infinity();
  for (int c = 0; c < kChannels; ++c) {
    if (bridged(c)) continue;
    const ChannelReadings& r = series.channel[static_cast<std::size_t>(c)];
    first = std::max(first, r.time.front() - max_gap);
    last = std::min(last, r.time.back() + max_gap);
  }
  return {first, last};
}

NavOnGrid nav_on_grid(const NavSeries& series, std::span<const double> fix_times, const SensorModel& model,
                      double max_gap, const std::string& limit) {
  NavOnGrid out;
  const std::vector<double> grid = grid_times(series, fix_times, usable_span(series, max_gap));
  check_gaps(series, grid, max_gap, limit);
  out.grid_note = grid_note(series, grid, model);
  NavLog& log = out.log;
  log.time = grid;
  dvl_on_grid(series, grid, model, log);
  for (const int c : {roll, pitch, heading, altitude, depth}) enclose_on_grid(series, c, grid, model, log);
  return out;
}

}  // namespace gesmi::io
