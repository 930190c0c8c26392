// MissionReadings::released_after_use (solve_mission.h): the solve empties the DVL and
// depth readings once its sensor enclosures are built. Its results must be bit for bit
// those of the solve that keeps them, in every mode; an inconsistent cold solve leaves
// its diagnosis pending, and diagnose_inconsistency() on the mission with its readings
// gives the diagnosis and the message the keeping solve gives. A warm rerun from a
// result its caller gives up (MissionSolution&&) is the same as from one it keeps.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

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
// others fall between two samples, where the networks read the DVL (DvlExcerpt).
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
// per-sample DVL and depth half-widths (released too), and marks and fixes between
// samples.
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

void expect_released(Mission& m) {
  EXPECT_TRUE(readings_released(m));
  for (const std::vector<double>* v : released_readings(m)) {
    EXPECT_TRUE(v->empty());
    EXPECT_EQ(v->capacity(), 0u) << "emptied but its memory kept";
  }
  // What the waterfall and the result still read.
  for (const auto* v : {&m.time, &m.roll, &m.pitch, &m.heading, &m.altitude}) EXPECT_EQ(v->size(), m.time.size());
}

TEST(DvlExcerpt, HoldsTheSamplesOnBothSidesOfEachTime) {
  Mission m;
  m.time = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  m.vx = {10.0, 11.0, 12.0, 13.0, 14.0, 15.0};
  m.vy = {20.0, 21.0, 22.0, 23.0, 24.0, 25.0};
  m.vz = {30.0, 31.0, 32.0, 33.0, 34.0, 35.0};
  m.half_widths.vy = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  const std::vector<double> times = {3.0, 1.5};  // on the grid at 3, between 1 and 2
  const DvlExcerpt dvl(m, times);
  EXPECT_EQ(dvl.size(), 3u);  // 1 and 2 around 1.5; 3 and the one before it
  for (const std::size_t k : {1u, 2u, 3u}) {
    const DvlSample& s = dvl.at(k);
    EXPECT_EQ(s.reading[0], m.vx[k]);
    EXPECT_EQ(s.reading[1], m.vy[k]);
    EXPECT_EQ(s.reading[2], m.vz[k]);
    EXPECT_FALSE(s.given[0]);
    EXPECT_TRUE(s.given[1]);
    EXPECT_EQ(s.half_width[1], m.half_widths.vy[k]);
  }
  EXPECT_THROW(dvl.at(0), std::logic_error);
  EXPECT_THROW(dvl.at(4), std::logic_error);
  m.vx.clear();
  EXPECT_THROW(DvlSample::of(m, 1), std::logic_error);
}

TEST(ReleasedReadings, TheTestMissionsHaveMarksAndFixesBetweenSamples) {
  for (const std::uint64_t seed : {5u, 6u, 31u}) {
    SCOPED_TRACE(seed);
    const Mission m = mission_with_margins(seed, seed == 31 ? 1 : 0);
    const MissionNetwork net = build_network(m, m.model, gps_fixes(m));
    std::size_t marks = 0, fixes = 0;
    for (const Detection& d : net.detections) marks += d.at.on_grid ? 0 : 1;
    for (const Anchor& a : net.anchors) fixes += a.at.on_grid ? 0 : 1;
    EXPECT_GE(marks, 3u);
    EXPECT_EQ(fixes, 1u);
  }
}

TEST(ReleasedReadings, ColdSolvesAreTheSameBitForBit) {
  const Mission kept = mission_with_margins(5, 0);
  Mission released = kept;
  const MissionSolution a = solve_mission(kept);
  const MissionSolution b = solve_mission(released, {}, MissionReadings::released_after_use);
  ASSERT_TRUE(a.report.consistent);
  expect_same_solution(a, b);
  expect_released(released);
}

// Both outlier modes, on a mission with a wrong mark (q* = 1) and without.
TEST(ReleasedReadings, OutlierSolvesAreTheSameBitForBit) {
  for (const int wrong : {0, 1})
    for (const OutlierMode mode : {OutlierMode::relaxed, OutlierMode::minimal}) {
      SCOPED_TRACE(::testing::Message() << wrong << " wrong mark, mode " << static_cast<int>(mode));
      const Mission kept = mission_with_margins(wrong ? 31 : 5, wrong);
      SolveOptions options;
      options.max_outliers = 1;
      options.outlier_mode = mode;
      Mission released = kept;
      const MissionSolution a = solve_mission(kept, options);
      const MissionSolution b = solve_mission(released, options, MissionReadings::released_after_use);
      ASSERT_TRUE(a.report.consistent);
      EXPECT_EQ(a.report.minimal_outliers, wrong);
      expect_same_solution(a, b);
      expect_released(released);
    }
}

