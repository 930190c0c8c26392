// The GPS bounds rule (docs/formats.md, "GPS bounds"): a fix's own half-widths replace
// the model's GPS bounds, but a --config that sets those bounds makes each fix's box the
// larger of the two, in `gesmi solve` and `gesmi kalman` alike, with a one-line notice.
// (Before, such a config was silently ignored: outputs identical at 0.5 m and 25 m.)

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/files/kalman_result.h"
#include "solver/kalman/kalman_smoother.h"
#include "io/files/mission_file.h"
#include "io/files/result_file.h"
#include "io/geodesy.h"
#include "io/hdf5/h5_file.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

// A simulated mission whose fixes carry their own half-widths of 3 m.
std::string mission_with_own_fix_bounds(const std::string& dir) {
  EXPECT_EQ(run_gesmi({"simulate", "--seed", "2", "--duration", "1200", "-o", dir + "/sim.h5"}).exit_code, 0);
  Mission m = io::read_mission(dir + "/sim.h5");
  m.gps_given_north_halfwidth.assign(m.gps_time.size(), 3.0);
  m.gps_given_east_halfwidth.assign(m.gps_time.size(), 3.0);
  io::write_mission(m, dir + "/m.h5");
  return dir + "/m.h5";
}

void write_config(const std::string& path, double metres) {
  std::ofstream(path) << "gps_metres: " << metres << "\n";
}

TEST(GpsBoundsRule, AConfigWiderThanTheFixesOwnBoundsWidensTheirBoxes) {
  const std::string dir = temp_folder("gps-rule");
  const std::string path = mission_with_own_fix_bounds(dir);
  Mission m = io::read_mission(path);
  ASSERT_FALSE(m.gps_time.empty());
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) EXPECT_LT(m.gps_north_halfwidth[i], 3.1);  // its own, as given
  write_config(dir + "/wide.yaml", 25.0);
  const auto notice = io::merge_model_config(m, dir + "/wide.yaml");
  ASSERT_TRUE(notice.has_value());
  EXPECT_NE(notice->find("larger of the two"), std::string::npos) << *notice;
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) {
    EXPECT_GE(m.gps_north_halfwidth[i], 25.0);
    EXPECT_GE(m.gps_east_halfwidth[i], 25.0);
  }
  // A config narrower than the fixes' own bounds leaves them: the larger is theirs.
  Mission narrow = io::read_mission(path);
  write_config(dir + "/narrow.yaml", 0.5);
  ASSERT_TRUE(io::merge_model_config(narrow, dir + "/narrow.yaml").has_value());
  for (std::size_t i = 0; i < narrow.gps_time.size(); ++i) {
    EXPECT_GE(narrow.gps_north_halfwidth[i], 3.0);
    EXPECT_LT(narrow.gps_north_halfwidth[i], 3.1);
  }
  // A config that leaves the GPS bounds alone says nothing.
  Mission other = io::read_mission(path);
  std::ofstream(dir + "/marks.yaml") << "mark_range: 1.5\n";
  EXPECT_FALSE(io::merge_model_config(other, dir + "/marks.yaml").has_value());
}

TEST(GpsBoundsRule, SolveAndKalmanBothFollowIt) {
  const std::string dir = temp_folder("gps-rule-cli");
  const std::string path = mission_with_own_fix_bounds(dir);
  write_config(dir + "/narrow.yaml", 0.5);
  write_config(dir + "/wide.yaml", 25.0);
  for (const char* name : {"narrow", "wide"}) {
    const std::string config = dir + "/" + name + ".yaml";
    const CommandResult solved = run_gesmi({"solve", path, "--config", config, "-o", dir + "/r_" + name + ".h5"});
    ASSERT_EQ(solved.exit_code, 0) << solved.err;
    EXPECT_NE(solved.err.find("gesmi solve: note: "), std::string::npos) << solved.err;
    const CommandResult smoothed = run_gesmi({"kalman", path, "--config", config, "-o", dir + "/k_" + name + ".h5"});
    ASSERT_EQ(smoothed.exit_code, 0) << smoothed.err;
    EXPECT_NE(smoothed.err.find("gesmi kalman: note: "), std::string::npos) << smoothed.err;
  }
  // The first fix bounds the start: 25 m widens the tube there, and the Kalman variance.
  const TubeDomains narrow = io::read_result(dir + "/r_narrow.h5", {.waterfall = false}).solution.domains;
  const TubeDomains wide = io::read_result(dir + "/r_wide.h5", {.waterfall = false}).solution.domains;
  EXPECT_GT(wide.px[0].width(), narrow.px[0].width() + 40.0);
  // The smoother weighs the first fix less: its estimate there moves.
  const io::H5File kn = io::H5File::open_read(dir + "/k_narrow.h5"), kw = io::H5File::open_read(dir + "/k_wide.h5");
  EXPECT_NE(kn.read_doubles("/kalman/mean"), kw.read_doubles("/kalman/mean"));
  // And its variance there grows (the smoother on the same missions, in process).
  Mission mn = io::read_mission(path), mw = io::read_mission(path);
  io::merge_model_config(mn, dir + "/narrow.yaml");
  io::merge_model_config(mw, dir + "/wide.yaml");
  const KalmanResult rn = kalman_smooth(mn, mn.model, gps_fixes(mn)), rw = kalman_smooth(mw, mw.model, gps_fixes(mw));
  EXPECT_GT(rw.covariance[0], 10.0 * rn.covariance[0]);  // north variance at the start
}

}  // namespace
}  // namespace gesmi::test
