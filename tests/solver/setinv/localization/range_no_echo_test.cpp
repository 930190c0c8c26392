// "No echo" (seed 002: a sensor that hears nothing within max_range) and the blind
// zone through the data layer: the feasible set against readings computed apart,
// the simulator's promise, RangeData's verdicts against the points of random nested
// boxes, and the range contractor, which must keep every pose where the data hold.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "solver/setinv/localization/measurement_simulator.h"
#include "solver/setinv/localization/range_contractor.h"
#include "solver/setinv/localization/range_data.h"
#include "solver/setinv/localization/range_model.h"
#include "solver/model/angles.h"

namespace gesmi {
namespace {


// Readings a true range r can give: d with r in d [1 - alpha, 1 + alpha]. "No echo"
// is possible when one of them, sampled finely, exceeds max_range.
bool no_echo_possible(double r, double alpha, double max_range) {
  const double lo = r / (1.0 + alpha), hi = r / (1.0 - alpha);
  for (int k = 0; k <= 1000; ++k)
    if (lo + (hi - lo) * k / 1000.0 > max_range) return true;
  return false;
}

TEST(RangeNoEcho, FeasibleSetHoldsEveryRangeThatCanReadBeyondMaxRange) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> range(0.5, 20.0), precision(0.0, 0.1), rel(-0.2, 0.2);
  int possible = 0, impossible = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    RangeSensor s{"s", 0, 0, 0, 10 * kRadiansPerDegree, precision(rng)};
    s.max_range = range(rng);
    const Interval y = feasible_range({0, kNoEcho}, s);
    EXPECT_EQ(y.hi(), kInf);
    const double threshold = s.max_range * (1.0 - s.precision);
    // Around the threshold, and within 1e-12 of it on both sides.
    for (const double r : {threshold * (1.0 + rel(rng)), threshold * (1.0 + 1e-12), threshold * (1.0 - 1e-12)}) {
      if (no_echo_possible(r, s.precision, s.max_range)) {
        ++possible;
        EXPECT_TRUE(y.contains(r)) << trial << " r=" << r << " lo=" << y.lo();
      } else {
        ++impossible;
        EXPECT_FALSE(y.contains(r)) << trial << " r=" << r << " lo=" << y.lo();
      }
    }
    // No wall in the cone at all: +inf on points, [DBL_MAX, +inf] on boxes.
    EXPECT_TRUE(y.contains(far_away<double>()));
    EXPECT_TRUE(member(far_away<Interval>(), y).is_true());
  }
  EXPECT_GT(possible, 1000);
  EXPECT_GT(impossible, 1000);
}

// A 6 m x 4 m room open on its right side (x = 6): no wall to hear that way.
std::vector<Segment> open_room() {
  return {{0, 0, 6, 0}, {6, 4, 0, 4}, {0, 4, 0, 0}, {2, 1.5, 2, 2.5}, {2, 2.5, 2.6, 2.5}, {2.6, 2.5, 2.6, 1.5}, {2.6, 1.5, 2, 1.5}};
}

std::vector<RangeSensor> belt(double max_range, double blind) {
  std::vector<RangeSensor> sensors;
  for (int i = 0; i < 8; ++i) {
    const double a = i * 45 * kRadiansPerDegree;
    RangeSensor s{"s" + std::to_string(i), 0.25 * std::cos(a), 0.25 * std::sin(a), a, 11.3 * kRadiansPerDegree, 0.02};
    s.max_range = max_range;
    s.blind_distance = blind;
    sensors.push_back(s);
  }
  return sensors;
}

TEST(RangeNoEcho, SimulatorReportsNoEchoOnlyForSensorsWithAMaxRange) {
  const std::vector<Segment> walls = open_room();
  const LocalizationMap map{walls, {}};
  const Pose<double> truth{1.0, 1.0, 0.0};  // s0 looks out through the open side
  MeasurementSimulationOptions options;
  const auto unlimited = simulate_ranges(map, belt(kInf, 0.0), truth, options);
  EXPECT_EQ(unlimited.size(), 7u);  // the sensor without an echo is dropped, as before
  for (const RangeMeasurement& m : unlimited) EXPECT_FALSE(m.no_echo());
  const auto limited = simulate_ranges(map, belt(8.0, 0.3), truth, options);
  ASSERT_EQ(limited.size(), 8u);
  EXPECT_TRUE(limited[0].no_echo());
  // Seeds and poses: every datum holds at the truth, and some are "no echo".
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(0.5, 5.5), y(0.5, 3.5), th(-std::numbers::pi, std::numbers::pi);
  int no_echo = 0;
  for (std::uint32_t seed = 1; seed <= 200; ++seed) {
    const Pose<double> p{x(rng), y(rng), th(rng)};
    const std::vector<RangeSensor> sensors = belt(3.0, 0.3);
    options.seed = seed;
    for (const RangeMeasurement& m : simulate_ranges(map, sensors, p, options)) {
      no_echo += m.no_echo();
      const double f = simulated_range(p, sensors[m.sensor], std::span<const Segment>(walls));
      EXPECT_TRUE(feasible_range(m, sensors[m.sensor]).contains(f)) << seed << " sensor " << m.sensor << " f=" << f;
    }
  }
  EXPECT_GT(no_echo, 100);
}

