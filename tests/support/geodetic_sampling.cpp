#include "tests/support/geodetic_sampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <GeographicLib/Geodesic.hpp>

namespace gesmi::test {

GeoOrigin geodesic_destination(const GeoOrigin& from, double azimuth_deg, double distance) {
  GeoOrigin to{};
  GeographicLib::Geodesic::WGS84().Direct(from.latitude, from.longitude, azimuth_deg, distance, to.latitude,
                                          to.longitude);
  return to;
}

SampledExtremes sample_inside(const io::LocalFrame& frame, const Interval& north, const Interval& east,
                              const io::GeodeticBox& bounds, int edge, int grid) {
  SampledExtremes x{INFINITY, -INFINITY, INFINITY, -INFINITY};
  int outside = 0;
  const auto sample = [&](double n, double e) {
    const GeoOrigin g = io::geodetic_point(frame, n, e);
    const bool inside = g.latitude >= bounds.latitude_lo && g.latitude <= bounds.latitude_hi &&
                        g.longitude >= bounds.longitude_lo && g.longitude <= bounds.longitude_hi;
    if (!inside && outside++ == 0)
      ADD_FAILURE() << "the point (" << n << ", " << e << ") m, at " << g.latitude << ", " << g.longitude
                    << " degrees, is outside [" << bounds.latitude_lo << ", " << bounds.latitude_hi << "] x ["
                    << bounds.longitude_lo << ", " << bounds.longitude_hi << "]";
    x.lat_lo = std::min(x.lat_lo, g.latitude);
    x.lat_hi = std::max(x.lat_hi, g.latitude);
    x.lon_lo = std::min(x.lon_lo, g.longitude);
    x.lon_hi = std::max(x.lon_hi, g.longitude);
  };
  for (int i = 0; i <= edge; ++i) {
    const double f = static_cast<double>(i) / edge;
    const double n = north.lo() + f * north.width(), e = east.lo() + f * east.width();
    sample(north.lo(), e);
    sample(north.hi(), e);
    sample(n, east.lo());
    sample(n, east.hi());
  }
  for (int i = 0; i <= grid; ++i)
    for (int j = 0; j <= grid; ++j) sample(north.lo() + north.width() * i / grid, east.lo() + east.width() * j / grid);
  EXPECT_EQ(outside, 0) << "points outside the bounds";
  return x;
}

}  // namespace gesmi::test
