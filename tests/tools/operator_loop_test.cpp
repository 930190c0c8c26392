// The operator loop through the gesmi command: marks
// editing, warm rerun equal to a cold solve, association without numbers, windows
// holding the missed detections, the outlier-tolerant solve, and bad inputs.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "io/files/mission_file.h"
#include "io/files/result_file.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

void expect_ok(const CommandResult& r) { ASSERT_EQ(r.exit_code, 0) << r.err << r.out; }

void expect_bad(const CommandResult& r, const std::string& must_contain, const std::string& not_written) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(must_contain), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(not_written)) << not_written;
}

std::string simulate(const std::string& folder, const std::vector<std::string>& extra) {
  const std::string path = folder + "/mission.h5";
  std::vector<std::string> args = {"simulate", "-o", path};
  args.insert(args.end(), extra.begin(), extra.end());
  if (std::find(extra.begin(), extra.end(), "--seed") == extra.end()) args.insert(args.end(), {"--seed", "1"});
  expect_ok(run_gesmi(args));
  return path;
}

TEST(OperatorLoop, MarksCommandsEditAndValidate) {
  const std::string dir = temp_folder("marks");
  const std::string mission = simulate(dir, {"--seed", "2"});
  const CommandResult list = run_gesmi({"marks", "list", mission});
  expect_ok(list);
  const Mission m = io::read_mission(mission);
  EXPECT_NE(list.out.find(std::to_string(m.mark_count()) + " marks"), std::string::npos);
  const std::string out = dir + "/out.h5";
  expect_ok(run_gesmi({"marks", "add", mission, "--time", "1000", "--range", "30", "-o", out}));
  const Mission added = io::read_mission(out);
  ASSERT_EQ(added.mark_count(), m.mark_count() + 1);
  EXPECT_EQ(added.mark_mine.back(), -1);  // default: unknown mine
  EXPECT_EQ(added.mark_side.back(), 1);   // default: starboard
  expect_ok(run_gesmi({"marks", "remove", out, "0", "-o", dir + "/removed.h5"}));
  EXPECT_EQ(io::read_mission(dir + "/removed.h5").mark_count(), m.mark_count());

  const std::string bad = dir + "/bad.h5";
  expect_bad(run_gesmi({"marks", "add", mission, "--time", "9000", "--range", "30", "-o", bad}), "--time", bad);
  expect_bad(run_gesmi({"marks", "add", mission, "--time", "100", "--range", "-3", "-o", bad}), "--range", bad);
  expect_bad(run_gesmi({"marks", "add", mission, "--time", "100", "--range", "80", "-o", bad}), "maximum range", bad);
  expect_bad(run_gesmi({"marks", "add", mission, "--time", "100", "--range", "30", "--mine", "9", "-o", bad}), "--mine", bad);
  expect_bad(run_gesmi({"marks", "add", mission, "--time", "100", "--range", "30", "--side", "left", "-o", bad}), "--side", bad);
  expect_bad(run_gesmi({"marks", "remove", mission, "999", "-o", bad}), "INDEX", bad);
}

// The missed detections of a simulation, as (time, mine, range).
std::vector<std::array<double, 3>> missed_marks(const std::string& mission) {
  const Mission m = io::read_mission(mission);
  std::vector<std::array<double, 3>> out;
  for (std::size_t i = 0; i + 2 < m.truth_missed_marks.size(); i += 3)
    out.push_back({m.truth_missed_marks[i], m.truth_missed_marks[i + 1], m.truth_missed_marks[i + 2]});
  return out;
}

double largest_difference(const MissionSolution& a, const MissionSolution& b) {
  double d = 0.0;
  const auto compare = [&](const std::vector<Interval>& x, const std::vector<Interval>& y) {
    for (std::size_t k = 0; k < x.size(); ++k) d = std::max({d, std::fabs(x[k].lo() - y[k].lo()), std::fabs(x[k].hi() - y[k].hi())});
  };
  compare(a.domains.px, b.domains.px);
  compare(a.domains.py, b.domains.py);
  compare(a.domains.pz, b.domains.pz);
  for (std::size_t i = 0; i < a.domains.mines.size(); ++i)
    for (int c = 0; c < 3; ++c)
      d = std::max({d, std::fabs(a.domains.mines[i][c].lo() - b.domains.mines[i][c].lo()),
                    std::fabs(a.domains.mines[i][c].hi() - b.domains.mines[i][c].hi())});
  return d;
}

