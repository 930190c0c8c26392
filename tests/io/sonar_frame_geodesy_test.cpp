// The sonar's geometry far from the frame's origin against WGS84 (GeographicLib): a
// robot up to 90 km from the origin and a mine on the floor 45 m abeam, placed on the
// ellipsoid from the robot's own north-east-down axes. The frame's q - m (the tangent
// plane's projections of their surface points, depths along their own verticals)
// differs from the sonar's offset at the robot by up to sonar_frame_slack(), which
// SonarPlane::contract takes: with it the truth stays in millimetre boxes; without it
// (the negative control) the contraction, or the waterfall's pre-filter on the
// distances the boxes allow (SonarPlane::possible_ranges), loses the truth where the
// beam is radial.

#include <GeographicLib/LocalCartesian.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "io/geodesy.h"
#include "solver/mission/frame_scale.h"
#include "solver/mission/meridian_convergence.h"
#include "solver/network/sonar_plane.h"
#include "tests/support/geodetic_sampling.h"
#include "solver/model/angles.h"

namespace gesmi::io {
namespace {

constexpr double kBox = 1e-3;  // m: the half-width of every box but the heading's

struct Scene {
  SonarPlane plane;
  Vec3I q, m;
  Interval range;
  double truth_q[3], truth_m[3];
};

// The robot `distance` metres from the origin at `azimuth` (deg), `depth` deep, heading
// so that its starboard beam points at `beam` (deg from true north); the mine 45 m
// across and 10 m below it.
Scene scene(const GeoOrigin& origin, double azimuth, double distance, double beam) {
  const double depth = 20.0, across = 45.0, below = 10.0;
  const GeoOrigin robot = test::geodesic_destination(origin, azimuth, distance);
  // The mine from the robot's own axes (east, north, up).
  const double b = beam * kRadiansPerDegree;
  const GeographicLib::LocalCartesian at_robot(robot.latitude, robot.longitude, -depth);
  double lat = 0, lon = 0, height = 0;
  at_robot.Reverse(across * std::sin(b), across * std::cos(b), -below, lat, lon, height);
  const LocalFrame frame(origin);
  const NorthEast p = frame.to_local(robot.latitude, robot.longitude), m = frame.to_local(lat, lon);
  Scene s;
  s.truth_q[0] = p.north;
  s.truth_q[1] = p.east;
  s.truth_q[2] = depth;
  s.truth_m[0] = m.north;
  s.truth_m[1] = m.east;
  s.truth_m[2] = -height;
  for (int i = 0; i < 3; ++i) {
    s.q[i] = Interval::around(s.truth_q[i], kBox);
    s.m[i] = Interval::around(s.truth_m[i], kBox);
  }
  s.range = Interval::around(std::hypot(across, below), kBox);
  // True north turns against the frame's by the meridian convergence: the heading box
  // takes its bound there, as the solver's does.
  const double turn = meridian_convergence_within(origin.latitude, distance + 100.0);
  s.plane.attitude = make_attitude(Interval::around(0.0, 1e-9), Interval::around(0.0, 1e-9),
                                   Interval::around(b - std::numbers::pi / 2, 1e-9).inflated(turn));
  s.plane.altitude = Interval::around(below, kBox);
  s.plane.along_tolerance = kBox;
  s.plane.depth_band = 0.0;
  s.plane.side = SonarSide::starboard;
  return s;
}

bool keeps_truth(Scene s, double slack) {
  s.plane.frame_slack = slack;
  // The waterfall's pre-filter first (the distances the boxes allow), then the contraction.
  s.range = intersect(s.range, s.plane.possible_ranges(s.q, s.m));
  if (!s.plane.contract(s.q, s.m, s.range)) return false;
  for (int i = 0; i < 3; ++i)
    if (!s.q[i].contains(s.truth_q[i]) || !s.m[i].contains(s.truth_m[i])) return false;
  return true;
}

TEST(SonarFrameGeodesy, TheSlackKeepsTheTruthAnywhereInTheZone) {
  int lost_without = 0, radial = 0;
  for (const GeoOrigin& origin : test::kFrameOrigins)
    for (const double distance : {100.0, 5000.0, 50000.0, 90000.0})
      for (double azimuth = 0.0; azimuth < 360.0; azimuth += 45.0)
        for (const double turn : {0.0, 90.0, 180.0, 270.0}) {
          const Scene s = scene(origin, azimuth, distance, azimuth + turn);
          // The frame's scale where the robot is, and the depth's at the floor (30 m
          // plus the boxes).
          const double scale = frame_scale_within(distance + 100.0) + depth_scale_within(31.0);
          const double slack = sonar_frame_slack(scale, s.range.hi());
          EXPECT_TRUE(keeps_truth(s, slack)) << origin.latitude << " " << distance << " m at " << azimuth << " beam +"
                                             << turn;
          if (distance == 100.0) {
            EXPECT_TRUE(keeps_truth(s, 0.0));  // near the origin the boxes hold it all
          }
          if (distance == 90000.0 && (turn == 0.0 || turn == 180.0)) {
            ++radial;
            lost_without += !keeps_truth(s, 0.0);
          }
        }
  // Negative control: 90 km out with a radial beam the frame shrinks the offset by
  // about 4.5 mm, beyond the millimetre boxes.
  EXPECT_EQ(lost_without, radial);
}

TEST(SonarFrameGeodesy, ThePreFilterAllowsTheTrueRange) {
  int excluded_without = 0, radial = 0;
  for (const GeoOrigin& origin : test::kFrameOrigins)
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 45.0)
      for (const double turn : {0.0, 90.0, 180.0, 270.0}) {
        Scene s = scene(origin, azimuth, 90000.0, azimuth + turn);
        const double true_range = std::hypot(45.0, 10.0);
        s.plane.frame_slack = sonar_frame_slack(frame_scale_within(90100.0) + depth_scale_within(31.0), 50.0);
        EXPECT_TRUE(s.plane.possible_ranges(s.q, s.m).contains(true_range)) << origin.latitude << " " << azimuth;
        // The pre-rejection of the waterfall, for a sonar whose largest range is this one.
        EXPECT_FALSE(boxes_beyond(s.q, s.m, true_range + 2.0 * s.plane.frame_slack)) << origin.latitude << " " << azimuth;
        if (turn == 0.0 || turn == 180.0) {
          ++radial;
          s.plane.frame_slack = 0.0;
          excluded_without += !s.plane.possible_ranges(s.q, s.m).contains(true_range);
        }
      }
  EXPECT_EQ(excluded_without, radial);  // the distance of the frame's boxes alone misses it
}

}  // namespace
}  // namespace gesmi::io
