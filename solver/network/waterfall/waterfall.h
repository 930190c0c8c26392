#pragma once
// The reconstructed waterfall (seed 001, section V-D, Fig. 8): for each time step
// and mine, the interval of slant ranges ||e|| at which the mine can appear on the
// sonar record, i.e. lie in the sonar plane, on the sonar's side, below the robot
// and within the sonar's range, given the final tube and mine box. Only the feasible
// cells are kept (a mine is within the sonar's reach on few steps): elsewhere the
// mine cannot appear. Each cell is sonar_ranges() (sonar_ranges.h), computed by the
// upward-rounding kernel (waterfall_kernel.h) with the same bounds.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

struct Waterfall {
  std::size_t steps = 0, mines = 0;
  /// The feasible cells in strictly increasing (step, mine) order, as the result file
  /// stores them: mine mine[c] can appear at step step[c] at slant ranges within
  /// [lower[c], upper[c]].
  std::vector<std::int32_t> step, mine;
  std::vector<double> lower, upper;

  std::size_t cells() const { return step.size(); }
  /// Appends a cell; it must come after every cell already there.
  void add(std::size_t k, std::size_t i, double lo, double hi) {
    step.push_back(static_cast<std::int32_t>(k));
    mine.push_back(static_cast<std::int32_t>(i));
    lower.push_back(lo);
    upper.push_back(hi);
  }
  /// Appends the cells of `later`, all of whose steps come after this one's.
  void append(const Waterfall& later);
  /// The index of the first cell at step k or later (binary search).
  std::size_t first_cell_at(std::size_t k) const;
  /// The cell (k, i), or none when mine i cannot appear at step k (binary search).
  std::optional<std::size_t> cell(std::size_t k, std::size_t i) const;
  bool feasible(std::size_t k, std::size_t i) const { return cell(k, i).has_value(); }
  /// Bounds of the cell (k, i); NaN when it is not feasible.
  double lo(std::size_t k, std::size_t i) const;
  double hi(std::size_t k, std::size_t i) const;
};

/// A waterfall computed earlier on the same navigation (a warm rerun's previous result),
/// and which boxes are bitwise those of then. A cell is copied, not recomputed, where its
/// position boxes (the step's and its neighbours', which fix the heading margin there)
/// and its mine box are, so the result is the one a full computation gives. Made by
/// waterfall_before() while the earlier domains are at hand; they are not read after
/// (a warm rerun frees its earlier tube before the waterfall, 480 MB at 10^7 steps).
struct WaterfallBefore {
  const Waterfall& waterfall;
  std::vector<unsigned char> position_kept;  // per step: its position box is that of then
  std::vector<unsigned char> mine_kept;      // per mine: its box is that of then
};
/// `then` and `now`: the domains `earlier` was computed on and the current ones, of the
/// same mission (nothing is kept when their sizes differ).
WaterfallBefore waterfall_before(const Waterfall& earlier, const TubeDomains& then, const TubeDomains& now);

/// `max_speed`: speed_bound(mission) (frame_margins.h) when the caller has it.
/// `on_progress` receives the fraction done, from the calling thread.
Waterfall compute_waterfall(const Mission& mission, const SensorModel& model, const TubeDomains& domains,
                            const WaterfallBefore* before = nullptr, std::optional<double> max_speed = std::nullopt,
                            const std::function<void(double)>& on_progress = {});

}  // namespace gesmi
