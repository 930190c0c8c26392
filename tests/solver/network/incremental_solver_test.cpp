// A warm rerun after adding detections equals a cold solve of the whole mission,
// to within the solver's tolerance, and stays sound.

#include "solver/network/incremental_solver.h"

#include <gtest/gtest.h>

#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

constexpr double kTolerance = 1e-6;

TubeDomains cold(const test::TinyMission& t, SolverReport* report = nullptr) {
  const MissionNetwork net = build_network(t.mission, t.mission.model, t.fixes);
  TubeDomains d = initial_domains(t.mission, t.mission.model, net);
  SolverOptions o;
  o.tolerance = kTolerance;
  const SolverReport r = solve(net, d, o);
  if (report) *report = r;
  return d;
}

test::TinyMission without_last_mark(test::TinyMission t) {
  t.mission.mark_time.pop_back();
  t.mission.mark_mine.pop_back();
  t.mission.mark_range.pop_back();
  t.mission.mark_side.pop_back();
  return t;
}

void expect_close(const Interval& a, const Interval& b, const char* what, std::size_t k) {
  EXPECT_NEAR(a.lo(), b.lo(), 1e-3) << what << " " << k;
  EXPECT_NEAR(a.hi(), b.hi(), 1e-3) << what << " " << k;
}

TEST(IncrementalSolver, WarmRerunMatchesAColdSolve) {
  for (const std::uint64_t seed : {21u, 22u, 23u, 24u}) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    const test::TinyMission full = test::make_tiny_mission(seed, test::TinyErrors::uniform);
    const test::TinyMission before = without_last_mark(full);
    const TubeDomains previous = cold(before);
    const MissionNetwork before_net = build_network(before.mission, before.mission.model, before.fixes);
    std::vector<std::uint64_t> by_mark(before.mission.mark_count());
    for (std::size_t j = 0; j < before_net.detections.size(); ++j) by_mark[before_net.detections[j].mark] = previous.candidates[j];

    const MissionNetwork net = build_network(full.mission, full.mission.model, full.fixes);
    TubeDomains warm = previous;
    warm.candidates = initial_domains(full.mission, full.mission.model, net).candidates;
    const std::vector<std::size_t> added = carry_candidates(net, warm, by_mark);
    ASSERT_EQ(added.size(), 1u);
    SolverOptions o;
    o.tolerance = kTolerance;
    const IncrementalReport r = propagate_from(net, warm, added, o);
    ASSERT_TRUE(r.solver.consistent());
    EXPECT_GT(r.work_items, 0u);

    const TubeDomains reference = cold(full);
    for (std::size_t k = 0; k < reference.size(); ++k) {
      expect_close(warm.px[k], reference.px[k], "north", k);
      expect_close(warm.py[k], reference.py[k], "east", k);
      expect_close(warm.pz[k], reference.pz[k], "down", k);
      if (::testing::Test::HasFailure()) return;
      EXPECT_TRUE(warm.px[k].contains(full.mission.truth_x[k]));
    }
    for (int c = 0; c < 3; ++c) expect_close(warm.mines[0][c], reference.mines[0][c], "mine", 0);
  }
}

}  // namespace
}  // namespace gesmi
