#pragma once
// Geodesy with GeographicLib: WGS84 latitude/longitude <-> the mission's local NED
// frame about its origin (a local tangent plane, GeographicLib::LocalCartesian),
// and the GPS boxes of a mission in that frame.
//
// Conversion error (docs/formats.md, measured in tests/io/geodesy_test.cpp): points
// convert both ways exactly (to_local projects the sea-surface point on the plane
// tangent at the origin, to_geodetic inverts it within 10 nm over the zone). The
// solver integrates DVL distances along the sea surface while the plane holds their
// projections: along a path at distance rho from the origin the plane's scale differs
// from 1 by at most rho^2 / (2 M^2) (M = b^2/a, the smallest radius of curvature;
// 1.25e-4 at the zone's 100 km edge), which the solver adds per sample
// (Mission::frame_scale_margin). Straight distances between points differ by up to
// d^3 / (3 M^2) (8.3 m across 2 x 100 km), which no box needs: fixes are placed by
// projection, not by distance. fill_local_gps() widens every fix box by
// kLocalFrameError = 1 cm (far above the conversion's rounding), then by the meridian
// convergence that turns a fix's north/east axes against the frame's. Meridian
// convergence (true north turning against the frame's north) is returned separately
// for the heading bound.

#include <GeographicLib/LocalCartesian.hpp>
#include <string>

#include "solver/mission/mission.h"

namespace gesmi::io {

inline constexpr double kLocalFrameError = 0.01;   // m, within kLocalFrameZone of the origin
inline constexpr double kLocalFrameZone = 100000.0;  // m

/// "the fix is D m from the origin, beyond the 100 km zone of the local frame: ...",
/// for the readers that refuse such a fix.
std::string fix_beyond_zone(double distance);

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
  const GeoOrigin& origin() const { return origin_; }

 private:
  GeoOrigin origin_;
  GeographicLib::LocalCartesian plane_;  // built once: exports convert every tube corner
};

/// Sets the fixes' longitude and latitude from gps_north/east (simulated missions,
/// whose fixes are made in the local frame).
void set_geodetic_gps(Mission& mission);

/// The deepest point the sonar's geometry reaches (m): the floor under the robot, its
/// largest depth plus altitude readings with their bounds, plus what the floor's rate
/// adds over half the longest step (the faster of max_depth_rate + max_altitude_rate
/// and the floor's slope times speed_bound()), plus the mine's depth band
/// (Mission::depth_scale_margin).
double deepest(const Mission& mission);

/// Fills gps_north/east and their half-widths, heading_frame_margin and the frame's
/// scale margins (frame_scale_margin, depth_scale_margin), from the
/// fixes, the origin and the sensor model (or the per-fix given bounds when the
/// mission has them). Throws FormatError (naming `source` and
/// the fix) when a fix lies farther than kLocalFrameZone from the origin.
void fill_local_gps(Mission& mission, const std::string& source);

}  // namespace gesmi::io
