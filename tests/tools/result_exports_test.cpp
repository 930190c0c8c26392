// gesmi export of a result (tube-csv, mines-csv, geojson) and the refusal of an
// inconsistent result, checked from the files: local bounds read back exactly as the
// result holds them; latitude/longitude bounds contain the local box's corners and
// centre converted one by one; the GeoJSON envelope contains every sampled tube box's
// corners (an even-odd test over its rings, independent of the outline code); every
// row and feature carries the status; candidates, waterfall and export refuse an
// inconsistent result (exit 3, one line, nothing written) unless --show-inconsistent.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/files/mission_file.h"
#include "io/files/result_file.h"
#include "io/geodesy.h"
#include "io/time/utc_time.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;

void expect_ok(const CommandResult& r) { ASSERT_EQ(r.exit_code, 0) << r.err << r.out; }

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

double number(const std::string& text) { return std::stod(text); }

// A consistent mission with a UTC epoch, solved once for all the tests.
struct Solved {
  std::string dir, mission, result;
  Solved() {
    dir = temp_folder("exports");
    mission = dir + "/mission.h5";
    expect_ok(run_gesmi({"simulate", "-o", dir + "/sim.h5", "--seed", "3", "--duration", "1200"}));
    Mission m = io::read_mission(dir + "/sim.h5");
    m.epoch = 1778745600;  // 2026-05-14T08:00:00Z
    io::write_mission(m, mission);
    result = dir + "/result.h5";
    expect_ok(run_gesmi({"solve", mission, "-o", result}));
  }
};

const Solved& solved() {
  static const Solved s;
  return s;
}

TEST(ResultExports, TubeCsvHoldsTheExactLocalBoundsAndOutwardGeodeticOnes) {
  const Solved& s = solved();
  const std::string csv = s.dir + "/tube.csv";
  expect_ok(run_gesmi({"export", s.result, "--format", "tube-csv", "-o", csv}));
  const io::SolveResult r = io::read_result(s.result);
  const auto rows = read_csv(csv);
  ASSERT_EQ(rows.size(), r.solution.time.size() + 1);
  ASSERT_EQ(rows[0].size(), 13u);  // time, utc, 6 local bounds, 4 geodetic ones, status
  EXPECT_EQ(rows[0][1], "utc");
  EXPECT_EQ(rows[1][1], "2026-05-14T08:00:00.000000Z");
  const io::LocalFrame frame(*r.origin);
  const TubeDomains& d = r.solution.domains;
  for (std::size_t k = 0; k < d.size(); k += 7) {
    const auto& row = rows[k + 1];
    EXPECT_EQ(number(row[0]), r.solution.time[k]);
    EXPECT_EQ(row[12], "consistent");
    const Interval* axes[3] = {&d.px[k], &d.py[k], &d.pz[k]};
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(number(row[2 + 2 * c]), axes[c]->lo()) << "row " << k;
      ASSERT_EQ(number(row[3 + 2 * c]), axes[c]->hi()) << "row " << k;
    }
    for (const double n : {d.px[k].lo(), d.px[k].mid(), d.px[k].hi()})
      for (const double e : {d.py[k].lo(), d.py[k].mid(), d.py[k].hi()}) {
        const GeoOrigin g = frame.to_geodetic(n, e);
        ASSERT_LE(number(row[8]), g.latitude);
        ASSERT_GE(number(row[9]), g.latitude);
        ASSERT_LE(number(row[10]), g.longitude);
        ASSERT_GE(number(row[11]), g.longitude);
      }
  }
}

TEST(ResultExports, MinesCsvBoundsReadBackExactlyWithTheirMarks) {
  const Solved& s = solved();
  const std::string csv = s.dir + "/mines.csv";
  expect_ok(run_gesmi({"export", s.result, "--format", "mines-csv", "-o", csv}));
  const io::SolveResult r = io::read_result(s.result, {.tube = false, .waterfall = false});
  const Mission m = io::read_mission(s.mission);
  const auto rows = read_csv(csv);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(m.mine_count) + 1);
  for (int i = 0; i < m.mine_count; ++i) {
    const auto& row = rows[static_cast<std::size_t>(i) + 1];
    // The simulator labels every mark with its mine: the mine's marks are those rows.
    EXPECT_EQ(std::stoi(row[1]), std::count(m.mark_mine.begin(), m.mark_mine.end(), i)) << "mine " << i;
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(number(row[2 + 2 * c]), r.solution.domains.mines[i][c].lo());
      EXPECT_EQ(number(row[3 + 2 * c]), r.solution.domains.mines[i][c].hi());
    }
    EXPECT_LT(number(row[8]), number(row[9]));
    EXPECT_EQ(row[12], "consistent");
  }
}

