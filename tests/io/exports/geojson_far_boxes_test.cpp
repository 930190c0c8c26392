// The GeoJSON envelope leaves out the tube boxes beyond the export radius (500 km) and
// counts them as far_samples: the envelope of a tube with one far box is the envelope of
// the same tube without it. (Without far boxes the export outlines the tube's own boxes;
// with some, a copy where they are empty: both paths are checked here.)

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/exports/result_exports.h"
#include "tests/support/run_command.h"

namespace gesmi::io {
namespace {

SolveResult tube_result(bool with_far_box) {
  SolveResult r;
  r.origin = GeoOrigin{48.2129, -4.4582};
  MissionSolution& s = r.solution;
  s.report.consistent = true;
  for (int k = 0; k < 10; ++k) {
    s.time.push_back(k);
    s.domains.px.emplace_back(10.0 * k, 10.0 * k + 12.0);  // overlapping: one polygon
    s.domains.py.emplace_back(-4.0 + k, 4.0 + k);
    s.domains.pz.emplace_back(5.0, 6.0);
  }
  if (with_far_box) {
    s.time.push_back(10.0);
    s.domains.px.emplace_back(600000.0, 600010.0);  // 600 km north
    s.domains.py.emplace_back(0.0, 10.0);
    s.domains.pz.emplace_back(5.0, 6.0);
  }
  return r;
}

nlohmann::json envelope_of(const SolveResult& r, const std::string& path) {
  write_geojson(r, nullptr, path);
  const nlohmann::json collection = nlohmann::json::parse(std::ifstream(path));
  for (const nlohmann::json& feature : collection["features"])
    if (feature["properties"]["kind"] == "envelope") return feature;
  ADD_FAILURE() << "no envelope in " << path;
  return {};
}

TEST(GeojsonEnvelope, LeavesOutAndCountsTheBoxesBeyondTheExportRadius) {
  const std::string folder = test::temp_folder("geojson-far");
  const nlohmann::json near = envelope_of(tube_result(false), folder + "/near.geojson");
  const nlohmann::json with_far = envelope_of(tube_result(true), folder + "/far.geojson");
  EXPECT_EQ(near["properties"]["far_samples"], 0);
  EXPECT_EQ(near["properties"]["samples"], 10);
  EXPECT_EQ(with_far["properties"]["far_samples"], 1);
  EXPECT_EQ(with_far["properties"]["samples"], 11);
  EXPECT_EQ(with_far["properties"]["unbounded_samples"], 0);
  EXPECT_EQ(with_far["geometry"], near["geometry"]);
  EXPECT_EQ(near["geometry"]["type"], "Polygon");
  for (const nlohmann::json& point : near["geometry"]["coordinates"][0]) EXPECT_LT(point[1].get<double>(), 48.22);
}

}  // namespace
}  // namespace gesmi::io
