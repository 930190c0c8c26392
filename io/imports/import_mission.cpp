#include "io/imports/import_mission.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/input_file.h"
#include "io/imports/column_map.h"
#include "io/imports/import_gps_csv.h"
#include "io/imports/import_mapped_nav.h"
#include "io/imports/import_nmea.h"
#include "io/imports/import_marks_csv.h"
#include "io/imports/import_nav_csv.h"
#include "io/imports/import_truth_csv.h"
#include "io/files/mission_file.h"
#include "io/files/sensor_model_yaml.h"
#include "solver/network/mission_network.h"

namespace gesmi::io {
namespace {

std::ifstream open_input(const std::string& path) {
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(path + ": cannot open the file (does it exist?)");
  return in;
}

SensorModel model_from(const ImportInputs& inputs) {
  SensorModel model;
  if (!inputs.config.empty()) merge_sensor_model_yaml(inputs.config, model);
  return model;
}

void set_mine_count(Mission& m, std::optional<int> mines, const std::string& truth_source) {
  if (mines) {
    if (*mines < 0 || *mines > kMaxMines)
      throw FormatError("--mines: " + std::to_string(*mines) + " is not between 0 and " + std::to_string(kMaxMines));
    if (!m.truth_mines.empty() && m.truth_mines.size() != 3 * static_cast<std::size_t>(*mines))
      throw FormatError("--mines: " + std::to_string(*mines) + " differs from the " +
                        std::to_string(m.truth_mines.size() / 3) + " mines of " + truth_source);
    m.mine_count = *mines;
  } else if (!m.truth_mines.empty()) {
    m.mine_count = static_cast<int>(m.truth_mines.size() / 3);
  }
}

// The marks of a CSV. A mission with no mines, when --mines did not say how many, takes
// the table's largest mine number + 1 (a mission with mines still refuses an unknown
// number: a typo must not make a phantom mine).
void read_marks(Mission& m, const std::string& path, std::optional<int> mines, const std::string& map) {
  std::ifstream in = open_input(path);
  const bool from_table = !mines && m.mine_count == 0;
  MarkRules rules = mark_rules(m);
  if (from_table) rules.mine_count = kMaxMines;
  MarkTable marks = map.empty() ? read_marks_csv(in, path, rules)
                                : read_mapped_marks_csv(in, path, rules, read_column_map(map, marks_map_schema(), false), m.epoch);
  if (from_table)
    for (const std::int32_t mine : marks.mine) m.mine_count = std::max(m.mine_count, mine + 1);
  replace_marks(m, std::move(marks));
}

// The fixes of an NMEA log inside `span` (s after the epoch); the others are listed in
// `unused`, with `why`.
GpsLog read_nmea_gps(const std::string& path, const Mission& m, const ImportInputs& inputs, std::pair<double, double> span,
                     const std::string& why, ImportNotes& notes) {
  if (!m.epoch)
    throw FormatError(path + ": NMEA fixes carry UTC times and the navigation has none: give its time as iso8601 or epoch in "
                             "the map, or --epoch for a log in seconds");
  std::ifstream in = open_input(path);
  const NmeaFixes fixes = read_nmea(in, path, inputs.gps_date);
  GpsLog log;
  std::size_t outside = 0, repeated = 0;
  for (std::size_t i = 0; i < fixes.time.size(); ++i) {
    const double t = fixes.time[i].since(*m.epoch);
    if (t < span.first || t > span.second) {
      ++outside;
      notes.unused_fixes.push_back({path + ":" + std::to_string(fixes.line[i]), t, why});
      continue;
    }
    if (!log.time.empty() && !(t > log.time.back())) {
      if (t == log.time.back()) {
        ++repeated;  // the same fix from a second talker
        continue;
      }
      throw FormatError(path + ":" + std::to_string(fixes.line[i]) + ": GGA field 1: the fix goes back in time (" +
                        format_number(t) + " s after " + format_number(log.time.back()) + " s on line " +
                        std::to_string(log.line.back()) + ")");
    }
    log.time.push_back(t);
    log.latitude.push_back(fixes.latitude[i]);
    log.longitude.push_back(fixes.longitude[i]);
    log.line.push_back(fixes.line[i]);
  }
  notes.lines.push_back(path + ": " + std::to_string(log.time.size()) + " GGA fixes taken; skipped: " +
                  std::to_string(fixes.bad_checksum) + " sentences with a bad checksum, " + std::to_string(fixes.no_fix) +
                  " GGA without a fix, " + std::to_string(outside) + " fixes not usable (below), " +
                  std::to_string(repeated) + " repeated; " + std::to_string(fixes.other) + " other sentences ignored");
  return log;
}

bool is_nmea(const std::string& path, GpsFormat format) {
  if (format != GpsFormat::detect) return format == GpsFormat::nmea;
  std::ifstream in = open_input(path);
  return looks_like_nmea(in);
}

void move_nav(NavLog&& nav, Mission& m) {
  m.time = std::move(nav.time);
  m.roll = std::move(nav.roll);
  m.pitch = std::move(nav.pitch);
  m.heading = std::move(nav.heading);
  m.vx = std::move(nav.vx);
  m.vy = std::move(nav.vy);
  m.vz = std::move(nav.vz);
  m.altitude = std::move(nav.altitude);
  m.depth = std::move(nav.depth);
  m.half_widths = std::move(nav.half_widths);
}

// The GPS fixes within `span`; those outside listed in notes.unused_fixes with `why`.
GpsLog read_gps(const Mission& m, const ImportInputs& inputs, std::pair<double, double> span, const std::string& why,
                ImportNotes& notes) {
  if (inputs.gps.empty()) return {};
  if (is_nmea(inputs.gps, inputs.gps_format)) return read_nmea_gps(inputs.gps, m, inputs, span, why, notes);
  std::ifstream in = open_input(inputs.gps);
  return read_gps_csv(in, inputs.gps, span.first, span.second, &notes.unused_fixes, why);
}

// The navigation on the grid over its readings and the fixes (nav_grid.h), into `m`.
void take_grid(const std::string& nav_csv, NavOnGrid on_grid, Mission& m, ImportNotes& notes) {
  notes.lines.push_back(nav_csv + ": " + on_grid.grid_note);
  for (const std::string& line : fill_lines(on_grid.log.half_widths)) notes.lines.push_back(nav_csv + ": " + line);
  move_nav(std::move(on_grid.log), m);
}

// A logger's export: the readings, then the fixes the navigation can place, then the
// grid over both.
GpsLog import_mapped(const std::string& nav_csv, const ImportInputs& inputs, Mission& m, ImportNotes& notes) {
  std::ifstream in = open_input(nav_csv);
  MappedNavLog mapped = read_mapped_nav(in, nav_csv, read_column_map(inputs.map, nav_map_schema(), true), m.model, m.epoch);
  m.model = mapped.model;
  m.conversion_margins = mapped.conversion_margins;
  m.epoch = mapped.epoch;
  const std::pair<double, double> span = usable_span(mapped.series, mapped.max_gap);
  const std::string why = "no attitude or depth reading within max_gap (" + format_number(mapped.max_gap) +
                          " s) of it, so nothing places the robot there (raise max_gap in " + inputs.map + ")";
  GpsLog gps = read_gps(m, inputs, span, why, notes);
  take_grid(nav_csv, nav_on_grid(mapped.series, gps.time, m.model, mapped.max_gap, mapped.limit), m, notes);
  return gps;
}

// gesmi's navigation CSV: its rows carry every channel and are the grid. The fixes up
// to kDefaultMaxGap before its first or after its last row extend it as a logger
// export's (the DVL bridged, the other channels enclosed from the row nearest); only
// then are the rows turned into a series, which holds several times their memory. A
// gap between rows is the solver's to cross, whatever its length.
GpsLog import_rows(const std::string& nav_csv, const ImportInputs& inputs, Mission& m, ImportNotes& notes) {
  std::ifstream in = open_input(nav_csv);
  NavLog rows = read_nav_csv(in, nav_csv);
  const double first = rows.time.front(), last = rows.time.back();
  const std::string why = "more than " + format_number(kDefaultMaxGap) + " s before the first or after the last row of " +
                          nav_csv + ", so nothing places the robot there";
  GpsLog gps = read_gps(m, inputs, {first - kDefaultMaxGap, last + kDefaultMaxGap}, why, notes);
  if (std::none_of(gps.time.begin(), gps.time.end(), [&](double t) { return t < first || t > last; })) {
    move_nav(std::move(rows), m);
    return gps;
  }
  const NavSeries series = series_of_rows(std::move(rows), m.model, nav_csv);
  take_grid(nav_csv, nav_on_grid(series, gps.time, m.model, std::numeric_limits<double>::infinity(), ""), m, notes);
  return gps;
}

}  // namespace

Mission import_nav(const std::string& nav_csv, const ImportInputs& inputs, ImportNotes* notes_out) {
  ImportNotes notes;
  Mission m;
  m.model = model_from(inputs);
  m.epoch = inputs.epoch;
  GpsLog gps = inputs.map.empty() ? import_rows(nav_csv, inputs, m, notes) : import_mapped(nav_csv, inputs, m, notes);
  if (inputs.origin) {
    m.origin = *inputs.origin;
  } else if (!gps.time.empty()) {
    m.origin = {gps.latitude[0], gps.longitude[0]};
  } else {
    throw FormatError(nav_csv + ": no GPS fix to take the local frame's origin from: give --origin LAT,LON");
  }
  const LocalFrame frame(m.origin);
  for (std::size_t i = 0; i < gps.time.size(); ++i) {
    const NorthEast p = frame.to_local(gps.latitude[i], gps.longitude[i]);
    if (std::hypot(p.north, p.east) > kLocalFrameZone)
      throw FormatError(inputs.gps + ":" + std::to_string(gps.line[i]) + ": longitude, latitude: " +
                        fix_beyond_zone(std::hypot(p.north, p.east)));
  }
  m.gps_time = std::move(gps.time);
  m.gps_longitude = std::move(gps.longitude);
  m.gps_latitude = std::move(gps.latitude);
  m.gps_given_north_halfwidth = std::move(gps.north_halfwidth);
  m.gps_given_east_halfwidth = std::move(gps.east_halfwidth);

  if (!inputs.truth.empty()) {
    std::ifstream in = open_input(inputs.truth);
    TruthTrack truth = read_truth_csv(in, inputs.truth, m.time);
    m.truth_x = std::move(truth.north);
    m.truth_y = std::move(truth.east);
    m.truth_z = std::move(truth.down);
  }
  if (!inputs.truth_mines.empty()) {
    std::ifstream in = open_input(inputs.truth_mines);
    m.truth_mines = read_truth_mines_csv(in, inputs.truth_mines);
  }
  set_mine_count(m, inputs.mines, inputs.truth_mines);
  if (!inputs.marks.empty()) read_marks(m, inputs.marks, inputs.mines, inputs.marks_map);
  validate_mission(m, nav_csv);
  fill_local_gps(m, inputs.gps);
  if (notes_out) *notes_out = std::move(notes);
  return m;
}

Mission import_gesmi_txt(const std::string& path, GesmiXy xy, const ImportInputs& inputs) {
  const SensorModel model = model_from(inputs);
  std::ifstream in = open_input(path);
  Mission m = mission_from_gesmi_txt(read_gesmi_txt(in, path), path, inputs.origin.value_or(kRedermorStartFix), model, xy);
  set_mine_count(m, inputs.mines, path);  // a text log has no truth mines
  if (!inputs.marks.empty()) read_marks(m, inputs.marks, inputs.mines, inputs.marks_map);
  validate_mission(m, path);
  fill_local_gps(m, path);
  return m;
}

void import_marks(Mission& m, const std::string& marks_csv, std::optional<int> mines, const std::string& map) {
  set_mine_count(m, mines, "the mission's truth");
  read_marks(m, marks_csv, mines, map);
}

}  // namespace gesmi::io
