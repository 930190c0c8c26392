// gesmi solve writes the result file, and its siblings only when asked (--png,
// --geojson, --mines-csv); it names every file it wrote; a later run without a flag
// removes the sibling an earlier run left, so no stale picture outlives its result.

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

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
  EXPECT_NE(stats.out.find("\"files\": [\"" + out + "/r.h5\", \"" + out + "/r.envelope.png\"]"), std::string::npos)
      << stats.out;
}

}  // namespace
}  // namespace gesmi::test
