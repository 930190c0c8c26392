// The local frame's conversion error (io/geodesy.h, docs/formats.md) measured
// against GeographicLib's geodesics on WGS84 over the frame's 100 km zone: points
// convert back and forth exactly; straight distances along the surface and in the
// frame differ by up to d^3 / (3 M^2) (8.3 m across the zone, M = b^2/a), which no
// box relies on; along a path the frame's scale differs from 1 by at most
// d^2 / (2 M^2) (1.25e-4 at 100 km), inside frame_scale_within(); meridian
// convergence stays inside heading_frame_margin.

#include "io/geodesy.h"
#include "solver/mission/frame_scale.h"
#include "tests/support/geodetic_sampling.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace gesmi::io {
namespace {

using GeographicLib::Geodesic;

constexpr double kZone = kLocalFrameZone;
// The smallest radius of curvature of WGS84 (meridian, at the equator): b^2 / a.
const double kRadius = GeographicLib::Constants::WGS84_a() * (1.0 - GeographicLib::Constants::WGS84_f()) *
                       (1.0 - GeographicLib::Constants::WGS84_f());
const double kChordBound = std::pow(kZone, 3) / (3.0 * kRadius * kRadius);  // 8.3 m
const double kScaleBound = kZone * kZone / (2.0 * kRadius * kRadius);        // 1.25e-4

// The angle between true north at p and the local frame's north axis, measured by
// GeographicLib: the frame direction of a 1 m step north from p.
double true_convergence(const GeoOrigin& origin, const GeoOrigin& p) {
  const LocalFrame frame(origin);
  const GeoOrigin north = test::geodesic_destination(p, 0.0, 1.0);
  const NorthEast a = frame.to_local(p.latitude, p.longitude), b = frame.to_local(north.latitude, north.longitude);
  return std::fabs(std::atan2(b.east - a.east, b.north - a.north));
}

double surface_distance(const GeoOrigin& a, const GeoOrigin& b) {
  double s = 0.0;
  Geodesic::WGS84().Inverse(a.latitude, a.longitude, b.latitude, b.longitude, s);
  return s;
}

double frame_distance(const LocalFrame& frame, const GeoOrigin& a, const GeoOrigin& b) {
  const NorthEast p = frame.to_local(a.latitude, a.longitude), q = frame.to_local(b.latitude, b.longitude);
  return std::hypot(p.north - q.north, p.east - q.east);
}

TEST(Geodesy, PointsConvertBackAndForthWithin10Nanometres) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-kZone / std::numbers::sqrt2, kZone / std::numbers::sqrt2);
  for (const GeoOrigin& origin : test::kFrameOrigins) {
    const LocalFrame frame(origin);
    for (int i = 0; i < 2000; ++i) {
      const double north = coordinate(rng), east = coordinate(rng);
      const GeoOrigin g = frame.to_geodetic(north, east);
      const NorthEast back = frame.to_local(g.latitude, g.longitude);
      ASSERT_NEAR(back.north, north, 1e-8);
      ASSERT_NEAR(back.east, east, 1e-8);
    }
  }
}

// Straight distances: what a fix placed by distance would need (none is: fixes are
// projected), and the bound that says the projection is the one measured.
TEST(Geodesy, DistancesAcrossTheZoneDifferFromTheSurfaceByTheChordBound) {
  double worst = 0.0;
  for (const GeoOrigin& origin : test::kFrameOrigins) {
    const LocalFrame frame(origin);
    for (double azimuth = 0.0; azimuth < 180.0; azimuth += 7.5) {
      // Across the whole zone through the origin (the worst case, 200 km), and from
      // the origin to its edge.
      const GeoOrigin a = test::geodesic_destination(origin, azimuth, kZone),
                      b = test::geodesic_destination(origin, azimuth + 180.0, kZone);
      const double across = std::fabs(surface_distance(a, b) - frame_distance(frame, a, b));
      const double radial = std::fabs(surface_distance(origin, a) - frame_distance(frame, origin, a));
      EXPECT_LE(across, 1.02 * kChordBound) << origin.latitude << " " << azimuth;
      EXPECT_LE(radial, 1.02 * kChordBound / 2.0) << origin.latitude << " " << azimuth;
      worst = std::max(worst, across);
    }
  }
  // Random pairs of points of the zone.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> azimuth(0.0, 360.0), radius(0.0, 1.0);
  for (const GeoOrigin& origin : test::kFrameOrigins) {
    const LocalFrame frame(origin);
    for (int i = 0; i < 2000; ++i) {
      const GeoOrigin a = test::geodesic_destination(origin, azimuth(rng), kZone * std::sqrt(radius(rng)));
      const GeoOrigin b = test::geodesic_destination(origin, azimuth(rng), kZone * std::sqrt(radius(rng)));
      worst = std::max(worst, std::fabs(surface_distance(a, b) - frame_distance(frame, a, b)));
    }
  }
  RecordProperty("worst_distance_error_mm", std::to_string(worst * 1e3));
  std::printf("worst surface-vs-frame distance error over the 100 km zone: %.3f m (bound d^3/3M^2 = %.3f m)\n",
              worst, kChordBound);
  EXPECT_GT(worst, 0.9 * kChordBound);  // the bound is reached: it is the right one
}

