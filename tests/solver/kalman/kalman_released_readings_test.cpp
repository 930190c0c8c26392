// MissionReadings::released_after_use for the smoother (kalman_smoother.h): without
// biases the readings only the dead reckoning reads are emptied once it is done, and
// the result is bit for bit that of a smoothing that keeps them; with biases nothing is
// released. The marks' samples kept aside are checked against the mission's own arrays
// at each mark's step, found here by a plain scan.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "solver/kalman/kalman_measurements.h"
#include "solver/kalman/kalman_smoother.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace gesmi {
namespace {

Mission simulated(std::uint64_t seed) {
  SimulationOptions so;
  so.seed = seed;
  so.duration = 1800.0;
  return simulate_mission(so);
}

// Per-sample half-widths on every reading (the smoother reads none of them).
void give_half_widths(Mission& m) {
  NavHalfWidths& h = m.half_widths;
  for (std::vector<double>* v : {&h.roll, &h.pitch, &h.heading, &h.vx, &h.vy, &h.vz, &h.depth, &h.altitude})
    v->assign(m.size(), 0.01);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_bits(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(same_bits(a[i], b[i])) << what << "[" << i << "]: " << a[i] << " vs " << b[i];
}

void expect_same_result(const KalmanResult& a, const KalmanResult& b) {
  expect_same_bits(a.mean, b.mean, "mean");
  expect_same_bits(a.covariance, b.covariance, "covariance");
  expect_same_bits(a.mine_mean, b.mine_mean, "mine_mean");
  expect_same_bits(a.mine_covariance, b.mine_covariance, "mine_covariance");
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_TRUE(same_bits(a.last_step, b.last_step));
  EXPECT_TRUE(same_bits(a.consistency.chi2, b.consistency.chi2));
  ASSERT_EQ(a.tests.size(), b.tests.size());
  for (std::size_t i = 0; i < a.tests.size(); ++i) {
    EXPECT_TRUE(same_bits(a.tests[i].chi2, b.tests[i].chi2)) << "test " << i;
    EXPECT_TRUE(same_bits(a.tests[i].max_normalised, b.tests[i].max_normalised)) << "test " << i;
  }
  for (int c = 0; c < kBiasCount; ++c) EXPECT_TRUE(same_bits(a.bias_estimate[c], b.bias_estimate[c])) << "bias " << c;
}

TEST(KalmanReleasedReadings, ReleasesWhatOnlyTheDeadReckoningReadsAndChangesNoBit) {
  Mission m = simulated(3);
  give_half_widths(m);
  ASSERT_GT(m.mark_count(), 0u);
  const auto fixes = gps_fixes(m);
  const KalmanResult kept = kalman_smooth(m, m.model, fixes);
  Mission released = m;
  const KalmanResult r = kalman_smooth(released, released.model, fixes, {}, MissionReadings::released_after_use);
  expect_same_result(kept, r);
  for (const std::vector<double>* v : {&released.vx, &released.vy, &released.vz, &released.roll, &released.pitch,
                                       &released.heading, &released.altitude})
    EXPECT_TRUE(v->empty() && v->capacity() == 0);
  const NavHalfWidths& h = released.half_widths;
  for (const std::vector<double>* v : {&h.roll, &h.pitch, &h.heading, &h.vx, &h.vy, &h.vz, &h.depth, &h.altitude})
    EXPECT_TRUE(v->empty() && v->capacity() == 0);
  // What the passes and the command after them read stays.
  EXPECT_EQ(released.time, m.time);
  EXPECT_EQ(released.depth, m.depth);
  EXPECT_EQ(released.mark_time, m.mark_time);
  EXPECT_TRUE(readings_released(released));
  // A smoothing or a solve needs the readings: refused, not read out of bounds.
  EXPECT_THROW(kalman_smooth(released, released.model, fixes), std::logic_error);
  EXPECT_THROW(solve_mission(released), std::invalid_argument);
}

// Marks on a mission without samples: no sample to keep aside, nothing read.
TEST(KalmanReleasedReadings, AMissionWithoutSamplesKeepsNoMarkSample) {
  Mission m;
  m.mine_count = 1;
  m.mark_time = {10.0};
  m.mark_range = {20.0};
  m.mark_mine = {0};
  m.mark_side = {1};
  EXPECT_TRUE(mark_samples(m).empty());
  const KalmanResult r = kalman_smooth(m, m.model, {}, {}, MissionReadings::released_after_use);
  EXPECT_EQ(r.steps, 0u);
  EXPECT_TRUE(std::isnan(r.mine_mean.at(0)));
}

TEST(KalmanReleasedReadings, KeepsEverythingWhenAskedOrWithBiases) {
  const Mission m = simulated(4);
  const auto fixes = gps_fixes(m);
  Mission kept_copy = m;
  const KalmanResult k = kalman_smooth(kept_copy, kept_copy.model, fixes, {}, MissionReadings::kept);
  EXPECT_FALSE(readings_released(kept_copy));
  // With biases every pass linearises the odometry again from the readings.
  KalmanOptions biases;
  biases.biases = true;
  biases.max_iterations = 3;
  const KalmanResult a = kalman_smooth(m, m.model, fixes, biases);
  Mission with_biases = m;
  const KalmanResult b = kalman_smooth(with_biases, with_biases.model, fixes, biases, MissionReadings::released_after_use);
  EXPECT_FALSE(readings_released(with_biases));
  EXPECT_EQ(with_biases.vx, m.vx);
  EXPECT_EQ(with_biases.heading, m.heading);
  expect_same_result(a, b);
  EXPECT_GT(k.iterations, 0);
}

// The samples kept for the marks are the mission's at the first sample at or after each
// mark's time (the last sample when none is), found here by a scan.
TEST(KalmanReleasedReadings, MarkSamplesAreTheMissionsAtEachMarksStep) {
  Mission m = simulated(5);
  // A mark at a sample's own time, one just after it, and one at the mission's end.
  m.mark_time.push_back(m.time[1234]);
  m.mark_time.push_back(std::nextafter(m.time[2345], m.time[2346]));
  m.mark_time.push_back(m.time.back());
  for (int extra = 0; extra < 3; ++extra) {
    m.mark_mine.push_back(-1);
    m.mark_range.push_back(20.0);
    m.mark_side.push_back(1);
  }
  const std::vector<MarkSample> samples = mark_samples(m);
  ASSERT_EQ(samples.size(), m.mark_count());
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    std::size_t k = 0;
    while (k + 1 < m.size() && m.time[k] < m.mark_time[j]) ++k;
    EXPECT_EQ(samples[j].roll, m.roll[k]) << "mark " << j;
    EXPECT_EQ(samples[j].pitch, m.pitch[k]) << "mark " << j;
    EXPECT_EQ(samples[j].heading, m.heading[k]) << "mark " << j;
    EXPECT_EQ(samples[j].altitude, m.altitude[k]) << "mark " << j;
  }
  EXPECT_EQ(samples[m.mark_count() - 3].heading, m.heading[1234]);
  EXPECT_EQ(samples[m.mark_count() - 2].heading, m.heading[2346]);
  EXPECT_EQ(samples[m.mark_count() - 1].heading, m.heading.back());
}

}  // namespace
}  // namespace gesmi
