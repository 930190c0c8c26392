// The scenario reader: a valid scenario round-trips; every bad input is one
// FormatError naming the source, the line and the key.

#include "io/localization/localization_scenario.h"

#include <gtest/gtest.h>

#include <numbers>
#include <sstream>

#include "io/format_error.h"

namespace gesmi {
namespace {

const char* kValid = R"(name: tiny
map:
  walls:
    - [0, 0, 4, 0]
    - [4, 0, 4, 3]
  landmarks:
    - [1, 2]
sensors:
  - {name: front, type: range, x: 0.2, y: 0, heading_deg: 0, half_aperture_deg: 10, precision: 0.02}
  - {name: cam, type: bearing, heading_deg: 90, precision_deg: 0.5}
measurements:
  - {sensor: front, range: 2.5}
  - {sensor: cam, bearing_deg: -45}
prior:
  boxes:
    - {x: [0, 4], y: [0, 3], theta_deg: [-180, 180]}
  halfplanes:
    - [1, 1, 6]
solver:
  epsilon: 0.05
outliers:
  policy: minimal
  extra: 1
truth: {x: 1, y: 1, theta_deg: 30}
)";

LocalizationProblem parse(const std::string& text) {
  std::istringstream in(text);
  return io::parse_localization_scenario(in, "scene.yaml");
}

TEST(LocalizationScenario, ReadsEverySection) {
  const LocalizationProblem p = parse(kValid);
  EXPECT_EQ(p.name, "tiny");
  ASSERT_EQ(p.map.walls.size(), 2u);
  EXPECT_EQ(p.map.walls[1].by, 3.0);
  ASSERT_EQ(p.range_sensors.size(), 1u);
  EXPECT_NEAR(p.range_sensors[0].half_aperture, 10 * std::numbers::pi / 180, 1e-15);
  ASSERT_EQ(p.bearing_sensors.size(), 1u);
  EXPECT_NEAR(p.bearing_sensors[0].heading, std::numbers::pi / 2, 1e-15);
  ASSERT_EQ(p.ranges.size(), 1u);
  ASSERT_EQ(p.bearings.size(), 1u);
  EXPECT_NEAR(p.bearings[0].bearing, -std::numbers::pi / 4, 1e-15);
  ASSERT_EQ(p.priors.size(), 1u);
  EXPECT_NEAR(p.priors[0][2].width(), 2 * std::numbers::pi, 1e-12);
  ASSERT_EQ(p.constraints.size(), 1u);
  EXPECT_EQ(p.policy, OutlierPolicy::minimal);
  EXPECT_EQ(p.extra_outliers, 1);
  EXPECT_DOUBLE_EQ(p.epsilon, 0.05);
  ASSERT_TRUE(p.truth);
  EXPECT_NEAR(p.truth->theta, std::numbers::pi / 6, 1e-15);
}

TEST(LocalizationScenario, NumbersDataAsTheFileListsThem) {
  // The problem stores ranges first; outputs name data by their place in the file.
  std::string text = kValid;
  const std::string range = "  - {sensor: front, range: 2.5}\n", bearing = "  - {sensor: cam, bearing_deg: -45}\n";
  text.replace(text.find(range + bearing), range.size() + bearing.size(), bearing + range);
  const LocalizationProblem p = parse(text);
  ASSERT_EQ(p.datum_count(), 2u);
  EXPECT_EQ(p.file_number(0), 2u);  // the range, second in the file
  EXPECT_EQ(p.file_number(1), 1u);  // the bearing, first
}

struct BadCase {
  std::string from, to;  // replace `from` in the valid text by `to`
  std::string key;       // must be named
  std::string line;      // ":N:" expected, or empty
};

TEST(LocalizationScenario, BadInputsNameTheFileTheLineAndTheKey) {
  const BadCase cases[] = {
      {"half_aperture_deg: 10", "half_aperture_deg: 60", "sensors[0].half_aperture_deg", ":9:"},
      {"precision: 0.02", "precision: -1", "sensors[0].precision", ":9:"},
      {"type: bearing", "type: lidar", "sensors[1].type", ":10:"},
      {"{sensor: cam, bearing_deg: -45}", "{sensor: nose, bearing_deg: -45}", "measurements[1].sensor", ":13:"},
      {"range: 2.5", "range: -2.5", "measurements[0].range", ":12:"},
      {"range: 2.5", "range: abc", "measurements[0].range", ":12:"},
      {"    - [4, 0, 4, 3]", "    - [4, 0, 4]", "map.walls[1]", ":5:"},
      {"    - [4, 0, 4, 3]", "    - [4, 0, 4, 0]", "map.walls[1]", ":5:"},
      {"x: [0, 4], y: [0, 3]", "x: [4, 0], y: [0, 3]", "prior.boxes[0].x", ":16:"},
      {"theta_deg: [-180, 180]", "theta_deg: [-180, 200]", "prior.boxes[0].theta_deg", ":16:"},
      {"epsilon: 0.05", "epsilon: 0", "solver.epsilon", ":20:"},
      {"epsilon: 0.05", "epsilonn: 0.05", "solver.epsilonn", ":20:"},
      {"policy: minimal", "policy: some", "outliers.policy", ":22:"},
      {"extra: 1", "extra: 9", "outliers.extra", ":23:"},
      {"truth: {x: 1, y: 1, theta_deg: 30}", "truth: {x: 1, y: 1}", "truth.theta_deg", ":24:"},
      {"solver:\n  epsilon: 0.05\n", "", "solver", ""},
      {"  - {name: cam, type: bearing,", "  - {name: front, type: bearing,", "sensors[1].name", ":10:"},
      // The range model's options (docs/setinversion.md, 3.1).
      {"precision: 0.02}", "precision: 0.02, max_range: -1}", "sensors[0].max_range", ":9:"},
      {"precision: 0.02}", "precision: 0.02, max_range: 0}", "sensors[0].max_range", ":9:"},
      {"precision: 0.02}", "precision: 0.02, max_range: far}", "sensors[0].max_range", ":9:"},
      {"precision: 0.02}", "precision: 0.02, blind_distance: -0.1}", "sensors[0].blind_distance", ":9:"},
      {"precision: 0.02}", "precision: 0.02, max_range: 3, blind_distance: 3}", "sensors[0].blind_distance", ":9:"},
      {"precision: 0.02}", "precision: 0.02, max_range: 3, blind_distance: 4}", "sensors[0].blind_distance", ":9:"},
      {"range: 2.5", "range: none", "measurements[0].range", ":12:"},  // no max_range
      {"precision: 0.02}", "precision: 0.02, max_range: 2}", "measurements[0].range", ":12:"},  // 2.5 > 2
      {"range: 2.5", "range: None", "measurements[0].range", ":12:"},
  };
  for (const BadCase& c : cases) {
    std::string text = kValid;
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, c.from.size(), c.to);
    try {
      parse(text);
      ADD_FAILURE() << "accepted: " << c.to;
    } catch (const io::FormatError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("scene.yaml", 0), 0u) << what;
      EXPECT_NE(what.find(c.key), std::string::npos) << what;
      if (!c.line.empty()) {
        EXPECT_NE(what.find(c.line), std::string::npos) << what;
      }
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(LocalizationScenario, ReadsTheRangeOptionsAndNoEcho) {
  std::string text = kValid;
  text.replace(text.find("precision: 0.02}"), 16, "precision: 0.02, max_range: 6, blind_distance: 0.3}");
  text.replace(text.find("range: 2.5"), 10, "range: none");
  const LocalizationProblem p = parse(text);
  EXPECT_DOUBLE_EQ(p.range_sensors[0].max_range, 6.0);
  EXPECT_DOUBLE_EQ(p.range_sensors[0].blind_distance, 0.3);
  ASSERT_EQ(p.ranges.size(), 1u);
  EXPECT_TRUE(p.ranges[0].no_echo());
  // Without the options: no max range, no blind zone.
  const LocalizationProblem q = parse(kValid);
  EXPECT_FALSE(q.range_sensors[0].has_max_range());
  EXPECT_EQ(q.range_sensors[0].blind_distance, 0.0);
  // "No echo" is written back as `range: none`.
  const std::string block = io::localization_measurements_yaml(p);
  EXPECT_NE(block.find("{sensor: front, range: none}"), std::string::npos) << block;
  const auto begin = text.find("measurements:"), end = text.find("prior:");
  text.replace(begin, end - begin, block);
  EXPECT_TRUE(parse(text).ranges[0].no_echo());
}

TEST(LocalizationScenario, BrokenYamlIsReportedWithItsLine) {
  try {
    parse("map: [\n  walls: {\n");
    ADD_FAILURE();
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.yaml:"), std::string::npos) << e.what();
  }
}

TEST(LocalizationScenario, MeasurementsBlockRoundTrips) {
  const LocalizationProblem p = parse(kValid);
  std::string text = kValid;
  const auto begin = text.find("measurements:"), end = text.find("prior:");
  text.replace(begin, end - begin, io::localization_measurements_yaml(p));
  const LocalizationProblem q = parse(text);
  ASSERT_EQ(q.ranges.size(), 1u);
  EXPECT_NEAR(q.ranges[0].range, 2.5, 1e-9);
  EXPECT_NEAR(q.bearings[0].bearing, p.bearings[0].bearing, 1e-9);
}

TEST(LocalizationScenario, SimulatedReadingsNearMaxRangeAreWrittenSoTheReaderTakesThem) {
  // Ten significant digits would round 3.23456789096 up to 3.234567891, above the
  // sensor's max_range 3.23456789099, which the reader refuses.
  std::string text = kValid;
  const std::string plain = "precision: 0.02}";
  text.replace(text.find(plain), plain.size(), "precision: 0.02, max_range: 3.23456789099}");
  LocalizationProblem p = parse(text);
  p.ranges = {{0, 3.23456789096}, {0, 0.5}};
  const std::string block = io::localization_measurements_yaml(p);
  EXPECT_NE(block.find("range: 0.5}"), std::string::npos) << block;  // the others keep ten digits
  const auto begin = text.find("measurements:"), end = text.find("prior:");
  text.replace(begin, end - begin, block);
  const LocalizationProblem q = parse(text);  // would throw "beyond the max_range"
  ASSERT_EQ(q.ranges.size(), 2u);
  EXPECT_EQ(q.ranges[0].range, 3.23456789096);
}

}  // namespace
}  // namespace gesmi
