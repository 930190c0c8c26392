#pragma once
// The mission's time grid from a navigation log read channel by channel, and every
// channel on it (docs/formats.md, "Logger exports"; docs/model.md, "The surface").
//
// The grid is the rows with a DVL reading, extended to the whole mission: before the
// first and after the last of them (the surface, the dive, a log that goes on with
// attitude only), the rows of the other channels and the times of the GPS fixes
// outside every row. There the DVL is bridged: reading 0 with the half-width
// surface_max_speed on each component (the speed over ground at the surface bounds the
// body-frame components too). The other channels are enclosed at grid times without a
// reading of their own from the readings around them (solver/mission/between_readings.h).

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/imports/import_nav_csv.h"
#include "solver/mission/between_readings.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

/// A navigation log as each channel's own readings (nav_channels() order: roll, pitch,
/// heading, vx, vy, vz, altitude, depth), each reading with its bound and its line.
struct NavSeries {
  std::string name;  // the file, for messages
  std::array<ChannelReadings, 8> channel;
  std::array<std::vector<std::size_t>, 8> line;
  std::vector<double> row_time;  // every row with some reading, non-decreasing
  std::vector<std::size_t> row_line;
  std::size_t rows = 0;          // of the file, with a reading or not
  /// Whether a channel's bounds came with the log, per reading (a half-width column),
  /// rather than from the model.
  std::array<bool, 8> given{};
};

/// Longest time without a reading of any navigation sensor unless a map's `max_gap`
/// says otherwise (s); also how far before the first and after the last row of gesmi's
/// navigation CSV a fix is placed.
inline constexpr double kDefaultMaxGap = 60.0;

/// gesmi's navigation CSV (every channel on every row) as a series: each reading's bound
/// its own half-width column's, or the model's.
NavSeries series_of_rows(NavLog rows, const SensorModel& model, const std::string& name);

/// A GPS fix the import could not use, and why.
struct UnusedFix {
  std::string where;  // "gps.nmea:12"
  double time = 0.0;
  std::string reason;
};

/// One line per channel the import filled (NavHalfWidths::fill), for the summary.
std::vector<std::string> fill_lines(const NavHalfWidths& half_widths);
/// "the fix at T s is not used: REASON", naming the file and line.
std::string unused_fix_line(const UnusedFix& fix);

/// The times a fix can be used at: within `max_gap` of the first and the last reading of
/// every channel that is enclosed by its rate (attitude and depth; the DVL and the
/// altitude are bridged, which needs no reading nearby).
std::pair<double, double> usable_span(const NavSeries& series, double max_gap);

struct NavOnGrid {
  NavLog log;  // with what the import filled (log.half_widths.fill)
  std::string grid_note;  // "grid: the N rows with a DVL reading, of M; ..."
};

/// The grid and every channel on it. `fix_times`: the fixes the mission keeps,
/// increasing, within usable_span(). `limit`: where max_gap comes from, for messages.
/// FormatError on a channel silent longer than max_gap between its readings, whose
/// readings conflict (the model's rate bound cannot join them), or a DVL gap that the
/// step model 'sample' cannot cross.
NavOnGrid nav_on_grid(const NavSeries& series, std::span<const double> fix_times, const SensorModel& model,
                      double max_gap, const std::string& limit);

}  // namespace gesmi::io
