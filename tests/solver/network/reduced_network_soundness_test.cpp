// The reduced network (solver/network/reduced_network.h) is a relaxation of the
// full one on its event samples: its solution there must enclose the truth and
// the full network's solution, and an inconsistency of the reduced network must
// never come with a consistent full network (the outlier solver discards a
// hypothesis on that evidence alone). Missions: the tiny mission (marks on and
// between samples), and short simulated missions; variants corrupt one mark range
// or shift one GPS fix by 0.5, 3 or 40 m, from consistent to plainly inconsistent.

#include "solver/network/reduced_network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "solver/network/mission_solver.h"
#include "solver/sim/simulator.h"
#include "tests/support/tiny_mission.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

struct SoundnessCase {
  std::string name;
  Mission mission;
  std::vector<PositionFix> fixes;
  bool truthful = true;  // no corruption: the truth must be inside
};

// The tiny mission with its marks moved half a step later, ranges recomputed
// from the truth there (linear between samples: off by 1e-4 m, far inside the
// mark bound), so that the reduced network has marks between two events.
test::TinyMission with_marks_between_samples(test::TinyMission t) {
  Mission& m = t.mission;
  const Vec3d mine(m.truth_mines[0], m.truth_mines[1], m.truth_mines[2]);
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const auto k = static_cast<std::size_t>(std::lround(m.mark_time[j] / 0.1));
    const Vec3d a(m.truth_x[k], m.truth_y[k], m.truth_z[k]), b(m.truth_x[k + 1], m.truth_y[k + 1], m.truth_z[k + 1]);
    m.mark_time[j] = 0.5 * (m.time[k] + m.time[k + 1]);
    m.mark_range[j] = (0.5 * (a + b) - mine).norm() + 0.3 * (j % 2 ? 1.0 : -1.0);
  }
  return t;
}

std::vector<SoundnessCase> base_cases() {
  std::vector<SoundnessCase> cases;
  for (const std::uint64_t seed : {41u}) {
    for (const test::TinyErrors e : {test::TinyErrors::uniform, test::TinyErrors::worst_case}) {
      test::TinyMission t = test::make_tiny_mission(seed, e);
      cases.push_back({"tiny " + std::to_string(seed), t.mission, t.fixes});
      t = with_marks_between_samples(std::move(t));
      cases.push_back({"tiny between samples " + std::to_string(seed), t.mission, t.fixes});
    }
  }
  for (const std::uint64_t seed : {5u, 6u}) {
    SimulationOptions o;
    o.seed = seed;
    o.duration = 600.0;
    o.errors = seed == 5 ? SimulatedErrors::uniform : SimulatedErrors::worst_case;
    Mission m = simulate_mission(o);
    std::vector<PositionFix> fixes = gps_fixes(m);
    cases.push_back({"simulated " + std::to_string(seed), std::move(m), std::move(fixes)});
  }
  return cases;
}

// Corruptions of one constraint each: a mark's range, a fix's position.
std::vector<SoundnessCase> variants(const SoundnessCase& base) {
  std::vector<SoundnessCase> out = {base};
  for (const double delta : {0.5, 3.0, 40.0}) {
    for (std::size_t j = 0; j < base.mission.mark_count(); j += std::max<std::size_t>(1, base.mission.mark_count() / 3)) {
      SoundnessCase c = base;
      c.name += " mark " + std::to_string(j) + " +" + std::to_string(delta);
      c.mission.mark_range[j] += (j % 2 ? -1.0 : 1.0) * delta;
      c.truthful = false;
      out.push_back(std::move(c));
    }
    for (std::size_t f = 0; f < base.fixes.size(); f += std::max<std::size_t>(1, base.fixes.size() / 2)) {
      SoundnessCase c = base;
      c.name += " fix " + std::to_string(f) + " +" + std::to_string(delta);
      c.fixes[f].box[f % 2] = c.fixes[f].box[f % 2] + Interval(delta);
      c.truthful = false;
      out.push_back(std::move(c));
    }
  }
  return out;
}

// Both solves round outward, each in its own order (the full chain adds the
// increments one step at a time, the reduced one adds their sum), so the reduced
// domain encloses the full one up to the rounding the full chain accumulated:
// thousands of steps times an ulp of a few hundred metres, below kRounding.
constexpr double kRounding = 1e-8;  // m
double worst_excess = 0.0;