std::size_t widest(const Box& box) {
  std::size_t d = 0;
  for (std::size_t k = 1; k < box.size(); ++k)
    if (box[k].width() > box[d].width()) d = k;
  return d;
}

// Data for the belt with a max range and a blind zone: simulated at `truth`, then
// some replaced by wrong values (random echoes and wrong "no echo"), so that the
// verdicts on boxes go both ways.
std::vector<RangeMeasurement> mixed_data(const std::vector<Segment>& walls, const std::vector<RangeSensor>& sensors,
                                         const Pose<double>& truth, std::mt19937& rng) {
  std::vector<RangeMeasurement> data = simulate_ranges({walls, {}}, sensors, truth, {});
  std::uniform_real_distribution<double> any(0.2, 3.0), coin(0, 1);
  for (RangeMeasurement& m : data)
    if (coin(rng) < 0.3) m.range = coin(rng) < 0.5 ? kNoEcho : any(rng);
  return data;
}

TEST(RangeNoEcho, RangeDataVerdictsHoldAtEveryPointOfRandomNestedBoxes) {
  const std::vector<Segment> walls = open_room();
  const std::vector<RangeSensor> sensors = belt(3.0, 0.35);
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> unit01(0, 1);
  int decided = 0, no_echo_true = 0, no_echo_false = 0;
  for (int path = 0; path < 100; ++path) {
    const Pose<double> truth{0.5 + 5 * unit01(rng), 0.5 + 3 * unit01(rng), (2 * unit01(rng) - 1) * std::numbers::pi};
    const std::vector<RangeMeasurement> data = mixed_data(walls, sensors, truth, rng);
    RangeData ranges(walls, sensors, data);
    std::vector<IBool> out(data.size(), IBool::maybe());
    Box box{Interval(-0.5, 6.5), Interval(-0.5, 4.5), Interval(-std::numbers::pi, std::numbers::pi)};
    // One random descent: a child always follows its father, as in SIVIA.
    for (int depth = 0; depth < 18; ++depth) {
      ranges.evaluate(box, depth, out, 99);
      const Pose<Interval> pb{box[0], box[1], box[2]};
      for (std::size_t i = 0; i < data.size(); ++i) {
        const Interval& y = ranges.feasible(i);
        const IBool full = member(simulated_range(pb, sensors[data[i].sensor], std::span<const Segment>(walls)), y);
        if (!full.is_maybe()) {
          EXPECT_TRUE(out[i] == full) << path << " " << depth << " " << i;  // pruning keeps the verdict
        }
        if (out[i].is_maybe()) continue;
        ++decided;
        if (data[i].no_echo()) (out[i].is_true() ? no_echo_true : no_echo_false) += 1;
        for (int k = 0; k < 10; ++k) {
          const Pose<double> p{box[0].lo() + box[0].width() * unit01(rng), box[1].lo() + box[1].width() * unit01(rng),
                               box[2].lo() + box[2].width() * unit01(rng)};
          const bool holds = y.contains(simulated_range(p, sensors[data[i].sensor], std::span<const Segment>(walls)));
          EXPECT_EQ(holds, out[i].is_true()) << path << " " << depth << " datum " << i << (data[i].no_echo() ? " (no echo)" : "");
        }
      }
      const std::size_t d = widest(box);
      const double m = box[d].mid();
      box[d] = unit01(rng) < 0.5 ? Interval(box[d].lo(), m) : Interval(m, box[d].hi());
    }
  }
  EXPECT_GT(decided, 2000);
  EXPECT_GT(no_echo_true, 100);
  EXPECT_GT(no_echo_false, 100);
}

