// The GESMI text log reader: header lines, half-widths replacing the model, x/y as
// position fixes or as truth, every bad row named; and the sample in missions/ is
// what its documented command makes.

#include "io/imports/import_gesmi_txt.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/imports/import_mission.h"
#include "solver/sim/simulator.h"
#include "tests/support/paths.h"

namespace gesmi::io {
namespace {

// A data row: t, then (value, half-width) for the ten columns.
std::string row(double t, const std::string& x_and_y = "nan nan nan nan", const std::string& heading_hw = "0.01") {
  std::ostringstream s;
  s << t << " 0.01 0.001 0.02 0.001 0.5 " << heading_hw << " 1.5 0.02 0 0.02 0 0.02 6 2 12 0.2 " << x_and_y << "\n";
  return s.str();
}

GesmiTextLog read_log(const std::string& text) {
  std::istringstream in(text);
  return read_gesmi_txt(in, "log.txt");
}

std::string log_error(const std::string& text) {
  try {
    read_log(text);
  } catch (const FormatError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

TEST(GesmiTxt, SkipsHeaderLinesAndReadsValueHalfWidthPairs) {
  const GesmiTextLog log =
      read_log("Redermor mission, GESMA\nt phi dphi theta ...\n1 2 3\n\n" + row(0.0, "0.06 1 0 1") + row(0.1) + "\n");
  ASSERT_EQ(log.time.size(), 2u);
  EXPECT_EQ(log.line, (std::vector<std::size_t>{5, 6}));
  EXPECT_EQ(log.value[GesmiColumn::heading][0], 0.5);
  EXPECT_EQ(log.half_width[GesmiColumn::depth][1], 2.0);
  EXPECT_EQ(log.value[GesmiColumn::x][0], 0.06);
  EXPECT_TRUE(std::isnan(log.half_width[GesmiColumn::x][1]));
}

TEST(GesmiTxt, NamesLineFieldAndReasonOfEveryBadRow) {
  const struct {
    std::string text;
    const char* message;
  } cases[] = {
      {"", "log.txt:1: no data row (rows of 21 numbers"},
      {"a header\nanother\n", "log.txt:2: no data row"},
      {row(0.0), "log.txt:1: a mission needs at least 2 data rows, found 1"},
      {row(0.0) + "0.1 1 2 3\n", "log.txt:2: expected 21 numbers: t, then value and half-width of roll, pitch, heading"},
      {row(0.0) + row(0.1).substr(0, row(0.1).rfind(' ')) + "\n", "log.txt:2: expected 21 numbers"},
      {row(0.0) + row(0.1, "nan nan nan nan", "abc"), "log.txt:2: heading half-width: expected a number, found 'abc'"},
      {row(0.0) + row(0.1, "nan nan nan nan", "-0.01"), "log.txt:2: heading half-width: -0.01 is negative"},
      {row(0.0) + row(0.0), "log.txt:2: t: 0 s does not increase (0 s on line 1)"},
      {row(0.0) + "nan" + row(0.1).substr(3), "log.txt:2: t: is NaN"},
      {row(0.0) + row(0.1, "1 1 nan nan"), "log.txt:2: x half-width: x and y half-widths are given together"},
      {row(0.0) + row(0.1, "nan 1 2 1"), "log.txt:2: x: is NaN"},
      {"0 inf 0.001 0.02 0.001 0.5 0.01 1.5 0.02 0 0.02 0 0.02 6 2 12 0.2 nan nan nan nan\n" + row(0.1), "log.txt:1: roll: is infinite"},
  };
  for (const auto& c : cases) {
    const std::string what = log_error(c.text);
    EXPECT_NE(what.find(c.message), std::string::npos) << "got: " << what << "\nwanted: " << c.message;
  }
}

TEST(GesmiTxt, GivenHalfWidthsReplaceTheModelAndMissingOnesKeepIt) {
  // Heading half-width given on the first row only: the second keeps the model's.
  const SensorModel model;
  Mission m = mission_from_gesmi_txt(read_log(row(0.0) + row(0.1, "nan nan nan nan", "inf")), "log.txt",
                                     kRedermorStartFix, model, GesmiXy::fixes);
  EXPECT_EQ(m.half_widths.heading, (std::vector<double>{0.01, model.heading}));
  EXPECT_EQ(m.half_widths.depth, (std::vector<double>{2.0, 2.0}));
  EXPECT_EQ(m.depth, (std::vector<double>{6.0, 6.0}));
  EXPECT_EQ(m.altitude, (std::vector<double>{12.0, 12.0}));
  EXPECT_TRUE(m.gps_time.empty());
  // With no half-width at all for a sensor, the mission keeps the model (no array).
  m = mission_from_gesmi_txt(read_log(row(0.0, "nan nan nan nan", "nan") + row(0.1, "nan nan nan nan", "nan")),
                             "log.txt", kRedermorStartFix, model, GesmiXy::fixes);
  EXPECT_TRUE(m.half_widths.heading.empty());
}

TEST(GesmiTxt, RowsWithXYHalfWidthsBecomeFixesNorthEastAboutTheOrigin) {
  const GeoOrigin origin{48.2, -4.4};
  Mission m = mission_from_gesmi_txt(read_log(row(0.0, "100 3 -50 4") + row(0.1) + row(0.2, "120 1 -40 2")), "log.txt",
                                     origin, SensorModel{}, GesmiXy::fixes);
  ASSERT_EQ(m.gps_time, (std::vector<double>{0.0, 0.2}));
  EXPECT_EQ(m.gps_given_north_halfwidth, (std::vector<double>{3.0, 1.0}));
  EXPECT_EQ(m.gps_given_east_halfwidth, (std::vector<double>{4.0, 2.0}));
  EXPECT_GT(m.gps_latitude[0], origin.latitude);    // x is north
  EXPECT_LT(m.gps_longitude[0], origin.longitude);  // y is east (negative: west)
  fill_local_gps(m, "log.txt");
  EXPECT_NEAR(m.gps_north[0], 100.0, 1e-6);
  EXPECT_NEAR(m.gps_east[0], -50.0, 1e-6);
  // The given bound plus 1 cm, plus the other axis's bound turned by the meridian
  // convergence 130 m from the origin (io/geodesy.h): under 3e-5 rad at 48.2°.
  EXPECT_GT(m.gps_north_halfwidth[1], 1.0 + kLocalFrameError);
  EXPECT_LT(m.gps_north_halfwidth[1], 1.0 + kLocalFrameError + (2.0 + kLocalFrameError) * 3e-5);
  EXPECT_GE(m.gps_east_halfwidth[1], 2.0 + kLocalFrameError);
}

TEST(GesmiTxt, RowsWhoseXYBoundIsUnknownAreNotFixes) {
  // Logs write "unknown" as a huge bound (1e9): such a row says nothing about x, y.
  Mission m = mission_from_gesmi_txt(
      read_log(row(0.0, "100 3 -50 4") + row(0.1, "0 1e9 0 1e9") + row(0.2, "0 200000 0 3") + row(0.3, "120 1 -40 2")),
      "log.txt", GeoOrigin{48.2, -4.4}, SensorModel{}, GesmiXy::fixes);
  EXPECT_EQ(m.gps_time, (std::vector<double>{0.0, 0.3}));
}

TEST(GesmiTxt, TruthReadingTakesXYAndDepthAsTheTrajectoryLikeCodac) {
  Mission m = mission_from_gesmi_txt(read_log(row(0.0, "0.06 0 0 0") + row(0.1, "0.2 inf 0.1 inf")), "log.txt",
                                     kRedermorStartFix, SensorModel{}, GesmiXy::truth);
  EXPECT_EQ(m.truth_x, (std::vector<double>{0.06, 0.2}));
  EXPECT_EQ(m.truth_y, (std::vector<double>{0.0, 0.1}));
  EXPECT_EQ(m.truth_z, m.depth);
  ASSERT_EQ(m.gps_time.size(), 1u);  // the start position
  try {
    mission_from_gesmi_txt(read_log(row(0.0, "0.06 0 0 0") + row(0.1)), "log.txt", kRedermorStartFix, SensorModel{},
                           GesmiXy::truth);
    ADD_FAILURE() << "accepted a row without x";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("log.txt:2: x: needed as ground truth, found nan"), std::string::npos) << e.what();
  }
}

TEST(GesmiTxt, RefusesFixesBeyondTheLocalFrameZone) {
  try {
    mission_from_gesmi_txt(read_log(row(0.0, "0 1 0 1") + row(0.1, "120000 1 0 1")), "log.txt", kRedermorStartFix,
                           SensorModel{}, GesmiXy::fixes);
    ADD_FAILURE() << "accepted";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("log.txt:2: x, y: the fix is 120000 m from the origin"), std::string::npos)
        << e.what();
  }
}

// missions/gesmi_txt/README.md: gesmi simulate --seed 3 --duration 29.9, exported
// with gesmi export --format gesmi-txt.
TEST(GesmiTxt, TheSampleInMissionsIsTheDocumentedSimulation) {
  const std::string path = test::source_dir() + "/missions/gesmi_txt/redermor_start.txt";
  const Mission m = import_gesmi_txt(path, GesmiXy::fixes, {});
  SimulationOptions o;
  o.seed = 3;
  o.duration = 29.9;
  const Mission sim = simulate_mission(o);
  ASSERT_EQ(m.size(), 300u);
  EXPECT_EQ(m.time, sim.time);
  EXPECT_EQ(m.heading, sim.heading);
  EXPECT_EQ(m.vx, sim.vx);
  EXPECT_EQ(m.depth, sim.depth);
  EXPECT_EQ(m.altitude, sim.altitude);
  EXPECT_EQ(m.origin.latitude, kRedermorStartFix.latitude);
  ASSERT_EQ(m.gps_time, sim.gps_time);
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) {
    EXPECT_NEAR(m.gps_north[i], sim.gps_north[i], 1e-6);
    EXPECT_NEAR(m.gps_east[i], sim.gps_east[i], 1e-6);
    // The box still holds the true position.
    EXPECT_LE(std::fabs(m.gps_north[i] - sim.truth_x[i == 0 ? 0 : sim.size() - 1]), m.gps_north_halfwidth[i]);
  }
  // Half-widths: the model's, written out and read back per sample.
  EXPECT_EQ(m.half_widths.roll, std::vector<double>(300, sim.model.roll));
}

}  // namespace
}  // namespace gesmi::io
