// gesmi localize --json: the outlier fields of each hypothesis, S_q split by outlier
// set, and Remark 6's safety with --safety, on the warehouse with two bearing outliers.

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace gesmi::test
