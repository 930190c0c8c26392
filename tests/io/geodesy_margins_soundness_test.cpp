// The local frame's margins (io/geodesy.h, docs/formats.md "Local frame and
// geodesy") against an independent computation: WGS84 geodetic -> Earth-centred
// coordinates -> the origin's east/north/up axes, written out in long double here
// (no GeographicLib), at adversarial places: origins from the equator to 89°
// (the largest latitude a mission file accepts), on the antimeridian, and fixes
// at the edge of the 100 km zone in every direction.
//  - to_local is the orthographic projection of the sea-surface point on the
//    origin's tangent plane, and to_geodetic inverts it;
//  - heading_frame_margin bounds the angle between a true azimuth at any point
//    of the mission area and its direction in the frame, for every azimuth;
//  - a fix's box in the frame holds the projection of every point the fix allows:
//    its degree box (latitude, longitude +- the model's degree bounds) and its
//    metric box (north and east half-widths about the fix, in the fix's own
//    north/east axes).

#include "io/geodesy.h"
#include "tests/support/geodetic_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace gesmi::io {
namespace {

constexpr long double kA = 6378137.0L;                   // WGS84 semi-major axis (m)
constexpr long double kF = 1.0L / 298.257223563L;        // WGS84 flattening
constexpr long double kE2 = kF * (2.0L - kF);            // first eccentricity squared
constexpr long double kDegree = std::numbers::pi_v<long double> / 180.0L;

struct V3 {
  long double x, y, z;
};
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(long double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
long double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Earth-centred coordinates of the sea-surface point (height 0).
V3 surface_point(long double lat_deg, long double lon_deg) {
  const long double phi = lat_deg * kDegree, lambda = lon_deg * kDegree;
  const long double n = kA / std::sqrt(1.0L - kE2 * std::sin(phi) * std::sin(phi));
  return {n * std::cos(phi) * std::cos(lambda), n * std::cos(phi) * std::sin(lambda), n * (1.0L - kE2) * std::sin(phi)};
}
V3 north_axis(long double lat_deg, long double lon_deg) {
  const long double phi = lat_deg * kDegree, lambda = lon_deg * kDegree;
  return {-std::sin(phi) * std::cos(lambda), -std::sin(phi) * std::sin(lambda), std::cos(phi)};
}
V3 east_axis(long double lon_deg) {
  const long double lambda = lon_deg * kDegree;
  return {-std::sin(lambda), std::cos(lambda), 0.0L};
}

// The frame about an origin: projection on its tangent plane.
struct IndependentFrame {
  V3 centre, north, east;
  explicit IndependentFrame(const GeoOrigin& o)
      : centre(surface_point(o.latitude, o.longitude)),
        north(north_axis(o.latitude, o.longitude)),
        east(east_axis(o.longitude)) {}
  void project(V3 p, long double& n, long double& e) const {
    n = dot(p - centre, north);
    e = dot(p - centre, east);
  }
};

const GeoOrigin kMarginOrigins[] = {{0.0, 10.0},   {48.212920614, -4.458227931}, {70.0, 20.0}, {80.0, -60.0},
                              {89.0, 135.0}, {-89.0, 0.0},                 {-60.0, 180.0}, {30.0, -179.999}};

std::string where(const GeoOrigin& o, double azimuth, double distance) {
  char b[120];
  std::snprintf(b, sizeof b, "origin (%.6f, %.6f), %.0f m at azimuth %.0f", o.latitude, o.longitude, distance, azimuth);
  return b;
}

TEST(GeodesyMarginsSoundness, TheFrameIsTheOrthographicProjectionOfTheSurfacePoint) {
  double worst = 0.0;
  for (const GeoOrigin& origin : kMarginOrigins) {
    const LocalFrame frame(origin);
    const IndependentFrame oracle(origin);
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 15.0)
      for (const double distance : {0.0, 1.0, 2500.0, 9999.0, 99999.0}) {
        const GeoOrigin p = test::geodesic_destination(origin, azimuth, distance);
        const NorthEast got = frame.to_local(p.latitude, p.longitude);
        long double n, e;
        oracle.project(surface_point(p.latitude, p.longitude), n, e);
        worst = std::max({worst, static_cast<double>(std::fabs(got.north - n)), static_cast<double>(std::fabs(got.east - e))});
        // to_geodetic finds the surface point whose projection is (north, east).
        const GeoOrigin back = frame.to_geodetic(static_cast<double>(n), static_cast<double>(e));
        long double n2, e2;
        oracle.project(surface_point(back.latitude, back.longitude), n2, e2);
        ASSERT_NEAR(static_cast<double>(n2), static_cast<double>(n), 1e-6) << where(origin, azimuth, distance);
        ASSERT_NEAR(static_cast<double>(e2), static_cast<double>(e), 1e-6) << where(origin, azimuth, distance);
      }
  }
  std::printf("to_local against the independent projection: worst difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-6);
}

// A mission whose fixes are the origin and one point `distance` away at `azimuth`.
Mission mission_with_fix(const GeoOrigin& origin, double azimuth, double distance) {
  Mission m;
  m.origin = origin;
  m.gps_time = {0.0, 1.0};
  const GeoOrigin far = test::geodesic_destination(origin, azimuth, distance);
  m.gps_latitude = {origin.latitude, far.latitude};
  m.gps_longitude = {origin.longitude, far.longitude};
  return m;
}

// Angle between the true azimuth alpha at p and its direction in the frame.
long double frame_turn(const IndependentFrame& frame, const GeoOrigin& p, long double alpha_deg) {
  const long double alpha = alpha_deg * kDegree;
  const V3 t = std::cos(alpha) * north_axis(p.latitude, p.longitude) + std::sin(alpha) * east_axis(p.longitude);
  const long double turn = std::atan2(dot(t, frame.east), dot(t, frame.north)) - alpha;
  return std::remainder(turn, 2.0L * std::numbers::pi_v<long double>);
}

TEST(GeodesyMarginsSoundness, HeadingMarginHoldsEveryAzimuthOverTheMissionArea) {
  int failures = 0;
  std::string first;
  double tightest = 0.0;  // largest ratio of a turn to the margin
  for (const GeoOrigin& origin : kMarginOrigins) {
    const IndependentFrame oracle(origin);
    for (const double fix_distance : {0.0, 10000.0, 50000.0, 80000.0, 99999.0}) {
      Mission m = mission_with_fix(origin, 45.0, fix_distance);
      fill_local_gps(m, "test");
      // The area the margin claims: within the farthest fix's distance + 2 km
      // (at most the 100 km zone) of the origin.
      const double extent = std::min(fix_distance + 2000.0, kLocalFrameZone);
      for (double bearing = 0.0; bearing < 360.0; bearing += 10.0)
        for (const double fraction : {0.5, 1.0}) {
          const GeoOrigin p = test::geodesic_destination(origin, bearing, extent * fraction);
          for (double alpha = 0.0; alpha < 360.0; alpha += 15.0) {
            const long double turn = std::fabs(frame_turn(oracle, p, alpha));
            tightest = std::max(tightest, static_cast<double>(turn / m.heading_frame_margin));
            if (turn > m.heading_frame_margin && failures++ == 0)
              first = where(origin, bearing, extent * fraction) + ", azimuth " + std::to_string(alpha) + ": turn " +
                      std::to_string(static_cast<double>(turn)) + " rad > margin " + std::to_string(m.heading_frame_margin);
          }
        }
    }
  }
  std::printf("heading margin: worst turn / margin = %.4f\n", tightest);
  EXPECT_EQ(failures, 0) << first;
  EXPECT_GT(tightest, 0.9);  // the margin is not loose by more than 10 %
}

// The projections of the corners and edge midpoints of a fix's uncertainty region
// must lie in its box in the frame.
struct BoxCheck {
  int failures = 0;
  std::string first;
  double worst = -1e300;  // largest excess over the box (m; negative: inside)
  void check(const Mission& m, std::size_t i, long double n, long double e, const std::string& what) {
    const long double over = std::max(std::fabs(n - m.gps_north[i]) - m.gps_north_halfwidth[i],
                                      std::fabs(e - m.gps_east[i]) - m.gps_east_halfwidth[i]);
    worst = std::max(worst, static_cast<double>(over));
    if (over > 0.0L && failures++ == 0) {
      char b[160];
      std::snprintf(b, sizeof b, ": outside the fix's box by %.4Lf m", over);
      first = what + b;
    }
  }
};

void check_fix_boxes(SensorModel model, bool given_bounds, BoxCheck& c) {
  for (const GeoOrigin& origin : kMarginOrigins) {
    const IndependentFrame oracle(origin);
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 45.0) {
      Mission m = mission_with_fix(origin, azimuth, 99999.0);
      m.model = model;
      if (given_bounds) {
        m.gps_given_north_halfwidth = {0.5, 0.5};
        m.gps_given_east_halfwidth = {2.5, 2.5};
      }
      fill_local_gps(m, "test");
      const std::size_t i = 1;
      const GeoOrigin fix{m.gps_latitude[i], m.gps_longitude[i]};
      const V3 centre = surface_point(fix.latitude, fix.longitude);
      const V3 north = north_axis(fix.latitude, fix.longitude), east = east_axis(fix.longitude);
      for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b) {
          long double n, e;
          if (given_bounds || model.gps_metres > 0.0) {
            // The metric box about the fix, in the fix's north/east axes (on the
            // tangent plane at the fix: a 2.5 m offset is 0.5 um off the surface).
            const long double hn = given_bounds ? 0.5L : model.gps_metres, he = given_bounds ? 2.5L : model.gps_metres;
            oracle.project(centre + (a * hn) * north + (b * he) * east, n, e);
            c.check(m, i, n, e, where(origin, azimuth, 99999.0) + " metric corner");
          }
          if (!given_bounds) {  // the degree box
            oracle.project(surface_point(fix.latitude + a * model.gps_lat_deg, fix.longitude + b * model.gps_lon_deg), n, e);
            c.check(m, i, n, e, where(origin, azimuth, 99999.0) + " degree corner");
          }
        }
    }
  }
}

TEST(GeodesyMarginsSoundness, FixBoxesHoldTheProjectionOfEveryPointTheFixAllows) {
  SensorModel degrees_only;
  degrees_only.gps_metres = 0.0;  // the degree bounds alone
  const struct {
    const char* name;
    SensorModel model;
    bool given;
  } kinds[] = {{"model defaults (2.5 m box)", SensorModel{}, false},
               {"degree bounds alone", degrees_only, false},
               {"per-fix half-widths 0.5 m north, 2.5 m east", SensorModel{}, true}};
  for (const auto& kind : kinds) {
    BoxCheck c;
    check_fix_boxes(kind.model, kind.given, c);
    std::printf("fix boxes, %s: worst excess of an allowed point over its box %.5f m\n", kind.name, c.worst);
    EXPECT_EQ(c.failures, 0) << kind.name << ": " << c.first;
  }
}

}  // namespace
}  // namespace gesmi::io
