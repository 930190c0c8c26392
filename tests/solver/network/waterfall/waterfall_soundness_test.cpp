// Soundness of the reconstructed waterfall (solver/network/waterfall/waterfall.h): the cell
// (k, i) claims every slant range ||p(k) - m_i|| at which mine i can appear on the
// sonar record given the tube box at k, the mine box, the attitude and altitude
// boxes of sample k and the sonar geometry (in the sonar plane within the
// along-track tolerance, on a side the sonar looks to, below the robot, within the
// sonar's reach, mine depth = altitude + depth +- band). Feasible configurations
// are constructed independently in long double: a robot point of the tube box, an
// attitude and altitude in their sample boxes (corners included), the depth offset
// and along-track offset at their bounds, and a mine inside the mine box; each is
// certified against the mark equation, and its range must lie in the cell (a NaN
// cell claims that none exists).

#include "solver/network/waterfall/waterfall.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

#include "solver/network/sensors/sensor_boxes.h"
#include "tests/support/rotation_long_double.h"
#include "tests/support/sonar_configuration.h"
#include "tests/support/random_draws.h"

namespace gesmi {
namespace {

using test::adversarial;

using test::uniform;
// A double of [x.lo, x.hi], its ends a third of the time each.
double point_of(std::mt19937_64& rng, const Interval& x) {
  switch (rng() % 3) {
    case 0: return x.lo();
    case 1: return x.hi();
    default: return std::clamp(static_cast<double>(uniform(rng, x.lo(), x.hi())), x.lo(), x.hi());
  }
}

struct Scene {
  Mission mission;
  TubeDomains domains;
};

// A robot on a straight leg of heading psi past mines on both sides, readings
// with small random attitudes; tube boxes 0.5 to 5 m wide around the leg, mine
// boxes 1 to 6 m wide around the mines.
Scene make_scene(std::uint64_t seed, double psi, SonarSide sonar_side) {
  std::mt19937_64 rng(seed);
  Scene s;
  Mission& m = s.mission;
  m.model.sonar_side = sonar_side;
  const std::size_t n = 200;
  const double speed = 1.5, depth = 10.0, floor = 35.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 0.1 * static_cast<double>(k), along = speed * t - 15.0;
    m.time.push_back(t);
    m.roll.push_back(static_cast<double>(uniform(rng, -0.05L, 0.05L)));
    m.pitch.push_back(static_cast<double>(uniform(rng, -0.05L, 0.05L)));
    m.heading.push_back(std::remainder(psi + static_cast<double>(uniform(rng, -0.02L, 0.02L)), 2.0 * std::numbers::pi));
    m.vx.push_back(speed);
    m.vy.push_back(0.0);
    m.vz.push_back(0.0);
    m.depth.push_back(depth);
    m.altitude.push_back(floor - depth + static_cast<double>(uniform(rng, -0.3L, 0.3L)));
    const double centre[3] = {along * std::cos(psi), along * std::sin(psi), depth};
    for (int i = 0; i < 3; ++i) {
      const double w = static_cast<double>(uniform(rng, 0.25L, 2.5L));
      const Interval box(centre[i] - w * static_cast<double>(uniform(rng, 0.2L, 1.0L)), centre[i] + w);
      (i == 0 ? s.domains.px : i == 1 ? s.domains.py : s.domains.pz).push_back(box);
    }
  }
  // Mines abeam of the middle of the leg: 20 m to starboard, 30 m to port, and
  // 70 m to starboard, at the edge of the sonar's 75 m reach.
  m.mine_count = 3;
  for (const double offset : {20.0, -30.0, 70.0}) {
    const double c[3] = {-offset * std::sin(psi), offset * std::cos(psi), floor};
    Vec3I box;
    for (int i = 0; i < 3; ++i) {
      const double w = static_cast<double>(uniform(rng, 0.5L, 3.0L));
      box[i] = Interval(c[i] - w, c[i] + w * static_cast<double>(uniform(rng, 0.3L, 1.0L)));
    }
    s.domains.mines.push_back(box);
  }
  return s;
}

struct Tally {
  int cells = 0, feasible_cells = 0, configurations = 0, failures = 0;
  std::string first;
};

// Tries `tries` constructions of a feasible configuration for cell (k, i) and
// checks each certified one against the cell.
void check_cell(const Scene& s, const Waterfall& w, std::size_t k, std::size_t i, int tries, std::mt19937_64& rng,
                Tally& t) {
  const Mission& m = s.mission;
  const SensorModel& model = m.model;
  const SensorBoxes boxes(m, model);
  const Vec3I box_p = s.domains.position(k), box_m = s.domains.mines[i];
  const Interval alt = boxes.altitude(k);
  bool seen = false;
  for (int n = 0; n < tries; ++n) {
    test::SonarConfiguration c;
    c.roll = point_of(rng, boxes.roll(k));
    c.pitch = point_of(rng, boxes.pitch(k));
    c.heading = point_of(rng, boxes.heading(k));
    const int sides[2] = {1, -1};
    c.side = model.sonar_side == SonarSide::both ? sides[rng() % 2] : static_cast<int>(model.sonar_side);
    for (int j = 0; j < 3; ++j) c.p[j] = point_of(rng, box_p[j]);
    c.altitude = point_of(rng, alt);
    // e = p - m must lie in p - box_m; its down component e.z = -(a + s).
    const long double lo[3] = {c.p[0] - static_cast<long double>(box_m[0].hi()), c.p[1] - static_cast<long double>(box_m[1].hi()),
                               c.p[2] - static_cast<long double>(box_m[2].hi())};
    const long double hi[3] = {c.p[0] - static_cast<long double>(box_m[0].lo()), c.p[1] - static_cast<long double>(box_m[1].lo()),
                               c.p[2] - static_cast<long double>(box_m[2].lo())};
    const long double ez_lo = std::max(lo[2], -c.altitude - model.mine_depth_band);
    const long double ez_hi = std::min(hi[2], -c.altitude + model.mine_depth_band);
    if (ez_lo > ez_hi) continue;
    long double e[3];
    e[2] = adversarial(rng, ez_lo, ez_hi);
    // The along-track component (first column of R) at a chosen offset fixes one
    // horizontal component from the other; solve for the better-conditioned one.
    const test::RotationLd r(c.roll, c.pitch, c.heading);
    const long double along = adversarial(rng, -model.along_track_tolerance, model.along_track_tolerance);
    const int solve = std::fabs(r.r[0][0]) > std::fabs(r.r[1][0]) ? 0 : 1, other = 1 - solve;
    e[other] = uniform(rng, lo[other], hi[other]);
    e[solve] = (along - r.r[other][0] * e[other] - r.r[2][0] * e[2]) / r.r[solve][0];
    for (int j = 0; j < 3; ++j) c.m[j] = static_cast<double>(c.p[j] - e[j]);
    c.range = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    c.measured_range = static_cast<double>(c.range);
    // Certify with the rounded mine: inside its box, the mark equation, the reach.
    bool inside = true;
    for (int j = 0; j < 3; ++j) inside = inside && box_m[j].contains(c.m[j]);
    long double exact[3];
    for (int j = 0; j < 3; ++j) exact[j] = static_cast<long double>(c.p[j]) - c.m[j];
    c.range = std::sqrt(exact[0] * exact[0] + exact[1] * exact[1] + exact[2] * exact[2]);
    c.measured_range = static_cast<double>(c.range);
    if (!inside || c.range > model.sonar_max_range || !test::satisfies_mark_geometry(c, model)) continue;
    ++t.configurations;
    seen = true;
    if (!(w.lo(k, i) <= c.range && c.range <= w.hi(k, i)) && t.failures++ == 0) {
      char b[300];
      std::snprintf(b, sizeof b, "cell (%zu, %zu) = [%.17g, %.17g] misses the feasible range %.17Lg (side %d, along %.3Lg)",
                    k, i, w.lo(k, i), w.hi(k, i), c.range, c.side, along);
      t.first = b;
    }
  }
  ++t.cells;
  t.feasible_cells += seen;
}

TEST(WaterfallSoundness, EveryCellHoldsEveryFeasibleRange) {
  const auto start = std::chrono::steady_clock::now();
  Tally t;
  std::mt19937_64 rng(0xfa11);
  std::uint64_t seed = 0x3a7e;
  for (const auto& [psi, side] : {std::pair{0.0, SonarSide::starboard}, std::pair{2.5, SonarSide::both},
                                  std::pair{-std::numbers::pi + 0.01, SonarSide::port}}) {
    const Scene s = make_scene(seed++, psi, side);
    const Waterfall w = compute_waterfall(s.mission, s.mission.model, s.domains);
    for (std::size_t k = 0; k < w.steps; ++k)
      for (std::size_t i = 0; i < w.mines; ++i) check_cell(s, w, k, i, 300, rng, t);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("waterfall: %d cells, %d with a feasible configuration found, %d configurations, %d failures; %.2f s\n",
              t.cells, t.feasible_cells, t.configurations, t.failures, seconds);
  EXPECT_EQ(t.failures, 0) << t.first;
  EXPECT_GT(t.feasible_cells, 100);  // the constructions reach the sonar plane often
}

}  // namespace
}  // namespace gesmi
