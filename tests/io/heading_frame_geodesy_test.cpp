// The frame's margins against the meridian convergence and the scale GeographicLib
// measures (solver/network/frame/frame_margins.h, io/geodesy.h): per-sample margins over a
// tube hold the convergence and the scale at every point the robot can reach from its
// boxes, and a mission whose gyrocompass reads from true north keeps its truth inside
// the tube.

#include <gtest/gtest.h>

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "io/geodesy.h"
#include "solver/mission/frame_scale.h"
#include "solver/mission/meridian_convergence.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"
#include "tests/support/truth_checks.h"
#include "tests/support/geodetic_sampling.h"

namespace gesmi::io {
namespace {

// The signed angle from the local frame's north axis to true north at the frame
// point (north, east): the frame direction of a 1 m geodesic step north.
double convergence_at(const LocalFrame& frame, double north, double east) {
  const GeoOrigin p = frame.to_geodetic(north, east);
  const GeoOrigin q = test::geodesic_destination(p, 0.0, 1.0);
  const NorthEast a = frame.to_local(p.latitude, p.longitude), b = frame.to_local(q.latitude, q.longitude);
  return std::atan2(b.east - a.east, b.north - a.north);
}

// The frame's scale error at the frame point (north, east): 1 - the frame length of a
// 10 m geodesic step away from the origin (the radial direction, which shrinks most).
double scale_error_at(const LocalFrame& frame, double north, double east) {
  const GeoOrigin p = frame.to_geodetic(north, east);
  const double azimuth = std::atan2(east, north) * 180.0 / std::numbers::pi;
  const GeoOrigin q = test::geodesic_destination(p, azimuth, 10.0);
  const NorthEast a = frame.to_local(p.latitude, p.longitude), b = frame.to_local(q.latitude, q.longitude);
  return 1.0 - std::hypot(b.east - a.east, b.north - a.north) / 10.0;
}

TEST(HeadingFrameGeodesy, TheSolverUsesWgs84sSemiMajorAxis) {
  EXPECT_EQ(kWgs84SemiMajorAxis, GeographicLib::Constants::WGS84_a());
}

// n samples of a robot at 2.5 m/s anywhere within 90 km of `origin`, and a tube of
// boxes up to 300 m wide around them (unbounded at every 50th sample from the 7th).
void random_tube(const GeoOrigin& origin, std::mt19937_64& random, std::size_t n, Mission& m, TubeDomains& tube) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  m.origin = origin;
  m.heading_frame_margin = meridian_convergence_within(origin.latitude, kLocalFrameZone);
  m.frame_scale_margin = frame_scale_within(kLocalFrameZone);
  double t = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    m.time.push_back(t);
    t += 0.1 + 3.0 * unit(random);
    for (auto* v : {&m.roll, &m.pitch, &m.heading, &m.vy, &m.vz, &m.altitude, &m.depth}) v->push_back(0.0);
    m.vx.push_back(2.5);
    const double azimuth = 2 * std::numbers::pi * unit(random), distance = 90000.0 * unit(random);
    const double half = k % 50 == 7 ? INFINITY : 0.5 + 300.0 * unit(random) * unit(random);
    tube.px.push_back(Interval::around(distance * std::cos(azimuth), half));
    tube.py.push_back(Interval::around(distance * std::sin(azimuth), half));
  }
}

TEST(HeadingFrameGeodesy, MarginsOverATubeHoldTheConvergenceWhereverTheRobotCanBe) {
  std::mt19937_64 random(5);
  for (const GeoOrigin& origin : test::kFrameOrigins) {
    Mission m;
    TubeDomains tube;
    const std::size_t n = 300;
    random_tube(origin, random, n, m, tube);
    const FrameMarginValues values = frame_margins_over(m, tube);
    const std::vector<float>& margins = values.heading;
    ASSERT_EQ(margins.size(), n);
    ASSERT_EQ(values.scale.size(), n);
    const LocalFrame frame(origin);
    for (std::size_t k = 0; k < n; ++k) {
      // (stored as floats rounded up: within a relative 3e-7 of the zone's)
      ASSERT_LE(margins[k], m.heading_frame_margin * (1 + 3e-7));
      ASSERT_LE(values.scale[k], m.frame_scale_margin * (1 + 3e-7));
      if (!tube.px[k].is_bounded()) {
        EXPECT_GE(margins[k], m.heading_frame_margin);
        EXPECT_GE(values.scale[k], m.frame_scale_margin);
        continue;
      }
      // The corners of the sample's box and of its neighbours', pushed away from the
      // origin by half a step's travel at the DVL's largest speed: the farthest points
      // the robot reaches around t_k.
      for (std::size_t j = k == 0 ? 0 : k - 1; j <= std::min(k + 1, n - 1); ++j) {
        if (!tube.px[j].is_bounded()) continue;
        const std::size_t step = j < k ? j : k;
        const double travel = step + 1 < n ? 0.5 * 2.6 * (m.time[step + 1] - m.time[step]) : 0.0;
        for (const double north : {tube.px[j].lo(), tube.px[j].hi()})
          for (const double east : {tube.py[j].lo(), tube.py[j].hi()}) {
            const double r = std::hypot(north, east), stretch = (r + (j == k ? 0.0 : travel)) / r;
            if (r + travel > kLocalFrameZone) continue;
            const double turn = std::fabs(convergence_at(frame, north * stretch, east * stretch));
            EXPECT_LE(turn, margins[k]) << origin.latitude << " sample " << k;
            EXPECT_LE(scale_error_at(frame, north * stretch, east * stretch), values.scale[k])
                << origin.latitude << " sample " << k;
          }
      }
      // No looser than the convergence due east at the farthest corner's distance, the
      // worst direction (geodesy_test checks that bound against the whole circle).
      double r = 0.0;
      for (std::size_t j = k == 0 ? 0 : k - 1; j <= std::min(k + 1, n - 1); ++j)
        r = std::max(r, std::hypot(tube.px[j].mag(), tube.py[j].mag()));
      if (origin.latitude != 0.0 && std::isfinite(r)) {
        EXPECT_LE(margins[k], 1.08 * std::fabs(convergence_at(frame, 0.0, std::min(r + 10.0, kLocalFrameZone))) + 1e-9)
            << origin.latitude << " sample " << k;
      }
      // And the scale no looser than the one measured radially there.
      if (std::isfinite(r)) {
        EXPECT_LE(values.scale[k], 1.05 * scale_error_at(frame, std::min(r + 10.0, kLocalFrameZone), 0.0) + 1e-12)
            << origin.latitude << " sample " << k;
      }
    }
  }
}

