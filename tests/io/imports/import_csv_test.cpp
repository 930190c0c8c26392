// The CSV readers of gesmi import (nav, GPS, marks, truth): what they accept, and
// one line "FILE:LINE: field: reason" for everything they refuse.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/imports/import_gps_csv.h"
#include "io/imports/import_marks_csv.h"
#include "io/imports/import_nav_csv.h"
#include "io/imports/import_truth_csv.h"

namespace gesmi::io {
namespace {

NavLog nav(const std::string& text) {
  std::istringstream in(text);
  return read_nav_csv(in, "nav.csv");
}

MarkTable marks(const std::string& text, const MarkRules& rules = {0.0, 100.0, 76.0, 3}) {
  std::istringstream in(text);
  return read_marks_csv(in, "marks.csv", rules);
}

GpsLog gps(const std::string& text) {
  std::istringstream in(text);
  return read_gps_csv(in, "gps.csv", 0.0, 100.0);
}

// The error of `reading`, checked to be one line starting with the file name.
template <class Reading>
std::string error_of(Reading reading) {
  try {
    reading();
  } catch (const FormatError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  ADD_FAILURE() << "accepted";
  return {};
}

const std::string kNavHeader = "time,roll,pitch,heading,vx,vy,vz,altitude,depth\n";

TEST(CsvNumber, ParsesWholeFieldsOnly) {
  EXPECT_EQ(parse_number("1.5"), 1.5);
  EXPECT_EQ(parse_number("+2"), 2.0);
  EXPECT_EQ(parse_number("-3e2"), -300.0);
  EXPECT_TRUE(std::isnan(*parse_number("nan")));
  EXPECT_TRUE(std::isinf(*parse_number("inf")));
  EXPECT_TRUE(std::isinf(*parse_number("1e999")));
  EXPECT_EQ(parse_number("1e-999"), 0.0);
  EXPECT_FALSE(parse_number(""));
  EXPECT_FALSE(parse_number("1.5x"));
  EXPECT_FALSE(parse_number("abc"));
  EXPECT_FALSE(parse_number("+-1"));
  EXPECT_EQ(parse_integer("-1"), -1);
  EXPECT_FALSE(parse_integer("1.0"));
}

TEST(CsvNumber, FormattedNumbersReadBackExactly) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100000; ++i) {
    double x = 0.0;
    const std::uint64_t bits = rng();
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    EXPECT_EQ(*parse_number(format_number(x)), x) << format_number(x);
  }
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(std::numeric_limits<double>::infinity()), "inf");
}

TEST(NavCsv, ReadsColumnsAndOptionalHalfWidths) {
  const NavLog log = nav("time,roll,pitch,heading,vx,vy,vz,altitude,depth,depth_halfwidth,roll_halfwidth\r\n"
                         "0, 0.01,0.02,0.03,1.5,0,0,12,5,2,0.001\r\n"
                         "\n"
                         "0.1,0.01,0.02,0.03,+1.6,0,0,12,5.1,2.5,0.002\r\n");
  ASSERT_EQ(log.time.size(), 2u);
  EXPECT_EQ(log.vx[1], 1.6);
  EXPECT_EQ(log.depth[1], 5.1);
  EXPECT_EQ(log.half_widths.depth, (std::vector<double>{2.0, 2.5}));
  EXPECT_EQ(log.half_widths.roll, (std::vector<double>{0.001, 0.002}));
  EXPECT_TRUE(log.half_widths.vx.empty());
}

TEST(NavCsv, IgnoresAByteOrderMark) {
  EXPECT_EQ(nav("\xEF\xBB\xBF" + kNavHeader + "0,0,0,0,1,0,0,10,5\n1,0,0,0,1,0,0,10,5\n").time.size(), 2u);
}

