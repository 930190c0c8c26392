// Channels enclosed between their readings (solver/mission/between_readings.h):
// rate-bounded true signals, readings off by up to their bounds (at the bounds'
// ends too), grid times between them; every grid box must hold the truth.
#include "solver/mission/between_readings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace gesmi {
namespace {


// y(t) = a sin(w t + p) + b t with |y'| <= a w + |b| = rate.
struct Signal {
  double a, w, p, b;
  double operator()(double t) const { return a * std::sin(w * t + p) + b * t; }
};

Signal random_signal(std::mt19937_64& rng, double rate) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double share = u(rng);  // of the rate taken by the sine
  const double w = 0.05 + 2.0 * u(rng);
  return {share * rate / w, w, 2.0 * std::numbers::pi * u(rng), (u(rng) < 0.5 ? -1.0 : 1.0) * (1.0 - share) * rate};
}

double wrapped(double angle) { return std::remainder(angle, 2.0 * std::numbers::pi); }

struct Case {
  ChannelReadings readings;
  std::vector<double> grid;
};

// Readings every ~`every` s with jitter, errors anywhere in [-e, e] (a third at the
// ends, to a relative 1e-9); the grid at 10 Hz over the same span and beyond its ends.
Case make_case(std::mt19937_64& rng, const Signal& y, double every, double e, bool wrap) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Case c;
  for (double t = 0.3 * u(rng); t < 120.0; t += every * (0.5 + u(rng))) {
    // Just inside the bound: the reading y + error is rounded, and the box must hold y.
    const double pick = u(rng), edge = e * (1.0 - 1e-9);
    const double error = pick < 1.0 / 3 ? edge : pick < 2.0 / 3 ? -edge : edge * (2.0 * u(rng) - 1.0);
    c.readings.time.push_back(t);
    c.readings.value.push_back(wrap ? wrapped(y(t) + error) : y(t) + error);
    c.readings.half_width.push_back(e);
  }
  for (int k = 0; k < 1220; ++k) c.grid.push_back(-1.0 + 0.1 * k);
  // Some grid times exactly on readings.
  for (std::size_t i = 0; i < c.readings.time.size(); i += 3) c.grid.push_back(c.readings.time[i]);
  std::sort(c.grid.begin(), c.grid.end());
  return c;
}

TEST(BetweenReadings, EveryGridBoxHoldsTheRateBoundedTruth) {
  std::mt19937_64 rng(11);
  std::size_t checked = 0, own = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double rate = trial % 2 ? 0.5 : 0.05, e = trial % 3 ? 1.5 : 1e-3;
    const Signal y = random_signal(rng, rate);
    const Case c = make_case(rng, y, trial % 4 ? 1.0 : 7.0, e, false);
    const ChannelAtGrid at = enclose_between_readings(c.readings, c.grid, rate, false);
    ASSERT_FALSE(at.conflict) << "trial " << trial;
    for (std::size_t k = 0; k < c.grid.size(); ++k) {
      const double truth = y(c.grid[k]);
      ASSERT_LE(std::fabs(truth - at.value[k]), at.half_width[k]) << "trial " << trial << " t " << c.grid[k];
      ++checked;
      own += at.own_reading[k];
    }
  }
  EXPECT_GT(checked, 200000u);
  EXPECT_GT(own, 5000u);
}

TEST(BetweenReadings, HeadingsAcrossTheWrapHoldTheTruthModuloTwoPi) {
  std::mt19937_64 rng(5);
  std::size_t checked = 0, wraps = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double rate = 0.05, e = 5.27e-3;
    Signal y = random_signal(rng, rate);
    y.p += std::numbers::pi;  // start near the wrap: the drift and the sine cross +-pi
    const Case c = make_case(rng, y, trial % 4 ? 0.05 : 40.0, e, true);
    const ChannelAtGrid at = enclose_between_readings(c.readings, c.grid, rate, true);
    ASSERT_FALSE(at.conflict) << "trial " << trial;
    for (std::size_t i = 1; i < c.readings.value.size(); ++i)
      wraps += std::fabs(c.readings.value[i] - c.readings.value[i - 1]) > std::numbers::pi;
    for (std::size_t k = 0; k < c.grid.size(); ++k) {
      const double off = wrapped(y(c.grid[k]) - at.value[k]);
      ASSERT_LE(std::fabs(off), at.half_width[k]) << "trial " << trial << " t " << c.grid[k];
      ++checked;
    }
  }
  EXPECT_GT(checked, 200000u);
  EXPECT_GT(wraps, 50u);  // the readings do jump across +-pi
}