// The waterfall takes the zone's margins everywhere, then the tube's at the samples it
// reads: those must be frame_margins_over()'s, bit for bit, and no sample's may exceed
// the zone's as stored (the waterfall finds the samples it reads with them).
TEST(HeadingFrameGeodesy, MarginsNarrowedAtSomeSamplesAreTheTubesThereAndTheZonesElsewhere) {
  std::mt19937_64 random(8);
  std::bernoulli_distribution pick(0.5);
  for (const GeoOrigin& origin : test::kFrameOrigins) {
    for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{300}}) {
      Mission m;
      TubeDomains tube;
      random_tube(origin, random, n, m, tube);
      // An empty box here and there (its distance is NaN: the zone's margins).
      for (std::size_t k = 5; k < n; k += 97) tube.px[k] = Interval::empty();
      const double speed = speed_bound(m);
      const FrameMarginValues whole = frame_margins_over(m, tube, speed);
      std::vector<unsigned char> wanted(n);
      for (std::size_t k = 0; k < n; ++k) wanted[k] = pick(random);
      FrameMarginValues all = zone_margin_values(m, n);
      narrow_margins_over(all, m, tube, speed, std::vector<unsigned char>(n, 1));
      EXPECT_EQ(all.heading, whole.heading);
      EXPECT_EQ(all.scale, whole.scale);
      EXPECT_EQ(all.beyond_zone, whole.beyond_zone);
      FrameMarginValues some = zone_margin_values(m, n);
      const FrameMarginValues zone = some;
      narrow_margins_over(some, m, tube, speed, wanted);
      ASSERT_EQ(some.heading.size(), n);
      ASSERT_EQ(some.scale.size(), n);
      for (std::size_t k = 0; k < n; ++k) {
        SCOPED_TRACE(::testing::Message() << origin.latitude << " sample " << k << " of " << n);
        ASSERT_LE(whole.heading[k], zone.heading[k]);
        ASSERT_LE(whole.scale[k], zone.scale[k]);
        EXPECT_EQ(some.heading[k], wanted[k] ? whole.heading[k] : zone.heading[k]);
        EXPECT_EQ(some.scale[k], wanted[k] ? whole.scale[k] : zone.scale[k]);
      }
      EXPECT_LE(some.beyond_zone, whole.beyond_zone);
    }
  }
}

// A simulated mission moved to 70° N, its gyrocompass reading from true north: the
// heading differs from the frame's by up to the convergence at the true position.
Mission true_north_mission(std::uint64_t seed) {
  SimulationOptions o;
  o.seed = seed;
  o.errors = SimulatedErrors::worst_case;
  o.duration = 2000.0;
  Mission m = simulate_mission(o);
  m.origin = {70.0, 20.0};
  const LocalFrame frame(m.origin);
  for (std::size_t k = 0; k < m.size(); ++k) m.heading[k] -= convergence_at(frame, m.truth_x[k], m.truth_y[k]);
  set_geodetic_gps(m);
  fill_local_gps(m, "simulated mission");
  return m;
}

TEST(HeadingFrameGeodesy, AMissionReadingFromTrueNorthKeepsItsTruth) {
  for (const std::uint64_t seed : {91u, 92u}) {
    const Mission m = true_north_mission(seed);
    const MissionSolution s = solve_mission(m);
    ASSERT_TRUE(s.report.consistent) << s.report.message;
    EXPECT_TRUE(test::truth_inside(m, s.domains));
  }
}