TEST(NavCsv, NamesLineFieldAndReasonOfEveryBadRow) {
  const std::string row0 = "0,0,0,0,1,0,0,10,5\n";
  const struct {
    std::string text;
    const char* message;
  } cases[] = {
      {"", "nav.csv:1: header: the file is empty"},
      {"\n\n", "nav.csv:2: header: the file is empty"},
      {"time,roll,pitch\n", "nav.csv:1: header: expected 'time,roll,pitch,heading,vx,vy,vz,altitude,depth'"},
      {"time,pitch,roll,heading,vx,vy,vz,altitude,depth\n", "nav.csv:1: header: expected"},
      {kNavHeader.substr(0, kNavHeader.size() - 1) + ",speed\n", "found 'time,roll,pitch,heading,vx,vy,vz,altitude,depth,speed'"},
      {kNavHeader.substr(0, kNavHeader.size() - 1) + ",roll_halfwidth,roll_halfwidth\n", "nav.csv:1: header"},
      {kNavHeader, "nav.csv:1: a navigation log needs at least 2 rows, found 0"},
      {kNavHeader + row0, "nav.csv:2: a navigation log needs at least 2 rows, found 1"},
      {kNavHeader + row0 + "0.1,0,0,0,1,0,0,10\n", "nav.csv:3: depth: missing column (expected 9 fields, found 8)"},
      {kNavHeader + row0 + "0.1,0,0,0,1,0,0\n", "nav.csv:3: altitude: missing column"},
      {kNavHeader + row0 + "0.1,0,0,0,1,0,0,10,5,7\n", "nav.csv:3: expected 9 fields, found 10 (extra field '7')"},
      {kNavHeader + row0 + "0.1,0,0,abc,1,0,0,10,5\n", "nav.csv:3: heading: expected a number, found 'abc'"},
      {kNavHeader + row0 + "0.1,0,0,0,1,,0,10,5\n", "nav.csv:3: vy: missing value"},
      {kNavHeader + row0 + "0.1,0,0,0,1,0,0,10,nan\n", "nav.csv:3: depth: is NaN"},
      {kNavHeader + row0 + "0.1,0,0,0,inf,0,0,10,5\n", "nav.csv:3: vx: is infinite"},
      {kNavHeader + row0 + "0,0,0,0,1,0,0,10,5\n", "nav.csv:3: time: 0 s does not increase (0 s on line 2)"},
      {kNavHeader + row0 + "0.2,0,0,0,1,0,0,10,5\n0.1,0,0,0,1,0,0,10,5\n", "nav.csv:4: time: 0.1 s does not increase (0.2 s on line 3)"},
      {"time,roll,pitch,heading,vx,vy,vz,altitude,depth,vx_halfwidth\n0,0,0,0,1,0,0,10,5,-1\n",
       "nav.csv:2: vx_halfwidth: a half-width must be >= 0"},
  };
  for (const auto& c : cases) {
    const std::string what = error_of([&] { nav(c.text); });
    EXPECT_NE(what.find(c.message), std::string::npos) << "got: " << what << "\nwanted: " << c.message;
  }
}

TEST(GpsCsv, ReadsFixesAndOptionalBounds) {
  const GpsLog log = gps("time,longitude,latitude,north_halfwidth,east_halfwidth\n0,-4.45,48.21,3,4\n100,-4.44,48.22,1,2\n");
  ASSERT_EQ(log.time.size(), 2u);
  EXPECT_EQ(log.latitude[1], 48.22);
  EXPECT_EQ(log.east_halfwidth, (std::vector<double>{4.0, 2.0}));
  EXPECT_EQ(log.line, (std::vector<std::size_t>{2, 3}));
  EXPECT_TRUE(gps("time,longitude,latitude\n").time.empty());
}

TEST(GpsCsv, RefusesFixesOutsideTheMissionAndTheGlobe) {
  const struct {
    std::string text;
    const char* message;
  } cases[] = {
      {"", "gps.csv:1: header: the file is empty"},
      {"time,lon,lat\n", "gps.csv:1: header: expected 'time,longitude,latitude'"},
      {"time,longitude,latitude,north_halfwidth\n", "gps.csv:1: header: north_halfwidth and east_halfwidth go together"},
      {"time,longitude,latitude\n101,-4.4,48.2\n", "gps.csv:2: time: 101 s is outside the mission [0, 100] s"},
      {"time,longitude,latitude\n-1,-4.4,48.2\n", "gps.csv:2: time: -1 s is outside the mission"},
      {"time,longitude,latitude\n1,-4.4,91\n", "gps.csv:2: latitude: 91 is not in [-90, 90] degrees"},
      {"time,longitude,latitude\n1,181,48\n", "gps.csv:2: longitude: 181 is not in [-180, 180] degrees"},
      {"time,longitude,latitude\n1,-4.4\n", "gps.csv:2: latitude: missing column"},
      {"time,longitude,latitude\n5,-4.4,48\n5,-4.4,48\n", "gps.csv:3: time: 5 s does not increase (5 s on line 2)"},
      {"time,longitude,latitude,north_halfwidth,east_halfwidth\n5,-4.4,48,1,-2\n", "gps.csv:2: east_halfwidth: a half-width must be >= 0"},
  };
  for (const auto& c : cases) {
    const std::string what = error_of([&] { gps(c.text); });
    EXPECT_NE(what.find(c.message), std::string::npos) << "got: " << what << "\nwanted: " << c.message;
  }
}

TEST(MarksCsv, AcceptsTheDocumentedMineAndSideForms) {
  const MarkTable t = marks("time,mine,range,side\n10,0,52.4,starboard\n20,,12,port\n30,?,5,+1\n40,-1,76,-1\n50,2,0,1\n");
  EXPECT_EQ(t.mine, (std::vector<std::int32_t>{0, -1, -1, -1, 2}));
  EXPECT_EQ(t.side, (std::vector<std::int32_t>{1, -1, 1, -1, 1}));
  EXPECT_EQ(t.range[3], 76.0);
  EXPECT_TRUE(marks("time,mine,range,side\n").time.empty());
}

