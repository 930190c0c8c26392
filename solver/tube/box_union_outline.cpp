#include "solver/tube/box_union_outline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace gesmi {
namespace {

// Filled cells on a grid with an empty border of one cell on every side.
struct CellGrid {
  double x0 = 0, y0 = 0, cell = 1;
  std::size_t columns = 0, rows = 0;
  std::vector<std::uint8_t> filled;

  std::uint8_t& at(std::size_t row, std::size_t column) { return filled[row * columns + column]; }
  std::uint8_t at(std::size_t row, std::size_t column) const { return filled[row * columns + column]; }
  // Index of the cell holding coordinate v along an axis starting at `origin`.
  std::size_t index(double v, double origin, std::size_t count) const {
    const double i = std::floor((v - origin) / cell) + 1.0;
    return static_cast<std::size_t>(std::clamp(i, 1.0, static_cast<double>(count - 2)));
  }
};

// Fills a cell of each 2x2 block whose filled cells touch only at a corner: the traced
// rings then never touch themselves or each other. Filling only adds area (outward). One
// scan of the grid; a fill can only make new such blocks among the four around the
// filled cell, which a worklist re-checks.
void join_corner_contacts(CellGrid& g) {
  std::vector<std::pair<std::size_t, std::size_t>> blocks;  // lower-left cells of blocks to re-check
  const auto fix = [&](std::size_t r, std::size_t c) {
    const bool a = g.at(r, c), b = g.at(r, c + 1), d = g.at(r + 1, c), e = g.at(r + 1, c + 1);
    if (!(a == e && b == d && a != b)) return;
    const std::size_t fr = r, fc = a ? c + 1 : c;  // the empty cell of the block's lower row
    g.at(fr, fc) = 1;
    for (std::size_t br = fr > 0 ? fr - 1 : 0; br <= fr && br + 1 < g.rows; ++br)
      for (std::size_t bc = fc > 0 ? fc - 1 : 0; bc <= fc && bc + 1 < g.columns; ++bc) blocks.emplace_back(br, bc);
  };
  for (std::size_t r = 0; r + 1 < g.rows; ++r)
    for (std::size_t c = 0; c + 1 < g.columns; ++c) {
      fix(r, c);
      while (!blocks.empty()) {
        const auto [br, bc] = blocks.back();
        blocks.pop_back();
        fix(br, bc);
      }
    }
}

double signed_area(const OutlineRing& ring) {
  double area = 0;
  for (std::size_t i = 0; i + 1 < ring.size(); ++i)
    area += ring[i][0] * ring[i + 1][1] - ring[i + 1][0] * ring[i][1];
  return area / 2;
}

bool inside(const OutlineRing& ring, const OutlinePoint& p) {
  bool in = false;
  for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
    const OutlinePoint& a = ring[i];
    const OutlinePoint& b = ring[i + 1];
    if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) in = !in;
  }
  return in;
}

// Traces the boundary edges (filled cell on the left) into closed rings of lattice
// vertices, keeping only the corners.
std::vector<OutlineRing> trace_rings(const CellGrid& g) {
  const std::size_t stride = g.columns + 1;
  std::unordered_map<std::size_t, std::size_t> next;  // lattice vertex -> the next along its ring
  const auto vertex = [&](std::size_t r, std::size_t c) { return r * stride + c; };
  for (std::size_t r = 1; r + 1 < g.rows; ++r)
    for (std::size_t c = 1; c + 1 < g.columns; ++c) {
      if (!g.at(r, c)) continue;
      if (!g.at(r - 1, c)) next[vertex(r, c)] = vertex(r, c + 1);                // bottom, eastward
      if (!g.at(r, c + 1)) next[vertex(r, c + 1)] = vertex(r + 1, c + 1);        // right, northward
      if (!g.at(r + 1, c)) next[vertex(r + 1, c + 1)] = vertex(r + 1, c);        // top, westward
      if (!g.at(r, c - 1)) next[vertex(r + 1, c)] = vertex(r, c);                // left, southward
    }
  std::vector<std::size_t> starts;
  starts.reserve(next.size());
  for (const auto& edge : next) starts.push_back(edge.first);
  std::vector<OutlineRing> rings;
  const auto point = [&](std::size_t v) {
    return OutlinePoint{g.x0 + (static_cast<double>(v % stride) - 1.0) * g.cell,
                        g.y0 + (static_cast<double>(v / stride) - 1.0) * g.cell};
  };
  for (const std::size_t start : starts) {
    if (!next.contains(start)) continue;  // on a ring already traced
    std::vector<std::size_t> lattice;
    for (std::size_t v = start;;) {
      lattice.push_back(v);
      const auto it = next.find(v);
      // Unreachable once corner contacts are joined (every vertex has one way on).
      if (it == next.end()) throw std::logic_error("outline_of_boxes: a boundary that does not close");
      v = it->second;
      next.erase(it);
      if (v == start) break;
    }
    OutlineRing ring;
    const std::size_t n = lattice.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t before = lattice[(i + n - 1) % n], here = lattice[i], after = lattice[(i + 1) % n];
      // A corner: the direction changes (horizontal steps keep the row, vertical ones the column).
      const bool in_row = before / stride == here / stride, out_row = here / stride == after / stride;
      if (in_row != out_row) ring.push_back(point(here));
    }
    ring.push_back(ring.front());
    rings.push_back(std::move(ring));
  }
  return rings;
}

}  // namespace