TEST(RangeNoEcho, RangeDataVerdictsHoldAtTheEdgeOfMaxRange) {
  // A "no echo" whose bound M (1 - alpha) lies within 1 % of the true range, and boxes
  // shrinking onto the true pose: the points of the boxes fall on both sides of it.
  const std::vector<Segment> walls = open_room();
  std::mt19937 rng(83);
  std::uniform_real_distribution<double> unit01(0, 1), edge(-0.01, 0.01);
  int held = 0, failed = 0;
  for (int trial = 0; trial < 600; ++trial) {
    std::vector<RangeSensor> sensors = belt(kInf, 0.35);
    const Pose<double> truth{0.3 + 5.4 * unit01(rng), 0.3 + 3.4 * unit01(rng), (2 * unit01(rng) - 1) * std::numbers::pi};
    const std::size_t k = static_cast<std::size_t>(trial % 8);
    const double f = simulated_range(truth, sensors[k], std::span<const Segment>(walls));
    if (!std::isfinite(f)) continue;
    sensors[k].max_range = f / (1.0 - sensors[k].precision) * (1.0 + edge(rng));
    RangeData ranges(walls, sensors, {{k, kNoEcho}});
    std::vector<IBool> out(1, IBool::maybe());
    Box box{Interval(-0.5, 6.5), Interval(-0.5, 4.5), Interval(-std::numbers::pi, std::numbers::pi)};
    const double at[3] = {truth.x, truth.y, truth.theta};
    for (int depth = 0; depth < 26; ++depth) {
      ranges.evaluate(box, depth, out, 99);
      if (!out[0].is_maybe()) {
        for (int n = 0; n < 10; ++n) {
          const Pose<double> p{box[0].lo() + box[0].width() * unit01(rng), box[1].lo() + box[1].width() * unit01(rng),
                               box[2].lo() + box[2].width() * unit01(rng)};
          const bool holds = ranges.feasible(0).contains(simulated_range(p, sensors[k], std::span<const Segment>(walls)));
          EXPECT_EQ(holds, out[0].is_true()) << trial << " " << depth;
          (holds ? held : failed) += 1;
        }
      }
      // Bisect the widest side, keeping the half that holds the true pose.
      const std::size_t d = widest(box);
      const double m = box[d].mid();
      box[d] = at[d] <= m ? Interval(box[d].lo(), m) : Interval(m, box[d].hi());
    }
  }
  EXPECT_GT(held, 2000);
  EXPECT_GT(failed, 700);
}

TEST(RangeNoEcho, ContractorIgnoresNoEchoData) {
  const std::vector<Segment> walls = open_room();
  const std::vector<RangeSensor> sensors = belt(3.0, 0.3);
  const CtcRangeRelaxed ctc(walls, sensors, {{0, kNoEcho}, {3, kNoEcho}});
  Box box{Interval(1, 2), Interval(1, 2), Interval(-0.3, 0.3)};
  const Box before = box;
  ctc.contract(box);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(box[k], before[k]) << k;
}

TEST(RangeNoEcho, ContractorKeepsEveryPoseWhereTheDataHold) {
  // Truths with echoes (some at the blind distance) and "no echo"; boxes around them.
  const std::vector<Segment> walls = open_room();
  const std::vector<RangeSensor> sensors = belt(3.0, 0.35);
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> unit01(0, 1);
  int narrowed = 0, no_echo = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Pose<double> truth{0.3 + 5.4 * unit01(rng), 0.3 + 3.4 * unit01(rng), (2 * unit01(rng) - 1) * std::numbers::pi};
    MeasurementSimulationOptions o;
    o.seed = static_cast<std::uint32_t>(trial + 1);
    const std::vector<RangeMeasurement> data = simulate_ranges({walls, {}}, sensors, truth, o);
    for (const RangeMeasurement& m : data) no_echo += m.no_echo();
    const CtcRangeRelaxed ctc(walls, sensors, data);
    const double h = 0.02 + 0.5 * unit01(rng), a = 0.01 + 0.3 * unit01(rng);
    Box box{Interval(truth.x - h * unit01(rng), truth.x + h * unit01(rng)),
            Interval(truth.y - h * unit01(rng), truth.y + h * unit01(rng)),
            Interval(truth.theta - a * unit01(rng), truth.theta + a * unit01(rng))};
    const double area = box[0].width() * box[1].width();
    ctc.contract(box);
    ASSERT_TRUE(box[0].contains(truth.x) && box[1].contains(truth.y)) << trial;
    narrowed += box[0].width() * box[1].width() < area;
  }
  EXPECT_GT(no_echo, 200);
  EXPECT_GT(narrowed, 50);
}

}  // namespace
}  // namespace gesmi
