// gesmi localize, run as a program: outputs of a good run, and bad inputs that give
// one line on stderr, exit code 2 and no output folder.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/hdf5/h5_file.h"
#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

std::string scenario(const std::string& name) { return source_dir() + "/missions/localization/" + name; }

TEST(LocalizeCli, WritesPavingsComponentsSummaryAndPicture) {
  const std::string out = temp_folder("localize") + "/triangle";
  const CommandResult r = run_gesmi({"localize", scenario("triangle_two_hypotheses.yaml"), "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("hypotheses (connected components): 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("holds the true pose"), std::string::npos) << r.out;
  for (const char* f : {"inner.csv", "boundary.csv", "components.csv", "summary.txt", "summary.json", "paving.h5", "paving.png"})
    EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
  EXPECT_EQ(file_text(out + "/summary.txt"), r.out);
  const std::string components = file_text(out + "/components.csv");
  EXPECT_EQ(line_count(components), 3);
  EXPECT_EQ(file_text(out + "/inner.csv").rfind("component,x_lo,x_hi,y_lo,y_hi,theta_lo_rad,theta_hi_rad\n", 0), 0u);
  // The HDF5 file holds the same boxes as the CSV files.
  const io::H5File h5 = io::H5File::open_read(out + "/paving.h5");
  EXPECT_EQ(static_cast<int>(h5.shape("/inner/boxes").rows) + 1, line_count(file_text(out + "/inner.csv")));
  EXPECT_EQ(static_cast<int>(h5.shape("/boundary/boxes").rows) + 1, line_count(file_text(out + "/boundary.csv")));
  EXPECT_EQ(h5.shape("/components/hull").rows, 2u);
  EXPECT_EQ(h5.string_attribute("/", "scenario").value_or(""), "triangle_two_hypotheses");
  // No temporary file is left behind.
  for (const auto& e : fs::directory_iterator(out)) EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos);
}

TEST(LocalizeCli, SimulatePrintsMeasurementsAndWritesNothing) {
  const CommandResult r = run_gesmi({"localize", scenario("belt24_outliers.yaml"), "--simulate", "--seed", "3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("measurements:\n", 0), 0u);
  EXPECT_EQ(line_count(r.out), 25);
}

TEST(LocalizeCli, NoEchoIsSimulatedSolvedAndNamed) {
  const CommandResult sim = run_gesmi({"localize", scenario("no_echo_doorway.yaml"), "--simulate", "--seed", "1"});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  EXPECT_NE(sim.out.find("{sensor: S2, range: none}"), std::string::npos) << sim.out;
  EXPECT_EQ(line_count(sim.out), 6);  // a "no echo" is a datum: one per sensor
  const std::string out = temp_folder("localize") + "/doorway";
  const CommandResult r = run_gesmi({"localize", scenario("no_echo_doorway.yaml"), "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("#2:S2:beyond"), std::string::npos) << r.out;
  const io::H5File h5 = io::H5File::open_read(out + "/paving.h5");
  const std::vector<double> range = h5.read_doubles("/data/range"), max_range = h5.read_doubles("/data/range_max_range");
  ASSERT_EQ(range.size(), 5u);
  EXPECT_EQ(range[1], std::numeric_limits<double>::infinity());
  EXPECT_EQ(max_range[1], 8.0);
  EXPECT_EQ(h5.read_doubles("/data/range_blind_distance")[0], 0.25);
}

struct BadRun {
  std::string text;        // scenario content ("" = use `file`)
  std::string file;        // existing scenario
  std::vector<std::string> extra;
  std::string must_name;
};

TEST(LocalizeCli, BadInputIsOneLineExitTwoAndNothingWritten) {
  const std::string dir = temp_folder("localize_bad");
  std::string valid = file_text(scenario("triangle_two_hypotheses.yaml"));
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string t = valid;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  const BadRun cases[] = {
      {with("half_aperture_deg: 12, precision: 0.02}\n  - {name: T2", "half_aperture_deg: 90, precision: 0.02}\n  - {name: T2"), "", {}, "half_aperture_deg"},
      {with("epsilon: 0.01", "epsilon: -1"), "", {}, "solver.epsilon"},
      {with("policy: fixed", "policy: sometimes"), "", {}, "outliers.policy"},
      {with("sensor: T3,", "sensor: T9,"), "", {}, "unknown sensor"},
      {"map: [unclosed\n", "", {}, "not valid YAML"},
      {"", "/no/such/scenario.yaml", {}, "cannot open"},
      {"", scenario("triangle_two_hypotheses.yaml"), {"--frobnicate"}, "frobnicate"},
      // The range model's options (docs/setinversion.md, 3.1).
      {with("{sensor: T1, range: 1.470557107}", "{sensor: T1, range: none}"), "", {}, "measurements[0].range"},
      {with("heading_deg: 0, half_aperture_deg: 12, precision: 0.02}", "heading_deg: 0, half_aperture_deg: 12, precision: 0.02, max_range: -4}"),
       "", {}, "sensors[0].max_range"},
      {with("heading_deg: 0, half_aperture_deg: 12, precision: 0.02}",
            "heading_deg: 0, half_aperture_deg: 12, precision: 0.02, max_range: 1, blind_distance: 1}"),
       "", {}, "sensors[0].blind_distance"},
  };
  int k = 0;
  for (const BadRun& c : cases) {
    std::string path = c.file;
    if (path.empty()) {
      path = dir + "/bad" + std::to_string(k) + ".yaml";
      std::ofstream(path) << c.text;
    }
    const std::string out = dir + "/out" + std::to_string(k++);
    std::vector<std::string> args{"localize", path, "-o", out};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const CommandResult r = run_gesmi(args);
    EXPECT_EQ(r.exit_code, 2) << c.must_name << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.must_name), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(out)) << out;
  }
}

TEST(LocalizeCli, AFolderNamedWithATrailingSlashIsCreated) {
  // As the README shows it: -o out/ for a folder that does not exist yet.
  const std::string out = temp_folder("localize") + "/fresh/";
  const CommandResult r = run_gesmi({"localize", scenario("triangle_two_hypotheses.yaml"), "-o", out, "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out + "summary.txt"));
  // And again into the folder that now exists.
  EXPECT_EQ(run_gesmi({"localize", scenario("triangle_two_hypotheses.yaml"), "-o", out, "--quiet"}).exit_code, 0);
}

TEST(LocalizeCli, MissingOutputFolderParentIsRefusedBeforeSolving) {
  const CommandResult r = run_gesmi({"localize", scenario("triangle_two_hypotheses.yaml"), "-o", "/no/such/parent/out"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

TEST(LocalizeCli, NoConsistentPoseExitsThreeWithAResult) {
  // Fixed policy, no outlier allowed, one range far beyond any wall: empty set.
  const std::string dir = temp_folder("localize_empty");
  std::string t = file_text(scenario("triangle_two_hypotheses.yaml"));
  const std::string from = "{sensor: T1, range: ";
  const auto at = t.find(from) + from.size();
  t.replace(at, t.find('}', at) - at, "40.0");
  std::ofstream(dir + "/empty.yaml") << t;
  const CommandResult r = run_gesmi({"localize", dir + "/empty.yaml", "-o", dir + "/out"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/out/summary.txt"));
  EXPECT_EQ(io::H5File::open_read(dir + "/out/paving.h5").shape("/inner/boxes").rows, 0u);
  EXPECT_NE(r.out.find("hypotheses (connected components): 0"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace gesmi::test
