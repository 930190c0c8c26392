// Every reader of gesmi import / export / solve refuses bad input through the
// binary with exit code 2, one line on stderr naming the file, the line or
// dataset, the field and the reason, and writes nothing: the output path does not
// exist afterwards and no temporary file is left beside it.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "tests/support/h5py_edits.h"
#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

const std::string kNavHeader = "time,roll,pitch,heading,vx,vy,vz,altitude,depth\n";
const std::string kNav = kNavHeader + "0,0,0,0,1.5,0,0,12,5\n0.1,0,0,0,1.5,0,0,12,5\n0.2,0,0,0,1.5,0,0,12,5\n";
const std::string kGps = "time,longitude,latitude\n0,-4.458227931,48.212920614\n0.2,-4.458227,48.212922\n";
const std::string kMarks = "time,mine,range,side\n0.1,0,20,starboard\n";
const std::string kTxtRow = " 0 1e-4 0 1e-4 0.5 5e-3 1.5 0.01 0 0.01 0 0.01 5 2.5 12 0.1 nan nan nan nan\n";

struct Case {
  const char* title;
  std::map<std::string, std::string> files;  // name -> content, written in the case's folder
  std::vector<std::string> args;             // "@" is replaced by the folder
  std::vector<std::string> must_name;        // substrings of the one error line
};

std::string in_folder(const std::string& arg, const std::string& folder) {
  std::string out = arg;
  for (std::size_t at = out.find('@'); at != std::string::npos; at = out.find('@', at + folder.size()))
    out.replace(at, 1, folder);
  return out;
}

// A short simulated mission shared by the HDF5 cases, and a truncated copy.
const std::string& simulated_mission() {
  static const std::string path = [] {
    const std::string p = temp_folder("bad-input-mission") + "/sim.h5";
    const CommandResult r = run_gesmi({"simulate", "--seed", "2", "--duration", "600", "-o", p});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    fs::copy_file(p, p + ".truncated.h5");
    fs::resize_file(p + ".truncated.h5", fs::file_size(p) / 3);
    return p;
  }();
  return path;
}

