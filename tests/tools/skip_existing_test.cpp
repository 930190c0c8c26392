// --skip-existing on every command that writes outputs (docs/batch.md): when all of a
// command's outputs exist it says so, exits 0 and leaves them alone (even a file that
// is not what the command would write: existence is the test); when one is missing it
// runs.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

void put(const std::string& path, const std::string& text) { std::ofstream(path) << text; }
void expect_skipped(const std::vector<std::string>& args, const std::vector<std::string>& outputs) {
  for (const std::string& o : outputs) put(o, "placeholder");
  std::vector<std::string> with = args;
  with.push_back("--skip-existing");
  const CommandResult r = run_gesmi(with);
  EXPECT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
  EXPECT_NE(r.out.find("skipped (--skip-existing)"), std::string::npos) << args[0] << ": " << r.out;
  for (const std::string& o : outputs) EXPECT_EQ(file_text(o), "placeholder") << o;
}

TEST(SkipExisting, EveryWritingCommandSkipsWhenItsOutputsExist) {
  const std::string d = temp_folder("skip-existing");
  const std::string mission = d + "/m.h5", result = d + "/r.h5";
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "3", "--duration", "60", "-o", mission}).exit_code, 0);
  ASSERT_EQ(run_gesmi({"solve", mission, "-o", result}).exit_code, 0);
  put(d + "/marks.csv", "time,mine,range,side\n10,0,20,starboard\n");
  expect_skipped({"simulate", "--seed", "3", "-o", d + "/s.h5"}, {d + "/s.h5"});
  expect_skipped({"solve", mission, "-o", d + "/r2.h5", "--png"}, {d + "/r2.h5", d + "/r2.envelope.png"});
  expect_skipped({"kalman", mission, "-o", d + "/k.h5"}, {d + "/k.h5"});
  expect_skipped({"waterfall", result, "-o", d + "/w.png"}, {d + "/w.png"});
  expect_skipped({"import", "marks", d + "/marks.csv", "--into", mission, "-o", d + "/i.h5"}, {d + "/i.h5"});
  put(d + "/nav.csv", "time,roll,pitch,heading,vx,vy,vz,altitude,depth\n0,0,0,0,1,0,0,5,10\n0.1,0,0,0,1,0,0,5,10\n");
  expect_skipped({"import", "nav", d + "/nav.csv", "--origin", "48.2,-4.4", "-o", d + "/n.h5"}, {d + "/n.h5"});
  put(d + "/log.txt", "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");
  expect_skipped({"import", "gesmi-txt", d + "/log.txt", "-o", d + "/g.h5"}, {d + "/g.h5"});
  fs::create_directories(d + "/loc");
  std::vector<std::string> files;
  for (const char* f : {"inner.csv", "boundary.csv", "components.csv", "summary.txt", "summary.json", "paving.h5", "paving.png"})
    files.push_back(d + "/loc/" + f);
  expect_skipped({"localize", source_dir() + "/missions/localization/triangle_two_hypotheses.yaml", "-o", d + "/loc"},
                 files);
  fs::create_directories(d + "/est");
  expect_skipped({"estimate", source_dir() + "/missions/setinv/seed004_example2.yaml", "-o", d + "/est"},
                 {d + "/est/summary.txt", d + "/est/summary.json", d + "/est/boxes.csv"});
  expect_skipped({"export", result, "--format", "tube-csv", "-o", d + "/t.csv"}, {d + "/t.csv"});
  expect_skipped({"export", mission, "--format", "gesmi-txt", "-o", d + "/m.txt"}, {d + "/m.txt"});
  // A folder export is renamed into place whole: its import-command.txt stands for it.
  fs::create_directories(d + "/csv");
  expect_skipped({"export", mission, "-o", d + "/csv"}, {d + "/csv/import-command.txt"});
  fs::create_directories(d + "/demo");
  files.clear();
  for (const char* f : {"mission.h5", "result.h5", "result.envelope.png", "waterfall.png", "result.mines.csv", "result.geojson"})
    files.push_back(d + "/demo/" + f);
  expect_skipped({"demo", "-o", d + "/demo"}, files);
}

TEST(SkipExisting, AFolderExportWithoutItsLastFileIsNotSkipped) {
  const std::string d = temp_folder("skip-export");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "3", "--duration", "60", "-o", d + "/m.h5"}).exit_code, 0);
  fs::create_directories(d + "/csv");
  put(d + "/csv/nav.csv", "placeholder");
  const CommandResult r = run_gesmi({"export", d + "/m.h5", "-o", d + "/csv", "--skip-existing"});
  EXPECT_EQ(r.exit_code, 2) << r.err;  // not skipped: the folder is not empty, as without the option
  EXPECT_NE(r.err.find("not empty"), std::string::npos) << r.err;
}

TEST(SkipExisting, WhatWouldBeAnErrorStaysOne) {
  // The outputs and options are checked before the skip: an output that is an input, a
  // folder, or a bad option still exits 2 with one line.
  const std::string d = temp_folder("skip-existing");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "3", "--duration", "60", "-o", d + "/m.h5"}).exit_code, 0);
  put(d + "/marks.csv", "time,mine,range,side\n10,0,20,starboard\n");
  fs::create_directories(d + "/folder");
  const std::vector<std::vector<std::string>> cases = {
      {"import", "marks", d + "/marks.csv", "--into", d + "/m.h5", "-o", d + "/m.h5"},
      {"solve", d + "/m.h5", "-o", d + "/m.h5"},
      {"solve", d + "/m.h5", "-o", d + "/folder"},
      {"simulate", "--seed", "3", "--preset", "bogus", "-o", d + "/m.h5"}};
  for (std::vector<std::string> args : cases) {
    args.push_back("--skip-existing");
    const CommandResult r = run_gesmi(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << " " << args[1] << ": " << r.out;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_EQ(r.out.find("skipped"), std::string::npos) << r.out;
  }
}

TEST(SkipExisting, AMissingOutputIsWritten) {
  const std::string d = temp_folder("skip-existing");
  // The result exists but the picture asked for does not: the solve runs.
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "3", "--duration", "60", "-o", d + "/m.h5"}).exit_code, 0);
  put(d + "/r.h5", "placeholder");
  const CommandResult r = run_gesmi({"solve", d + "/m.h5", "-o", d + "/r.h5", "--png", "--skip-existing"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("skipped"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(d + "/r.envelope.png"));
  EXPECT_NE(file_text(d + "/r.h5"), "placeholder");
}

}  // namespace
}  // namespace gesmi::test
