#pragma once
// Where to look again on the sonar record (seed 001, end of section V): for each
// mine, the time windows in which it can lie on the sonar swath (the reconstructed
// waterfall is not empty) but no detection that may be this mine was recorded,
// with the interval of slant ranges, narrowest windows first.

#include <cstdint>
#include <span>
#include <vector>

#include "solver/network/mission_network.h"
#include "solver/network/waterfall/waterfall.h"

namespace gesmi {

struct LookAgainWindow {
  int mine = 0;
  std::size_t k_start = 0, k_end = 0;  // sample indices, inclusive
  double t_start = 0.0, t_end = 0.0;   // s
  double range_lo = 0.0, range_hi = 0.0;  // m
};

/// Windows of consecutive feasible steps with no detection that may be this mine,
/// sorted by duration (narrowest first), then by mine and start time.
std::vector<LookAgainWindow> look_again_windows(const Waterfall& waterfall, std::span<const double> time,
                                                const MissionNetwork& network, const TubeDomains& domains);
/// Same from the mark table: mark times and their candidate mines (bit i: mine i).
std::vector<LookAgainWindow> look_again_windows(const Waterfall& waterfall, std::span<const double> time,
                                                std::span<const double> mark_time,
                                                std::span<const std::uint64_t> mark_candidates);

}  // namespace gesmi
