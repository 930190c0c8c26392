#pragma once
// The reconstructed waterfall (seed 001, section V-D, Fig. 8): for each time step
// and mine, the interval of slant ranges ||e|| at which the mine can appear on the
// sonar record, i.e. lie in the sonar plane, on the sonar's side, below the robot
// and within the sonar's range, given the final tube and mine box. Where that is
// impossible both bounds are NaN.

#include <optional>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

struct Waterfall {
  std::size_t steps = 0, mines = 0;
  std::vector<double> lower, upper;  // steps x mines, row-major (index k * mines + i)

  double lo(std::size_t k, std::size_t i) const { return lower[k * mines + i]; }
  double hi(std::size_t k, std::size_t i) const { return upper[k * mines + i]; }
  bool feasible(std::size_t k, std::size_t i) const { return lower[k * mines + i] == lower[k * mines + i]; }
};

/// A waterfall computed earlier on the same navigation (a warm rerun's previous result):
/// a cell whose position boxes (the step's and its neighbours', which fix the heading
/// margin there) and mine box are bitwise those of then is copied, not recomputed, so
/// the result is the one a full computation gives.
struct WaterfallBefore {
  const TubeDomains& domains;
  const Waterfall& waterfall;
};

/// `max_speed`: speed_bound(mission) (heading_frame.h) when the caller has it.
Waterfall compute_waterfall(const Mission& mission, const SensorModel& model, const TubeDomains& domains,
                            const WaterfallBefore* before = nullptr, std::optional<double> max_speed = std::nullopt);

}  // namespace gesmi
