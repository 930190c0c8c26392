// gesmi estimate on missions/setinv/seed004_example2.yaml (seed 004, Example 2):
// the outlier sets of exactly q data that the program proves present, for q = 0..6,
// against a grid over the frame with phi computed in plain doubles
// (gaussian_example.h); the data numbered from 1; summary.txt equal to stdout; a bad
// scenario refused in one line, exit code 2, nothing written.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/solver/setinv/gaussian_example.h"
#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;
using Sets = std::set<std::vector<std::size_t>>;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The outlier sets (numbered from 1) met on a 1001 x 1000 grid of the frame, by size.
std::map<std::size_t, Sets> grid_sets() {
  std::map<std::size_t, Sets> out;
  for (int i = 0; i <= 1000; ++i)
    for (int k = 1; k <= 1000; ++k) {
      std::vector<std::size_t> phi = gaussian_phi(-2.0 + 0.01 * i, 0.003 * k);
      for (std::size_t& d : phi) ++d;
      out[phi.size()].insert(phi);
    }
  return out;
}

TEST(EstimateScenario, Seed004Example2ProvesTheOutlierSetsOfTheGrid) {
  const std::string out = temp_folder("estimate") + "/example2";
  const CommandResult r = run_gesmi({"estimate", source_dir() + "/missions/setinv/seed004_example2.yaml", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read(out + "/summary.txt"), r.out);
  const nlohmann::json summary = nlohmann::json::parse(read(out + "/summary.json"));
  std::map<std::size_t, Sets> proved;
  std::size_t levels = 0;
  for (const nlohmann::json& level : summary["levels"]) {
    EXPECT_EQ(level["q"], levels++);
    EXPECT_FALSE(level["limit_hit"]);
  }
  EXPECT_EQ(levels, 7u);
  for (const nlohmann::json& h : summary["hypotheses"]) {
    const auto set = h["outliers"].get<std::vector<std::size_t>>();
    EXPECT_EQ(set.size(), h["q"].get<std::size_t>());
    for (std::size_t d : set) EXPECT_TRUE(d >= 1 && d <= 6) << "data numbered from 1";
    EXPECT_LE(h["inner_volume"].get<double>(), h["outer_volume"].get<double>());
    if (h["proved"]) proved[set.size()].insert(set);
  }
  const std::map<std::size_t, Sets> grid = grid_sets();
  for (std::size_t q = 0; q <= 6; ++q) {
    const Sets none;
    EXPECT_EQ(proved.count(q) ? proved.at(q) : none, grid.count(q) ? grid.at(q) : none) << "q = " << q;
  }
  // The seed's conclusion: one outlier suffices, and it is datum 5.
  EXPECT_EQ(grid.at(1), Sets({{5}}));
  EXPECT_EQ(grid.count(0), 0u);
}

TEST(EstimateScenario, BadScenarioGivesOneLineAndWritesNothing) {
  const std::string dir = temp_folder("estimate_bad");
  const std::string path = dir + "/bad.yaml";
  std::ofstream(path) << "model: gaussian_density\ndata:\n  - {t: 1, y: [0.3, 0.2]}\nprior: [[-2, 8], [0, 3]]\nsolver: {epsilon: 0.01}\n";
  const CommandResult r = run_gesmi({"estimate", path, "-o", dir + "/out"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.yaml:3: data[1].y: lower bound above upper bound"), std::string::npos) << r.err;
  EXPECT_EQ(line_count(r.err), 1);
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

}  // namespace
}  // namespace gesmi::test