// Earth-centred coordinates of the frame point (north, east) at `depth` below the sea.
std::array<double, 3> earth_centred(const LocalFrame& frame, double north, double east, double depth) {
  const GeoOrigin g = frame.to_geodetic(north, east);
  std::array<double, 3> x{};
  GeographicLib::Geocentric::WGS84().Forward(g.latitude, g.longitude, -depth, x[0], x[1], x[2]);
  return x;
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// A simulated mission moved `north` and `east` metres away from its origin on WGS84:
// its DVL reads the robot's own speed (the frame shrinks the surface's, the depth
// slows the robot's against the surface point's), its gyrocompass reads from true
// north, its mark ranges are the Earth-centred distances, its fixes are projections.
Mission far_mission(std::uint64_t seed, const GeoOrigin& origin, double north, double east) {
  SimulationOptions o;
  o.seed = seed;
  o.errors = SimulatedErrors::worst_case;
  o.duration = 2000.0;
  Mission m = simulate_mission(o);
  m.origin = origin;
  const LocalFrame frame(origin);
  // The robot's position at time t, from the truth between samples (marks fall there).
  const auto truth_at = [&](double t) {
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(m.time.begin(), m.time.end(), t) - m.time.begin()), m.size() - 1);
    const std::size_t a = k == 0 ? 0 : k - 1;
    const double w = k == a ? 0.0 : (t - m.time[a]) / (m.time[k] - m.time[a]);
    return std::array<double, 3>{m.truth_x[a] + w * (m.truth_x[k] - m.truth_x[a]),
                                 m.truth_y[a] + w * (m.truth_y[k] - m.truth_y[a]),
                                 m.truth_z[a] + w * (m.truth_z[k] - m.truth_z[a])};
  };
  // Ranges: the flat world's error kept, the distance taken on the ellipsoid.
  std::vector<double> flat(m.mark_count());
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const std::array<double, 3> p = truth_at(m.mark_time[j]);
    const double* mine = &m.truth_mines[3 * static_cast<std::size_t>(m.truth_marks_mine[j])];
    flat[j] = std::hypot(p[0] - mine[0], p[1] - mine[1], p[2] - mine[2]);
  }
  for (std::size_t k = 0; k < m.size(); ++k) {
    m.truth_x[k] += north;
    m.truth_y[k] += east;
  }
  for (std::size_t i = 0; i < m.truth_mines.size(); i += 3) {
    m.truth_mines[i] += north;
    m.truth_mines[i + 1] += east;
  }
  for (std::size_t i = 0; i < m.gps_north.size(); ++i) {
    m.gps_north[i] += north;
    m.gps_east[i] += east;
  }
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    const std::array<double, 3> p = truth_at(m.mark_time[j]);
    const double* mine = &m.truth_mines[3 * static_cast<std::size_t>(m.truth_marks_mine[j])];
    m.mark_range[j] += distance(earth_centred(frame, p[0], p[1], p[2]), earth_centred(frame, mine[0], mine[1], mine[2])) -
                       flat[j];
  }
  for (std::size_t k = 0; k < m.size(); ++k) {
    // The robot's horizontal speed against the frame's, over the step from k (to k
    // from k - 1 at the end).
    const std::size_t a = k + 1 < m.size() ? k : k - 1, b = a + 1;
    const double plane = std::hypot(m.truth_x[b] - m.truth_x[a], m.truth_y[b] - m.truth_y[a]);
    const double dz = m.truth_z[b] - m.truth_z[a];
    const double full = distance(earth_centred(frame, m.truth_x[a], m.truth_y[a], m.truth_z[a]),
                                 earth_centred(frame, m.truth_x[b], m.truth_y[b], m.truth_z[b]));
    const double factor = plane > 1e-6 ? std::sqrt(std::max(full * full - dz * dz, 0.0)) / plane : 1.0;
    m.vx[k] *= factor;
    m.vy[k] *= factor;
    m.heading[k] -= convergence_at(frame, m.truth_x[k], m.truth_y[k]);
  }
  set_geodetic_gps(m);
  fill_local_gps(m, "simulated mission");
  return m;
}

TEST(HeadingFrameGeodesy, AMissionFarFromTheOriginKeepsItsTruth) {
  // 78 km and 94 km from the origin, at 48° and 70°.
  const struct {
    GeoOrigin origin;
    double north, east;
  } cases[] = {{{48.2, -4.4}, 60000.0, 50000.0}, {{70.0, 20.0}, -30000.0, 90000.0}};
  std::uint64_t seed = 93;
  for (const auto& c : cases) {
    const Mission m = far_mission(seed++, c.origin, c.north, c.east);
    const MissionSolution s = solve_mission(m);
    ASSERT_TRUE(s.report.consistent) << s.report.message;
    EXPECT_TRUE(test::truth_inside(m, s.domains)) << c.origin.latitude;
  }
}

}  // namespace
}  // namespace gesmi::io