TEST(OperatorLoop, WarmRerunAfterAddingMissedMarksEqualsAColdSolve) {
  for (const std::string seed : {"1", "2", "3"}) {
    SCOPED_TRACE("seed " + seed);
    const std::string dir = temp_folder("warm");
    const std::string mission = simulate(dir, {"--seed", seed, "--missed", "0.3"});
    expect_ok(run_gesmi({"solve", mission, "-o", dir + "/first.h5"}));
    // The operator finds the missed marks (their true ranges) without their numbers.
    std::string current = mission;
    int added = 0;
    for (const auto& [t, mine, range] : missed_marks(mission)) {
      const std::string next = dir + "/m" + std::to_string(added++) + ".h5";
      expect_ok(run_gesmi({"marks", "add", current, "--time", std::to_string(t), "--range", std::to_string(range), "-o", next}));
      current = next;
    }
    ASSERT_GT(added, 0);
    const CommandResult warm = run_gesmi({"solve", current, "--from", dir + "/first.h5", "-o", dir + "/warm.h5", "--stats"});
    expect_ok(warm);
    EXPECT_EQ(nlohmann::json::parse(warm.out)["solve"]["mode"], "warm") << warm.out;
    expect_ok(run_gesmi({"solve", current, "-o", dir + "/cold.h5"}));
    // Both are fixpoints of the same network but for the heading frame's margins, which
    // each takes over its own earlier tube (frame_margins.h): a few mm apart.
    EXPECT_LT(largest_difference(io::read_result(dir + "/warm.h5").solution, io::read_result(dir + "/cold.h5").solution), 5e-3);
  }
}

TEST(OperatorLoop, WarmRerunRefusesAnotherMissionOrADamagedResult) {
  const std::string dir = temp_folder("refuse");
  const std::string a = simulate(dir, {"--seed", "4"});
  expect_ok(run_gesmi({"solve", a, "-o", dir + "/a.h5"}));
  const std::string b = dir + "/b.h5";
  expect_ok(run_gesmi({"simulate", "--seed", "5", "-o", b}));
  const std::string out = dir + "/out.h5";
  expect_bad(run_gesmi({"solve", b, "--from", dir + "/a.h5", "-o", out}), "navigation data", out);
  expect_ok(run_gesmi({"marks", "remove", a, "0", "-o", dir + "/fewer.h5"}));
  expect_bad(run_gesmi({"solve", dir + "/fewer.h5", "--from", dir + "/a.h5", "-o", out}), "mark table", out);
  std::ofstream(dir + "/damaged.h5") << "not an hdf5 file";
  expect_bad(run_gesmi({"solve", a, "--from", dir + "/damaged.h5", "-o", out}), "damaged.h5", out);
  expect_bad(run_gesmi({"solve", a, "--max-outliers", "-1", "-o", out}), "--max-outliers", out);
  expect_bad(run_gesmi({"solve", a, "--max-outliers", "two", "-o", out}), "--max-outliers", out);
  expect_bad(run_gesmi({"solve", a, "--mines", "3", "-o", out}), "--mines", out);
}

TEST(OperatorLoop, MarksWithoutNumbersKeepTheirTrueMine) {
  int decided = 0, total = 0;
  for (const std::string seed : {"6", "7"}) {
    const std::string dir = temp_folder("assoc");
    const std::string mission = simulate(dir, {"--seed", seed, "--unassociated", "1"});
    expect_ok(run_gesmi({"solve", mission, "-o", dir + "/r.h5"}));
    const Mission m = io::read_mission(mission);
    const MissionSolution r = io::read_result(dir + "/r.h5", {.waterfall = false}).solution;
    // With every number removed the mines are only defined up to relabelling: the
    // solver labels them in order of first detection. Relabel the truth the same way.
    std::vector<std::size_t> order(m.mark_count());
    for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return m.mark_time[a] < m.mark_time[b]; });
    std::map<int, int> label;
    for (const std::size_t j : order)
      if (!label.count(m.truth_marks_mine[j])) label.emplace(m.truth_marks_mine[j], static_cast<int>(label.size()));
    for (std::size_t j = 0; j < m.mark_count(); ++j) {
      EXPECT_TRUE(r.candidates[j] >> label.at(m.truth_marks_mine[j]) & 1) << "mark " << j << " lost its mine";
      decided += std::popcount(r.candidates[j]) == 1;
      ++total;
    }
  }
  std::printf("[ report ] marks without numbers decided: %d of %d\n", decided, total);
  EXPECT_GT(decided, 0);
}

