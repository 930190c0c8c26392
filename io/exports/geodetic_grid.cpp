#include "io/exports/geodetic_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gesmi::io {
namespace {

constexpr int kCacheBits = 12;  // 4096 nodes: a tube's neighbourhood many times over
constexpr std::int64_t kNoTile = std::numeric_limits<std::int64_t>::min();

std::size_t slot(std::int64_t i, std::int64_t j) {
  const auto h = static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(j) * 0xC2B2AE3D27D4EB4Full;
  return static_cast<std::size_t>(h >> (64 - kCacheBits));
}

}  // namespace

/// The box side [lo, hi]'s corners and the grid lines between them, or none when the
/// side spans more than kGeodeticGridSpan tiles. A fraction's rounding moves its point
/// by under 1e-9 m, which kLocalFrameError covers (geodetic_grid.h).
bool GeodeticGrid::cuts_of(double lo, double hi, double tile, std::vector<Cut>& cuts) {
  cuts.clear();
  const double first = std::floor(lo / tile), last = std::ceil(hi / tile);
  if (!(last - first <= kGeodeticGridSpan)) return false;
  const auto at = [tile](double x) {
    const double t = std::floor(x / tile);
    return Cut{static_cast<std::int64_t>(t), std::clamp((x - t * tile) / tile, 0.0, 1.0)};
  };
  cuts.push_back(at(lo));
  for (double k = first + 1; k < last; ++k) cuts.push_back({static_cast<std::int64_t>(k), 0.0});
  cuts.push_back(at(hi));
  return true;
}

GeodeticGrid::GeodeticGrid(const LocalFrame& frame, double tile)
    : frame_(frame), tile_(tile), cache_(std::size_t{1} << kCacheBits, Node{kNoTile, kNoTile, 0.0, 0.0}) {}

GeodeticGrid::Node GeodeticGrid::node(std::int64_t i, std::int64_t j) {
  Node& n = cache_[slot(i, j)];
  if (n.i != i || n.j != j) {
    const GeoOrigin g = geodetic_point(frame_, static_cast<double>(i) * tile_, static_cast<double>(j) * tile_);
    n = {i, j, g.latitude, g.longitude};
  }
  return n;
}

GeodeticBox GeodeticGrid::box(const Interval& north, const Interval& east) {
  if (!cuts_of(north.lo(), north.hi(), tile_, north_cuts_) || !cuts_of(east.lo(), east.hi(), tile_, east_cuts_))
    return geodetic_box(frame_, north, east);
  GeodeticBox box = kNoPoint;
  double farthest = 0.0;  // largest |latitude| of the tiles' corners
  for (const Cut& n : north_cuts_)
    for (const Cut& e : east_cuts_) {
      // B at the point: the bilinear mean of its tile's four corners (two of them may
      // share a cache slot: node() returns copies).
      const Node a = node(n.tile, e.tile);
      const Node b = node(n.tile + 1, e.tile);
      const Node c = node(n.tile, e.tile + 1);
      const Node d = node(n.tile + 1, e.tile + 1);
      const double u = n.fraction, v = e.fraction;
      const double wa = (1 - u) * (1 - v), wb = u * (1 - v), wc = (1 - u) * v, wd = u * v;
      const double latitude = wa * a.latitude + wb * b.latitude + wc * c.latitude + wd * d.latitude;
      const double longitude = wa * a.longitude + wb * b.longitude + wc * c.longitude + wd * d.longitude;
      extend(box, latitude, longitude);
      for (const Node* corner : {&a, &b, &c, &d}) farthest = std::max(farthest, std::abs(corner->latitude));
    }
  // The latitude the margins are taken at, as in geodetic_box(): the tiles' farthest
  // from the equator plus a slack above what a tile's interior may add.
  const double latitude = std::min(farthest + 0.01, 89.9);
  return widened(box, kLocalFrameError + tile_ * tile_ * geodetic_curvature(latitude) / 4.0, latitude);
}

}  // namespace gesmi::io
