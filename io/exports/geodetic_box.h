#pragma once
// Local boxes to latitude/longitude, outward: a geodetic box or polygon that contains
// every sea-surface point whose projection on the local plane lies in the local box.
//
// The plane-to-geodetic map is smooth but not affine: along a straight local segment
// of length h its latitude and longitude leave the chord between the end images by at
// most h^2 K / 8, with K = 4 (1 + |tan(latitude)|) / M (M = b^2/a, the smallest
// radius of curvature) a bound of the map's second derivatives in metres per metre^2.
// Segments are cut into pieces of at most kGeodeticPiece metres and every bound is
// widened by that deviation plus kLocalFrameError (the conversion's own error, far
// below 1 cm). tests/io/geodetic_box_test.cpp checks the bounds against dense
// sampling with GeographicLib.

#include <cmath>

#include "io/geodesy.h"
#include "solver/interval/interval.h"

namespace gesmi::io {

inline constexpr double kGeodeticPiece = 50.0;  // m: longest local segment between converted points

/// Latitude and longitude bounds (degrees).
struct GeodeticBox {
  double latitude_lo, latitude_hi, longitude_lo, longitude_hi;
};
/// The box extend() starts from: it holds no point.
inline constexpr GeodeticBox kNoPoint{INFINITY, -INFINITY, INFINITY, -INFINITY};

/// Grows the box to hold the point (degrees).
void extend(GeodeticBox& box, double latitude, double longitude);
/// The box widened on every side by `metres`, taken at latitudes up to |max_latitude|.
GeodeticBox widened(GeodeticBox box, double metres, double max_latitude);

/// K (1/m): the bound of the plane-to-geodetic map's second derivative along any
/// straight local line, at latitudes up to |max_latitude| degrees.
double geodetic_curvature(double max_latitude);

/// The widening (m) that covers the chord deviation of pieces up to `piece` metres
/// long at latitudes up to |max_latitude| degrees, plus the conversion error.
double geodetic_margin(double piece, double max_latitude);

/// Largest |latitude| (degrees) the geodetic exports accept for an origin: the
/// longitude's scale grows without bound toward the poles.
inline constexpr double kGeodeticExportLatitude = 85.0;
/// Largest distance (m) from the origin of a box the geodetic exports convert: the
/// frame's conversion error stays under 1 mm there (3.7e-4 m at 500 km, 0.18 m at
/// 1000 km), and with the origin within kGeodeticExportLatitude no pole is that close
/// (5 degrees of latitude are 555 km). A box reaching farther is exported as unbounded.
inline constexpr double kGeodeticExportRadius = 500000.0;
/// The largest |latitude| a box within kGeodeticExportRadius of an origin at
/// `origin_latitude` reaches, plus a slack (below 90).
double farthest_latitude(double origin_latitude);

/// True when the local box lies within kGeodeticExportRadius of the origin.
bool within_export_radius(const Interval& north, const Interval& east);

/// The local frame's point (north, east) with its longitude taken within 180 degrees of
/// the origin's: a box or polygon across the antimeridian stays contiguous (its
/// longitudes may pass 180 or -180, as GDAL and most GIS accept).
GeoOrigin geodetic_point(const LocalFrame& frame, double north, double east);
/// A longitude taken within 180 degrees of `origin_longitude` (degrees).
double longitude_near(double longitude, double origin_longitude);

/// Outward geodetic bounds of the local box north x east (both bounded, non-empty and
/// within_export_radius).
GeodeticBox geodetic_box(const LocalFrame& frame, const Interval& north, const Interval& east);

}  // namespace gesmi::io