TEST(Geodesy, TheFrameScaleAlongAPathStaysWithinTheMarginAtTheZonesEdge) {
  // A 10 m step at the edge of the zone, radial and tangential: the frame shortens
  // radial steps by cos(d/R), so a path's error grows with its length (docs/formats.md).
  double worst = 0.0;
  for (const GeoOrigin& origin : test::kFrameOrigins) {
    const LocalFrame frame(origin);
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 30.0) {
      const GeoOrigin edge = test::geodesic_destination(origin, azimuth, kZone - 10.0);
      for (const double turn : {0.0, 90.0}) {
        const GeoOrigin step = test::geodesic_destination(edge, azimuth + turn, 10.0);
        const double scale = frame_distance(frame, edge, step) / surface_distance(edge, step);
        worst = std::max(worst, std::fabs(1.0 - scale));
      }
    }
  }
  std::printf("worst frame scale error at 100 km: %.4g (bound d^2/2M^2 = %.4g)\n", worst, kScaleBound);
  EXPECT_LE(worst, 1.05 * kScaleBound);
  EXPECT_GT(worst, 0.8 * kScaleBound);
  // The margins (Mission::frame_scale_margin, and the per-sample ones) hold what was
  // measured, at the zone's edge and within it.
  EXPECT_LE(worst, frame_scale_within(kZone));
  for (const double within : {1000.0, 10000.0, 50000.0}) {
    double inside = 0.0;
    for (const GeoOrigin& origin : test::kFrameOrigins) {
      const LocalFrame frame(origin);
      for (double azimuth = 0.0; azimuth < 360.0; azimuth += 30.0) {
        const GeoOrigin edge = test::geodesic_destination(origin, azimuth, within - 10.0);
        const GeoOrigin step = test::geodesic_destination(edge, azimuth, 10.0);
        inside = std::max(inside, std::fabs(1.0 - frame_distance(frame, edge, step) / surface_distance(edge, step)));
      }
    }
    EXPECT_LE(inside, frame_scale_within(within)) << within;
    EXPECT_GT(inside, 0.8 * within * within / (2.0 * kRadius * kRadius)) << within;
  }
}

// A robot at depth D sees the surface point above it move faster by D / (R - D), R the
// radius of curvature (at least M = b^2/a): the margin holds it up to 6 km deep.
TEST(Geodesy, DepthScaleMarginHoldsTheDepthEffect) {
  for (const double depth : {0.0, 20.0, 300.0, 6000.0}) {
    EXPECT_GE(depth_scale_within(depth), depth / (kRadius - depth)) << depth;
    EXPECT_LE(depth_scale_within(depth), 1.02 * depth / kRadius) << depth;
  }
  // The deepest point of the sonar's geometry: the floor under the robot.
  Mission m;
  m.depth = {5.0, 80.0, 12.0};
  m.altitude = {3.0, 2.0, 4.0};
  m.time = {0.0, 1.0, 2.0};
  // (speeds of 1 m/s at most: the depth's and altitude's rates are the faster)
  for (auto* v : {&m.roll, &m.pitch, &m.heading, &m.vx, &m.vy, &m.vz}) v->assign(3, 0.1);
  const double band = m.model.mine_depth_band, rates = 0.5 * (m.model.max_depth_rate + m.model.max_altitude_rate);
  EXPECT_GE(deepest(m), 80.0 + m.model.depth_absolute + m.model.depth_relative * 80.0 + 2.0 + m.model.altitude + band);
  m.half_widths.depth = {1.0, 0.5, 100.0};
  m.half_widths.altitude = {0.1, 0.1, 0.5};
  // 12 + 100 deep, 4 + 0.5 above the floor, and half a second at both rates.
  EXPECT_GE(deepest(m), 116.5 + rates + band);
  EXPECT_LT(deepest(m), 116.5 + rates + band + 0.001);
  // A mission's margin is the depth effect there.
  m.gps_time = {0.0};
  m.origin = test::kFrameOrigins[0];
  m.gps_latitude = {m.origin.latitude};
  m.gps_longitude = {m.origin.longitude};
  fill_local_gps(m, "m");
  const double floor = 116.5 + rates + band;
  EXPECT_GE(m.depth_scale_margin, floor / (kRadius - floor));
  EXPECT_LE(m.depth_scale_margin, 1.02 * (floor + 0.001) / kRadius);
  // The frame's margin holds the scale measured at the zone's edge.
  const LocalFrame frame(m.origin);
  const GeoOrigin edge = test::geodesic_destination(m.origin, 30.0, kZone - 10.0),
                  step = test::geodesic_destination(edge, 30.0, 10.0);
  EXPECT_GE(m.frame_scale_margin, 1.0 - frame_distance(frame, edge, step) / surface_distance(edge, step));
}

