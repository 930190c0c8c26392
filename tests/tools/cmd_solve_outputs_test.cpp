// gesmi solve writes the result file, and its siblings only when asked (--png,
// --geojson, --mines-csv); it names every file it wrote; a later run without a flag
// removes the sibling an earlier run left, so no stale picture outlives its result.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <set>

#include <fstream>

#include "io/files/result_file.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

TEST(CmdSolveOutputs, WritesTheResultAloneUnlessSiblingsAreAsked) {
  const std::string folder = temp_folder("solve-outputs");
  const std::string mission = folder + "/in/m.h5";
  fs::create_directories(folder + "/in");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "600", "-o", mission}).exit_code, 0);
  const std::string out = folder + "/out";
  fs::create_directories(out);

  const CommandResult plain = run_gesmi({"solve", mission, "-o", out + "/r.h5"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(names_in(out), (std::set<std::string>{"r.h5"}));
  EXPECT_NE(plain.out.find("written to " + out + "/r.h5\n"), std::string::npos) << plain.out;

  const CommandResult all = run_gesmi({"solve", mission, "-o", out + "/r.h5", "--png", "--geojson", "--mines-csv"});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_EQ(names_in(out), (std::set<std::string>{"r.h5", "r.mines.csv", "r.geojson", "r.envelope.png"}));
  for (const char* name : {"/r.h5", "/r.mines.csv", "/r.geojson", "/r.envelope.png"})
    EXPECT_NE(all.out.find(out + name), std::string::npos) << name << " not named in: " << all.out;

  const CommandResult stats = run_gesmi({"solve", mission, "-o", out + "/r.h5", "--png", "--stats"});
  ASSERT_EQ(stats.exit_code, 0) << stats.err;
  EXPECT_EQ(names_in(out), (std::set<std::string>{"r.h5", "r.envelope.png"})) << "stale siblings were kept";
  EXPECT_EQ(nlohmann::json::parse(stats.out)["outputs"], nlohmann::json::array({out + "/r.h5", out + "/r.envelope.png"}))
      << stats.out;
}

// The solve reads no truth, but the envelope picture of a simulated mission draws it
// (the blue path and dots, plot_envelope.cpp): counted in the PNG by matplotlib.
TEST(CmdSolveOutputs, TheEnvelopePictureOfASimulatedMissionShowsTheTruth) {
  const std::string folder = temp_folder("solve-truth");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "600", "-o", folder + "/m.h5"}).exit_code, 0);
  const CommandResult r = run_gesmi({"solve", folder + "/m.h5", "-o", folder + "/r.h5", "--png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Truth blue is (0.1, 0.3, 0.9): pixels whose blue exceeds their red by 0.3, line
  // edges included. Nothing else is blue: the same mission without its truth gives none,
  // with it about 2,000.
  const std::string count =
      "/usr/bin/python3 -c \"import sys, matplotlib.image as i; a = i.imread(sys.argv[1]); "
      "sys.exit(0 if (a[:, :, 2] > a[:, :, 0] + 0.3).sum() > 500 else 1)\" " +
      folder + "/r.envelope.png";
  EXPECT_EQ(std::system(count.c_str()), 0) << "no truth drawn";
}

}  // namespace
}  // namespace gesmi::test

namespace gesmi::test {
namespace {

// `--config` changes the model after the mission was read: the fixes' boxes, which
// derive from its GPS bounds, must follow (they did not before: a 30 m GPS bound
// solved exactly as the mission's 2.5 m, excluding positions the user's bounds allow).
TEST(CmdSolveOutputs, ConfigGpsBoundsReachTheFixBoxes) {
  const std::string folder = temp_folder("solve-config-gps");
  const std::string mission = folder + "/m.h5";
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "600", "-o", mission}).exit_code, 0);
  { std::ofstream(folder + "/wide.yaml") << "gps_metres: 30\n"; }
  ASSERT_EQ(run_gesmi({"solve", mission, "-o", folder + "/a.h5"}).exit_code, 0);
  const CommandResult wide = run_gesmi({"solve", mission, "--config", folder + "/wide.yaml", "-o", folder + "/b.h5"});
  ASSERT_EQ(wide.exit_code, 0) << wide.err;
  const io::SolveResult a = io::read_result(folder + "/a.h5"), b = io::read_result(folder + "/b.h5");
  const TubeDomains &da = a.solution.domains, &db = b.solution.domains;
  ASSERT_EQ(da.size(), db.size());
  // Wider bounds: every box contains the narrower one, and the fix at t = 0 is ±30 m.
  for (std::size_t k = 0; k < da.size(); ++k) {
    ASSERT_TRUE(db.px[k].is_superset(da.px[k])) << k;
    ASSERT_TRUE(db.py[k].is_superset(da.py[k])) << k;
  }
  EXPECT_GT(db.px[0].width(), 2 * 25.0);
  EXPECT_LT(da.px[0].width(), 2 * 5.0);
}

}  // namespace
}  // namespace gesmi::test
