#pragma once
// The DVL readings of a few samples: those on both sides of some times. A mission
// network reads the DVL only to place the marks and fixes that fall between two
// samples (TimeLocation), so this is all a solve keeps of the DVL once the sensor
// enclosures are built, when its caller gave up the full readings (MissionReadings,
// solver/solve/solve_mission.h).

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "solver/mission/mission.h"

namespace gesmi {

/// One sample's DVL readings (body frame, m/s) and, where the mission gives them, their
/// own half-widths (else the model's bound applies).
struct DvlSample {
  std::array<double, 3> reading{};
  std::array<double, 3> half_width{};
  std::array<bool, 3> given{};

  /// Sample k of the mission (std::logic_error when its DVL readings were released).
  static DvlSample of(const Mission& mission, std::size_t k);
};

class DvlExcerpt {
 public:
  /// The samples on both sides of each of `times` (and the sample at a time on the grid).
  DvlExcerpt(const Mission& mission, std::span<const double> times);

  /// Sample k's; std::logic_error when k is not one of the excerpt's.
  const DvlSample& at(std::size_t k) const;
  std::size_t size() const { return index_.size(); }

 private:
  std::vector<std::size_t> index_;  // increasing
  std::vector<DvlSample> samples_;
};

}  // namespace gesmi
