#include "io/exports/geodetic_box.h"

#include <algorithm>
#include <cmath>

#include "solver/mission/frame_scale.h"
#include "solver/model/angles.h"

namespace gesmi::io {
namespace {

constexpr double kRoundingSlack = 1.0 + 1e-9;  // covers the doubles' rounding in the margins below

// A margin in metres as degrees of latitude, and of longitude at latitudes up to
// |max_latitude| degrees (both outward).
double metres_as_latitude(double metres) { return metres / kWgs84SmallestRadius * kDegreesPerRadian * kRoundingSlack; }

double metres_as_longitude(double metres, double max_latitude) {
  return metres / (kWgs84EquatorialRadius * std::cos(std::abs(max_latitude) / kDegreesPerRadian)) * kDegreesPerRadian * kRoundingSlack;
}

}  // namespace

void extend(GeodeticBox& box, double latitude, double longitude) {
  box.latitude_lo = std::min(box.latitude_lo, latitude);
  box.latitude_hi = std::max(box.latitude_hi, latitude);
  box.longitude_lo = std::min(box.longitude_lo, longitude);
  box.longitude_hi = std::max(box.longitude_hi, longitude);
}

GeodeticBox widened(GeodeticBox box, double metres, double max_latitude) {
  const double dlat = metres_as_latitude(metres), dlon = metres_as_longitude(metres, max_latitude);
  box.latitude_lo -= dlat;
  box.latitude_hi += dlat;
  box.longitude_lo -= dlon;
  box.longitude_hi += dlon;
  return box;
}

double geodetic_curvature(double max_latitude) {
  return 4.0 * (1.0 + std::tan(std::abs(max_latitude) / kDegreesPerRadian)) / kWgs84SmallestRadius * kRoundingSlack;
}

double geodetic_margin(double piece, double max_latitude) {
  return (kLocalFrameError + piece * piece * geodetic_curvature(max_latitude) / 8.0) * kRoundingSlack;
}

double farthest_latitude(double origin_latitude) {
  // A degree of latitude is at least M pi / 180 = 110.57 km long.
  const double reach = kGeodeticExportRadius / (kWgs84SmallestRadius / kDegreesPerRadian);
  return std::min(std::abs(origin_latitude) + reach + 0.01, 89.9);
}

bool within_export_radius(const Interval& north, const Interval& east) {
  const double n = std::max(std::abs(north.lo()), std::abs(north.hi())), e = std::max(std::abs(east.lo()), std::abs(east.hi()));
  return std::hypot(n, e) <= kGeodeticExportRadius;
}

double longitude_near(double longitude, double origin_longitude) {
  if (longitude - origin_longitude > 180.0) return longitude - 360.0;
  if (longitude - origin_longitude < -180.0) return longitude + 360.0;
  return longitude;
}

GeoOrigin geodetic_point(const LocalFrame& frame, double north, double east) {
  GeoOrigin g = frame.to_geodetic(north, east);
  g.longitude = longitude_near(g.longitude, frame.origin().longitude);
  return g;
}

GeodeticBox geodetic_box(const LocalFrame& frame, const Interval& north, const Interval& east) {
  const double corners[5][2] = {{north.lo(), east.lo()}, {north.lo(), east.hi()}, {north.hi(), east.hi()},
                                {north.hi(), east.lo()}, {north.lo(), east.lo()}};
  GeodeticBox box = kNoPoint;
  double longest_piece = 0;
  for (int side = 0; side < 4; ++side) {
    const double* a = corners[side];
    const double* b = corners[side + 1];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const int pieces = static_cast<int>(std::clamp(std::ceil(length / kGeodeticPiece), 1.0, 1024.0));
    longest_piece = std::max(longest_piece, length / pieces);
    for (int i = 0; i < pieces; ++i) {
      const double f = static_cast<double>(i) / pieces;
      const GeoOrigin g = geodetic_point(frame, a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]));
      extend(box, g.latitude, g.longitude);
    }
  }
  // The latitude the margins are taken at: the box's farthest from the equator, plus
  // what the margin itself may add (well under a degree).
  const double latitude = std::min(std::max(std::abs(box.latitude_lo), std::abs(box.latitude_hi)) + 0.01, 89.9);
  return widened(box, geodetic_margin(longest_piece * kRoundingSlack, latitude), latitude);
}

}  // namespace gesmi::io
