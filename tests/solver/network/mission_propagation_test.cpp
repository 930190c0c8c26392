// The mission solve's sweeps leave out the chains' steps nothing narrowed since the
// last sweep (steps_to_sweep.h): a solve must end exactly where full sweeps end, with
// the same number of sweeps, tube, mines, candidates and report.

#include "solver/network/detail/mission_propagation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver/sim/simulator.h"
#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

// solve() with every step of every chain swept each time: the chains through the full
// sweeps (chain_sweep.h), the fixes and detections through MissionPropagation, which
// makes no marks when it is not the one sweeping.
SolverReport solve_with_full_sweeps(const MissionNetwork& net, TubeDomains& d, const SolverOptions& options) {
  SolverReport report;
  detail::MissionPropagation propagation(net, d);
  const auto chains = [&](bool forward, double& move) {
    const std::array<std::span<Interval>, 3> p{d.px, d.py, d.pz};
    const ChainsSweepResult r =
        forward ? chains_forward(p, {std::span<const Interval>(d.dx), std::span<const Interval>(d.dy),
                                     std::span<const Interval>(d.dz)})
                : chains_backward(p, {std::span<Interval>(d.dx), std::span<Interval>(d.dy), std::span<Interval>(d.dz)});
    if (!r.consistent()) {
      report.inconsistency = propagation.evolution_failure(r.chain, r.sweep.first_empty, forward);
      return false;
    }
    move = std::max(move, r.sweep.max_shrink);
    return true;
  };
  while (report.sweeps < options.max_sweeps) {
    double move = 0.0;
    const bool ok = chains(true, move) && propagation.sparse(move, report.inconsistency) && chains(false, move) &&
                    propagation.sparse(move, report.inconsistency);
    ++report.sweeps;
    if (!ok) return report;
    report.last_move = move;
    if (move <= options.tolerance) {
      report.converged = true;
      return report;
    }
  }
  return report;
}

void expect_same(const std::vector<Interval>& full, const std::vector<Interval>& marked, const char* what) {
  ASSERT_EQ(full.size(), marked.size()) << what;
  for (std::size_t k = 0; k < full.size(); ++k) {
    ASSERT_EQ(full[k].lo(), marked[k].lo()) << what << " " << k;
    ASSERT_EQ(full[k].hi(), marked[k].hi()) << what << " " << k;
  }
}

void expect_same_solve(const Mission& mission, std::span<const PositionFix> fixes, const SolverOptions& options) {
  const MissionNetwork net = build_network(mission, mission.model, fixes);
  TubeDomains full = initial_domains(mission, mission.model, net);
  TubeDomains marked = full;
  const SolverReport f = solve_with_full_sweeps(net, full, options);
  const SolverReport m = solve(net, marked, options);
  EXPECT_EQ(f.sweeps, m.sweeps);
  EXPECT_EQ(f.converged, m.converged);
  EXPECT_EQ(f.last_move, m.last_move);
  ASSERT_EQ(f.consistent(), m.consistent());
  if (!f.consistent()) {
    EXPECT_EQ(f.inconsistency->kind, m.inconsistency->kind);
    EXPECT_EQ(f.inconsistency->step, m.inconsistency->step);
    EXPECT_EQ(f.inconsistency->axis, m.inconsistency->axis);
    return;
  }
  expect_same(full.px, marked.px, "north");
  expect_same(full.py, marked.py, "east");
  expect_same(full.pz, marked.pz, "down");
  expect_same(full.dx, marked.dx, "north step");
  expect_same(full.dy, marked.dy, "east step");
  expect_same(full.dz, marked.dz, "down step");
  ASSERT_EQ(full.mines.size(), marked.mines.size());
  for (std::size_t i = 0; i < full.mines.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(full.mines[i][c].lo(), marked.mines[i][c].lo()) << "mine " << i;
      EXPECT_EQ(full.mines[i][c].hi(), marked.mines[i][c].hi()) << "mine " << i;
    }
  EXPECT_EQ(full.candidates, marked.candidates);
}

TEST(MissionPropagation, SweepsOverTheMarkedStepsEndWhereFullSweepsEnd) {
  for (const test::TinyErrors errors : {test::TinyErrors::uniform, test::TinyErrors::worst_case})
    for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
      SCOPED_TRACE(::testing::Message() << "tiny mission, seed " << seed);
      const test::TinyMission t = test::make_tiny_mission(seed, errors);
      expect_same_solve(t.mission, t.fixes, {});
    }
  // A survey with unassociated marks (disjunctions) and off-grid fixes, solved to a tighter
  // tolerance than the default (more sweeps, which move less and less of the tube).
  for (const std::uint64_t seed : {2u, 5u}) {
    SCOPED_TRACE(::testing::Message() << "simulated survey, seed " << seed);
    SimulationOptions o;
    o.seed = seed;
    o.duration = 1500.0;
    o.missed = 0.3;
    const Mission m = simulate_mission(o);
    const std::vector<PositionFix> fixes = gps_fixes(m);
    SolverOptions tight;
    tight.tolerance = 1e-6;
    expect_same_solve(m, fixes, {});
    expect_same_solve(m, fixes, tight);
  }
}

TEST(MissionPropagation, AnInconsistentSolveFailsWhereFullSweepsFail) {
  test::TinyMission t = test::make_tiny_mission(3, test::TinyErrors::uniform);
  ASSERT_GE(t.mission.mark_count(), 1u);
  t.mission.mark_range[0] += 40.0;  // a mark no position of the tube can explain
  expect_same_solve(t.mission, t.fixes, {});
}

}  // namespace
}  // namespace gesmi
