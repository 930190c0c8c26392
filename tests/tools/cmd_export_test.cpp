// gesmi export -> gesmi import round trip through the binary: the command written
// to import-command.txt rebuilds the mission, whose export is byte-identical and
// which the solver accepts; the GESMI text export reads back with gesmi import.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/files/mission_file.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

// The words of import-command.txt, with the folder's file names made absolute.
std::vector<std::string> import_command(const std::string& folder, const std::string& output) {
  std::istringstream words(file_text(folder + "/import-command.txt"));
  std::string word;
  words >> word;
  EXPECT_EQ(word, "gesmi");
  std::vector<std::string> args;
  while (words >> word) {
    if (word == "mission.h5") word = output;
    else if (fs::exists(folder + "/" + word)) word = folder + "/" + word;
    args.push_back(word);
  }
  return args;
}

TEST(CmdExport, ImportCommandRebuildsTheMissionAndTheExportIsIdentical) {
  const std::string folder = temp_folder("cmd-export");
  const std::string original = folder + "/sim.h5";
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "900", "--unassociated", "0.5", "-o", original}).exit_code, 0);
  const CommandResult exported = run_gesmi({"export", original, "-o", folder + "/csv"});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("nav.csv (9001 rows)"), std::string::npos) << exported.out;

  const CommandResult imported = run_gesmi(import_command(folder + "/csv", folder + "/back.h5"));
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  ASSERT_EQ(run_gesmi({"export", folder + "/back.h5", "-o", folder + "/csv2"}).exit_code, 0);
  for (const char* file : {"nav.csv", "gps.csv", "marks.csv", "truth.csv", "truth_mines.csv", "model.yaml", "import-command.txt"})
    EXPECT_EQ(file_text(folder + "/csv/" + file), file_text(folder + "/csv2/" + file)) << file;

  // Same mission for the solver: identical navigation, fixes and marks.
  const Mission a = io::read_mission(original), b = io::read_mission(folder + "/back.h5");
  EXPECT_EQ(a.heading, b.heading);
  EXPECT_EQ(a.gps_north, b.gps_north);
  EXPECT_EQ(a.gps_north_halfwidth, b.gps_north_halfwidth);
  EXPECT_EQ(a.heading_frame_margin, b.heading_frame_margin);
  EXPECT_EQ(a.mark_mine, b.mark_mine);
  EXPECT_EQ(a.truth_x, b.truth_x);
  const CommandResult solved = run_gesmi({"solve", folder + "/back.h5", "-o", folder + "/result.h5"});
  EXPECT_EQ(solved.exit_code, 0) << solved.err;
}

TEST(CmdExport, GesmiTextExportReadsBackWithImport) {
  const std::string folder = temp_folder("cmd-export");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "5", "--duration", "60", "-o", folder + "/sim.h5"}).exit_code, 0);
  const CommandResult exported = run_gesmi({"export", folder + "/sim.h5", "--format", "gesmi-txt", "-o", folder + "/log.txt"});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("601 rows, 2 position fixes"), std::string::npos) << exported.out;
  const CommandResult imported = run_gesmi({"import", "gesmi-txt", folder + "/log.txt", "-o", folder + "/back.h5"});
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  const Mission a = io::read_mission(folder + "/sim.h5"), b = io::read_mission(folder + "/back.h5");
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.vx, b.vx);
  ASSERT_EQ(b.gps_time, a.gps_time);
  for (std::size_t i = 0; i < a.gps_time.size(); ++i) EXPECT_NEAR(b.gps_north[i], a.gps_north[i], 1e-6);
  EXPECT_EQ(b.gps_given_north_halfwidth.size(), 2u);  // the boxes travel with the fixes
}

TEST(CmdExport, HelpListsTheFormats) {
  const CommandResult r = run_gesmi({"export", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("gesmi-txt"), std::string::npos);
}

}  // namespace
}  // namespace gesmi::test
