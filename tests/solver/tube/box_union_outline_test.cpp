// outline_of_boxes() checked by independent geometry: every widened box lies inside
// the outline (even-odd point test over all rings), the outline adds at most a cell
// beyond the boxes, rings are closed and oriented (exteriors counter-clockwise, holes
// clockwise inside their exterior), and the polygons are valid: no two edges of any
// rings cross or touch except consecutive edges at their shared vertex.

#include "solver/tube/box_union_outline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

namespace gesmi {
namespace {

struct Boxes {
  std::vector<Interval> x, y;
  void add(double x0, double x1, double y0, double y1) {
    x.emplace_back(x0, x1);
    y.emplace_back(y0, y1);
  }
};

std::vector<const OutlineRing*> all_rings(const BoxOutline& o) {
  std::vector<const OutlineRing*> rings;
  for (const OutlinePolygon& p : o.polygons) {
    rings.push_back(&p.exterior);
    for (const OutlineRing& h : p.holes) rings.push_back(&h);
  }
  return rings;
}

bool inside_outline(const BoxOutline& o, double px, double py) {
  bool in = false;
  for (const OutlineRing* ring : all_rings(o))
    for (std::size_t i = 0; i + 1 < ring->size(); ++i) {
      const auto& a = (*ring)[i];
      const auto& b = (*ring)[i + 1];
      if ((a[1] > py) != (b[1] > py) && px < a[0] + (py - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) in = !in;
    }
  return in;
}

double area(const OutlineRing& r) {
  double s = 0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) s += r[i][0] * r[i + 1][1] - r[i + 1][0] * r[i][1];
  return s / 2;
}

// Closed segments [a, b] and [c, d] of axis-parallel rings share a point.
bool touch(const OutlinePoint& a, const OutlinePoint& b, const OutlinePoint& c, const OutlinePoint& d) {
  const double x0 = std::max(std::min(a[0], b[0]), std::min(c[0], d[0])), x1 = std::min(std::max(a[0], b[0]), std::max(c[0], d[0]));
  const double y0 = std::max(std::min(a[1], b[1]), std::min(c[1], d[1])), y1 = std::min(std::max(a[1], b[1]), std::max(c[1], d[1]));
  return x0 <= x1 && y0 <= y1;
}

void expect_valid(const BoxOutline& o) {
  struct Edge {
    OutlinePoint a, b;
    std::size_t ring, index, count;
  };
  std::vector<Edge> edges;
  const std::vector<const OutlineRing*> rings = all_rings(o);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const OutlineRing& ring = *rings[r];
    ASSERT_GE(ring.size(), 5u);
    ASSERT_EQ(ring.front(), ring.back());
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
      // Axis-parallel edges with a real turn at every vertex.
      ASSERT_TRUE(ring[i][0] == ring[i + 1][0] || ring[i][1] == ring[i + 1][1]);
      edges.push_back({ring[i], ring[i + 1], r, i, ring.size() - 1});
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& e = edges[i];
      const Edge& f = edges[j];
      const bool adjacent = e.ring == f.ring && ((e.index + 1) % e.count == f.index || (f.index + 1) % f.count == e.index);
      if (adjacent) continue;
      ASSERT_FALSE(touch(e.a, e.b, f.a, f.b)) << "ring " << e.ring << " edge " << e.index << " touches ring " << f.ring
                                             << " edge " << f.index;
    }
  for (const OutlinePolygon& p : o.polygons) {
    EXPECT_GT(area(p.exterior), 0.0);
    for (const OutlineRing& h : p.holes) {
      EXPECT_LT(area(h), 0.0);
      OutlineRing only{p.exterior};
      BoxOutline exterior;
      exterior.polygons.push_back({only, {}});
      EXPECT_TRUE(inside_outline(exterior, (h[0][0] + h[1][0]) / 2, (h[0][1] + h[1][1]) / 2 + 1e-9) ||
                  inside_outline(exterior, (h[0][0] + h[1][0]) / 2 + 1e-9, (h[0][1] + h[1][1]) / 2));
    }
  }
}

void expect_contains_boxes(const BoxOutline& o, const Boxes& b, double pad) {
  for (std::size_t k = 0; k < b.x.size(); ++k) {
    if (!b.x[k].is_bounded() || !b.y[k].is_bounded()) continue;
    const double inner = pad * 0.999;  // off the cell boundaries the widened box may meet exactly
    const double x0 = b.x[k].lo() - inner, x1 = b.x[k].hi() + inner, y0 = b.y[k].lo() - inner, y1 = b.y[k].hi() + inner;
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j)
        ASSERT_TRUE(inside_outline(o, x0 + (x1 - x0) * i / 4, y0 + (y1 - y0) * j / 4)) << "box " << k;
  }
}

// No point of the outline is farther than a cell's diagonal beyond every widened box.
void expect_tight(const BoxOutline& o, const Boxes& b, double pad, std::mt19937& rng) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const OutlinePolygon& p : o.polygons)
    for (const auto& q : p.exterior) {
      x0 = std::min(x0, q[0]);
      x1 = std::max(x1, q[0]);
      y0 = std::min(y0, q[1]);
      y1 = std::max(y1, q[1]);
    }
  std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1);
  for (int s = 0; s < 3000; ++s) {
    const double px = ux(rng), py = uy(rng);
    if (!inside_outline(o, px, py)) continue;
    double nearest = INFINITY;
    for (std::size_t k = 0; k < b.x.size(); ++k) {
      if (!b.x[k].is_bounded() || !b.y[k].is_bounded()) continue;
      const double dx = std::max({b.x[k].lo() - pad - px, 0.0, px - b.x[k].hi() - pad});
      const double dy = std::max({b.y[k].lo() - pad - py, 0.0, py - b.y[k].hi() - pad});
      nearest = std::min(nearest, std::hypot(dx, dy));
    }
    ASSERT_LE(nearest, o.cell * std::sqrt(2.0) * 1.000001) << px << ", " << py;
  }
}

