// Logger exports through column maps (io/imports/column_map.h, import_mapped_nav.h):
// layouts, units, the grid, channels between readings, gaps, and each refusal; and
// gesmi's navigation CSV on the same grid (nav_grid.h).
#include "io/imports/import_mapped_nav.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "io/format_error.h"
#include "io/imports/import_nav_csv.h"
#include "solver/interval/rounding.h"
#include "tests/support/run_command.h"

namespace gesmi::io {
namespace {

std::string write_map(const std::string& text) {
  // In this process's own folder: CTest runs the tests of this file side by side.
  const std::string path = test::temp_folder("map") + "/map.yaml";
  std::ofstream(path) << text;
  return path;
}

const char* kMap =
    "time:     {column: t, format: seconds}\n"
    "roll:     {column: r, unit: deg}\n"
    "pitch:    {column: p, unit: deg}\n"
    "heading:  {column: h, unit: deg}\n"
    "vx:       {column: u, unit: knots}\n"
    "vy:       {column: v}\n"
    "vz:       {column: w}\n"
    "altitude: {column: alt}\n"
    "depth:    {column: z}\n";

// The readings, then the grid without GPS fixes (nav_grid.h), as `gesmi import nav` makes them.
struct MappedRead {
  NavLog log;
  SensorModel model;
  std::optional<std::int64_t> epoch;
  std::vector<std::string> notes;  // the grid's, then what was filled
};

MappedRead read_mapped(const std::string& csv, const std::string& map_text = kMap, const SensorModel& model = {}) {
  std::istringstream in(csv);
  MappedNavLog m =
      read_mapped_nav(in, "log.csv", read_column_map(write_map(map_text), nav_map_schema(), true), model, std::nullopt);
  NavOnGrid on_grid = nav_on_grid(m.series, {}, m.model, m.max_gap, m.limit);
  MappedRead r{std::move(on_grid.log), m.model, m.epoch, {on_grid.grid_note}};
  for (const std::string& line : fill_lines(r.log.half_widths)) r.notes.push_back(line);
  return r;
}

std::string mapped_error(const std::string& csv, const std::string& map_text = kMap, const SensorModel& model = {}) {
  try {
    read_mapped(csv, map_text, model);
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

TEST(MappedNav, AnyOrderExtraColumnsUnitsAndTheDvlGrid) {
  // Semicolons, detected; attitude every row, DVL every other row, depth on two rows.
  const MappedRead log = read_mapped(
      "status;z;h;t;u;v;w;alt;p;r;temp\n"
      "ok;10;90;0.0;2;0;0;5;1;-1;12\n"
      "ok;;91;0.1;;;;;1;-1;12\n"
      "ok;;92;0.2;NaN;nan;;;1;-1;12\n"
      "ok;;93;0.3;2;0;0;5;1;-1;12\n"
      "ok;11;94;0.4;2;0;0;5;1;-1;12\n");
  ASSERT_EQ(log.log.time, (std::vector<double>{0.0, 0.3, 0.4}));
  EXPECT_NEAR(log.log.heading[0], 90.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_NEAR(log.log.vx[0], 2.0 * 1852.0 / 3600.0, 1e-15);
  EXPECT_NEAR(log.log.roll[2], -std::numbers::pi / 180.0, 1e-15);
  // Depth read at 0 and 0.4 only: half-widths everywhere, from the model where read.
  const SensorModel model;
  ASSERT_EQ(log.log.half_widths.depth.size(), 3u);
  EXPECT_EQ(log.log.depth[0], 10.0);
  EXPECT_GE(log.log.half_widths.depth[0], model.depth_absolute + model.depth_relative * 10.0);
  // At 0.3: [10 ± 3.5] widened by 0.3 × 0.5, met with [11 ± 3.7] widened by 0.05.
  const double lo = std::max(10.0 - 3.5 - 0.15, 11.0 - 3.7 - 0.05), hi = std::min(10.0 + 3.5 + 0.15, 11.0 + 3.7 + 0.05);
  EXPECT_NEAR(log.log.depth[1] - log.log.half_widths.depth[1], lo, 1e-12);
  EXPECT_NEAR(log.log.depth[1] + log.log.half_widths.depth[1], hi, 1e-12);
  EXPECT_TRUE(log.log.half_widths.heading.empty());  // read on every grid row
  // Converted channels: the model's bounds grow by the conversion's rounding.
  EXPECT_GT(log.model.heading, model.heading);
  EXPECT_LT(log.model.heading, model.heading + 1e-14);
  EXPECT_GT(log.model.dvl_absolute, model.dvl_absolute);
  EXPECT_EQ(log.model.altitude, model.altitude);
  ASSERT_EQ(log.notes.size(), 2u);
  EXPECT_NE(log.notes[1].find("depth: enclosed by max_depth_rate at 1 samples without a reading: 1 between its readings"),
            std::string::npos)
      << log.notes[1];
}

TEST(MappedNav, AnyConvertedDvlComponentWidensTheDvlBound) {
  std::string map = kMap;
  map.replace(map.find("{column: u, unit: knots}"), 24, "{column: u}");
  map.replace(map.find("{column: w}"), 11, "{column: w, unit: knots}");
  const std::string csv = "t,r,p,h,u,v,w,alt,z\n0,0,0,0,1,0,3,5,10\n1,0,0,0,1,0,3,5,10\n";
  const MappedRead log = read_mapped(csv, map);
  EXPECT_GT(log.model.dvl_absolute, SensorModel{}.dvl_absolute);
  std::string si = kMap;
  si.replace(si.find("{column: u, unit: knots}"), 24, "{column: u}");
  EXPECT_EQ(read_mapped(csv, si).model.dvl_absolute, SensorModel{}.dvl_absolute);
}

TEST(MappedNav, DelimitersDeclaredOrDetected) {
  const std::string rows = "0 0 0 0 1 0 0 5 10\n1 0 0 0 1 0 0 5 10\n";
  const std::string map = std::string(kMap) + "delimiter: whitespace\n";
  EXPECT_EQ(read_mapped("t r p h u v w alt z\n" + rows, map).log.time.size(), 2u);
  EXPECT_EQ(read_mapped("t\tr\tp\th\tu\tv\tw\talt\tz\n0\t0\t0\t0\t1\t0\t0\t5\t10\n1\t0\t0\t0\t1\t0\t0\t5\t10\n")
                .log.time.size(),
            2u);
  EXPECT_EQ(read_mapped("t,r,p,h,u,v,w,alt,z\n0,0,0,0,1,0,0,5,10\n1,0,0,0,1,0,0,5,10\n").log.time.size(), 2u);
}

TEST(MappedNav, AbsoluteTimesSetTheEpochAtTheFirstWholeSecond) {
  const std::string map = std::string(kMap).replace(0, std::string(kMap).find('\n'), "time: {column: t, format: iso8601}");
  const MappedRead log = read_mapped(
      "t,r,p,h,u,v,w,alt,z\n"
      "2026-05-14T10:00:00.5+02:00,0,0,0,1,0,0,5,10\n"
      "2026-05-14T08:00:01.75Z,0,0,0,1,0,0,5,10\n", map);
  ASSERT_TRUE(log.epoch);
  EXPECT_EQ(*log.epoch, 1778745600);  // 2026-05-14T08:00:00Z
  EXPECT_EQ(log.log.time, (std::vector<double>{0.5, 1.75}));
}

TEST(MappedNav, GapsBeyondTheLimitAndSilentChannelsAreRefused) {
  std::string csv = "t,r,p,h,u,v,w,alt,z\n";
  for (int k = 0; k <= 100; ++k) {
    const bool dvl = k < 40 || k > 75;  // 35 s without DVL
    csv += std::to_string(k) + ",0,0,0," + (dvl ? "1,0,0,5" : ",,,") + "," + (k % 10 == 0 ? "10" : "") + "\n";
  }
  EXPECT_EQ(read_mapped(csv).log.time.size(), 65u);
  SensorModel sample;
  sample.step_model = StepModel::sample;
  EXPECT_NE(mapped_error(csv, kMap, sample)
                .find("log.csv:78: vx: a DVL gap of 37 s (from line 41), which the step model 'sample'"),
            std::string::npos)
      << mapped_error(csv, kMap, sample);
  const std::string gap = mapped_error(csv, std::string(kMap) + "max_gap: 30\n");
  EXPECT_NE(gap.find("log.csv:78: vx: no reading for 37 s (from 39 s to 76 s), beyond the 30 s limit (max_gap in"), std::string::npos)
      << gap;
  std::string slow_depth = "t,r,p,h,u,v,w,alt,z\n";
  for (int k = 0; k <= 30; ++k) slow_depth += std::to_string(k) + ",0,0,0,1,0,0,5," + (k % 10 == 0 ? "10" : "") + "\n";
  const std::string depth = mapped_error(slow_depth, std::string(kMap) + "max_gap: 5\n");
  EXPECT_NE(depth.find("depth: no reading for 10 s"), std::string::npos) << depth;
  std::string silent = "t,r,p,h,u,v,w,alt,z\n0,0,0,0,1,0,0,5,\n1,0,0,0,1,0,0,5,\n";
  EXPECT_NE(mapped_error(silent).find("log.csv: depth: no reading in the file (column 'z')"), std::string::npos);
}

TEST(MappedNav, RowsAndMapsThatCannotBeReadAreRefusedPrecisely) {
  const std::string header = "t,r,p,h,u,v,w,alt,z\n";
  EXPECT_NE(
      mapped_error(header + "0,0,0,0,1,,0,5,10\n").find("log.csv:2: v: missing: a DVL reading needs vx, vy and vz"),
      std::string::npos);
  EXPECT_NE(mapped_error(header + "0,100,0,0,1,0,0,5,10\n1,0,0,0,1,0,0,5,10\n").find("r: 1.7"), std::string::npos);
  EXPECT_NE(mapped_error(header + "1,0,0,0,1,0,0,5,10\n0,0,0,0,1,0,0,5,10\n").find("log.csv:3: t: goes back in time"),
            std::string::npos);
  EXPECT_NE(mapped_error(header + "0,0,0,0,1,0,0,5,10\n0,0,0,0,1,0,0,5,10\n").find("a second DVL reading"),
            std::string::npos);
  EXPECT_NE(mapped_error(header + "0,0,0,0,inf,0,0,5,10\n").find("u: is infinite"), std::string::npos);
  EXPECT_NE(mapped_error(header + "0,0,0,0,1,0,0,5,10\n").find("at least 2 rows with a DVL reading"),
            std::string::npos);
  const std::string missing = mapped_error("t,r,p,h,u,v,w,alt\n0,0,0,0,1,0,0,5\n");
  EXPECT_NE(missing.find("log.csv:1: header: no column 'z'"), std::string::npos) << missing;
  EXPECT_NE(missing.find(".yaml:9: depth.column names it"), std::string::npos) << missing;
  const auto map_error = [&](const std::string& map) { return mapped_error(header + "0,0,0,0,1,0,0,5,10\n", map); };
  std::string no_unit = kMap;
  no_unit.replace(no_unit.find(", unit: deg}\npitch"), 12, "}");
  EXPECT_NE(map_error(no_unit).find(":2: roll.unit: missing: say rad or deg"), std::string::npos) << map_error(no_unit);
  std::string grad = kMap;
  grad.replace(grad.find("unit: deg}\npitch"), 9, "unit: grad");
  EXPECT_NE(map_error(grad).find("roll.unit: unknown unit 'grad' (expected rad or deg)"), std::string::npos) << map_error(grad);
  EXPECT_NE(map_error(std::string(kMap) + "speed: {column: s}\n").find(":10: speed: unknown key"), std::string::npos);
  EXPECT_NE(map_error(std::string(kMap) + "delimiter: '|'\n").find("delimiter: expected"), std::string::npos);
  std::string no_depth = kMap;
  no_depth.erase(no_depth.find("depth:"));
  EXPECT_NE(map_error(no_depth).find("depth: missing"), std::string::npos);
  std::string bad_format = kMap;
  bad_format.replace(bad_format.find("seconds"), 7, "julian");
  EXPECT_NE(map_error(bad_format).find("time.format: expected iso8601, epoch or seconds, found 'julian'"), std::string::npos);
}

TEST(MappedNav, TheGridSpansTheSurfaceBeforeAndAfterTheDvlAndTheFixes) {
  // Attitude from 0 s to 5 s, depth at 0, 2 and 4 s, the DVL from 2 s to 4 s; fixes at
  // -1 s, 2.5 s and 6 s.
  const std::string csv =
      "t,r,p,h,u,v,w,alt,z\n"
      "0,0,0,0,,,,,0.3\n"
      "1,0,0,0,,,,,\n"
      "2,0,0,0,1,0,0,5,0.5\n"
      "3,0,0,0,1,0,0,5,\n"
      "4,0,0,0,1,0,0,5,12\n"
      "5,0,0,0,,,,,\n";
  std::istringstream in(csv);
  const std::string map = "time: {column: t}\nroll: {column: r, unit: rad}\npitch: {column: p, unit: rad}\n"
                          "heading: {column: h, unit: rad}\nvx: {column: u}\nvy: {column: v}\nvz: {column: w}\n"
                          "altitude: {column: alt}\ndepth: {column: z}\n";
  const SensorModel model;
  MappedNavLog m = read_mapped_nav(in, "log.csv", read_column_map(write_map(map), nav_map_schema(), true), model, std::nullopt);
  const auto [first, last] = usable_span(m.series, m.max_gap);
  // Within max_gap (60 s) of the attitude's and the depth's first and last readings.
  EXPECT_EQ(first, 0.0 - 60.0);
  EXPECT_EQ(last, 4.0 + 60.0);
  const std::vector<double> fixes = {-1.0, 2.5, 6.0};
  const NavOnGrid g = nav_on_grid(m.series, fixes, m.model, m.max_gap, m.limit);
  const NavLog& log = g.log;
  ASSERT_EQ(log.time, (std::vector<double>{-1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0}));
  // The DVL: its readings with the model's bound on its rows, 0 ± surface_max_speed elsewhere.
  for (std::size_t k = 0; k < log.time.size(); ++k) {
    const bool read_here = log.time[k] >= 2.0 && log.time[k] <= 4.0;
    EXPECT_EQ(log.vx[k], read_here ? 1.0 : 0.0) << k;
    EXPECT_EQ(log.half_widths.vx[k], read_here ? dvl_bound(model, 1.0) : model.surface_max_speed) << k;
    EXPECT_EQ(log.half_widths.vz[k], read_here ? dvl_bound(model, 0.0) : model.surface_max_speed) << k;
  }
  const ChannelFill& dvl = log.half_widths.fill[3];
  EXPECT_EQ(dvl.key, "surface_max_speed");
  EXPECT_EQ(dvl.before, 3u);
  EXPECT_EQ(dvl.after, 2u);
  EXPECT_EQ(dvl.between, 0u);
  // The depth between its readings: at the surface speed where a reading's box reaches
  // the surface layer (0.3 and 0.5 m), else at max_depth_rate.
  const ChannelFill& depth = log.half_widths.fill[7];
  EXPECT_EQ(depth.key, "max_depth_rate");
  EXPECT_EQ(depth.before, 1u);
  EXPECT_EQ(depth.between, 2u);
  EXPECT_EQ(depth.after, 2u);
  // At 1 s: both readings (0.3 and 0.5 m) reach the layer: widened by 6.5 m/s x 1 s.
  const double at_one_lo = std::max(0.3 - (1.5 + 0.2 * 0.3) - 6.5, 0.5 - (1.5 + 0.2 * 0.5) - 6.5);
  const double at_one_hi = std::min(0.3 + (1.5 + 0.2 * 0.3) + 6.5, 0.5 + (1.5 + 0.2 * 0.5) + 6.5);
  EXPECT_NEAR(log.depth[2] - log.half_widths.depth[2], at_one_lo, 1e-12);
  EXPECT_NEAR(log.depth[2] + log.half_widths.depth[2], at_one_hi, 1e-12);
  // Attitude, read on every row, is enclosed at the fixes' times only.
  EXPECT_EQ(log.half_widths.fill[2].before, 1u);
  EXPECT_EQ(log.half_widths.fill[2].after, 1u);
  EXPECT_NE(g.grid_note.find("grid: the 3 rows with a DVL reading, of 6, and 5 samples before and after them"),
            std::string::npos)
      << g.grid_note;
  const std::vector<std::string> lines = fill_lines(log.half_widths);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "vx, vy, vz: bridged by surface_max_speed at 5 samples without a reading: 3 before its first "
                      "reading (2 s), 2 after its last reading (4 s)");
}

TEST(NavRows, TheFixesOutsideTheRowsExtendTheGridAndTheRowsStayAsRead) {
  // Rows at 10, 11 and 12 s (depth 50 m, below the surface layer), the depth's bound
  // given per row; fixes at -50 s and 72 s (60 s from the first and last rows) and
  // 11.5 s (between rows: no sample of its own).
  const std::string csv =
      "time,roll,pitch,heading,vx,vy,vz,altitude,depth,depth_halfwidth\n"
      "10,0.01,0.02,3.1,1,0,0,5,50,0.25\n"
      "11,0.01,0.02,-3.1,1.2,0.1,0,5,50.5,0.25\n"
      "12,0.01,0.02,3.0,1,0,0,5,51,0.5\n";
  const SensorModel model;
  const auto series = [&] {
    std::istringstream in(csv);
    return series_of_rows(read_nav_csv(in, "nav.csv"), model, "nav.csv");
  };
  const NavSeries s = series();
  const auto [first, last] = usable_span(s, kDefaultMaxGap);
  EXPECT_EQ(first, -50.0);
  EXPECT_EQ(last, 72.0);
  const double inf = std::numeric_limits<double>::infinity();

  // Without a fix outside, the rows as read: the model's bounds stay the model's.
  const NavLog rows = nav_on_grid(s, std::vector<double>{11.5}, model, inf, "").log;
  EXPECT_EQ(rows.time, (std::vector<double>{10.0, 11.0, 12.0}));
  EXPECT_EQ(rows.heading, (std::vector<double>{3.1, -3.1, 3.0}));
  EXPECT_EQ(rows.vy, (std::vector<double>{0.0, 0.1, 0.0}));
  EXPECT_EQ(rows.half_widths.depth, (std::vector<double>{0.25, 0.25, 0.5}));
  EXPECT_TRUE(rows.half_widths.roll.empty());
  EXPECT_TRUE(rows.half_widths.vx.empty());
  EXPECT_TRUE(fill_lines(rows.half_widths).empty());

  const NavOnGrid g = nav_on_grid(series(), std::vector<double>{-50.0, 11.5, 72.0}, model, inf, "");
  const NavLog& log = g.log;
  ASSERT_EQ(log.time, (std::vector<double>{-50.0, 10.0, 11.0, 12.0, 72.0}));
  // The DVL bridged at the fixes: 0 +- surface_max_speed; its rows keep their model bound.
  for (const std::size_t k : {0u, 4u}) {
    EXPECT_EQ(log.vx[k], 0.0);
    EXPECT_EQ(log.half_widths.vx[k], model.surface_max_speed);
  }
  EXPECT_EQ(log.vx[2], 1.2);
  EXPECT_EQ(log.half_widths.vx[2], dvl_bound(model, 1.2));
  // The other channels from the nearest row, widened by their rate over 60 s (upward).
  const auto holds = [](double value, double half_width, double lo, double hi) {
    return value - half_width <= lo && value + half_width >= hi;
  };
  const double turn = mul_up(model.max_attitude_rate, 60.0);
  EXPECT_TRUE(holds(log.roll[0], log.half_widths.roll[0], 0.01 - model.roll - turn, 0.01 + model.roll + turn));
  EXPECT_TRUE(holds(log.heading[4], log.half_widths.heading[4], 3.0 - model.heading - turn, 3.0 + model.heading + turn));
  const double sink = mul_up(model.max_depth_rate, 60.0);
  EXPECT_TRUE(holds(log.depth[4], log.half_widths.depth[4], 51.0 - 0.5 - sink, 51.0 + 0.5 + sink));
  EXPECT_NEAR(log.half_widths.depth[4], 0.5 + sink, 1e-12);
  EXPECT_EQ(log.half_widths.depth[1], 0.25);
  const std::vector<std::string> lines = fill_lines(log.half_widths);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "vx, vy, vz: bridged by surface_max_speed at 2 samples without a reading: 1 before its first "
                      "reading (10 s), 1 after its last reading (12 s)");
  EXPECT_NE(g.grid_note.find("grid: the 3 rows with a DVL reading, of 3, and 2 samples before and after them; longest "
                             "step 60 s (from -50 s to 10 s, a fix's time)"),
            std::string::npos)
      << g.grid_note;
}

}  // namespace
}  // namespace gesmi::io