BoxOutline outline_of_boxes(std::span<const Interval> x, std::span<const Interval> y, double pad, double min_cell,
                            std::size_t max_cells) {
  BoxOutline out;
  double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!x[k].is_bounded() || !y[k].is_bounded() || x[k].is_empty() || y[k].is_empty()) {
      ++out.unbounded_boxes;
      continue;
    }
    kept.push_back(k);
    xlo = std::min(xlo, x[k].lo() - pad);
    xhi = std::max(xhi, x[k].hi() + pad);
    ylo = std::min(ylo, y[k].lo() - pad);
    yhi = std::max(yhi, y[k].hi() + pad);
  }
  if (kept.empty()) return out;
  CellGrid g;
  const double width = xhi - xlo, height = yhi - ylo;
  g.cell = std::max({min_cell, std::sqrt(width / static_cast<double>(max_cells) * height), width / 65536.0, height / 65536.0});
  // Lattice points stay exact enough only when the extent's coordinates are within 2^40
  // cells of zero; a box that far (a hostile file) is no tube anyone draws.
  if (!std::isfinite(width) || !std::isfinite(height) || !std::isfinite(g.cell) ||
      std::max({std::abs(xlo), std::abs(xhi), std::abs(ylo), std::abs(yhi)}) / g.cell > 0x1p40)
    throw std::invalid_argument("outline_of_boxes: boxes beyond the range an outline can be drawn over");
  g.x0 = xlo;
  g.y0 = ylo;
  g.columns = static_cast<std::size_t>(std::ceil(width / g.cell)) + 3;
  g.rows = static_cast<std::size_t>(std::ceil(height / g.cell)) + 3;
  // Each box adds +1 / -1 at its corners of a difference grid whose 2-D prefix sums
  // count the boxes over each cell: linear in boxes plus cells, whatever the boxes' sizes.
  std::vector<std::int32_t> count((g.rows + 1) * (g.columns + 1), 0);
  const auto at = [&](std::size_t r, std::size_t c) -> std::int32_t& { return count[r * (g.columns + 1) + c]; };
  for (const std::size_t k : kept) {
    const std::size_t c0 = g.index(x[k].lo() - pad, g.x0, g.columns), c1 = g.index(x[k].hi() + pad, g.x0, g.columns);
    const std::size_t r0 = g.index(y[k].lo() - pad, g.y0, g.rows), r1 = g.index(y[k].hi() + pad, g.y0, g.rows);
    ++at(r0, c0);
    --at(r0, c1 + 1);
    --at(r1 + 1, c0);
    ++at(r1 + 1, c1 + 1);
  }
  g.filled.assign(g.columns * g.rows, 0);
  for (std::size_t r = 0; r < g.rows; ++r)
    for (std::size_t c = 0; c < g.columns; ++c) {
      std::int32_t v = at(r, c);
      if (r > 0) v += at(r - 1, c);
      if (c > 0) v += at(r, c - 1);
      if (r > 0 && c > 0) v -= at(r - 1, c - 1);
      at(r, c) = v;
      g.filled[r * g.columns + c] = v > 0;
    }
  join_corner_contacts(g);
  out.cell = g.cell;

  std::vector<OutlineRing> holes;
  for (OutlineRing& ring : trace_rings(g)) {
    if (signed_area(ring) > 0)
      out.polygons.push_back({std::move(ring), {}});
    else
      holes.push_back(std::move(ring));
  }
  // Each hole belongs to the smallest exterior ring around a point just inside the
  // filled side of its first edge (islands may sit in the holes of larger polygons).
  std::vector<double> areas;
  for (const OutlinePolygon& p : out.polygons) areas.push_back(signed_area(p.exterior));
  for (OutlineRing& hole : holes) {
    const OutlinePoint& a = hole[0];
    const OutlinePoint& b = hole[1];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const OutlinePoint probe{(a[0] + b[0]) / 2 - (b[1] - a[1]) / length * g.cell / 2,
                             (a[1] + b[1]) / 2 + (b[0] - a[0]) / length * g.cell / 2};
    std::size_t owner = out.polygons.size();
    for (std::size_t i = 0; i < out.polygons.size(); ++i)
      if ((owner == out.polygons.size() || areas[i] < areas[owner]) && inside(out.polygons[i].exterior, probe)) owner = i;
    if (owner < out.polygons.size()) out.polygons[owner].holes.push_back(std::move(hole));
  }
  return out;
}

}  // namespace gesmi