bool encloses_up_to_rounding(const Interval& outer, const Interval& inner) {
  if (inner.is_empty() || outer.is_superset(inner)) return true;  // also for unbounded domains
  const double excess = std::max(outer.lo() - inner.lo(), inner.hi() - outer.hi());
  worst_excess = std::max(worst_excess, excess);
  return excess <= kRounding;
}

TEST(ReducedNetworkSoundness, EnclosesTheFullSolutionAndTheTruthAndNeverProvesAConsistentNetworkWrong) {
  const auto start = std::chrono::steady_clock::now();
  int solved = 0, reduced_inconsistent = 0, full_inconsistent = 0, failures = 0, events_checked = 0;
  std::string first;
  const auto fail = [&](const std::string& what) {
    if (failures++ == 0) first = what;
  };
  SolverOptions options;
  options.tolerance = 1e-6;  // near the fixpoint, so that containment compares settled domains
  options.max_sweeps = 400;
  for (const SoundnessCase& base : base_cases()) {
    for (const SoundnessCase& c : variants(base)) {
      const Mission& m = c.mission;
      const MissionNetwork net = build_network(m, m.model, c.fixes);
      const TubeDomains sensor = sensor_domains(m, m.model);
      TubeDomains full = sensor;
      add_network_priors(full, net);
      const bool full_ok = solve(net, full, options).consistent();
      ReducedNetwork reduced;
      bool reduced_ok = build_reduced_network(net, sensor, reduced);
      TubeDomains rd;
      if (reduced_ok) {
        rd = reduced.domains;
        add_network_priors(rd, reduced.net);
        reduced_ok = solve(reduced.net, rd, options).consistent();
      }
      ++solved;
      full_inconsistent += !full_ok;
      reduced_inconsistent += !reduced_ok;
      if (!reduced_ok && full_ok) fail(c.name + ": the reduced network is inconsistent, the full one is not");
      if (c.truthful && !reduced_ok) fail(c.name + ": truthful data, yet the reduced network is inconsistent");
      if (!reduced_ok || !full_ok) continue;
      for (std::size_t i = 0; i < reduced.time.size(); ++i) {
        const auto k = static_cast<std::size_t>(std::lower_bound(m.time.begin(), m.time.end(), reduced.time[i]) - m.time.begin());
        ++events_checked;
        for (int axis = 0; axis < 3; ++axis)
          if (!encloses_up_to_rounding(rd.position(i)[axis], full.position(k)[axis]))
            fail(c.name + ": event " + std::to_string(i) + " (sample " + std::to_string(k) + "), axis " +
                 std::to_string(axis) + ": the reduced domain " + test::to_string(rd.position(i)[axis]) +
                 " does not enclose the full one " + test::to_string(full.position(k)[axis]));
        if (c.truthful && m.has_truth()) {
          const double truth[3] = {m.truth_x[k], m.truth_y[k], m.truth_z[k]};
          for (int axis = 0; axis < 3; ++axis)
            if (!rd.position(i)[axis].contains(truth[axis]))
              fail(c.name + ": event " + std::to_string(i) + ": the reduced domain misses the truth");
        }
      }
      for (std::size_t j = 0; j < full.mines.size(); ++j)
        for (int axis = 0; axis < 3; ++axis) {
          if (!encloses_up_to_rounding(rd.mines[j][axis], full.mines[j][axis]))
            fail(c.name + ": mine " + std::to_string(j) + ": the reduced box does not enclose the full one");
          if (c.truthful && !rd.mines[j][axis].contains(m.truth_mines[3 * j + static_cast<std::size_t>(axis)]))
            fail(c.name + ": mine " + std::to_string(j) + ": the reduced box misses the truth");
        }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("reduced network: %d networks, %d events compared, %d full and %d reduced inconsistent, %d failures; "
              "full domains beyond the reduced ones by at most %.3g m; %.2f s\n",
              solved, events_checked, full_inconsistent, reduced_inconsistent, failures, worst_excess, seconds);
  EXPECT_EQ(failures, 0) << first;
  EXPECT_GT(reduced_inconsistent, 5);  // the screening really proves inconsistencies here
  EXPECT_GT(solved - full_inconsistent, 10);
}

}  // namespace
}  // namespace gesmi
