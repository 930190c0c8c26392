#pragma once
// Geodesy with GeographicLib: WGS84 latitude/longitude <-> the mission's local NED
// frame about its origin (a local tangent plane, GeographicLib::LocalCartesian),
// and the GPS boxes of a mission in that frame.
//
// Conversion error (docs/formats.md): the solver integrates DVL distances along the
// sea surface while the tangent plane holds their projections. Over a 10 km zone
// the difference is below d^3 / (3 R^2) = 8 mm; gps_boxes() widens every box by
// kLocalFrameError = 1 cm. Meridian convergence (true north turning against the
// frame's north) is returned separately for the heading bound.

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
  NorthEast to_local(double latitude, double longitude) const;
  GeoOrigin to_geodetic(double north, double east) const;

 private:
  GeoOrigin origin_;
};

/// Sets the fixes' longitude and latitude from gps_north/east (simulated missions,
/// whose fixes are made in the local frame).
void set_geodetic_gps(Mission& mission);

/// Fills gps_north/east and their half-widths, and heading_frame_margin, from the
/// fixes, the origin and the sensor model. Throws FormatError (naming `source` and
/// the fix) when a fix lies farther than kLocalFrameZone from the origin.
void fill_local_gps(Mission& mission, const std::string& source);

}  // namespace gesmi::io
