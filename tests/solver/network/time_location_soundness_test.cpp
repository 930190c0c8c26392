// Soundness of the positions between samples (solver/network/time_location.h):
// for a time t in [t_k, t_k+1], position() must hold the true p(t) whenever the
// tube holds the true p(t_k) and p(t_k+1), and narrow() with a box holding the
// true p(t) must keep the true p(t_k) and p(t_k+1). The truth is the adversarial
// bounded-rate motion of tests/support/bounded_rate_mission.h (excursions at the
// largest rates, irregular steps), its positions integrated independently in long
// double; the tube is the truth +- 1 nm, so any unsound shortcut shows.

#include "solver/network/time_location.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

#include "solver/network/sensors/sensor_boxes.h"
#include "tests/support/bounded_rate_mission.h"

namespace gesmi {
namespace {

using test::kDisplacementError;

constexpr long double kTube = 1e-9L;  // m: half-width of the tube around the truth

Interval around(long double v, long double r) { return Interval(static_cast<double>(v - r), static_cast<double>(v + r)); }

TubeDomains tube_around(const test::BoundedRateMission& b) {
  TubeDomains d;
  for (std::size_t k = 0; k < b.mission.size(); ++k) {
    d.px.push_back(around(b.px[k], kTube));
    d.py.push_back(around(b.py[k], kTube));
    d.pz.push_back(around(b.pz[k], kTube));
  }
  return d;
}

TEST(TimeLocationSoundness, PositionsBetweenSamplesHoldTheTruthAndNarrowingKeepsIt) {
  int failures = 0, checks = 0;
  std::string first;
  const auto fail = [&](const std::string& what) {
    if (failures++ == 0) first = what;
  };
  std::uint64_t seed = 0x7104;
  for (const double heading : {0.0, std::numbers::pi - 0.02}) {
    test::BoundedRateOptions options;
    options.model.step_model = StepModel::rate_hull;  // kinked truths: only the rates are bounded
    options.initial_heading = heading;
    options.samples = 300;
    const test::BoundedRateMission b = test::make_bounded_rate_mission(seed++, options);
    const Mission& m = b.mission;
    const SensorBoxes boxes(m, m.model);
    const TubeDomains tube = tube_around(b);
    std::mt19937_64 rng(seed);
    for (std::size_t k = 0; k + 1 < m.size(); ++k) {
      const double t0 = m.time[k], t1 = m.time[k + 1];
      const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
      for (const double t : {t0, std::nextafter(t0, t1), t0 + 0.25 * (t1 - t0), t0 + 0.5 * (t1 - t0), t0 + u * (t1 - t0),
                             std::nextafter(t1, t0)}) {
        ++checks;
        const TimeLocation at = TimeLocation::locate(m.time, t, boxes);
        if (at.k != k || at.on_grid != (t == t0)) {
          fail("time " + std::to_string(t) + " located at sample " + std::to_string(at.k));
          continue;
        }
        long double d[3];
        b.truth.displacement(t0, t, d);
        const long double p[3] = {b.px[k] + d[0], b.py[k] + d[1], b.pz[k] + d[2]};
        const Vec3I q = at.position(tube);
        for (int i = 0; i < 3; ++i) {
          const long double e = at.on_grid ? 0.0L : kDisplacementError;
          if (!(q[i].lo() <= p[i] - e && p[i] + e <= q[i].hi())) {
            char text[200];
            std::snprintf(text, sizeof text, "step %zu, t = %.9f, axis %d: position [%.17g, %.17g] misses %.17Lg", k, t,
                          i, q[i].lo(), q[i].hi(), p[i]);
            fail(text);
          }
        }
        // A contracted position that still holds the truth keeps the truth at both samples.
        TubeDomains narrowed = tube;
        const Vec3I truth_box(around(p[0], 2 * kTube), around(p[1], 2 * kTube), around(p[2], 2 * kTube));
        const bool ok = at.narrow(narrowed, truth_box);
        const std::size_t last = at.on_grid ? k : k + 1;
        for (std::size_t s = k; ok && s <= last; ++s) {
          const long double truth_at[3] = {b.px[s], b.py[s], b.pz[s]};
          for (int i = 0; i < 3; ++i)
            if (!narrowed.position(s)[i].contains(static_cast<double>(truth_at[i])))
              fail("narrow lost the truth at sample " + std::to_string(s) + " (t = " + std::to_string(t) + ")");
        }
        if (!ok) fail("narrow emptied the tube at t = " + std::to_string(t));
      }
    }
  }
  std::printf("time locations: %d times checked, %d failures\n", checks, failures);
  EXPECT_EQ(failures, 0) << first;
}

}  // namespace
}  // namespace gesmi
