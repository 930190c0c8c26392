// gesmi estimate on missions/setinv/seed004_example2.yaml (seed 004, Example 2):
// the outlier sets of exactly q data that the program proves present, for q = 0..6,
// against a grid over the frame with phi computed in plain doubles
// (gaussian_example.h); the data numbered from 1; summary.txt equal to stdout; a bad
// scenario (among them an epsilon finer than doubles can split) refused in one line,
// exit code 2, nothing written; a box limit reported.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
  EXPECT_EQ(file_text(out + "/summary.txt"), r.out);
  const nlohmann::json summary = nlohmann::json::parse(file_text(out + "/summary.json"));
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

// Example 2's file with its solver line replaced.
std::string example2_with_solver(const std::string& dir, const std::string& solver) {
  std::string text = file_text(source_dir() + "/missions/setinv/seed004_example2.yaml");
  const std::string line = "solver: {epsilon: 0.005}";
  const std::size_t at = text.find(line);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, line.size(), solver);
  const std::string path = dir + "/scenario.yaml";
  std::ofstream(path) << text;
  return path;
}

int line_of(const std::string& path, const std::string& text) {
  const std::string content = file_text(path);
  return 1 + static_cast<int>(std::count(content.begin(), content.begin() + static_cast<std::ptrdiff_t>(content.find(text)), '\n'));
}

TEST(EstimateScenario, EpsilonFinerThanDoublesCanSplitIsRefused) {
  const std::string dir = temp_folder("estimate_fine");
  const std::string path = example2_with_solver(dir, "solver: {epsilon: 1e-17}");
  const CommandResult r = run_gesmi({"estimate", path, "-o", dir + "/out"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  const std::string head = "gesmi estimate: " + path + ":" + std::to_string(line_of(path, "solver:")) +
                           ": solver.epsilon: 1e-17 is finer than doubles can split over the prior box: at least ";
  ASSERT_EQ(r.err.rfind(head, 0), 0u) << r.err;
  // Twice the spacing of doubles at the prior's largest magnitude, 8: 2 * 2^-49.
  EXPECT_EQ(std::stod(r.err.substr(head.size())), std::ldexp(1.0, -48));
  EXPECT_FALSE(fs::exists(dir + "/out"));
  // At that bound it is accepted (and stopped here by a small box limit).
  const std::string at_bound = example2_with_solver(dir, "solver: {epsilon: 3.552713678800501e-15, max_boxes: 500}");
  EXPECT_EQ(run_gesmi({"estimate", at_bound, "-o", dir + "/out", "-q"}).exit_code, 0);
}

TEST(EstimateScenario, BadLimitsAndRepeatedLevelsAreRefused) {
  const std::string dir = temp_folder("estimate_limits");
  for (const auto& [solver, reason] : std::vector<std::pair<std::string, std::string>>{
           {"solver: {epsilon: 0.005, max_seconds: 0}", "solver.max_seconds: must be positive"},
           {"solver: {epsilon: 0.005, max_seconds: .inf}", "solver.max_seconds:"},
           {"solver: {epsilon: 0.005, max_boxes: -3}", "solver.max_boxes: must be between 1 and 20000000"},
           {"solver: {epsilon: 0.005, max_boxes: 20000001}", "solver.max_boxes: must be between 1 and 20000000"},
           {"solver: {epsilon: 0.005, max_boxes: 2.5}", "solver.max_boxes:"},
           {"solver: {epsilon: 0.005, max_box: 10}", "max_box"},
           {"solver: {epsilon: 0.005}\noutliers: {levels: [0, 2, 0]}", "outliers.levels[2]: 0 is listed twice"}}) {
    const std::string path = example2_with_solver(dir, solver);
    std::string text = file_text(path);
    if (solver.find("outliers") != std::string::npos) {  // the file's own levels line goes
      const std::size_t at = text.rfind("outliers: {levels: [0, 1");
      text.erase(at, text.find('\n', at) - at);
      std::ofstream(path) << text;
    }
    const CommandResult r = run_gesmi({"estimate", path, "-o", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2) << solver;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("gesmi estimate: " + path + ":", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
}

TEST(EstimateScenario, MoreThan64DataAreRefusedAtThe65th) {
  const std::string dir = temp_folder("estimate_many");
  std::string text = "model: gaussian_density\ndata:\n";
  for (int i = 0; i < 65; ++i) text += "  - {t: " + std::to_string(i) + ", y: [0.1, 0.2]}\n";
  text += "prior: [[-2, 8], [0, 3]]\nsolver: {epsilon: 0.01}\n";
  const std::string path = dir + "/many.yaml";
  std::ofstream(path) << text;
  const CommandResult r = run_gesmi({"estimate", path, "-o", dir + "/out"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("gesmi estimate: " + path + ":67: data: at most 64 data, got 65", 0), 0u) << r.err;  // line 3 holds data[1]
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(EstimateScenario, ABoxLimitIsReportedInTheSummaryAndTheJson) {
  const std::string dir = temp_folder("estimate_box_limit");
  const std::string path = example2_with_solver(dir, "solver: {epsilon: 0.005, max_boxes: 3000}");
  const CommandResult r = run_gesmi({"estimate", path, "-o", dir + "/out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("WARNING: the box limit (solver.max_boxes: 3000) was hit"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("time limit"), std::string::npos) << r.out;
  const nlohmann::json summary = nlohmann::json::parse(file_text(dir + "/out/summary.json"));
  EXPECT_TRUE(summary["box_limit_hit"]);
  EXPECT_FALSE(summary["time_limit_hit"]);
  EXPECT_EQ(summary["limits"]["max_boxes"], 3000);
  EXPECT_EQ(summary["limits"]["max_seconds"], 600.0);  // the default
  EXPECT_TRUE(summary["levels"].back()["box_limit_hit"]);
  EXPECT_TRUE(summary["levels"].back()["limit_hit"]);
  EXPECT_GE(summary["timing"]["boxes_examined"].get<std::size_t>(), 3000u);
}

}  // namespace
}  // namespace gesmi::test
