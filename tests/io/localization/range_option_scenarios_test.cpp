// The scenarios of the range model's options (docs/setinversion.md, section 5): seed
// 000's two rooms of section 4.3, with a blind zone, give 2 then 1 hypotheses within
// the stated accuracy; the blind zone decides the truth; a "no echo" removes the
// hypotheses that the echoes alone allow.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "io/localization/localization_scenario.h"
#include "solver/setinv/localization/range_data.h"
#include "tests/support/paths.h"
#include "solver/model/angles.h"

namespace gesmi {
namespace {


LocalizationProblem scenario(const std::string& name) {
  return io::read_localization_scenario(test::source_dir() + "/missions/localization/" + name);
}

// The half turn about the room's centre (the origin) maps the symmetric room onto itself.
Pose<double> half_turn(const Pose<double>& p) { return {-p.x, -p.y, std::remainder(p.theta + std::numbers::pi, 2 * std::numbers::pi)}; }

// Seed 000, section 4.3: "less than +-10 cm for x and y, and less than +-4 degrees for theta".
void expect_within_stated_accuracy(const LocalizationHypothesis& h, const Pose<double>& pose) {
  const std::vector<Interval>& hull = h.component.hull;
  EXPECT_TRUE(Interval(pose.x - 0.1, pose.x + 0.1).is_superset(hull[0])) << hull[0].lo() << " " << hull[0].hi();
  EXPECT_TRUE(Interval(pose.y - 0.1, pose.y + 0.1).is_superset(hull[1])) << hull[1].lo() << " " << hull[1].hi();
  const double turns = std::round((hull[2].mid() - pose.theta) / (2 * std::numbers::pi));
  const double theta = pose.theta + turns * 2 * std::numbers::pi;
  EXPECT_TRUE(Interval(theta - 4 * kRadiansPerDegree, theta + 4 * kRadiansPerDegree).is_superset(hull[2]))
      << hull[2].lo() << " " << hull[2].hi();
}

const LocalizationHypothesis* holding(const LocalizationResult& r, const Pose<double>& pose) {
  for (const LocalizationHypothesis& h : r.hypotheses)
    if (box_holds_pose(h.component.hull, pose)) return &h;
  return nullptr;
}

TEST(RangeOptionScenarios, Seed000SymmetricRoomGivesTheTruthAndItsHalfTurn) {
  const LocalizationProblem p = scenario("seed000_symmetric.yaml");
  const LocalizationResult r = localize(p);
  ASSERT_EQ(r.hypotheses.size(), 2u);
  EXPECT_TRUE(r.truth_enclosed);
  const LocalizationHypothesis* truth = holding(r, *p.truth);
  const LocalizationHypothesis* turned = holding(r, half_turn(*p.truth));
  ASSERT_NE(truth, nullptr);
  ASSERT_NE(turned, nullptr);
  ASSERT_NE(truth, turned);
  EXPECT_TRUE(truth->contains_truth);
  EXPECT_NE(truth->range_walls, turned->range_walls);  // a radically different association
  expect_within_stated_accuracy(*truth, *p.truth);
  expect_within_stated_accuracy(*turned, half_turn(*p.truth));
}

TEST(RangeOptionScenarios, Seed000AsymmetricRoomGivesOneHypothesisWithinTheStatedAccuracy) {
  const LocalizationProblem p = scenario("seed000_asymmetric.yaml");
  const LocalizationResult r = localize(p);
  ASSERT_EQ(r.hypotheses.size(), 1u);
  EXPECT_TRUE(r.hypotheses[0].contains_truth);
  EXPECT_GT(r.hypotheses[0].component.inner.size(), 0u);
  expect_within_stated_accuracy(r.hypotheses[0], *p.truth);
}

TEST(RangeOptionScenarios, BlindZoneDecidesTheTruthInEveryRoom) {
  // S1 grazes the wall next to the robot; only the blind zone explains its reading.
  const std::pair<const char*, int> rooms[] = {
      {"seed000_symmetric.yaml", 4}, {"seed000_asymmetric.yaml", 4}, {"no_echo_doorway.yaml", 11}};  // that wall
  for (const auto& [name, wall] : rooms) {
    LocalizationProblem p = scenario(name);
    for (const RangeSensor& s : p.range_sensors) EXPECT_EQ(s.blind_distance, 0.25) << name;
    const RangeData blind(p.map.walls, p.range_sensors, p.ranges);
    EXPECT_EQ(blind.associate(*p.truth)[0], wall) << name;
    for (RangeSensor& s : p.range_sensors) s.blind_distance = 0.0;
    const RangeData seeing(p.map.walls, p.range_sensors, p.ranges);
    EXPECT_EQ(seeing.associate(*p.truth)[0], -1) << name;
    const LocalizationResult r = localize(p);
    EXPECT_FALSE(r.truth_enclosed) << name;
  }
}

TEST(RangeOptionScenarios, NoEchoRemovesTheHypothesesTheEchoesAloneAllow) {
  LocalizationProblem p = scenario("no_echo_doorway.yaml");
  ASSERT_EQ(p.ranges.size(), 5u);
  ASSERT_TRUE(p.ranges[1].no_echo());
  const LocalizationResult with = localize(p);
  ASSERT_EQ(with.hypotheses.size(), 1u);
  EXPECT_TRUE(with.hypotheses[0].contains_truth);
  EXPECT_EQ(with.hypotheses[0].range_walls[1], kNoWallInRange);
  // The same data without the "no echo" (what a model without the option keeps).
  p.ranges.erase(p.ranges.begin() + 1);
  p.file_numbers.clear();
  const LocalizationResult echoes = localize(p);
  EXPECT_EQ(echoes.hypotheses.size(), 6u);
  EXPECT_TRUE(echoes.truth_enclosed);
  EXPECT_NE(holding(echoes, half_turn(*p.truth)), nullptr);
}

}  // namespace
}  // namespace gesmi