TEST(OperatorLoop, EveryMissedDetectionLiesInAListedWindow) {
  const std::string dir = temp_folder("windows");
  const std::string mission = simulate(dir, {"--seed", "8", "--missed", "0.3"});
  expect_ok(run_gesmi({"solve", mission, "-o", dir + "/r.h5"}));
  expect_ok(run_gesmi({"candidates", dir + "/r.h5", "--csv", dir + "/w.csv"}));
  expect_ok(run_gesmi({"waterfall", dir + "/r.h5", "-o", dir + "/w.png"}));
  std::ifstream csv(dir + "/w.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "mine,t_start,t_end,range_lo,range_hi,status");
  struct Window {
    int mine;
    double t0, t1, r0, r1;
  };
  std::vector<Window> windows;
  while (std::getline(csv, line)) {
    Window w{};
    char comma;
    std::istringstream in(line);
    in >> w.mine >> comma >> w.t0 >> comma >> w.t1 >> comma >> w.r0 >> comma >> w.r1;
    windows.push_back(w);
  }
  const auto missed = missed_marks(mission);
  ASSERT_FALSE(missed.empty());
  for (const auto& [t, mine, range] : missed) {
    bool found = false;
    for (const Window& w : windows)
      found = found || (w.mine == static_cast<int>(mine) && w.t0 - 0.05 <= t && t <= w.t1 + 0.05 && w.r0 <= range && range <= w.r1);
    EXPECT_TRUE(found) << "missed detection at t = " << t << " of mine " << mine << " range " << range;
  }
}

TEST(OperatorLoop, OutlierTolerantSolveNamesTheInjectedMarks) {
  for (const std::string n : {"1", "2"}) {
    SCOPED_TRACE("outliers " + n);
    const std::string dir = temp_folder("outliers");
    const std::string mission = simulate(dir, {"--seed", "9", "--outliers", n});
    const CommandResult plain = run_gesmi({"solve", mission, "-o", dir + "/plain.h5"});
    EXPECT_EQ(plain.exit_code, 3) << plain.err;
    EXPECT_TRUE(fs::exists(dir + "/plain.h5"));  // written, marked inconsistent
    EXPECT_FALSE(io::read_result(dir + "/plain.h5", {.waterfall = false}).solution.report.consistent);
    expect_ok(run_gesmi({"solve", mission, "--max-outliers", "2", "-o", dir + "/r.h5"}));
    const MissionSolution r = io::read_result(dir + "/r.h5", {.waterfall = false}).solution;
    const Mission m = io::read_mission(mission);
    EXPECT_EQ(r.report.minimal_outliers, std::stoi(n));
    for (std::size_t j = 0; j < m.mark_count(); ++j)
      if (r.mark_outlier[j]) {
        EXPECT_EQ(m.truth_marks_outlier[j], 1) << "mark " << j << " wrongly named";
      }
    for (std::size_t k = 0; k < m.size(); ++k) {
      ASSERT_TRUE(r.domains.px[k].contains(m.truth_x[k])) << k;
      ASSERT_TRUE(r.domains.py[k].contains(m.truth_y[k])) << k;
    }
  }
}

// A wrong mark on a mine seen once cannot show as an inconsistency: the solve names the
// mines that rest on one mark, in its warnings, its --json report and the result.
TEST(OperatorLoop, MinesThatRestOnOneMarkAreNamed) {
  const std::string dir = temp_folder("single-mark");
  const std::string mission = simulate(dir, {"--seed", "27", "--duration", "1800", "--outliers", "1"});
  const Mission m = io::read_mission(mission);
  std::map<int, std::vector<std::size_t>> marks_of;
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    ASSERT_GE(m.mark_mine[j], 0);  // every simulated mark has its number
    marks_of[m.mark_mine[j]].push_back(j);
  }
  std::vector<int> single;
  std::vector<std::size_t> their_marks;
  for (const auto& [mine, rows] : marks_of)
    if (rows.size() == 1) {
      single.push_back(mine);
      their_marks.push_back(rows.front());
    }
  ASSERT_FALSE(single.empty());
  const CommandResult r = run_gesmi({"solve", mission, "-o", dir + "/r.h5", "--json"});
  expect_ok(r);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["solve"]["unchecked"]["mines"], nlohmann::json(single));
  EXPECT_EQ(report["solve"]["unchecked"]["marks"], nlohmann::json(their_marks));
  EXPECT_EQ(report["solve"]["unchecked"]["gps_fixes"], nlohmann::json::array());
  std::string mines;
  for (const int i : single) mines += (mines.empty() ? "" : ", ") + std::to_string(i);
  EXPECT_NE(r.err.find("rest" + std::string(single.size() == 1 ? "s" : "") + " on one mark"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(mines + " rest"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a wrong mark there cannot be detected; --max-outliers 1"), std::string::npos) << r.err;
  // The outlier-tolerant solve trusting the fixes encloses every mine, the corrupted
  // mark's too; it still names them, without the advice it already follows.
  const CommandResult tolerant = run_gesmi({"solve", mission, "--max-outliers", "1", "--trust-gps", "-o", dir + "/t.h5"});
  expect_ok(tolerant);
  EXPECT_NE(tolerant.err.find("a wrong mark there cannot be detected\n"), std::string::npos) << tolerant.err;
  const MissionSolution t = io::read_result(dir + "/t.h5", {.waterfall = false}).solution;
  for (int i = 0; i < m.mine_count; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(t.domains.mines[i][c].contains(m.truth_mines[3 * i + c])) << "mine " << i << " axis " << c;
}

}  // namespace
}  // namespace gesmi::test