bool inside_rings(const nlohmann::json& polygons, double lon, double lat) {
  bool in = false;
  for (const auto& polygon : polygons)
    for (const auto& ring : polygon)
      for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
        const double ax = ring[i][0], ay = ring[i][1], bx = ring[i + 1][0], by = ring[i + 1][1];
        if ((ay > lat) != (by > lat) && lon < ax + (lat - ay) * (bx - ax) / (by - ay)) in = !in;
      }
  return in;
}

TEST(ResultExports, GeoJsonEnvelopeContainsTheTubeAndCarriesTheStatus) {
  const Solved& s = solved();
  const std::string path = s.dir + "/r.geojson";
  expect_ok(run_gesmi({"export", s.result, "--format", "geojson", "--mission", s.mission, "-o", path}));
  std::ifstream in(path);
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["type"], "FeatureCollection");
  EXPECT_EQ(doc["status"], "consistent");
  const io::SolveResult r = io::read_result(s.result);
  const Mission m = io::read_mission(s.mission);
  std::map<std::string, int> kinds;
  nlohmann::json envelope;
  for (const auto& f : doc["features"]) {
    kinds[f["properties"]["kind"]]++;
    EXPECT_EQ(f["properties"]["status"], "consistent");
    if (f["properties"]["kind"] == "envelope") envelope = f["geometry"];
  }
  EXPECT_EQ(kinds["envelope"], 1);
  // A mine no mark saw has an unbounded box, which no polygon holds.
  const auto bounded = std::count_if(r.solution.domains.mines.begin(), r.solution.domains.mines.end(),
                                     [](const Vec3I& b) { return b[0].is_bounded() && b[1].is_bounded(); });
  EXPECT_GT(bounded, 0);
  EXPECT_EQ(kinds["mine"], bounded);
  EXPECT_EQ(kinds["gps_fix"], static_cast<int>(m.gps_time.size()));
  const nlohmann::json polygons = envelope["type"] == "Polygon" ? nlohmann::json::array({envelope["coordinates"]})
                                                                : envelope["coordinates"];
  const io::LocalFrame frame(*r.origin);
  const TubeDomains& d = r.solution.domains;
  for (std::size_t k = 0; k < d.size(); k += 97)
    for (const double n : {d.px[k].lo(), d.px[k].hi()})
      for (const double e : {d.py[k].lo(), d.py[k].hi()}) {
        const GeoOrigin g = frame.to_geodetic(n, e);
        ASSERT_TRUE(inside_rings(polygons, g.longitude, g.latitude)) << "sample " << k;
      }
}

TEST(ResultExports, AnInconsistentResultIsRefusedUnlessAskedAndThenMarked) {
  const std::string dir = temp_folder("inconsistent");
  expect_ok(run_gesmi({"simulate", "-o", dir + "/m.h5", "--seed", "9", "--outliers", "1"}));
  const CommandResult solved = run_gesmi({"solve", dir + "/m.h5", "-o", dir + "/r.h5", "--mines-csv", "--geojson"});
  ASSERT_EQ(solved.exit_code, 3) << solved.err;
  for (const auto& row : read_csv(dir + "/r.mines.csv")) {
    if (row[0] != "mine") {
      EXPECT_EQ(row.back(), "inconsistent");
    }
  }
  const std::vector<std::vector<std::string>> refused = {
      {"candidates", dir + "/r.h5", "--csv", dir + "/w.csv"},
      {"waterfall", dir + "/r.h5", "-o", dir + "/w.png"},
      {"export", dir + "/r.h5", "--format", "geojson", "-o", dir + "/e.geojson"},
      {"export", dir + "/r.h5", "--format", "tube-csv", "-o", dir + "/t.csv"}};
  for (const auto& args : refused) {
    const CommandResult r = run_gesmi(args);
    EXPECT_EQ(r.exit_code, 3) << args[0] << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--show-inconsistent"), std::string::npos) << r.err;
  }
  for (const char* name : {"w.csv", "w.png", "e.geojson", "t.csv"}) EXPECT_FALSE(fs::exists(dir + "/" + name)) << name;
  for (auto args : refused) {
    args.push_back("--show-inconsistent");
    const CommandResult r = run_gesmi(args);
    EXPECT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
    EXPECT_NE(r.out.find("INCONSISTENT"), std::string::npos) << r.out;
  }
  for (const auto& row : read_csv(dir + "/w.csv")) {
    if (row[0] != "mine") {
      EXPECT_EQ(row.back(), "inconsistent");
    }
  }
  std::ifstream in(dir + "/e.geojson");
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["status"], "inconsistent");
  EXPECT_FALSE(doc["inconsistency"].get<std::string>().empty());
  for (const auto& f : doc["features"]) EXPECT_EQ(f["properties"]["status"], "inconsistent");
}

}  // namespace
}  // namespace gesmi::test