TEST(ReleasedReadings, AWarmRerunIsTheSameBitForBit) {
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
  Mission released = m;
  const MissionSolution a = solve_mission(m, warm);
  const MissionSolution b = solve_mission(released, warm, MissionReadings::released_after_use);
  ASSERT_EQ(a.report.mode, SolveMode::warm) << a.report.cold_fallback.value_or("");
  EXPECT_EQ(b.report.mode, SolveMode::warm);
  expect_same_solution(a, b);
  expect_released(released);
  // The earlier result given up (solve_mission(..., MissionSolution&&), as `gesmi solve
  // --from` calls it): the same solution, its increments taken, not copied.
  MissionSolution given_up = first;
  const Interval* increments[3] = {given_up.domains.dx.data(), given_up.domains.dy.data(), given_up.domains.dz.data()};
  Mission released_again = m;
  const MissionSolution e =
      solve_mission(released_again, SolveOptions{}, MissionReadings::released_after_use, std::move(given_up));
  EXPECT_EQ(e.report.mode, SolveMode::warm);
  expect_same_solution(a, e);
  EXPECT_EQ(e.domains.dx.data(), increments[0]) << "the increments were copied, not taken";
  EXPECT_EQ(e.domains.dy.data(), increments[1]);
  EXPECT_EQ(e.domains.dz.data(), increments[2]);

  // A rerun the earlier result cannot warm-start (a mark edited) is solved cold, the
  // earlier result kept or given up.
  Mission edited = m;
  edited.mark_range[0] += 0.5;
  Mission edited_released = edited, edited_released_again = edited;
  const MissionSolution c = solve_mission(edited, warm);
  const MissionSolution d = solve_mission(edited_released, warm, MissionReadings::released_after_use);
  ASSERT_EQ(c.report.mode, SolveMode::cold);
  ASSERT_TRUE(c.report.cold_fallback.has_value());
  expect_same_solution(c, d);
  expect_released(edited_released);
  MissionSolution given_up_again = first;
  expect_same_solution(c, solve_mission(edited_released_again, SolveOptions{}, MissionReadings::released_after_use,
                                        std::move(given_up_again)));
}

TEST(ReleasedReadings, AnInconsistentSolveIsDiagnosedOnTheMissionReadAgain) {
  const Mission kept = mission_with_margins(31, 1);
  const MissionSolution a = solve_mission(kept);
  ASSERT_FALSE(a.report.consistent);
  ASSERT_TRUE(a.report.explained_by.has_value());
  ASSERT_FALSE(a.report.explained_by->empty()) << a.report.message;

  Mission released = kept;
  MissionSolution b = solve_mission(released, {}, MissionReadings::released_after_use);
  EXPECT_FALSE(b.report.consistent);
  EXPECT_TRUE(b.report.diagnosis_pending);
  EXPECT_FALSE(b.report.explained_by.has_value());
  expect_released(released);
  EXPECT_THROW(diagnose_inconsistency(released, {}, b), std::invalid_argument);
  // Readings put back into another mission (a mark edited, other bounds): refused.
  Mission other = kept;
  other.mark_range[0] += 1.0;
  EXPECT_THROW(diagnose_inconsistency(other, {}, b), std::invalid_argument);
  other = kept;
  other.model.mark_range *= 2.0;
  EXPECT_THROW(diagnose_inconsistency(other, {}, b), std::invalid_argument);
  EXPECT_TRUE(b.report.diagnosis_pending);

  // The readings put back into the mission solved, as gesmi solve does.
  const auto from = released_readings(other = kept), to = released_readings(released);
  for (std::size_t i = 0; i < to.size(); ++i) *to[i] = std::move(*from[i]);
  EXPECT_FALSE(readings_released(released));
  diagnose_inconsistency(released, {}, b);
  EXPECT_FALSE(b.report.diagnosis_pending);
  ASSERT_TRUE(b.report.explained_by.has_value());
  EXPECT_EQ(*b.report.explained_by, *a.report.explained_by);
  EXPECT_EQ(b.report.message, a.report.message);
  EXPECT_EQ(b.timings_ms.count("diagnose"), 1u);

  // Without a diagnosis asked for, none is pending.
  SolveOptions quiet;
  quiet.diagnose = false;
  Mission again = kept;
  EXPECT_FALSE(solve_mission(again, quiet, MissionReadings::released_after_use).report.diagnosis_pending);
}

TEST(ReleasedReadings, KeptReadingsAreLeftAlone) {
  Mission m = mission_with_margins(5, 0);
  const Mission copy = m;
  solve_mission(m, {}, MissionReadings::kept);
  EXPECT_EQ(m.vx, copy.vx);
  EXPECT_EQ(m.depth, copy.depth);
  EXPECT_EQ(m.half_widths.vz, copy.half_widths.vz);
}

}  // namespace
}  // namespace gesmi
