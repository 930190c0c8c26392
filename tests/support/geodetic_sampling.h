#pragma once
// The independent check of outward geodetic boxes (io/exports/geodetic_box.h,
// geodetic_grid.h): sea-surface points of a local box converted one by one with
// GeographicLib, each expected inside the box's bounds.

#include "io/exports/geodetic_box.h"

namespace gesmi::test {

/// Frame origins of the geodesy tests: the reference mission's, the equator, 70 N, and
/// 45 S by the antimeridian.
inline constexpr GeoOrigin kFrameOrigins[] = {
    {48.212920614, -4.458227931}, {0.0, 10.0}, {70.0, 20.0}, {-45.0, 170.0}};

/// The end of the WGS84 geodesic (GeographicLib) from `from`, at an azimuth in degrees,
/// `distance` metres long.
GeoOrigin geodesic_destination(const GeoOrigin& from, double azimuth_deg, double distance);

/// The extremes of the sampled latitudes and longitudes (degrees).
struct SampledExtremes {
  double lat_lo, lat_hi, lon_lo, lon_hi;
};

/// Samples the box north x east: each edge at edge + 1 evenly spaced points, the
/// interior on a (grid + 1) x (grid + 1) lattice. Points outside `bounds` fail the
/// calling test (naming the first and their number).
SampledExtremes sample_inside(const io::LocalFrame& frame, const Interval& north, const Interval& east,
                              const io::GeodeticBox& bounds, int edge, int grid);

}  // namespace gesmi::test
