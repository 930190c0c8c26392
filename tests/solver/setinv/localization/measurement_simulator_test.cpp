// The simulator's outliers always end: a range outlier where every reading within
// range lies near the truth's echo (a short max_range) becomes a wrong "no echo" or is
// refused by name, a narrow choice is drawn directly, and so is a bearing outlier
// whose precision leaves little of the circle. Expected values come from the rule
// (a margin of 4 alpha f + 0.2 m, 10 delta + 0.05 rad), not from the code.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "solver/setinv/localization/measurement_simulator.h"
#include "solver/setinv/localization/range_model.h"

namespace gesmi {
namespace {


// A 2 m square room, faces inwards (counter-clockwise), and one sonar looking to -x
// from the robot's origin: at x = 0.3 its echo is the wall x = 0, 0.3 m away.
const LocalizationMap kRoom{{{0, 0, 2, 0}, {2, 0, 2, 2}, {2, 2, 0, 2}, {0, 2, 0, 0}}, {}};
const Pose<double> kTruth{0.3, 1.0, 0.0};

RangeSensor backward_sonar(double max_range) {
  RangeSensor s{"back", 0.0, 0.0, std::numbers::pi, 11.3 * std::numbers::pi / 180.0, 0.02};
  s.max_range = max_range;
  return s;
}

MeasurementSimulationOptions outlier_on_sensor_0(std::uint32_t seed) {
  MeasurementSimulationOptions o;
  o.seed = seed;
  o.range_outliers = {0};
  return o;
}

TEST(MeasurementSimulator, RangeOutlierWithNoFarReadingIsAWrongNoEcho) {
  // max_range 0.5: readings in [0.25, 0.5], all within 0.224 m of the echo 0.3; and
  // 0.3 < 0.5 (1 - 0.02), so a no echo contradicts the truth.
  const RangeSensor s = backward_sonar(0.5);
  const double f = simulated_range(kTruth, s, std::span<const Segment>(kRoom.walls));
  ASSERT_NEAR(f, 0.3, 1e-12);
  const auto data = simulate_ranges(kRoom, {s}, kTruth, outlier_on_sensor_0(1));
  ASSERT_EQ(data.size(), 1u);
  EXPECT_TRUE(data[0].no_echo());
  EXPECT_FALSE(feasible_range(data[0], s).contains(f));
}

TEST(MeasurementSimulator, RangeOutlierThatCannotBeDrawnIsRefusedByName) {
  // max_range 0.305: 0.3 >= 0.305 (1 - 0.02), so even a no echo holds at the truth.
  try {
    simulate_ranges(kRoom, {backward_sonar(0.305)}, kTruth, outlier_on_sensor_0(1));
    ADD_FAILURE() << "no error";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("'back'"), std::string::npos) << e.what();
  }
}

TEST(MeasurementSimulator, NarrowRangeOutliersAreDrawnOutsideTheMargin) {
  // max_range 1: readings in [0.3, 1), the band 0.3 +- 0.224 leaves [0.524, 1).
  const RangeSensor s = backward_sonar(1.0);
  const double margin = 4.0 * 0.02 * 0.3 + 0.2;
  double lowest = 1.0, highest = 0.0;
  for (std::uint32_t seed = 1; seed <= 500; ++seed) {
    const auto data = simulate_ranges(kRoom, {s}, kTruth, outlier_on_sensor_0(seed));
    ASSERT_EQ(data.size(), 1u);
    const double d = data[0].range;
    ASSERT_TRUE(std::isfinite(d));
    EXPECT_GE(std::abs(d - 0.3), margin) << seed;
    EXPECT_GE(d, 0.3);
    EXPECT_LT(d, 1.0);
    lowest = std::min(lowest, d);
    highest = std::max(highest, d);
  }
  EXPECT_LT(lowest, 0.55);  // spread over what is left, not stuck at one end
  EXPECT_GT(highest, 0.95);
}

TEST(MeasurementSimulator, BearingOutliersEndWhateverThePrecision) {
  // One landmark straight ahead: the true bearing is 0.
  const LocalizationMap open{{}, {{5.0, 0.0}}};
  const Pose<double> origin{0.0, 0.0, 0.0};
  MeasurementSimulationOptions o;
  o.bearing_outliers = {0};
  for (const double precision : {0.01, 0.2, 0.3}) {  // margins 0.15, 2.05 and 3.05 rad
    const BearingSensor s{"laser", 0.0, 0.0, 0.0, precision};
    const double margin = 10.0 * precision + 0.05;
    for (std::uint32_t seed = 1; seed <= 200; ++seed) {
      o.seed = seed;
      const auto data = simulate_bearings(open, {s}, origin, o);
      ASSERT_EQ(data.size(), 1u);
      EXPECT_GE(std::abs(std::remainder(data[0].bearing, 2.0 * std::numbers::pi)), margin)
          << precision << " seed " << seed;
    }
  }
  // 10 delta + 0.05 >= pi: no bearing is that far.
  o.seed = 1;
  EXPECT_THROW(simulate_bearings(open, {BearingSensor{"laser", 0.0, 0.0, 0.0, 0.31}}, origin, o), std::domain_error);
}

}  // namespace
}  // namespace gesmi