TEST(MarksCsv, ValidatesEveryRowAgainstTheMission) {
  const struct {
    std::string text;
    const char* message;
  } cases[] = {
      {"", "marks.csv:1: header: the file is empty (expected the header 'time,mine,range,side')"},
      {"time,range,mine,side\n", "marks.csv:1: header: expected 'time,mine,range,side', found 'time,range,mine,side'"},
      {"time,mine,range,side,extra\n", "marks.csv:1: header"},
      {"time,mine,range,side\n101,0,10,port\n", "marks.csv:2: time: 101 s is outside the mission [0, 100] s"},
      {"time,mine,range,side\n10,0,10,left\n", "marks.csv:2: side: expected starboard, port, +1 or -1, found 'left'"},
      {"time,mine,range,side\n10,0,10,\n", "marks.csv:2: side: expected starboard, port, +1 or -1, found ''"},
      {"time,mine,range,side\n10,3,10,port\n", "marks.csv:2: mine: unknown mine 3: the mission's mines are 0..2"},
      {"time,mine,range,side\n10,x,10,port\n", "marks.csv:2: mine: expected a mine number, '?' or nothing, found 'x'"},
      {"time,mine,range,side\n10,-2,10,port\n", "marks.csv:2: mine: unknown mine -2"},
      {"time,mine,range,side\n10,0,-1,port\n", "marks.csv:2: range: -1 m is negative"},
      {"time,mine,range,side\n10,0,76.5,port\n", "marks.csv:2: range: 76.5 m is beyond the sonar's maximum range plus the range bound (76 m)"},
      {"time,mine,range,side\n10,0,nan,port\n", "marks.csv:2: range: is NaN"},
      {"time,mine,range,side\n10,0,10\n", "marks.csv:2: side: missing column"},
      {"time,mine,range,side\ninf,0,10,port\n", "marks.csv:2: time: is infinite"},
  };
  for (const auto& c : cases) {
    const std::string what = error_of([&] { marks(c.text); });
    EXPECT_NE(what.find(c.message), std::string::npos) << "got: " << what << "\nwanted: " << c.message;
  }
  const std::string none = error_of([] { marks("time,mine,range,side\n10,0,10,port\n", {0.0, 100.0, 76.0, 0}); });
  EXPECT_NE(none.find("unknown mine 0: the mission has no mines"), std::string::npos) << none;
}

TEST(TruthCsv, FollowsTheNavigationSamples) {
  const std::vector<double> time = {0.0, 0.1, 0.2};
  std::istringstream good("time,north,east,down\n0,1,2,3\n0.1,1,2,3\n0.2,1,2,3.5\n");
  EXPECT_EQ(read_truth_csv(good, "truth.csv", time).down[2], 3.5);
  // Rows between the samples (a truth on every row of a log whose grid takes some) are skipped.
  std::istringstream between("time,north,east,down\n0,1,2,3\n0.05,9,9,9\n0.1,1,2,3\n0.15,9,9,9\n0.2,1,2,3.5\n");
  const TruthTrack track = read_truth_csv(between, "truth.csv", time);
  EXPECT_EQ(track.down, (std::vector<double>{3.0, 3.0, 3.5}));
  std::istringstream shifted("time,north,east,down\n0,1,2,3\n0.15,1,2,3\n0.2,1,2,3\n");
  const std::string gap = error_of([&] { read_truth_csv(shifted, "truth.csv", time); });
  EXPECT_NE(gap.find("truth.csv:3: time: no row at the navigation sample 1 (0.1 s)"), std::string::npos) << gap;
  std::istringstream short_track("time,north,east,down\n0,1,2,3\n");
  const std::string short_error = error_of([&] { read_truth_csv(short_track, "truth.csv", time); });
  EXPECT_NE(short_error.find("truth.csv:2: no row at the navigation sample 1 (0.1 s)"), std::string::npos) << short_error;
  std::istringstream backwards("time,north,east,down\n0,1,2,3\n0,1,2,3\n");
  EXPECT_NE(error_of([&] { read_truth_csv(backwards, "truth.csv", time); }).find("truth.csv:3: time: 0 s does not follow 0 s"),
            std::string::npos);
  std::istringstream mines("mine,north,east,down\n0,1,2,3\n2,1,2,3\n");
  EXPECT_NE(error_of([&] { read_truth_mines_csv(mines, "truth_mines.csv"); })
                .find("truth_mines.csv:3: mine: expected mine 1"),
            std::string::npos);
}

}  // namespace
}  // namespace gesmi::io
