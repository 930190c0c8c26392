// The bearing model of seed 003: circular windows, sight lines through walls, and
// the inclusion property of the data tests on boxes.

#include "solver/setinv/localization/bearing_model.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "solver/setinv/localization/bearing_data.h"
#include "solver/setinv/localization/measurement_simulator.h"

namespace gesmi {
namespace {


TEST(BearingModel, AngleWindowsWrapAroundTheTurn) {
  EXPECT_TRUE(angle_within(std::numbers::pi - 0.01, -std::numbers::pi + 0.01, 0.03));
  EXPECT_FALSE(angle_within(0.5, 0.0, 0.3));
  EXPECT_TRUE(angle_within(Interval(2 * std::numbers::pi - 0.01, 2 * std::numbers::pi + 0.01), 0.0, 0.02).is_true());
  EXPECT_TRUE(angle_within(Interval(0.5, 0.6), 0.0, 0.3).is_false());
  EXPECT_TRUE(angle_within(Interval(0.2, 0.4), 0.0, 0.3).is_maybe());
  EXPECT_TRUE(angle_within(Interval(-4.0, 3.0), 1.0, 0.1).is_maybe());
}

TEST(BearingModel, WallsBlockSightLinesButLandmarksOnWallsStayVisible) {
  const std::vector<Segment> walls{{0, -1, 0, 1}};
  EXPECT_FALSE(landmark_visible(Vec2T<double>{-1, 0}, LandmarkPoint{1, 0}, std::span<const Segment>(walls)));
  EXPECT_TRUE(landmark_visible(Vec2T<double>{-1, 0}, LandmarkPoint{-0.5, 3}, std::span<const Segment>(walls)));
  EXPECT_TRUE(landmark_visible(Vec2T<double>{-1, 0}, LandmarkPoint{0, 0.5}, std::span<const Segment>(walls)));
  const IBool some = landmark_visible(Vec2T<Interval>{Interval(-1, -0.5), Interval(0.5, 3)}, LandmarkPoint{1, 0},
                                      std::span<const Segment>(walls));
  EXPECT_TRUE(some.is_maybe());
}

TEST(BearingModel, BoxVerdictsHoldForEveryPointOfTheBox) {
  LocalizationMap map;
  map.walls = {{0, 0, 10, 0}, {10, 0, 10, 8}, {10, 8, 0, 8}, {0, 8, 0, 0}, {4, 2, 4, 6}};
  map.landmarks = {{0.1, 1}, {0.1, 7}, {9.9, 1}, {9.9, 7}, {5, 7.9}, {5, 0.1}, {3.9, 4}, {4.1, 4}};
  const std::vector<BearingSensor> sensors{{"laser", 0.1, 0.0, 0.0, 0.01}};
  const Pose<double> truth{7.0, 3.0, 0.3};
  const std::vector<BearingMeasurement> m = simulate_bearings(map, sensors, truth, {});
  ASSERT_GE(m.size(), 5u);
  BearingData data(map.walls, map.landmarks, sensors, m);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> ux(0.5, 9.5), uy(0.5, 7.5), ut(-std::numbers::pi, std::numbers::pi),
      unit(0, 1);
  std::vector<IBool> box_out(m.size(), IBool::maybe()), point_out(m.size(), IBool::maybe());
  int settled = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double x = ux(rng), y = uy(rng), t = ut(rng), w = 0.4 * unit(rng), wt = 0.2 * unit(rng);
    const Box box{Interval(x, x + w), Interval(y, y + w), Interval(t, t + wt)};
    data.evaluate(box, 0, box_out, 99);
    for (int k = 0; k < 10; ++k) {
      const Box point{Interval(x + w * unit(rng)), Interval(y + w * unit(rng)), Interval(t + wt * unit(rng))};
      data.evaluate(point, 0, point_out, 99);
      for (std::size_t i = 0; i < m.size(); ++i) {
        if (box_out[i].is_maybe() || point_out[i].is_maybe()) continue;
        ++settled;
        EXPECT_TRUE(box_out[i] == point_out[i]) << trial << " " << i;
      }
    }
  }
  EXPECT_GT(settled, 1000);
  // At the truth every measurement is explained.
  data.evaluate(Box{Interval(truth.x), Interval(truth.y), Interval(truth.theta)}, 0, point_out, 99);
  for (IBool b : point_out) EXPECT_FALSE(b.is_false());
}

}  // namespace
}  // namespace gesmi
