#pragma once
// Outward geodetic boxes of many small local boxes (a tube's, row by row) at the cost of
// arithmetic: geodetic_box() converts every box corner (28 GeographicLib calls a box,
// 6.8 us a tube row), this converts the corners of a fixed grid of square tiles once.
//
// Within a tile of side h, latitude and longitude are bounded by the bilinear
// interpolation B of their values at the tile's corners: |f - B| <= h^2/8 (|f_nn| +
// |f_ee|) <= K h^2 / 4, with K the same bound of the map's second derivative along a
// straight local line that geodetic_box() uses (geodetic_curvature). Over a box, B is
// bilinear on each piece the grid lines cut the box into, so its extremes are at the
// pieces' corners: the box's corners, the grid lines' crossings of its edges, and the
// grid nodes inside it. The bounds are those extremes widened by K h^2 / 4 plus
// kLocalFrameError, which covers the corner conversions' error (a weighted mean of
// errors under 10 nm each) and the interpolation's rounding (under 1e-9 m). Boxes
// spanning more than kGeodeticGridSpan tiles take geodetic_box().
// tests/io/exports/geodetic_grid_test.cpp checks the bounds against dense sampling.

#include <cstdint>
#include <vector>

#include "io/exports/geodetic_box.h"

namespace gesmi::io {

/// The largest number of tiles a box may span along each axis before geodetic_grid
/// hands it to geodetic_box().
inline constexpr int kGeodeticGridSpan = 8;

class GeodeticGrid {
 public:
  /// `tile`: the grid's side (m); the default keeps the interpolation's bound under 1 mm
  /// at 48 degrees and 5 mm at 85.
  explicit GeodeticGrid(const LocalFrame& frame, double tile = kGeodeticPiece);

  /// geodetic_box(frame, north, east)'s contract: outward geodetic bounds of a local box
  /// (bounded, non-empty and within_export_radius).
  GeodeticBox box(const Interval& north, const Interval& east);

 private:
  /// A point along one axis as its tile and its fraction of the tile, in [0, 1].
  struct Cut {
    std::int64_t tile;
    double fraction;
  };
  static bool cuts_of(double lo, double hi, double tile, std::vector<Cut>& cuts);
  struct Node {
    std::int64_t i, j;  // tile corner (i tile, j tile) north and east
    double latitude, longitude;
  };
  /// The converted grid node (i, j), from the cache when there (a copy: the next call
  /// may reuse its slot).
  Node node(std::int64_t i, std::int64_t j);

  const LocalFrame& frame_;
  double tile_;
  std::vector<Node> cache_;  // direct-mapped by (i, j): a miss only costs a conversion
  std::vector<Cut> north_cuts_, east_cuts_;  // box()'s, kept to reuse their memory
};

}  // namespace gesmi::io