TEST(BoxUnionOutline, ASquareRingOfBoxesIsOnePolygonWithOneHole) {
  Boxes b;
  b.add(0, 10, 0, 2);
  b.add(8, 10, 0, 10);
  b.add(0, 10, 8, 10);
  b.add(0, 2, 0, 10);
  const BoxOutline o = outline_of_boxes(b.x, b.y, 0.01, 0.25);
  ASSERT_EQ(o.polygons.size(), 1u);
  EXPECT_EQ(o.polygons[0].holes.size(), 1u);
  expect_valid(o);
  expect_contains_boxes(o, b, 0.01);
  EXPECT_FALSE(inside_outline(o, 5, 5));
}

TEST(BoxUnionOutline, BoxesMeetingAtACornerBecomeOneValidPolygon) {
  Boxes b;
  b.add(0, 0.9, 0, 0.9);  // cells up to 1.0 on both axes
  b.add(1, 2, 1, 2);      // cells from 1.0: the two meet at the corner (1, 1) only
  const BoxOutline o = outline_of_boxes(b.x, b.y, 0.0, 0.25);
  ASSERT_EQ(o.polygons.size(), 1u);
  expect_valid(o);
  expect_contains_boxes(o, b, 0.0);
}

TEST(BoxUnionOutline, SeparateBoxesAreSeparatePolygonsAndUnboundedOnesAreCounted) {
  Boxes b;
  b.add(0, 1, 0, 1);
  b.add(5, 6, 5, 6);
  b.x.push_back(Interval(0, INFINITY));
  b.y.push_back(Interval(0, 1));
  b.x.push_back(Interval::empty());
  b.y.push_back(Interval(0, 1));
  const BoxOutline o = outline_of_boxes(b.x, b.y, 0.01, 0.25);
  EXPECT_EQ(o.polygons.size(), 2u);
  EXPECT_EQ(o.unbounded_boxes, 2u);
  expect_valid(o);
  expect_contains_boxes(o, b, 0.01);
}

TEST(BoxUnionOutline, RandomTubesAreContainedTightAndValid) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 12; ++trial) {
    Boxes b;
    std::normal_distribution<double> step(0.0, 3.0);
    std::uniform_real_distribution<double> width(0.3, 6.0);
    double x = 0, y = 0;
    for (int k = 0; k < 150; ++k) {
      x += step(rng);
      y += step(rng);
      const double wx = width(rng), wy = width(rng);
      b.add(x - wx, x + wx, y - wy, y + wy);
    }
    const double pad = trial % 2 ? 0.05 : 0.0;
    // A coarse grid (few cells) and a fine one.
    const BoxOutline o = outline_of_boxes(b.x, b.y, pad, trial < 6 ? 0.25 : 2.0);
    expect_valid(o);
    expect_contains_boxes(o, b, pad);
    expect_tight(o, b, pad, rng);
  }
}

TEST(BoxUnionOutline, HugeOrFarBoxesAreDrawnCoarselyOrRefusedNeverDropped) {
  // Huge: the cells grow with the extent (no crash, no endless loop, no empty answer).
  // The exports never get here: they leave out boxes beyond 500 km of the origin.
  Boxes b;
  b.add(0, 1, 0, 1);
  b.add(1e300, 1.5e300, 0, 1);
  const BoxOutline o = outline_of_boxes(b.x, b.y, 0.0);
  EXPECT_FALSE(o.polygons.empty());
  EXPECT_GT(o.cell, 1e290);
  // Far from zero for their size: the lattice could not be exact, so refused.
  Boxes far;
  far.add(1e17, 1e17 + 10, 0, 10);
  EXPECT_THROW(outline_of_boxes(far.x, far.y, 0.0), std::invalid_argument);
}

TEST(BoxUnionOutline, LargeOverlappingBoxesCostCellsNotTheirAreas) {
  // 20,000 boxes each nearly as large as the whole extent: their union is one square.
  Boxes b;
  for (int k = 0; k < 20000; ++k) b.add(-1000.0 + k * 0.01, 1000.0, -1000.0, 1000.0 - k * 0.01);
  const BoxOutline o = outline_of_boxes(b.x, b.y, 0.0, 0.25, std::size_t{1} << 22);
  ASSERT_EQ(o.polygons.size(), 1u);
  EXPECT_EQ(o.polygons[0].holes.size(), 0u);
  EXPECT_EQ(o.polygons[0].exterior.size(), 5u);  // a square: four corners and the closing point
  expect_valid(o);
}

TEST(BoxUnionOutline, TheGridStaysWithinItsCellBudget) {
  Boxes b;
  b.add(0, 1, 0, 1);
  b.add(9999, 10000, 9999, 10000);
  const BoxOutline o = outline_of_boxes(b.x, b.y, 0.0, 0.25, 10000);
  EXPECT_GE(o.cell, 100.0);  // 10 km squared over 10^4 cells
  EXPECT_EQ(o.polygons.size(), 2u);
  expect_valid(o);
}

}  // namespace
}  // namespace gesmi
