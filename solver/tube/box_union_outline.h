#pragma once
// The outline of a union of axis-aligned boxes (a tube's horizontal boxes) as valid
// polygons: the boxes, widened by `pad`, are filled into a grid of square cells (a
// cell is filled when it meets a box), cells that touch only at a corner get a filled
// neighbour, and the filled region's boundary is traced. The result contains every
// widened box (simplified only outward, by less than one cell) and is valid in the
// OGC sense: simple rings that neither cross nor touch, exterior rings
// counter-clockwise and holes clockwise (RFC 7946's right-hand rule, x east, y north).

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "solver/interval/interval.h"

namespace gesmi {

using OutlinePoint = std::array<double, 2>;        // (x, y)
using OutlineRing = std::vector<OutlinePoint>;     // closed: the last point repeats the first

struct OutlinePolygon {
  OutlineRing exterior;
  std::vector<OutlineRing> holes;
};

struct BoxOutline {
  std::vector<OutlinePolygon> polygons;
  double cell = 0.0;               // the grid's cell size: the most the outline adds beyond `pad`
  std::size_t unbounded_boxes = 0;  // boxes left out: empty or unbounded on an axis
};

/// Outline of the union of the boxes x[k] x y[k] widened by pad (>= 0). The grid holds
/// at most about max_cells cells, and its cells are at least min_cell wide.
BoxOutline outline_of_boxes(std::span<const Interval> x, std::span<const Interval> y, double pad,
                            double min_cell = 0.25, std::size_t max_cells = std::size_t{1} << 22);

}  // namespace gesmi