void run_case(const Case& c, const std::string& output_name = "out.h5") {  // "-o" in c.args overrides
  SCOPED_TRACE(c.title);
  const std::string folder = temp_folder("bad-input");
  for (const auto& [name, content] : c.files) std::ofstream(folder + "/" + name, std::ios::binary) << content;
  std::vector<std::string> args;
  for (const std::string& a : c.args) args.push_back(in_folder(a, folder));
  if (std::find(args.begin(), args.end(), "-o") == args.end()) {
    args.push_back("-o");
    args.push_back(folder + "/" + output_name);
  }
  const CommandResult r = run_gesmi(args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  for (const std::string& s : c.must_name) EXPECT_NE(r.err.find(in_folder(s, folder)), std::string::npos) << "wanted '" << s << "' in: " << r.err;
  // Nothing written: only the inputs are in the folder.
  for (const auto& entry : fs::directory_iterator(folder))
    EXPECT_TRUE(c.files.count(entry.path().filename().string())) << "left behind: " << entry.path();
}

TEST(BadInput, ImportNavNamesFileLineFieldAndReason) {
  const Case cases[] = {
      {"empty nav", {{"nav.csv", ""}}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"}, {"@/nav.csv:1: header: the file is empty"}},
      {"missing nav file", {}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"}, {"@/nav.csv: cannot open the file"}},
      {"wrong header", {{"nav.csv", "t,roll\n"}}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"}, {"@/nav.csv:1: header: expected 'time,roll,pitch"}},
      {"missing column", {{"nav.csv", kNavHeader + "0,0,0,0,1.5,0,0,12,5\n0.1,0,0,0,1.5,0,0,12\n"}}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"},
       {"@/nav.csv:3: depth: missing column"}},
      {"not a number", {{"nav.csv", kNavHeader + "0,0,0,0,1.5,0,0,12,5\n0.1,0,0,north,1.5,0,0,12,5\n"}}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"},
       {"@/nav.csv:3: heading: expected a number, found 'north'"}},
      {"NaN", {{"nav.csv", kNavHeader + "0,0,0,0,1.5,0,0,12,5\n0.1,0,nan,0,1.5,0,0,12,5\n"}}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"},
       {"@/nav.csv:3: pitch: is NaN"}},
      {"Inf", {{"nav.csv", kNavHeader + "0,0,0,0,1.5,0,0,12,5\n0.1,0,0,0,1.5,-inf,0,12,5\n"}}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"},
       {"@/nav.csv:3: vy: is infinite"}},
      {"time goes back", {{"nav.csv", kNav + "0.15,0,0,0,1.5,0,0,12,5\n"}}, {"import", "nav", "@/nav.csv", "--origin", "48,-4"},
       {"@/nav.csv:5: time: 0.15 s does not increase (0.2 s on line 4)"}},
      {"no origin", {{"nav.csv", kNav}}, {"import", "nav", "@/nav.csv"}, {"give --origin LAT,LON"}},
      {"bad origin", {{"nav.csv", kNav}}, {"import", "nav", "@/nav.csv", "--origin", "48"}, {"--origin: expected LAT,LON"}},
      {"origin at the pole", {{"nav.csv", kNav}}, {"import", "nav", "@/nav.csv", "--origin", "90,0"}, {"--origin: latitude must be in [-89, 89]"}},
      {"empty gps", {{"nav.csv", kNav}, {"gps.csv", ""}}, {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv"}, {"@/gps.csv:1: header: the file is empty"}},
      {"gps time goes back", {{"nav.csv", kNav}, {"gps.csv", "time,longitude,latitude\n0.2,-4.4,48.2\n0.1,-4.4,48.2\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv"}, {"@/gps.csv:3: time: 0.1 s does not increase (0.2 s on line 2)"}},
      {"gps far away", {{"nav.csv", kNav}, {"gps.csv", kGps}}, {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--origin", "49.2,-4.458"},
       {"@/gps.csv:2: longitude, latitude: the fix is", "beyond the 100 km zone of the local frame: import the log again with an origin nearer the mission"}},
      {"gps missing latitude", {{"nav.csv", kNav}, {"gps.csv", "time,longitude,latitude\n0,-4.4\n"}}, {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv"},
       {"@/gps.csv:2: latitude: missing column"}},
      {"empty marks", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"marks.csv", ""}}, {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--marks", "@/marks.csv", "--mines", "1"},
       {"@/marks.csv:1: header: the file is empty"}},
      {"mark outside the mission", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"marks.csv", "time,mine,range,side\n5,0,20,port\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--marks", "@/marks.csv", "--mines", "1"}, {"@/marks.csv:2: time: 5 s is outside the mission [0, 0.2] s"}},
      {"unknown side", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"marks.csv", "time,mine,range,side\n0.1,0,20,left\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--marks", "@/marks.csv", "--mines", "1"}, {"@/marks.csv:2: side: expected starboard, port, +1 or -1, found 'left'"}},
      {"unknown mine", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"marks.csv", kMarks}}, {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--marks", "@/marks.csv", "--mines", "0"},
       {"@/marks.csv:2: mine: unknown mine 0: the mission has no mines"}},
      {"range beyond the sonar", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"marks.csv", "time,mine,range,side\n0.1,?,90,starboard\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--marks", "@/marks.csv"}, {"@/marks.csv:2: range: 90 m is beyond the sonar's maximum range"}},
      {"mark row short", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"marks.csv", "time,mine,range,side\n0.1,?,20\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--marks", "@/marks.csv"}, {"@/marks.csv:2: side: missing column"}},
      {"unknown YAML key", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"bounds.yaml", "heading: 0.01\nspeed_of_sound: 1500\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--config", "@/bounds.yaml"}, {"@/bounds.yaml:2: unknown key 'speed_of_sound'"}},
      {"bad YAML value", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"bounds.yaml", "heading: fast\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--config", "@/bounds.yaml"}, {"@/bounds.yaml:1: heading: expected a number"}},
      {"truth rows", {{"nav.csv", kNav}, {"gps.csv", kGps}, {"truth.csv", "time,north,east,down\n0,0,0,5\n"}},
       {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--truth", "@/truth.csv"}, {"@/truth.csv:2: no row at the navigation sample 1 (0.1 s)"}},
      {"mines out of range", {{"nav.csv", kNav}, {"gps.csv", kGps}}, {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "--mines", "65"}, {"--mines: must be between 0 and 64"}},
      {"output folder missing", {{"nav.csv", kNav}, {"gps.csv", kGps}}, {"import", "nav", "@/nav.csv", "--gps", "@/gps.csv", "-o", "@/no/such/folder/out.h5"},
       {"folder @/no/such/folder does not exist"}},
  };
  for (const Case& c : cases) run_case(c);
}

// Integers outside an option's range are refused, never wrapped or truncated into it.
TEST(BadInput, IntegerOptionsOutsideTheirRangeAreRefused) {
  const std::string scenario = source_dir() + "/missions/localization/seed000_asymmetric.yaml";
  const std::vector<Case> cases = {
      {"outliers below int", {}, {"simulate", "--seed", "1", "--duration", "600", "--outliers", "-2147483649"}, {"--outliers must be >= 0"}},
      {"mines beyond int", {}, {"simulate", "--seed", "1", "--duration", "600", "--mines", "4294967297"}, {"--mines must be between 0 and 64"}},
      {"bursts beyond int", {}, {"simulate", "--seed", "1", "--duration", "600", "--bursts", "4294967297"}, {"--bursts must be between 0 and 1000"}},
      {"integer beyond long", {}, {"simulate", "--seed", "1", "--outliers", "99999999999999999999"}, {"--outliers: expected an integer"}},
      {"bias share", {}, {"simulate", "--seed", "1", "--errors", "bias-noise", "--bias-share", "1.5"}, {"--bias-share must be in [0, 1]"}},
      {"drift alone", {}, {"simulate", "--seed", "1", "--drift", "ramp"}, {"--drift: goes with --errors bias-noise"}},
      {"unknown drift", {}, {"simulate", "--seed", "1", "--errors", "bias-noise", "--drift", "sine"}, {"--drift: expected none, ramp or flip, got 'sine'"}},
      {"unknown errors", {}, {"simulate", "--seed", "1", "--errors", "bias"}, {"--errors: expected uniform, worst-case, at-samples, drifting, corners or bias-noise, got 'bias'"}},
      {"localize seed negative", {}, {"localize", scenario, "--simulate", "--seed", "-1"}, {"--seed: must be between 0 and 4294967295"}},
      {"localize seed beyond 32 bits", {}, {"localize", scenario, "--simulate", "--seed", "4294967296"}, {"--seed: must be between 0 and 4294967295"}},
  };
  for (const Case& c : cases) run_case(c, c.args[0] == std::string("localize") ? "out" : "out.h5");
}

// Options that cannot go together are refused before any input is read (the --from
// result here is not even a result).
TEST(BadInput, SolveOptionsThatCannotGoTogetherAreRefusedFirst) {
  const std::string mission = simulated_mission();
  const std::vector<Case> cases = {
      {"from with max-outliers", {}, {"solve", mission, "--from", mission, "--max-outliers", "1"},
       {"--from and --max-outliers cannot be combined"}},
      {"both outlier modes", {}, {"solve", mission, "--max-outliers", "1", "--minimal-outliers", "1"},
       {"--max-outliers and --minimal-outliers cannot be combined"}},
      {"trust-gps alone", {}, {"solve", mission, "--trust-gps"}, {"--trust-gps goes with --max-outliers or --minimal-outliers"}},
  };
  for (const Case& c : cases) run_case(c);
}

// Through the gesmi command: every kind of reader refuses a pipe at once (a reader that
// opened it would wait for a writer that never comes; the test's timeout would end it).
TEST(BadInput, EveryReaderRefusesAPipeAndADevice) {
  const std::string folder = temp_folder("input-pipe");
  const std::string pipe = folder + "/pipe";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  const std::vector<std::vector<std::string>> commands = {
      {"import", "nav", pipe, "--origin", "48,-4", "-o", folder + "/m.h5"},
      {"import", "gesmi-txt", "/dev/urandom", "-o", folder + "/m.h5"},
      {"solve", pipe, "-o", folder + "/r.h5"},
      {"kalman", "/dev/zero", "-o", folder + "/k.h5"},
      {"localize", "/dev/zero", "-o", folder + "/out"},
      {"waterfall", pipe, "-o", folder + "/w.png"},
  };
  for (const auto& args : commands) {
    const CommandResult r = run_gesmi(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(", not a file: gesmi reads its inputs from files"), std::string::npos) << r.err;
  }
}

TEST(BadInput, ImportGesmiTxtNamesLineFieldAndReason) {
  const Case cases[] = {
      {"empty log", {{"log.txt", ""}}, {"import", "gesmi-txt", "@/log.txt"}, {"@/log.txt:1: no data row (rows of 21 numbers"}},
      {"only headers", {{"log.txt", "Redermor\nt phi dphi\n"}}, {"import", "gesmi-txt", "@/log.txt"}, {"@/log.txt:2: no data row"}},
      {"short row", {{"log.txt", "header\n0" + kTxtRow + "0.1 0 1e-4 0 1e-4\n"}}, {"import", "gesmi-txt", "@/log.txt"},
       {"@/log.txt:3: expected 21 numbers", "found 5 fields"}},
      {"NaN value", {{"log.txt", "0" + kTxtRow + "0.1 0 1e-4 nan 1e-4 0.5 5e-3 1.5 0.01 0 0.01 0 0.01 5 2.5 12 0.1 nan nan nan nan\n"}},
       {"import", "gesmi-txt", "@/log.txt"}, {"@/log.txt:2: pitch: is NaN"}},
      {"time goes back", {{"log.txt", "1" + kTxtRow + "0.5" + kTxtRow}}, {"import", "gesmi-txt", "@/log.txt"}, {"@/log.txt:2: t: 0.5 s does not increase (1 s on line 1)"}},
      {"word in a row", {{"log.txt", "0" + kTxtRow + "0.1 0 1e-4 0 1e-4 0.5 5e-3 fast 0.01 0 0.01 0 0.01 5 2.5 12 0.1 nan nan nan nan\n"}},
       {"import", "gesmi-txt", "@/log.txt"}, {"@/log.txt:2: vx: expected a number, found 'fast'"}},
      {"unknown xy reading", {{"log.txt", "0" + kTxtRow + "0.1" + kTxtRow}}, {"import", "gesmi-txt", "@/log.txt", "--xy", "both"}, {"--xy: expected fixes or truth"}},
      {"truth needs x", {{"log.txt", "0" + kTxtRow + "0.1" + kTxtRow}}, {"import", "gesmi-txt", "@/log.txt", "--xy", "truth"}, {"@/log.txt:1: x: needed as ground truth, found nan"}},
  };
  for (const Case& c : cases) run_case(c);
}

TEST(BadInput, ImportMarksChecksEveryRowAgainstTheMission) {
  const std::string mission = simulated_mission();
  const Case cases[] = {
      {"outside the mission", {{"marks.csv", "time,mine,range,side\n601,0,20,port\n"}}, {"import", "marks", "@/marks.csv", "--into", mission},
       {"@/marks.csv:2: time: 601 s is outside the mission [0, 600] s"}},
      {"unknown mine", {{"marks.csv", "time,mine,range,side\n10,6,20,port\n"}}, {"import", "marks", "@/marks.csv", "--into", mission},
       {"@/marks.csv:2: mine: unknown mine 6: the mission's mines are 0..5"}},
      {"unknown side", {{"marks.csv", "time,mine,range,side\n10,?,20,up\n"}}, {"import", "marks", "@/marks.csv", "--into", mission}, {"@/marks.csv:2: side: expected starboard"}},
      {"negative range", {{"marks.csv", "time,mine,range,side\n10,?,-3,port\n"}}, {"import", "marks", "@/marks.csv", "--into", mission}, {"@/marks.csv:2: range: -3 m is negative"}},
      {"empty file", {{"marks.csv", ""}}, {"import", "marks", "@/marks.csv", "--into", mission}, {"@/marks.csv:1: header: the file is empty"}},
      {"mines against the truth", {{"marks.csv", kMarks}}, {"import", "marks", "@/marks.csv", "--into", mission, "--mines", "8"},
       {"--mines: 8 differs from the 6 mines of the mission's truth"}},
      {"truncated mission", {{"marks.csv", kMarks}}, {"import", "marks", "@/marks.csv", "--into", mission + ".truncated.h5"}, {mission + ".truncated.h5: ", "truncated"}},
      {"missing mission", {{"marks.csv", kMarks}}, {"import", "marks", "@/marks.csv", "--into", "@/none.h5"}, {"@/none.h5: cannot open the file"}},
  };
  for (const Case& c : cases) run_case(c);
}

TEST(BadInput, TruncatedOrForeignHdf5IsRefusedBySolveAndExport) {
  const std::string mission = simulated_mission();
  const Case cases[] = {
      {"solve truncated", {}, {"solve", mission + ".truncated.h5"}, {mission + ".truncated.h5: ", "truncated"}},
      {"solve empty file", {{"empty.h5", ""}}, {"solve", "@/empty.h5"}, {"@/empty.h5: not an HDF5 file"}},
      {"solve a text file", {{"nav.h5", kNav}}, {"solve", "@/nav.h5"}, {"@/nav.h5: not an HDF5 file"}},
  };
  for (const Case& c : cases) run_case(c);
  const Case exports[] = {
      {"export truncated", {}, {"export", mission + ".truncated.h5"}, {mission + ".truncated.h5: ", "truncated"}},
      {"export missing", {}, {"export", "@/none.h5"}, {"@/none.h5: cannot open the file"}},
      {"export a text file as gesmi-txt", {{"nav.h5", kNav}}, {"export", "@/nav.h5", "--format", "gesmi-txt"}, {"@/nav.h5: not an HDF5 file"}},
      {"unknown format", {}, {"export", mission, "--format", "json"}, {"--format: expected csv, logger, gesmi-txt, tube-csv, mines-csv or geojson"}},
  };
  for (const Case& c : exports) run_case(c, "csv");
  // Valid HDF5 with a missing dataset or a wrong shape, edited by Debian's h5py.
  const std::vector<std::string> copies = h5py_edited_copies(
      mission, {"del f['/nav/depth']", "f['/gps/halfwidth'] = np.ones((2, 3))", "f['/marks/time'][0] = np.nan"});
  const std::string& no_depth = copies[0];
  run_case({"missing dataset", {}, {"export", no_depth}, {no_depth + ": /nav/depth: missing dataset"}}, "csv");
  run_case({"missing dataset (solve)", {}, {"solve", no_depth}, {no_depth + ": /nav/depth: missing dataset"}});
  const std::string& bad_bounds = copies[1];
  run_case({"wrong shape", {}, {"export", bad_bounds}, {bad_bounds + ": /gps/halfwidth: expected 2 x 2"}}, "csv");
  const std::string& nan_time = copies[2];
  run_case({"NaN in a dataset", {}, {"export", nan_time, "--format", "gesmi-txt"}, {nan_time + ": /marks/time: row 0"}}, "log.txt");
  // A folder that is not empty is refused before anything is read.
  run_case({"export into a full folder", {{"keep.txt", "x"}}, {"export", mission, "-o", "@"}, {"the folder exists and is not empty"}});
}

}  // namespace
}  // namespace gesmi::test
