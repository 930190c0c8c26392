// geodetic_box() against dense sampling: every sea-surface point whose projection lies
// in a local box (its edges sampled every few metres and its interior on a grid,
// converted one by one) must fall inside the box's outward latitude/longitude bounds,
// at low and high latitudes, near and far (90 km) from the origin, across the
// antimeridian, for boxes of metres to kilometres. And the bounds stay tight: within a few centimetres of the
// sampled extremes.

#include "io/exports/geodetic_box.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/geodetic_sampling.h"

namespace gesmi::io {
namespace {

struct BoxCase {
  GeoOrigin origin;
  double north, east, size;  // box centre (m) and side (m)
};

class GeodeticBoxTest : public ::testing::TestWithParam<BoxCase> {};

TEST_P(GeodeticBoxTest, ContainsEverySampledPointAndStaysTight) {
  const BoxCase c = GetParam();
  const LocalFrame frame(c.origin);
  const Interval north(c.north - c.size / 2, c.north + c.size / 2 * 0.7);
  const Interval east(c.east - c.size / 2 * 0.8, c.east + c.size / 2);
  const GeodeticBox box = geodetic_box(frame, north, east);
  const auto [lat_lo, lat_hi, lon_lo, lon_hi] = test::sample_inside(frame, north, east, box, 4000, 40);
  // Tight: the margins add at most a few centimetres beyond the sampled extremes.
  const double farthest = std::max(std::abs(lat_lo), std::abs(lat_hi));
  const double metre_lat = 1.0 / 110000.0, metre_lon = metre_lat / std::cos(farthest * M_PI / 180.0);
  EXPECT_LT(lat_lo - box.latitude_lo, 0.05 * metre_lat);
  EXPECT_LT(box.latitude_hi - lat_hi, 0.05 * metre_lat);
  EXPECT_LT(lon_lo - box.longitude_lo, 0.05 * metre_lon);
  EXPECT_LT(box.longitude_hi - lon_hi, 0.05 * metre_lon);
}

INSTANTIATE_TEST_SUITE_P(
    LatitudesDistancesSizes, GeodeticBoxTest,
    ::testing::Values(BoxCase{{48.2129, -4.4582}, 500, 300, 20}, BoxCase{{48.2129, -4.4582}, 90000, 10000, 3000},
                      BoxCase{{0.0, 10.0}, -60000, 60000, 20000}, BoxCase{{70.0, 20.0}, 80000, -40000, 20000},
                      BoxCase{{84.0, -150.0}, 20000, 85000, 20000}, BoxCase{{-84.0, 179.99}, -90000, 1000, 5000},
                      BoxCase{{84.9, 0.0}, 0, 0, 40000}, BoxCase{{85.0, 30.0}, 470000, 0, 40000},
                      BoxCase{{-85.0, 30.0}, -470000, 20000, 30000}));

TEST(GeodeticExportRadius, BoxesFartherThanTheRadiusAreNotConverted) {
  EXPECT_TRUE(within_export_radius(Interval(-1000, 1000), Interval(499000, 499500)));
  EXPECT_FALSE(within_export_radius(Interval(-1000, 1000), Interval(499500, 500100)));
  EXPECT_FALSE(within_export_radius(Interval(1e300, 2e300), Interval(0, 1)));
  // Within the radius of an origin at the highest latitude allowed, no pole: the
  // latitude the margins take stays below 90 degrees.
  EXPECT_LT(farthest_latitude(kGeodeticExportLatitude), 90.0);
  EXPECT_GT(farthest_latitude(kGeodeticExportLatitude), kGeodeticExportLatitude + 4.5);
}

TEST(GeodeticMargin, GrowsWithThePieceAndTheLatitude) {
  EXPECT_GE(geodetic_margin(0.0, 0.0), kLocalFrameError);
  EXPECT_LT(geodetic_margin(kGeodeticPiece, 60.0), 0.011);
  EXPECT_GT(geodetic_margin(kGeodeticPiece, 84.0), geodetic_margin(kGeodeticPiece, 60.0));
  EXPECT_GT(geodetic_margin(2 * kGeodeticPiece, 60.0), geodetic_margin(kGeodeticPiece, 60.0));
}

}  // namespace
}  // namespace gesmi::io
