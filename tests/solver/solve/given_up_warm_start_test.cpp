// A warm rerun from a result its caller gives up (solve_mission(..., MissionSolution&&),
// as `gesmi solve --from` calls it) is bit for bit the same as from one it keeps, and
// takes the earlier increments instead of copying them.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace gesmi {
namespace {

bool bitwise_equal(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Interval)) == 0;
}

void expect_same_solution(const MissionSolution& a, const MissionSolution& b) {
  const SolveReport &r = a.report, &q = b.report;
  EXPECT_EQ(r.mode, q.mode);
  EXPECT_EQ(r.consistent, q.consistent);
  EXPECT_EQ(r.sweeps, q.sweeps);
  EXPECT_EQ(r.message, q.message);
  EXPECT_EQ(r.cold_fallback, q.cold_fallback);
  EXPECT_EQ(r.beyond_frame_zone, q.beyond_frame_zone);
  EXPECT_EQ(r.minimal_outliers, q.minimal_outliers);
  EXPECT_EQ(r.hypotheses, q.hypotheses);
  EXPECT_EQ(r.removal_sets, q.removal_sets);
  EXPECT_EQ(r.consistent_removal_sets, q.consistent_removal_sets);
  EXPECT_EQ(a.mark_outlier, b.mark_outlier);
  EXPECT_EQ(a.gps_outlier, b.gps_outlier);
  for (const auto member : {&TubeDomains::px, &TubeDomains::py, &TubeDomains::pz, &TubeDomains::dx, &TubeDomains::dy,
                            &TubeDomains::dz})
    EXPECT_TRUE(bitwise_equal(a.domains.*member, b.domains.*member));
  ASSERT_EQ(a.domains.mines.size(), b.domains.mines.size());
  for (std::size_t i = 0; i < a.domains.mines.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(a.domains.mines[i][c].lo(), b.domains.mines[i][c].lo());
      EXPECT_EQ(a.domains.mines[i][c].hi(), b.domains.mines[i][c].hi());
    }
  EXPECT_EQ(a.candidates, b.candidates);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.waterfall.step, b.waterfall.step);
  EXPECT_EQ(a.waterfall.mine, b.waterfall.mine);
  EXPECT_EQ(a.waterfall.lower, b.waterfall.lower);
  EXPECT_EQ(a.waterfall.upper, b.waterfall.upper);
}

// Every other sample of the navigation (and the last): the marks and fixes at the
// others fall between two samples.
void keep_every_other_sample(Mission& m) {
  const std::size_t n = m.size();
  // And one more GPS fix, true within its bound, at a sample to be dropped (the
  // simulator's are at the first and last samples).
  const std::size_t dropped = n / 2 | 1;
  const auto second = [](auto& v, auto value) { v.insert(v.begin() + 1, value); };
  second(m.gps_time, m.time[dropped]);
  second(m.gps_north, m.truth_x[dropped] + 0.5 * m.model.gps_metres);
  second(m.gps_east, m.truth_y[dropped] - 0.5 * m.model.gps_metres);
  second(m.gps_north_halfwidth, m.model.gps_metres);
  second(m.gps_east_halfwidth, m.model.gps_metres);
  for (std::vector<double>* v : {&m.gps_longitude, &m.gps_latitude})
    if (!v->empty()) second(*v, v->front());
  if (!m.truth_gps_outlier.empty()) second(m.truth_gps_outlier, 0);
  for (std::vector<double>* v : {&m.time, &m.roll, &m.pitch, &m.heading, &m.vx, &m.vy, &m.vz, &m.altitude, &m.depth,
                                 &m.truth_x, &m.truth_y, &m.truth_z}) {
    std::vector<double> kept;
    for (std::size_t k = 0; k < n; ++k)
      if (k % 2 == 0 || k + 1 == n) kept.push_back((*v)[k]);
    *v = std::move(kept);
  }
}

// A simulated mission with frame margins (two passes, as io/ sets them for real logs),
// per-sample DVL and depth half-widths, and marks and fixes between samples.
Mission mission_with_margins(std::uint64_t seed, int outliers) {
  SimulationOptions o;
  o.seed = seed;
  o.duration = 2000.0;
  o.missed = 0.4;
  o.outliers = outliers;
  Mission m = simulate_mission(o);
  keep_every_other_sample(m);
  m.heading_frame_margin = 1e-3;
  m.frame_scale_margin = 1e-5;
  // (a little wider than the model's bounds, which the simulated errors respect)
  const SensorModel& b = m.model;
  const std::vector<double>* readings[3] = {&m.vx, &m.vy, &m.vz};
  std::vector<double>* widths[3] = {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz};
  for (int c = 0; c < 3; ++c)
    for (const double v : *readings[c]) widths[c]->push_back(b.dvl_relative * std::fabs(v) + b.dvl_absolute + 1e-3);
  for (const double d : m.depth) m.half_widths.depth.push_back(b.depth_absolute + b.depth_relative * std::fabs(d) + 0.1);
  return m;
}

TEST(GivenUpWarmStart, IsTheSameBitForBitAsAKeptOne) {
  Mission m = mission_with_margins(6, 0);
  const MissionSolution first = solve_mission(m);
  ASSERT_TRUE(first.report.consistent);
  ASSERT_GE(m.truth_missed_marks.size(), 3u);
  m.mark_time.push_back(m.truth_missed_marks[0]);
  m.mark_mine.push_back(static_cast<std::int32_t>(m.truth_missed_marks[1]));
  m.mark_range.push_back(m.truth_missed_marks[2]);
  m.mark_side.push_back(1);
  SolveOptions warm;
  warm.warm_from = &first;
  const MissionSolution a = solve_mission(m, warm);
  ASSERT_EQ(a.report.mode, SolveMode::warm) << a.report.cold_fallback.value_or("");
  // The earlier result given up (as `gesmi solve --from` does): the same solution, its
  // increments taken, not copied.
  MissionSolution given_up = first;
  const Interval* increments[3] = {given_up.domains.dx.data(), given_up.domains.dy.data(), given_up.domains.dz.data()};
  const MissionSolution e = solve_mission(m, SolveOptions{}, std::move(given_up));
  EXPECT_EQ(e.report.mode, SolveMode::warm);
  expect_same_solution(a, e);
  EXPECT_EQ(e.domains.dx.data(), increments[0]) << "the increments were copied, not taken";
  EXPECT_EQ(e.domains.dy.data(), increments[1]);
  EXPECT_EQ(e.domains.dz.data(), increments[2]);

  // A rerun the earlier result cannot warm-start (a mark edited) is solved cold, the
  // earlier result kept or given up.
  Mission edited = m;
  edited.mark_range[0] += 0.5;
  const MissionSolution c = solve_mission(edited, warm);
  ASSERT_EQ(c.report.mode, SolveMode::cold);
  ASSERT_TRUE(c.report.cold_fallback.has_value());
  MissionSolution given_up_again = first;
  expect_same_solution(c, solve_mission(edited, SolveOptions{}, std::move(given_up_again)));
}

}  // namespace
}  // namespace gesmi
