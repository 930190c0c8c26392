// gesmi example paper2d: JSON contract and bad command lines.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

TEST(CmdExample, JsonHasExactlyTheDocumentedKeysAndPairs) {
  const CommandResult r = run_gesmi({"example", "paper2d", "--delta-v", "1", "--delta-z", "1", "--delta-x", "inf", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(line_count(r.out), 1);
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["schema"], "gesmi-report");
  EXPECT_EQ(doc["command"], "example paper2d");
  // z has one pair, vectors two: 3 + 2 * 9 = 21 pairs, each [lo, hi] with lo <= hi.
  std::size_t pairs = 0;
  for (const char* key : {"z1", "z2", "z3", "m", "v0", "v1", "v2", "v3", "x1", "x2", "x3", "x4"}) {
    ASSERT_TRUE(doc.contains(key)) << key;
    for (const auto& pair : doc[key]) {
      ASSERT_EQ(pair.size(), 2u) << key;
      if (pair[0].is_number() && pair[1].is_number()) {
        EXPECT_LE(pair[0].get<double>(), pair[1].get<double>()) << key;
      }
      ++pairs;
    }
  }
  EXPECT_EQ(pairs, 21u) << r.out;
}

TEST(CmdExample, UnboundedEndsAreWrittenAsStrings) {
  // Without range data (dz = inf) m stays unbounded.
  const CommandResult r = run_gesmi({"example", "paper2d", "--delta-v", "1", "--delta-z", "inf", "--delta-x", "inf", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["m"], nlohmann::json::parse(R"([["-inf", "inf"], ["-inf", "inf"]])")) << r.out;
}

struct BadLine {
  std::vector<std::string> args;
  const char* must_name;
};

TEST(CmdExample, RejectsBadCommandLinesWithOneLineNamingTheOption) {
  const BadLine cases[] = {
      {{"example", "paper2d", "--delta-v", "-1"}, "--delta-v"},
      {{"example", "paper2d", "--delta-z", "abc"}, "--delta-z"},
      {{"example", "paper2d", "--delta-x", "1.5x"}, "--delta-x"},
      {{"example", "paper2d", "--delta-x", "nan"}, "--delta-x"},
      {{"example", "paper2d", "--delta-v"}, "delta-v"},
      {{"example", "paper2d", "--frobnicate", "3"}, "frobnicate"},
      {{"example", "paper3d"}, "paper2d"},
      {{"example"}, "paper2d"},
  };
  for (const BadLine& c : cases) {
    const CommandResult r = run_gesmi(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.must_name << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.must_name), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(CmdExample, UnknownCommandIsABadInput) {
  const CommandResult r = run_gesmi({"frobnicate"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.err), 1);
}

}  // namespace
}  // namespace gesmi::test
