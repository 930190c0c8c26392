// Conformance against the ITF1788 vectors (tests/data/itf1788): the built
// itl-check runs every bare-interval test of the operations the library
// implements, with zero failures; and it reports bad input as documented.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
// GCC 12 with -fsanitize=address (the GESMI_SANITIZE build) reports a false
// -Wmaybe-uninitialized inside libstdc++'s <regex> (GCC bug 105616). The pragma
// covers that header's own code only; this file stays under every warning.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <regex>
#pragma GCC diagnostic pop
#include <string>
#include <vector>

#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi {
namespace {

std::vector<std::string> itl_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(test::itf1788_dir()))
    if (entry.path().extension() == ".itl") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string last_line(const std::string& out) {
  const std::size_t end = out.find_last_not_of('\n');
  const std::size_t start = out.rfind('\n', end);
  return out.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = test::temp_folder("itl") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(IntervalItf1788, EveryVectorPassesWithZeroFailures) {
  const std::vector<std::string> files = itl_files();
  ASSERT_GE(files.size(), 11u);  // the 11 files of tests/data/itf1788
  const test::CommandResult r = test::run_program("itl-check", files);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("FAILED"), std::string::npos) << r.out;
  std::smatch m;
  const std::string summary = last_line(r.out);
  ASSERT_TRUE(std::regex_match(summary, m, std::regex(R"((\d+) passed, (\d+) failed, (\d+) skipped)"))) << summary;
  EXPECT_GT(std::stoi(m[1]), 3000);  // most bare tests of the implemented operations
  EXPECT_EQ(std::stoi(m[2]), 0);
  EXPECT_EQ(test::line_count(r.out), static_cast<int>(files.size()) + 1);  // a line per file and the summary
}

TEST(IntervalItf1788, AWrongExpectationFailsWithExitCodeOne) {
  const std::string file = write_file("wrong.itl",
                                      "testcase t {\n"
                                      "  add [1.0, 2.0] [1.0, 2.0] = [2.0, 4.5]; // the sum is [2, 4]\n"
                                      "  isEmpty [empty] = false;\n"
                                      "  sqrt [4.0, 4.0] = [2.0, 2.0];\n"
                                      "  acosh [1.0, 1.0] = [0.0, 0.0];\n"
                                      "  add [1.0, 2.0]_com [1.0, 2.0]_com = [2.0, 4.0]_com;\n"
                                      "}\n");
  const test::CommandResult r = test::run_program("itl-check", {file});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(last_line(r.out), "1 passed, 2 failed, 2 skipped");
}

TEST(IntervalItf1788, MalformedOrMissingFilesExitWithTwoAndOneLine) {
  const std::string bad = write_file("bad.itl", "testcase t {\n  add [1.0, 2.0 = [1.0, 2.0];\n}\n");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{bad}, {"/nonexistent/file.itl"}, {"--bogus"}, std::vector<std::string>{}}) {
    const test::CommandResult r = test::run_program("itl-check", args);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_EQ(test::line_count(r.err), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace gesmi
