// gesmi export's CSV files read back by the importers give the same mission, bit
// for bit (numbers are written in their shortest exact form); and the GESMI text
// export reads back to the same navigation and fixes.

#include "io/exports/export_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/exports/export_gesmi_txt.h"
#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/imports/import_gesmi_txt.h"
#include "io/imports/import_mission.h"
#include "io/files/mission_file.h"
#include "solver/sim/simulator.h"
#include "tests/support/run_command.h"

namespace gesmi::io {
namespace {

Mission simulated() {
  SimulationOptions o;
  o.seed = 11;
  o.duration = 1200.0;
  o.unassociated = 0.5;
  SensorModel model;
  model.heading = 6e-3;
  model.depth_absolute = 0.7;
  Mission m = simulate_mission(o, model);
  m.origin = {48.212920614, -4.458227931};
  set_geodetic_gps(m);
  // Optional columns: per-sample depth bounds and per-fix GPS bounds.
  m.half_widths.depth.assign(m.size(), 0.0);
  for (std::size_t k = 0; k < m.size(); ++k) m.half_widths.depth[k] = 1.0 + 0.25 * m.depth[k];
  m.gps_given_north_halfwidth = {3.0, 4.5};
  m.gps_given_east_halfwidth = {2.0, 1.0 / 3.0};
  m.mark_side.back() = -1;
  return m;
}

void expect_same(const Mission& a, const Mission& b) {
  for (const auto member : {&Mission::time, &Mission::roll, &Mission::pitch, &Mission::heading, &Mission::vx,
                            &Mission::vy, &Mission::vz, &Mission::altitude, &Mission::depth, &Mission::gps_time,
                            &Mission::gps_longitude, &Mission::gps_latitude, &Mission::gps_given_north_halfwidth,
                            &Mission::gps_given_east_halfwidth, &Mission::mark_time, &Mission::mark_range,
                            &Mission::truth_x, &Mission::truth_y, &Mission::truth_z, &Mission::truth_mines})
    EXPECT_EQ(a.*member, b.*member);
  EXPECT_EQ(a.half_widths.depth, b.half_widths.depth);
  EXPECT_TRUE(b.half_widths.roll.empty());
  EXPECT_EQ(a.mark_mine, b.mark_mine);
  EXPECT_EQ(a.mark_side, b.mark_side);
  EXPECT_EQ(a.mine_count, b.mine_count);
  EXPECT_EQ(a.origin.latitude, b.origin.latitude);
  EXPECT_EQ(a.origin.longitude, b.origin.longitude);
  EXPECT_EQ(a.model.heading, b.model.heading);
  EXPECT_EQ(a.model.depth_absolute, b.model.depth_absolute);
  EXPECT_EQ(a.model.dvl_relative, b.model.dvl_relative);
  EXPECT_EQ(a.model.sonar_side, b.model.sonar_side);
}

TEST(ExportCsv, ImportOfTheExportedFilesGivesTheSameMission) {
  const Mission m = simulated();
  ASSERT_GT(m.mark_count(), 1u);
  const std::string folder = test::temp_folder("export") + "/csv";
  export_mission_csv(m, folder);
  for (const char* file : {"nav.csv", "gps.csv", "marks.csv", "truth.csv", "truth_mines.csv", "model.yaml", "import-command.txt"})
    EXPECT_TRUE(std::filesystem::exists(folder + "/" + file)) << file;

  ImportInputs inputs;
  inputs.gps = folder + "/gps.csv";
  inputs.marks = folder + "/marks.csv";
  inputs.config = folder + "/model.yaml";
  inputs.truth = folder + "/truth.csv";
  inputs.truth_mines = folder + "/truth_mines.csv";
  inputs.origin = m.origin;
  inputs.mines = m.mine_count;
  expect_same(m, import_nav(folder + "/nav.csv", inputs));
}

TEST(ExportCsv, TheImportArgumentsNameEveryFileAndTheOrigin) {
  const Mission m = simulated();
  std::string line;
  for (const std::string& a : import_arguments(m, "out.h5")) line += a + " ";
  EXPECT_EQ(line,
            "import nav nav.csv --gps gps.csv --marks marks.csv --config model.yaml --origin 48.212920614,-4.458227931 "
            "--mines 6 --truth truth.csv --truth-mines truth_mines.csv -o out.h5 ");
}

TEST(ExportCsv, RefusesAFolderThatIsNotEmptyAndLeavesNothingBehind) {
  const std::string parent = test::temp_folder("export");
  std::filesystem::create_directory(parent + "/full");
  std::ofstream(parent + "/full/keep.txt") << "x";
  EXPECT_THROW(export_mission_csv(simulated(), parent + "/full"), FormatError);
  EXPECT_THROW(export_mission_csv(simulated(), parent + "/missing/csv"), FormatError);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(parent)) ++entries;
  EXPECT_EQ(entries, 1u);  // only full/, no temporary folder
  // An empty folder is replaced.
  std::filesystem::create_directory(parent + "/empty");
  export_mission_csv(simulated(), parent + "/empty");
  EXPECT_TRUE(std::filesystem::exists(parent + "/empty/nav.csv"));
}

TEST(ExportGesmiTxt, ReadsBackToTheSameNavigationAndFixes) {
  Mission m = simulated();
  m.gps_given_north_halfwidth.clear();
  m.gps_given_east_halfwidth.clear();
  fill_local_gps(m, "m");
  std::stringstream text;
  write_gesmi_txt(m, "m.h5", text);
  Mission r = mission_from_gesmi_txt(read_gesmi_txt(text, "log.txt"), "log.txt", m.origin, m.model, GesmiXy::fixes);
  fill_local_gps(r, "log.txt");
  EXPECT_EQ(r.time, m.time);
  EXPECT_EQ(r.vy, m.vy);
  EXPECT_EQ(r.half_widths.depth, m.half_widths.depth);
  ASSERT_EQ(r.gps_time, m.gps_time);
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) {
    EXPECT_NEAR(r.gps_north[i], m.gps_north[i], 1e-6);
    // The box of the re-imported fix holds the original box.
    EXPECT_GE(r.gps_north_halfwidth[i], m.gps_north_halfwidth[i]);
    // Re-imported, the box is widened again: 1 cm, and the meridian convergence
    // turning the east half-width into the north axis (io/geodesy.h).
    EXPECT_LE(r.gps_north_halfwidth[i], m.gps_north_halfwidth[i] + kLocalFrameError +
                                            (m.gps_east_halfwidth[i] + kLocalFrameError) * r.heading_frame_margin + 1e-9);
  }
  // Every model-bound half-width written is at least the solver's bound.
  for (std::size_t k = 0; k < m.size(); ++k) {
    EXPECT_GE(r.half_widths.vx[k], m.model.dvl_relative * std::fabs(m.vx[k]) + m.model.dvl_absolute);
    EXPECT_EQ(r.half_widths.heading[k], m.model.heading);
  }
}

TEST(ExportGesmiTxt, RefusesFixesBetweenSamples) {
  Mission m = simulated();
  m.gps_time[1] -= 0.05;
  fill_local_gps(m, "m");
  std::stringstream text;
  try {
    write_gesmi_txt(m, "m.h5", text);
    ADD_FAILURE() << "accepted a fix between samples";
  } catch (const FormatError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("m.h5: /gps/time: fix 1 at ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace gesmi::io
