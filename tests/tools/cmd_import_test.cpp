// gesmi import through the binary: a navigation log with GPS and marks becomes a
// mission (origin at the first fix), marks replace a mission's table (also in
// place), and the GESMI text sample imports in both readings of x/y.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/files/mission_file.h"
#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

TEST(CmdImport, NavGpsAndMarksMakeAMissionAboutTheFirstFix) {
  const std::string folder = temp_folder("cmd-import");
  std::string nav = "time,roll,pitch,heading,vx,vy,vz,altitude,depth,depth_halfwidth\n";
  for (int k = 0; k <= 100; ++k) nav += std::to_string(k) + ",0.001,-0.002,0.5,1.5,0.01,0,12," + std::to_string(5 + 0.01 * k) + ",1\n";
  write(folder + "/nav.csv", nav);
  write(folder + "/gps.csv", "time,longitude,latitude\n0,-4.458227931,48.212920614\n100,-4.4570,48.2140\n");
  write(folder + "/marks.csv", "time,mine,range,side\n20.5,1,30,starboard\n40,?,12.5,port\n60,,8,-1\n");
  write(folder + "/bounds.yaml", "heading: 0.01\ndepth_relative: 0.1\n");
  const CommandResult r = run_gesmi({"import", "nav", folder + "/nav.csv", "--gps", folder + "/gps.csv", "--marks",
                                     folder + "/marks.csv", "--config", folder + "/bounds.yaml", "--mines", "2", "-o",
                                     folder + "/m.h5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("101 samples over 100 s, 2 GPS fixes, 3 marks, 2 mines"), std::string::npos) << r.out;
  const Mission m = io::read_mission(folder + "/m.h5");
  EXPECT_EQ(m.origin.latitude, 48.212920614);
  EXPECT_EQ(m.origin.longitude, -4.458227931);
  EXPECT_NEAR(m.gps_north[0], 0.0, 1e-9);
  EXPECT_EQ(m.model.heading, 0.01);
  EXPECT_EQ(m.model.depth_relative, 0.1);
  EXPECT_EQ(m.half_widths.depth, std::vector<double>(101, 1.0));
  EXPECT_EQ(m.mark_mine, (std::vector<std::int32_t>{1, -1, -1}));
  EXPECT_EQ(m.mark_side, (std::vector<std::int32_t>{1, -1, -1}));
  EXPECT_FALSE(m.has_truth());
}

TEST(CmdImport, MarksReplaceTheTableAndMayGrowTheMineCountOnRequest) {
  const std::string folder = temp_folder("cmd-import");
  const std::string mission = folder + "/sim.h5";
  ASSERT_EQ(run_gesmi({"import", "gesmi-txt", source_dir() + "/missions/gesmi_txt/redermor_start.txt", "-o", mission}).exit_code, 0);
  write(folder + "/marks.csv", "time,mine,range,side\n10,2,30,starboard\n20,?,45,port\n");
  // No mines yet: the table's largest mine number + 1.
  CommandResult r = run_gesmi({"import", "marks", folder + "/marks.csv", "--into", mission, "-o", folder + "/out.h5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3 mines"), std::string::npos) << r.out;
  EXPECT_EQ(io::read_mission(folder + "/out.h5").mine_count, 3);
  // A mission with mines refuses a number beyond them (a typo is not a new mine)...
  write(folder + "/typo.csv", "time,mine,range,side\n10,7,30,starboard\n");
  r = run_gesmi({"import", "marks", folder + "/typo.csv", "--into", folder + "/out.h5", "-o", folder + "/typo.h5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("mine: unknown mine 7: the mission's mines are 0..2"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/typo.h5"));
  // ...and --mines still decides on a mission without mines.
  r = run_gesmi({"import", "marks", folder + "/marks.csv", "--into", mission, "--mines", "2", "-o", folder + "/two.h5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("mine: unknown mine 2: the mission's mines are 0..1"), std::string::npos) << r.err;
  // Writing over the input is refused (the same file, whatever the path says), the input intact.
  r = run_gesmi({"import", "marks", folder + "/marks.csv", "--into", mission, "--mines", "3", "-o", folder + "/./sim.h5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is also an input of this command"), std::string::npos) << r.err;
  EXPECT_EQ(io::read_mission(mission).mine_count, 0);
  const std::string updated = folder + "/updated.h5";
  r = run_gesmi({"import", "marks", folder + "/marks.csv", "--into", mission, "--mines", "3", "-o", updated});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Mission m = io::read_mission(updated);
  EXPECT_EQ(m.mine_count, 3);
  EXPECT_EQ(m.mark_time, (std::vector<double>{10.0, 20.0}));
  EXPECT_EQ(m.mark_range, (std::vector<double>{30.0, 45.0}));
  // Replacing again with an empty table.
  write(folder + "/none.csv", "time,mine,range,side\n");
  ASSERT_EQ(run_gesmi({"import", "marks", folder + "/none.csv", "--into", updated, "-o", folder + "/empty.h5"}).exit_code, 0);
  EXPECT_EQ(io::read_mission(folder + "/empty.h5").mark_count(), 0u);
}

TEST(CmdImport, MarksOnASimulatedMissionDropThePerMarkTruth) {
  const std::string folder = temp_folder("cmd-import");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "1", "--duration", "1200", "-o", folder + "/sim.h5"}).exit_code, 0);
  write(folder + "/marks.csv", "time,mine,range,side\n100,5,30,starboard\n");
  ASSERT_EQ(run_gesmi({"import", "marks", folder + "/marks.csv", "--into", folder + "/sim.h5", "-o", folder + "/m.h5"}).exit_code, 0);
  const Mission m = io::read_mission(folder + "/m.h5");
  EXPECT_EQ(m.mark_count(), 1u);
  EXPECT_TRUE(m.truth_marks_mine.empty());
  EXPECT_TRUE(m.has_truth());  // the trajectory and the mines stay
  EXPECT_EQ(m.truth_mines.size(), 18u);
}

TEST(CmdImport, GesmiTextSampleInBothReadingsOfXY) {
  const std::string folder = temp_folder("cmd-import");
  const std::string sample = source_dir() + "/missions/gesmi_txt/redermor_start.txt";
  CommandResult r = run_gesmi({"import", "gesmi-txt", sample, "--origin", "48.2,-4.45", "-o", folder + "/fixes.h5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("300 samples over 29.9 s, 2 GPS fixes, 0 marks, 0 mines"), std::string::npos) << r.out;
  const Mission fixes = io::read_mission(folder + "/fixes.h5");
  EXPECT_EQ(fixes.origin.latitude, 48.2);
  EXPECT_EQ(fixes.gps_given_north_halfwidth.size(), 2u);
  EXPECT_EQ(fixes.half_widths.vx.size(), 300u);

  // --xy truth on the sample: its x, y are NaN between the fixes, so it is refused
  // with the first such line.
  r = run_gesmi({"import", "gesmi-txt", sample, "--xy", "truth", "-o", folder + "/truth.h5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("redermor_start.txt:5: x: needed as ground truth"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/truth.h5"));
}

TEST(CmdImport, UsageNamesTheKinds) {
  const CommandResult r = run_gesmi({"import", "json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("expected marks, nav or gesmi-txt"), std::string::npos) << r.err;
  EXPECT_EQ(run_gesmi({"import", "nav", "--help"}).exit_code, 0);
}

}  // namespace
}  // namespace gesmi::test