TEST(Geodesy, GpsBoxesAreWidenedAndHoldTheFixes) {
  Mission m;
  m.origin = test::kFrameOrigins[0];
  m.gps_time = {0.0, 1.0};
  const GeoOrigin far = test::geodesic_destination(m.origin, 40.0, 3000.0);
  m.gps_latitude = {m.origin.latitude, far.latitude};
  m.gps_longitude = {m.origin.longitude, far.longitude};
  fill_local_gps(m, "m");
  EXPECT_NEAR(m.gps_north[0], 0.0, 1e-9);
  EXPECT_NEAR(std::hypot(m.gps_north[1], m.gps_east[1]), 3000.0, 0.01);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_GE(m.gps_north_halfwidth[i], m.model.gps_metres + kLocalFrameError);
    EXPECT_GE(m.gps_east_halfwidth[i], m.model.gps_metres + kLocalFrameError);
  }
  // Per-fix bounds replace the model's, still widened.
  m.gps_given_north_halfwidth = {0.5, 7.0};
  m.gps_given_east_halfwidth = {0.25, 0.0};
  fill_local_gps(m, "m");
  // ... and turned by the meridian convergence where the fix is: each half-width
  // grows by the other times that angle (docs/formats.md), which the geodesic
  // measurement below bounds from below; at the origin it is (almost) nothing.
  const double north_turn = (m.gps_north_halfwidth[1] - 7.0 - kLocalFrameError) / kLocalFrameError;
  EXPECT_GE(north_turn, true_convergence(m.origin, far));
  EXPECT_LE(north_turn, m.heading_frame_margin);
  EXPECT_LT(north_turn, 0.5 * m.heading_frame_margin);  // 3 km of the 100 km zone
  EXPECT_NEAR(m.gps_north_halfwidth[0], 0.5 + kLocalFrameError, 1e-7);
  EXPECT_GE(m.gps_north_halfwidth[0], 0.5 + kLocalFrameError);
  EXPECT_GE(m.gps_east_halfwidth[1], kLocalFrameError);
  EXPECT_LT(m.gps_east_halfwidth[1], 2 * kLocalFrameError);
}

TEST(Geodesy, MeridianConvergenceOverTheMissionAreaIsInsideTheHeadingMargin) {
  for (const GeoOrigin& origin : test::kFrameOrigins) {
    Mission m;
    m.origin = origin;
    m.gps_time = {0.0, 1.0};
    const GeoOrigin far = test::geodesic_destination(origin, 60.0, 4000.0);
    m.gps_latitude = {origin.latitude, far.latitude};
    m.gps_longitude = {origin.longitude, far.longitude};
    fill_local_gps(m, "m");
    double worst = 0.0;
    // Points at the edge of the frame's zone, where the margin must hold.
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 10.0)
      worst = std::max(worst, true_convergence(origin, test::geodesic_destination(origin, azimuth, kZone)));
    EXPECT_LE(worst, m.heading_frame_margin) << origin.latitude;
    if (origin.latitude != 0.0) {
      EXPECT_GT(worst, 0.9 * m.heading_frame_margin) << origin.latitude;
    }
  }
}

}  // namespace
}  // namespace gesmi::io
