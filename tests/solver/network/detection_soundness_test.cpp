// Soundness of the detection contractor (solver/network/detection.h): for random
// configurations that satisfy the mark equation exactly (tests/support/
// sonar_configuration.h: along-track offset, depth offset and range error at
// their bounds, mine straight below or at the robot's level, any heading), and
// boxes around them from degenerate to unbounded, Detection::contract must keep
// the true robot position, mine position and slant range, and never report an
// empty result. The test also counts how often the contraction did narrow the
// boxes, so that it cannot pass by doing nothing.

#include "solver/network/detection.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "tests/support/sonar_configuration.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

// A box around the double x, from degenerate to unbounded, not centred on x.
Interval box_around(std::mt19937_64& rng, double x, const double* widths, std::size_t count) {
  const double w = widths[rng() % count];
  if (std::isinf(w)) return Interval::entire();
  const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  return Interval(sub_down(x, w * u), add_up(x, w * (1.0 - u)));
}

TEST(DetectionSoundness, TheTrueConfigurationSurvivesContraction) {
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(0xde7ec7);
  const SensorModel model;
  static const double kPositionWidths[] = {0.0, 1e-9, 0.5, 5.0, 50.0, 500.0, kInf};
  static const double kAngleWidths[] = {0.0, 1e-12, 1.75e-4, 5.27e-3, 0.05, 0.3};
  static const double kAltitudeWidths[] = {0.0, 1e-12, 0.1, 0.2, 2.0};
  int failures = 0, cases = 0, narrowed = 0, mine_found = 0;
  std::string first;
  for (int n = 0; n < 30000; ++n) {
    const test::SonarConfiguration c = test::random_sonar_configuration(rng, model, model.sonar_max_range);
    Detection det;
    det.plane.side = c.side > 0 ? SonarSide::starboard : SonarSide::port;
    det.plane.along_tolerance = model.along_track_tolerance;
    det.plane.depth_band = model.mine_depth_band;
    det.plane.attitude = make_attitude(box_around(rng, c.roll, kAngleWidths, 6), box_around(rng, c.pitch, kAngleWidths, 6),
                                 box_around(rng, c.heading, kAngleWidths, 6));
    const double a_lo = static_cast<double>(c.altitude), a_hi = a_lo < c.altitude ? next_up(a_lo) : a_lo;
    const Interval a_point(a_lo > c.altitude ? next_down(a_lo) : a_lo, a_hi);  // the doubles around the true altitude
    const double aw = kAltitudeWidths[rng() % 5];
    det.plane.altitude = Interval(sub_down(a_point.lo(), aw * 0.3), add_up(a_point.hi(), aw * 0.7));
    det.range = intersect(Interval::around(c.measured_range, model.mark_range), Interval::pos_reals());
    Vec3I q, m;
    for (int i = 0; i < 3; ++i) {
      q[i] = box_around(rng, c.p[i], kPositionWidths, 7);
      m[i] = box_around(rng, c.m[i], kPositionWidths, 7);
    }
    const Vec3I q0 = q, m0 = m;
    Interval r = det.range;
    ++cases;
    const bool ok = det.plane.contract(q, m, r);
    bool kept = ok && r.lo() <= c.range && c.range <= r.hi();
    for (int i = 0; kept && i < 3; ++i) kept = q[i].contains(c.p[i]) && m[i].contains(c.m[i]);
    if (!kept && failures++ == 0) {
      char b[400];
      std::snprintf(b, sizeof b,
                    "case %d: roll %a pitch %a heading %a side %d range %.17Lg altitude %.17Lg; p (%a, %a, %a) "
                    "m (%a, %a, %a); ok %d",
                    n, c.roll, c.pitch, c.heading, c.side, c.range, c.altitude, c.p[0], c.p[1], c.p[2], c.m[0], c.m[1],
                    c.m[2], ok);
      first = b;
      for (int i = 0; i < 3; ++i)
        first += "\n  q" + std::to_string(i) + " " + test::to_string(q0[i]) + " -> " + test::to_string(q[i]) + ", m" + std::to_string(i) +
                 " " + test::to_string(m0[i]) + " -> " + test::to_string(m[i]);
    }
    bool moved = false;
    for (int i = 0; i < 3; ++i) moved = moved || !(q[i] == q0[i]) || !(m[i] == m0[i]);
    narrowed += moved;
    mine_found += m0[0].is_entire() && m[0].is_bounded();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("detections: %d configurations, %d failures, %d narrowed a box, %d bounded an unknown mine; %.2f s\n", cases,
              failures, narrowed, mine_found, seconds);
  EXPECT_EQ(failures, 0) << first;
  EXPECT_GT(narrowed, cases / 2);  // the contractor works: it is not vacuously sound
  EXPECT_GT(mine_found, 100);
}

}  // namespace
}  // namespace gesmi