// Readings far apart at a high turn rate: several 2 pi branches are within reach, and
// only a one-sided box is sound (an intersection across branches lost the truth).
TEST(BetweenReadings, HeadingsFarApartKeepTheTruthWhenSeveralBranchesAreWithinReach) {
  std::mt19937_64 rng(9);
  std::size_t checked = 0, wraps = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double rate = 0.3, e = 5.27e-3;
    Signal y = random_signal(rng, rate);
    y.p += std::numbers::pi;
    const Case c = make_case(rng, y, trial % 2 ? 15.0 : 40.0, e, true);
    const ChannelAtGrid at = enclose_between_readings(c.readings, c.grid, rate, true);
    ASSERT_FALSE(at.conflict) << "trial " << trial;
    for (std::size_t i = 1; i < c.readings.value.size(); ++i)
      wraps += std::fabs(c.readings.value[i] - c.readings.value[i - 1]) > std::numbers::pi;
    for (std::size_t k = 0; k < c.grid.size(); ++k) {
      ASSERT_LE(std::fabs(wrapped(y(c.grid[k]) - at.value[k])), at.half_width[k]) << "trial " << trial << " t " << c.grid[k];
      ++checked;
    }
  }
  EXPECT_GT(checked, 200000u);
  EXPECT_GT(wraps, 50u);
  // The review's case: 1 rad at t = 0, 5.5 rad (= -0.783) at t = 10, exact readings,
  // 0.5 rad/s: the path through 0 is at -0.07 rad at t = 6.
  const ChannelReadings r{{0.0, 10.0}, {1.0, 5.5}, {0.0, 0.0}};
  const std::vector<double> grid = {6.0};
  const ChannelAtGrid at = enclose_between_readings(r, grid, 0.5, true);
  ASSERT_FALSE(at.conflict);
  EXPECT_LE(std::fabs(wrapped(1.0 - (1.0 - (5.5 - 2.0 * std::numbers::pi)) * 0.6 - at.value[0])), at.half_width[0]);
}

TEST(BetweenReadings, BoxesAreTheReadingAtItsTimeAndTheNarrowerSideBetween) {
  ChannelReadings r{{0.0, 10.0}, {5.0, 6.0}, {1.0, 1.0}};
  const std::vector<double> grid = {-2.0, 0.0, 1.0, 9.0, 10.0, 12.0};
  const ChannelAtGrid at = enclose_between_readings(r, grid, 0.5, false);
  ASSERT_FALSE(at.conflict);
  // Before the first and after the last: one side, widened by 0.5 per second.
  EXPECT_NEAR(at.value[0], 5.0, 1e-12);
  EXPECT_NEAR(at.half_width[0], 2.0, 1e-12);
  EXPECT_EQ(at.value[1], 5.0);
  EXPECT_EQ(at.half_width[1], 1.0);
  EXPECT_EQ(at.own_reading[1], 1);
  // At t = 1: [3.5, 6.5] from the first, [0.5, 11.5] from the second: the first.
  EXPECT_NEAR(at.value[2] - at.half_width[2], 3.5, 1e-12);
  EXPECT_NEAR(at.value[2] + at.half_width[2], 6.5, 1e-12);
  // At t = 9: [0.5, 9.5] and [4.5, 7.5].
  EXPECT_NEAR(at.value[3] - at.half_width[3], 4.5, 1e-12);
  EXPECT_NEAR(at.value[3] + at.half_width[3], 7.5, 1e-12);
  EXPECT_NEAR(at.half_width[5], 2.0, 1e-12);
}

TEST(BetweenReadings, ReadingsTheRateCannotJoinAreAConflictNamingBoth) {
  ChannelReadings r{{0.0, 1.0, 2.0}, {0.0, 0.1, 9.0}, {0.5, 0.5, 0.5}};
  const std::vector<double> grid = {0.0, 0.5, 1.5, 2.0};
  const ChannelAtGrid at = enclose_between_readings(r, grid, 1.0, false);
  ASSERT_TRUE(at.conflict);
  EXPECT_EQ(at.conflict->grid, 2u);
  EXPECT_EQ(at.conflict->before, 1u);
  EXPECT_EQ(at.conflict->after, 2u);
}

}  // namespace
}  // namespace gesmi
