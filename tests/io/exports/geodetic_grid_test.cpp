// GeodeticGrid::box() against dense sampling: for random local boxes (points, boxes
// within one tile, boxes on grid lines and across several tiles) every sea-surface
// point whose projection lies in the box, converted one by one with GeographicLib, must
// fall inside the grid's outward bounds; at low and high latitudes, near and far from
// the origin, across the antimeridian. Large tiles make the interpolation's own bound
// (K h^2 / 4) the margin that matters, so the test fails if that term is dropped. The
// default tile stays tight: within a few centimetres of the sampled extremes, as
// geodetic_box() (geodetic_box_test.cpp).

#include "io/exports/geodetic_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/support/geodetic_sampling.h"

namespace gesmi::io {
namespace {

struct Place {
  GeoOrigin origin;
  double north, east;  // where the boxes are (m from the origin)
};

// The edges every 1/120 of their length and a 9 x 9 interior lattice.
test::SampledExtremes sample_inside(const LocalFrame& frame, const Interval& north, const Interval& east,
                                    const GeodeticBox& bounds) {
  return test::sample_inside(frame, north, east, bounds, 120, 8);
}

// Random boxes around `place`: widths from 0 (a point) to 2.5 tiles, some with a side
// on a grid line.
std::vector<std::pair<Interval, Interval>> random_boxes(const Place& place, double tile, int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> offset(-3 * tile, 3 * tile), size(0.0, 2.5 * tile), unit(0.0, 1.0);
  std::vector<std::pair<Interval, Interval>> boxes;
  for (int b = 0; b < count; ++b) {
    double n = place.north + offset(random), e = place.east + offset(random);
    if (b % 5 == 1) n = std::round(n / tile) * tile;  // a side on a grid line
    const double wn = b % 7 == 0 ? 0.0 : size(random) * unit(random), we = b % 7 == 0 ? 0.0 : size(random) * unit(random);
    boxes.emplace_back(Interval(n, n + wn), Interval(e, e + we));
  }
  return boxes;
}

class GeodeticGridTest : public ::testing::TestWithParam<Place> {};

TEST_P(GeodeticGridTest, ContainsEverySampledPointAndStaysTight) {
  const Place place = GetParam();
  const LocalFrame frame(place.origin);
  GeodeticGrid grid(frame);
  for (const auto& [north, east] : random_boxes(place, kGeodeticPiece, 30, 1)) {
    const GeodeticBox box = grid.box(north, east);
    const test::SampledExtremes x = sample_inside(frame, north, east, box);
    // Tight: the margins (1 cm plus the interpolation's bound: 0.8 mm at 48 degrees,
    // 2.5 cm at 89) add at most a few centimetres beyond the sampled extremes.
    const double farthest = std::max(std::abs(x.lat_lo), std::abs(x.lat_hi));
    const double metre_lat = 1.0 / 110000.0, metre_lon = metre_lat / std::cos(farthest * M_PI / 180.0);
    EXPECT_LT(x.lat_lo - box.latitude_lo, 0.05 * metre_lat);
    EXPECT_LT(box.latitude_hi - x.lat_hi, 0.05 * metre_lat);
    EXPECT_LT(x.lon_lo - box.longitude_lo, 0.05 * metre_lon);
    EXPECT_LT(box.longitude_hi - x.lon_hi, 0.05 * metre_lon);
  }
}

TEST_P(GeodeticGridTest, LargeTilesStillContainEverySampledPoint) {
  // With 2 km and 5 km tiles the interpolation's bound is metres to tens of metres:
  // without it the boxes would miss points.
  const Place place = GetParam();
  const LocalFrame frame(place.origin);
  for (const double tile : {2000.0, 5000.0}) {
    GeodeticGrid grid(frame, tile);
    for (const auto& [north, east] : random_boxes(place, tile, 12, 2)) sample_inside(frame, north, east, grid.box(north, east));
  }
}

INSTANTIATE_TEST_SUITE_P(LatitudesAndDistances, GeodeticGridTest,
                         ::testing::Values(Place{{48.2129, -4.4582}, 500, 300}, Place{{48.2129, -4.4582}, 90000, 10000},
                                           Place{{0.0, 10.0}, -60000, 60000}, Place{{70.0, 20.0}, 80000, -40000},
                                           Place{{84.0, -150.0}, 20000, 85000}, Place{{-84.0, 179.99}, -90000, 1000},
                                           Place{{85.0, 30.0}, 450000, 0}, Place{{-85.0, 30.0}, -450000, 20000}));

TEST(GeodeticGrid, WideBoxesAcrossTheOriginsMeridianKeepTheLatitudeBulge) {
  // Along a line of constant north the latitude peaks on the origin's meridian (east 0),
  // between the box's corners: only the grid nodes inside the box see it. Across 6 to 8
  // tiles of 2 km the bulge (metres) exceeds the interpolation's margin.
  const GeoOrigin origin{60.0, 5.0};
  const LocalFrame frame(origin);
  GeodeticGrid grid(frame, 2000.0);
  for (const double half_width : {6100.0, 7300.0, 7900.0})
    for (const double north : {-3000.0, 500.0, 20000.0}) {
      const Interval n(north, north + 300.0), e(-half_width, half_width * 0.9);
      sample_inside(frame, n, e, grid.box(n, e));
    }
}

TEST(GeodeticGrid, EveryTileNearTheOriginContainsItsPoints) {
  // One point in each of the 160,801 tiles within 10 km of the origin (north and east),
  // in tile order and then in a stride that revisits tiles: whatever the cache holds
  // (corners of one tile may share its slots), each point lies inside its bounds.
  const LocalFrame frame({48.0, -4.0});
  GeodeticGrid grid(frame);
  const auto contains = [&](double north, double east) {
    const GeodeticBox box = grid.box(Interval(north), Interval(east));
    const GeoOrigin g = geodetic_point(frame, north, east);
    return g.latitude >= box.latitude_lo && g.latitude <= box.latitude_hi && g.longitude >= box.longitude_lo &&
           g.longitude <= box.longitude_hi;
  };
  int outside = 0;
  for (int i = -200; i <= 200; ++i)
    for (int j = -200; j <= 200; ++j) outside += contains(kGeodeticPiece * (i + 0.2), kGeodeticPiece * (j + 0.2)) ? 0 : 1;
  for (int s = 0; s < 20000; ++s) {
    const int i = (s * 37) % 401 - 200, j = (s * 53) % 401 - 200;
    outside += contains(kGeodeticPiece * (i + 0.7), kGeodeticPiece * (j + 0.4)) ? 0 : 1;
  }
  EXPECT_EQ(outside, 0);
  EXPECT_TRUE(contains(7610.0, 6510.0));  // tile (152, 130): two corners share a slot
}

TEST(GeodeticGrid, BoxesSpanningManyTilesTakeTheEdgeWalk) {
  const LocalFrame frame({48.2129, -4.4582});
  GeodeticGrid grid(frame);
  const Interval north(100.0, 100.0 + (kGeodeticGridSpan + 1) * kGeodeticPiece), east(-20.0, 20.0);
  const GeodeticBox a = grid.box(north, east), b = geodetic_box(frame, north, east);
  EXPECT_EQ(a.latitude_lo, b.latitude_lo);
  EXPECT_EQ(a.latitude_hi, b.latitude_hi);
  EXPECT_EQ(a.longitude_lo, b.longitude_lo);
  EXPECT_EQ(a.longitude_hi, b.longitude_hi);
}

TEST(GeodeticGrid, AgreesWithTheEdgeWalkWithinTheirMargins) {
  // Two sound methods of the same box: their bounds differ by less than their margins.
  const LocalFrame frame({48.2129, -4.4582});
  GeodeticGrid grid(frame);
  const double metre_lat = 1.0 / 110000.0, metre_lon = metre_lat / std::cos(48.3 * M_PI / 180.0);
  for (const auto& [north, east] : random_boxes({{48.2129, -4.4582}, 700, -300}, kGeodeticPiece, 40, 3)) {
    const GeodeticBox a = grid.box(north, east), b = geodetic_box(frame, north, east);
    EXPECT_NEAR(a.latitude_lo, b.latitude_lo, 0.005 * metre_lat);
    EXPECT_NEAR(a.latitude_hi, b.latitude_hi, 0.005 * metre_lat);
    EXPECT_NEAR(a.longitude_lo, b.longitude_lo, 0.005 * metre_lon);
    EXPECT_NEAR(a.longitude_hi, b.longitude_hi, 0.005 * metre_lon);
  }
}

}  // namespace
}  // namespace gesmi::io
