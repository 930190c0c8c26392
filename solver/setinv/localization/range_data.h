#pragma once
// The range measurements of a sonar belt as data tests (solver/setinv/datum_tests.h):
// datum i holds on a box when f_i(P) = min_j R_j(P) lies in its feasible set: [d_i
// (1 - alpha), d_i (1 + alpha)] (seed 000, 4.6), or [M (1 - alpha), +inf] for "no
// echo" (feasible_range). On boxes, walls that cannot change the verdict of the min
// are pruned per recursion level: a wall whose remoteness is above the feasible
// set's upper bound, or, for an unbounded set, not below its lower bound. Such a
// wall stays irrelevant on every sub-box, so deep boxes evaluate one or two walls
// per sensor instead of all.

#include <cstdint>
#include <span>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/depth_state.h"
#include "solver/setinv/localization/localization_map.h"

namespace gesmi {

/// associate()'s answer for a "no echo" datum that holds: no wall within range.
inline constexpr int kNoWallInRange = -2;

class RangeData {
 public:
  RangeData(std::vector<Segment> walls, std::vector<RangeSensor> sensors, std::vector<RangeMeasurement> measurements);

  std::size_t datum_count() const { return measurements_.size(); }
  void evaluate(const Box& box, int depth, std::span<IBool> out, int false_budget);

  /// At a point: the wall each measurement is explained by (-1 when the simulated
  /// range is outside the measurement's feasible set; kNoWallInRange for a "no echo"
  /// inside it).
  std::vector<int> associate(const Pose<double>& p) const;
  /// The simulated range of measurement i's sensor at p.
  double simulate(const Pose<double>& p, std::size_t i) const;
  const Interval& feasible(std::size_t i) const { return feasible_[i]; }
  const std::vector<RangeMeasurement>& measurements() const { return measurements_; }

 private:
  std::vector<Segment> walls_;
  std::vector<RangeSensor> sensors_;
  std::vector<RangeMeasurement> measurements_;
  std::vector<Interval> feasible_;
  std::size_t words_;                       // candidate words per datum
  LevelArrays<IBool> status_;               // per level: verdict of each datum
  LevelArrays<std::uint64_t> candidates_;   // per level: walls still relevant per datum
};

}  // namespace gesmi
