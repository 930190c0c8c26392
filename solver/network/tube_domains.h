#pragma once
// The state of the mission network: the domains being contracted. One flat array
// per axis for the positions p(k) (the tube, N entries) and for the increments
// d(k) = p(k+1) - p(k) (N - 1 entries), plus one box per mine.

#include <cstdint>
#include <vector>

#include "solver/interval/box.h"

namespace gesmi {

struct TubeDomains {
  std::vector<Interval> px, py, pz;  // north, east, down (m)
  std::vector<Interval> dx, dy, dz;  // increments (m)
  std::vector<Vec3I> mines;          // NED (m)
  /// Per detection of the network: the mines it may still belong to (bit i: mine i).
  std::vector<std::uint64_t> candidates;

  std::size_t size() const { return px.size(); }
  Vec3I position(std::size_t k) const { return Vec3I(px[k], py[k], pz[k]); }
  /// Largest horizontal width of the tube (max over k of the north and east widths).
  double max_horizontal_width() const;
};

/// Replaces every interval domain of `into` (positions, increments, mines) by
/// op(it, the same one of `other`); both of the same mission and network.
template <class Op>
void combine_domains(TubeDomains& into, const TubeDomains& other, Op op) {
  const auto each = [&](std::vector<Interval>& a, const std::vector<Interval>& b) {
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = op(a[k], b[k]);
  };
  each(into.px, other.px);
  each(into.py, other.py);
  each(into.pz, other.pz);
  each(into.dx, other.dx);
  each(into.dy, other.dy);
  each(into.dz, other.dz);
  for (std::size_t i = 0; i < into.mines.size(); ++i)
    for (int a = 0; a < 3; ++a) into.mines[i][a] = op(into.mines[i][a], other.mines[i][a]);
}

/// Intersects every domain of `into` with the same one of `other` (same mission and
/// network) and keeps only the candidate mines both allow. Empty results stay for the
/// solver to report.
void intersect_with(TubeDomains& into, const TubeDomains& other);

}  // namespace gesmi
