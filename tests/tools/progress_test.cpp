// The progress line of long commands (tools/gesmi/progress.h): drawn on a terminal over
// the whole command (reading, the solve's stages, writing) and cleared at the end;
// nothing on a pipe, nothing for a command that ends quickly. The terminal is a
// pseudo-terminal from util-linux's `script`, which Debian always installs.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <tuple>

#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

// What a command prints to a terminal (stdout and stderr together), and its exit code.
std::pair<int, std::string> on_terminal(const std::string& command) {
  const std::string line = "script -qec '" + command + "' /dev/null </dev/null 2>&1";
  std::FILE* pipe = ::popen(line.c_str(), "r");
  if (!pipe) return {-1, ""};
  std::string out;
  std::array<char, 4096> buffer;
  for (std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) out.append(buffer.data(), got);
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(Progress, ALongSolveShowsItsStagesOnATerminalAndClearsTheLine) {
  const std::string dir = temp_folder("progress");
  const std::string gesmi = test::bin_dir() + "/gesmi";
  // 10^6 steps: a solve of about a second, longer than the line's 0.3 s delay (3 x 10^5
  // steps once took 0.6 s, and then less than the delay as the command got faster).
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "3", "--duration", "100000", "-o", dir + "/m.h5"}).exit_code, 0);
  const auto [code, out] = on_terminal(gesmi + " solve " + dir + "/m.h5 -o " + dir + "/r.h5");
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("\r\033[Kgesmi solve: "), std::string::npos) << out;
  // A stage shows when it lasts across a redraw (every 0.1 s): the propagation's sweeps
  // do at this size; the waterfall (tens of milliseconds) need not.
  EXPECT_NE(out.find("sweep"), std::string::npos) << out;
  // Cleared before the summary: the last progress text is followed by an erase.
  const std::size_t last = out.rfind("gesmi solve: ");
  ASSERT_NE(last, std::string::npos);
  EXPECT_NE(out.find("\r\033[K", last), std::string::npos) << out.substr(last);
  EXPECT_NE(out.find("written to"), std::string::npos) << out;

  // The same command on a pipe: no progress at all.
  const CommandResult piped = run_gesmi({"solve", dir + "/m.h5", "-o", dir + "/r2.h5"});
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.err.find('\r'), std::string::npos);
  EXPECT_EQ(piped.out.find('\r'), std::string::npos);
}

// Simulate, export and import of 10^6 samples (about a second each) on a terminal:
// each shows its phase and clears the line before its summary.
TEST(Progress, SimulateExportAndImportShowTheirPhases) {
  const std::string dir = temp_folder("progress-io");
  const std::string gesmi = test::bin_dir() + "/gesmi";
  const auto expect_phase = [](const std::string& out, const std::string& label, const std::string& phase) {
    EXPECT_NE(out.find("\r\033[K" + label), std::string::npos) << out;
    EXPECT_NE(out.find(phase), std::string::npos) << out;
    const std::size_t last = out.rfind(label);
    ASSERT_NE(last, std::string::npos);
    EXPECT_NE(out.find("\r\033[K", last), std::string::npos) << out.substr(last);
    EXPECT_NE(out.find("wrote "), std::string::npos) << out;
  };
  auto [code, out] = on_terminal(gesmi + " simulate --seed 2 --duration 100000 -o " + dir + "/m.h5");
  ASSERT_EQ(code, 0) << out;
  expect_phase(out, "gesmi simulate: ", "simulating 1000000 samples");
  std::tie(code, out) = on_terminal(gesmi + " export " + dir + "/m.h5 -o " + dir + "/csv");
  ASSERT_EQ(code, 0) << out;
  expect_phase(out, "gesmi export: ", "writing " + dir + "/csv");
  std::tie(code, out) = on_terminal("cd " + dir + "/csv && " + gesmi + " import nav nav.csv --gps gps.csv --marks marks.csv "
                                    "--config model.yaml --mines 6 -o " + dir + "/back.h5");
  ASSERT_EQ(code, 0) << out;
  expect_phase(out, "gesmi import: ", "reading nav.csv");
}

// gesmi estimate on seed 004's Example 2 (about a second, seven levels): the level and
// the boxes examined on a terminal, cleared before the summary; nothing with -q.
TEST(Progress, EstimateShowsItsLevelsAndKeepsQuietWithQ) {
  const std::string dir = temp_folder("progress-estimate");
  const std::string command =
      test::bin_dir() + "/gesmi estimate " + source_dir() + "/missions/setinv/seed004_example2.yaml -o " + dir;
  auto [code, out] = on_terminal(command + "/e1");
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("\r\033[Kgesmi estimate: "), std::string::npos) << out;
  EXPECT_NE(out.find(" of 7): "), std::string::npos) << out;  // "q = 3 (level 4 of 7): 61852 boxes examined"
  const std::size_t last = out.rfind("gesmi estimate: ");
  ASSERT_NE(last, std::string::npos);
  EXPECT_NE(out.find("\r\033[K", last), std::string::npos) << out.substr(last);
  EXPECT_NE(out.find("s in all"), std::string::npos) << out;  // the summary follows

  std::tie(code, out) = on_terminal(command + "/e2 -q");
  ASSERT_EQ(code, 0) << out;
  EXPECT_EQ(out.find("gesmi estimate: "), std::string::npos) << out;
  EXPECT_EQ(out.find('\r'), std::string::npos) << out;
}

TEST(Progress, AQuickCommandDrawsNothingOnATerminal) {
  const std::string dir = temp_folder("progress-quick");
  ASSERT_EQ(run_gesmi({"simulate", "--seed", "3", "--duration", "60", "-o", dir + "/m.h5"}).exit_code, 0);
  const auto [code, out] = on_terminal(test::bin_dir() + "/gesmi solve " + dir + "/m.h5 -o " + dir + "/r.h5");
  ASSERT_EQ(code, 0) << out;
  // (its warnings may follow: a one-minute mission has mines seen once)
  EXPECT_EQ(out.find("gesmi solve: sensor"), std::string::npos) << out;
  EXPECT_EQ(out.find("\033[K"), std::string::npos) << out;  // no line drawn, none cleared
}

}  // namespace
}  // namespace gesmi::test
