#pragma once
// Geodesy with GeographicLib: WGS84 latitude/longitude <-> the mission's local NED
// frame about its origin (a local tangent plane, GeographicLib::LocalCartesian),
// and the GPS boxes of a mission in that frame.
//
// Conversion error (docs/formats.md, measured in tests/io/geodesy_test.cpp): the
// solver integrates DVL distances along the sea surface while the tangent plane
// holds their projections. Between two points of a zone of radius d = 10 km the
// difference is at most d^3 / (3 M^2) = 8.3 mm (M = b^2/a, the smallest radius of
// curvature); fill_local_gps() widens every box by kLocalFrameError = 1 cm, then by
// the meridian convergence that turns a fix's north/east axes against the frame's. Along a
// path the frame's scale differs from 1 by at most d^2 / (2 M^2) = 1.25e-6, so a
// path's error grows with its length (docs/formats.md). Points convert both ways
// exactly (to_geodetic inverts to_local). Meridian convergence (true north turning
// against the frame's north) is returned separately for the heading bound.

#include "solver/mission/mission.h"

namespace gesmi::io {

inline constexpr double kLocalFrameError = 0.01;   // m, within kLocalFrameZone of the origin
inline constexpr double kLocalFrameZone = 10000.0;  // m

struct NorthEast {
  double north, east;
};

class LocalFrame {
 public:
  explicit LocalFrame(const GeoOrigin& origin);
  /// Projection on the tangent plane of the sea-surface point (height 0).
  NorthEast to_local(double latitude, double longitude) const;
  /// The sea-surface point whose projection is (north, east): to_local's inverse.
  GeoOrigin to_geodetic(double north, double east) const;

 private:
  GeoOrigin origin_;
};

/// Sets the fixes' longitude and latitude from gps_north/east (simulated missions,
/// whose fixes are made in the local frame).
void set_geodetic_gps(Mission& mission);

/// The relative scale error of the local frame along a path within `reach` metres of
/// the origin, for a robot at most `depth` metres deep (Mission::frame_scale_margin).
double frame_scale_margin(double reach, double depth);
/// The deepest the robot can be (m): the largest depth reading plus its bound, plus
/// max_depth_rate for half the longest step.
double deepest(const Mission& mission);

/// Fills gps_north/east and their half-widths, heading_frame_margin and the frame's
/// scale margin (frame_scale_margin), from the
/// fixes, the origin and the sensor model (or the per-fix given bounds when the
/// mission has them). Throws FormatError (naming `source` and
/// the fix) when a fix lies farther than kLocalFrameZone from the origin.
void fill_local_gps(Mission& mission, const std::string& source);

}  // namespace gesmi::io
