// gesmi localize --json: the outlier fields of each hypothesis, S_q split by outlier
// set, and Remark 6's safety with --safety, on the warehouse with two bearing outliers.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

TEST(LocalizeCommand, JsonNamesTheOutlierSetsAndTheSafetyOfEachDatum) {
  const std::string scenario = source_dir() + "/missions/localization/warehouse_p04_outliers.yaml";
  const CommandResult r = run_gesmi({"localize", scenario, "-o", temp_folder("localize_json") + "/w", "--safety", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  const nlohmann::json& l = report["localization"];
  EXPECT_EQ(l["q"], 2);
  EXPECT_EQ(l["q_lower"], 2);
  ASSERT_EQ(l["hypotheses"].size(), 1u);
  const nlohmann::json& h = l["hypotheses"][0];
  // The scenario's injected outliers are bearings 3 and 8 (ranges: none).
  EXPECT_EQ(h["outliers"], nlohmann::json::array({3, 8}));
  EXPECT_EQ(h["agreed_outliers"], h["outliers"]);
  EXPECT_EQ(h["outlier_sets"], nlohmann::json::array({nlohmann::json::array({3, 8})}));
  EXPECT_TRUE(h["outlier_sets_complete"]);
  EXPECT_TRUE(h["outliers_determined"]);
  EXPECT_EQ(h["agreed_inliers"].size() + 2, l["safety"].size());
  ASSERT_EQ(l["outlier_sets"].size(), 1u);
  EXPECT_EQ(l["outlier_sets"][0]["outliers"], h["outliers"]);
  // One safety interval per datum, inside [0, 1].
  for (const nlohmann::json& s : l["safety"]) {
    EXPECT_GE(s["safety"][0].get<double>(), 0.0);
    EXPECT_LE(s["safety"][1].get<double>(), 1.0);
    EXPECT_LE(s["safety"][0].get<double>(), s["safety"][1].get<double>());
  }
}

// OUT/summary.json and the printed summary name data by their place in the scenario
// file (from 1): the injected bearing outliers 3 and 8 (from 0, all data bearings)
// are data 4 and 9.
TEST(LocalizeCommand, SummaryJsonAndTextNameTheOutlierSetsInFileNumbers) {
  const std::string scenario = source_dir() + "/missions/localization/warehouse_p04_outliers.yaml";
  const std::string out = temp_folder("localize_summary") + "/w";
  const CommandResult r = run_gesmi({"localize", scenario, "-o", out, "--safety"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(file_text(out + "/summary.txt"), r.out);
  EXPECT_NE(r.out.find("outliers: #4:laser #9:laser  (the only outlier set, proved)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("undetermined"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("safety of each datum"), std::string::npos) << r.out;
  const nlohmann::json s = nlohmann::json::parse(file_text(out + "/summary.json"));
  EXPECT_EQ(s["scenario"], "warehouse_p04_outliers");
  ASSERT_EQ(s["hypotheses"].size(), 1u);
  const nlohmann::json& h = s["hypotheses"][0];
  EXPECT_EQ(h["outliers"], nlohmann::json::array({4, 9}));
  EXPECT_EQ(h["outlier_sets"], nlohmann::json::array({nlohmann::json::array({4, 9})}));
  EXPECT_EQ(h["hull"].size(), 3u);
  EXPECT_GT(h["inner_boxes"].get<int>() + h["boundary_boxes"].get<int>(), 0);
  EXPECT_LE(h["inner_volume"].get<double>(), h["outer_volume"].get<double>());
  EXPECT_GT(s["timing"]["seconds"].get<double>(), 0.0);
  ASSERT_EQ(s["safety"].size(), 13u);
  EXPECT_EQ(s["safety"][0]["datum"], 1);
}

// Above q* a hypothesis holds several outlier sets: the summary lists what they
// agree on and the sets, not a single "outliers" line.
TEST(LocalizeCommand, SummaryListsTheSetsOfAnUndeterminedHypothesis) {
  const std::string dir = temp_folder("localize_q1");
  std::string text = file_text(source_dir() + "/missions/localization/triangle_two_hypotheses.yaml");
  text.replace(text.find("count: 0"), 8, "count: 1");
  text.replace(text.find("epsilon: 0.01"), 13, "epsilon: 0.04");  // fast; the sets stay apart
  std::ofstream(dir + "/t.yaml") << text;
  const CommandResult r = run_gesmi({"localize", dir + "/t.yaml", "-o", dir + "/out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // At q = 1, the empty set and single outliers may both hold near the true pose.
  EXPECT_NE(r.out.find("agreed outliers: none\n     outlier sets: {}"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("possible sets"), std::string::npos) << r.out;
  const nlohmann::json s = nlohmann::json::parse(file_text(dir + "/out/summary.json"));
  bool several = false;
  for (const nlohmann::json& h : s["hypotheses"]) several = several || h["outlier_sets"].size() > 1;
  EXPECT_TRUE(several);
}

// A search stopped by a limit says which limits it had and where to raise them.
TEST(LocalizeCommand, ALimitHitNamesTheLimitsAndHowToRaiseThem) {
  const std::string dir = temp_folder("localize_limit");
  std::string scenario = file_text(source_dir() + "/missions/localization/seed000_symmetric.yaml");
  const std::string solver = "solver:\n  epsilon: 0.02\n";
  ASSERT_NE(scenario.find(solver), std::string::npos);
  scenario.replace(scenario.find(solver), solver.size(), "solver:\n  epsilon: 1e-12\n  max_boxes: 2000\n");
  std::ofstream(dir + "/s.yaml") << scenario;
  const CommandResult r = run_gesmi({"localize", dir + "/s.yaml", "-o", dir + "/out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("WARNING: a limit was hit (solver.max_boxes: 2000 boxes, solver.max_seconds: 600 s): "
                       "undetermined boxes were kept unbisected (still an enclosure); raise them in the scenario's "
                       "solver section"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace gesmi::test
