// gesmi kalman and tools/compare_kalman.py through their command lines.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/hdf5/h5_file.h"
#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

TEST(CmdKalman, WritesTheDocumentedDatasetsAndStats) {
  const std::string dir = temp_folder("kalman");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "1200", "-o", dir + "/m.h5"}).exit_code, 0);
  const CommandResult r = run_gesmi({"kalman", dir + "/m.h5", "-o", dir + "/k.h5", "--stats"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"timings_ms\""), std::string::npos);
  EXPECT_NE(r.out.find("\"containment_3sigma_horizontal\""), std::string::npos);
  // The truth, read after the smoothing, gives every containment figure (null without it).
  for (const char* key : {"horizontal", "vertical", "mines", "mines_plane"}) {
    const std::string name = std::string("\"containment_") + (std::string(key).rfind("mines", 0) == 0 ? "" : "3sigma_") + key;
    EXPECT_NE(r.out.find(name + "\":"), std::string::npos) << name;
    EXPECT_EQ(r.out.find(name + "\":null"), std::string::npos) << name;
  }
  const io::H5File f = io::H5File::open_read(dir + "/k.h5");
  const io::H5Shape mean = f.shape("/kalman/mean");
  EXPECT_EQ(mean.rows, 12001u);
  EXPECT_EQ(mean.columns, 3u);
  EXPECT_EQ(f.shape("/time").rows, 12001u);
  EXPECT_EQ(f.shape("/kalman/mines/mean").rows, 6u);
  // The covariances are N x 3 x 3 (read by h5py, as a user would).
  const std::string command = "/usr/bin/python3 -c \"import h5py,sys; f=h5py.File(sys.argv[1]); "
                              "sys.exit(0 if f['/kalman/cov'].shape == (12001, 3, 3) and f['/kalman/mines/cov'].shape == (6, 3, 3) else 1)\" " +
                              dir + "/k.h5";
  EXPECT_EQ(std::system(command.c_str()), 0);
}

// A tolerance never met: the command stops at the rounding floor, says so in a note on
// stderr (not a warning), and records it in the file and the report.
TEST(CmdKalman, SaysWhenItStoppedAtTheRoundingFloor) {
  const std::string dir = temp_folder("kalman-stall");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "600", "-o", dir + "/m.h5"}).exit_code, 0);
  const CommandResult r = run_gesmi({"kalman", dir + "/m.h5", "-o", dir + "/k.h5", "--tolerance", "0", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("note: stopped after"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("\"stalled\":true"), std::string::npos) << r.out;
  const io::H5File f = io::H5File::open_read(dir + "/k.h5");
  EXPECT_EQ(f.int_attribute("/", "stalled"), std::optional<std::int64_t>(1));
  EXPECT_EQ(f.int_attribute("/", "converged"), std::optional<std::int64_t>(0));
  const CommandResult capped =
      run_gesmi({"kalman", dir + "/m.h5", "-o", dir + "/k2.h5", "--tolerance", "0", "--stall-fraction", "0",
                 "--max-iterations", "4"});
  ASSERT_EQ(capped.exit_code, 0) << capped.err;
  EXPECT_NE(capped.err.find("warning: not converged after 4"), std::string::npos) << capped.err;
}

TEST(CmdKalman, RejectsBadOptionsAndWritesNothing) {
  const std::string dir = temp_folder("kalman-bad");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "300", "-o", dir + "/m.h5"}).exit_code, 0);
  const std::string out = dir + "/k.h5";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"kalman", dir + "/m.h5", "-o", out, "--noise-factor", "0"},
        std::vector<std::string>{"kalman", dir + "/m.h5", "-o", out, "--noise-factor", "x"},
        std::vector<std::string>{"kalman", dir + "/m.h5", "-o", out, "--stall-fraction", "1"},
        std::vector<std::string>{"kalman", dir + "/m.h5", "-o", out, "--stall-fraction", "-0.1"},
        std::vector<std::string>{"kalman", dir + "/missing.h5", "-o", out},
        std::vector<std::string>{"kalman", dir + "/m.h5", "-o", dir + "/no/such/folder/k.h5"}}) {
    const CommandResult r = run_gesmi(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(CompareKalman, WritesTheReportAndTheThreeFigures) {
  const std::string dir = temp_folder("compare");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "6", "--duration", "1200", "-o", dir + "/m.h5"}).exit_code, 0);
  ASSERT_EQ(run_gesmi({"solve", dir + "/m.h5", "-o", dir + "/r.h5"}).exit_code, 0);
  ASSERT_EQ(run_gesmi({"kalman", dir + "/m.h5", "-o", dir + "/k.h5"}).exit_code, 0);
  const std::string script = source_dir() + "/tools/compare_kalman.py";
  const std::string command = "/usr/bin/python3 " + script + " " + dir + "/m.h5 " + dir + "/r.h5 " + dir + "/k.h5 -o " +
                              dir + "/report > " + dir + "/out.txt 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  for (const char* name : {"report.md", "track.png", "mines.png", "widths.png"}) EXPECT_TRUE(fs::exists(dir + "/report/" + name)) << name;
  std::ifstream in(dir + "/report/report.md");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("| trajectory (horizontal) |"), std::string::npos);
  EXPECT_NE(text.str().find("| mine 5 |"), std::string::npos);
  // Files of different missions are refused with exit code 2.
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "6", "--duration", "600", "-o", dir + "/short.h5"}).exit_code, 0);
  ASSERT_EQ(run_gesmi({"kalman", dir + "/short.h5", "-o", dir + "/k_short.h5"}).exit_code, 0);
  const std::string mismatch = "/usr/bin/python3 " + script + " " + dir + "/m.h5 " + dir + "/r.h5 " + dir +
                               "/k_short.h5 -o " + dir + "/report2 > /dev/null 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(mismatch.c_str())), 2);
}

TEST(CompareKalman, RefusesAnInconsistentResultUnlessAskedAndThenSaysSo) {
  const std::string dir = temp_folder("compare_inconsistent");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "9", "--outliers", "1", "--duration", "2400", "-o", dir + "/m.h5"}).exit_code, 0);
  ASSERT_EQ(run_gesmi({"solve", dir + "/m.h5", "-o", dir + "/r.h5"}).exit_code, 3);
  ASSERT_EQ(run_gesmi({"kalman", dir + "/m.h5", "-o", dir + "/k.h5"}).exit_code, 0);
  const std::string command = "/usr/bin/python3 " + source_dir() + "/tools/compare_kalman.py " + dir + "/m.h5 " + dir +
                              "/r.h5 " + dir + "/k.h5 -o " + dir + "/report";
  EXPECT_EQ(WEXITSTATUS(std::system((command + " > " + dir + "/out.txt 2> " + dir + "/err.txt").c_str())), 3);
  std::ifstream err(dir + "/err.txt");
  std::stringstream why;
  why << err.rdbuf();
  EXPECT_EQ(line_count(why.str()), 1) << why.str();
  EXPECT_NE(why.str().find("--show-inconsistent"), std::string::npos) << why.str();
  EXPECT_FALSE(fs::exists(dir + "/report"));
  ASSERT_EQ(std::system((command + " --show-inconsistent > /dev/null 2>&1").c_str()), 0);
  std::ifstream in(dir + "/report/report.md");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("INCONSISTENT"), std::string::npos);
}

}  // namespace
}  // namespace gesmi::test
