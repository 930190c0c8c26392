#pragma once
// A contractor for the range data, kept valid when up to q of them are outliers.
// If range i is not an outlier, its echo comes from a point m of some wall j, seen
// from the sensor s in a direction u of the emission cone at a distance in D_i:
// s = m - d u with m ∈ [a_j b_j], d ∈ D_i, u ∈ U(theta). The robot position is s
// minus the sensor's offset, so each datum bounds (x, y) by the hull over the walls
// of [a_j b_j] - D_i U - R(theta) (x_s, y_s). At least n - q data hold at any pose
// of S_q, so x and y are narrowed to the q-relaxed intersection of these bounds
// (relaxed_intersection.h). Seed 004, Remark 5: contractors before bisection.
// A "no echo" datum has no echo point: it bounds nothing (its bound is the box).
// A blind zone keeps the reasoning: the distance reported is that of a point of
// [a_j b_j] ∩ C (range_model.h).

#include <utility>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/localization/localization_map.h"

namespace gesmi {

class CtcRangeRelaxed {
 public:
  CtcRangeRelaxed(std::vector<Segment> walls, std::vector<RangeSensor> sensors, std::vector<RangeMeasurement> measurements,
                  int outliers = 0);

  /// The same contractor for another number of outliers (GOMNE's SIVIA(q)).
  CtcRangeRelaxed with_outliers(int q) const;
  void contract(Box& box) const;

 private:
  std::vector<Segment> walls_;
  std::vector<RangeSensor> sensors_;
  std::vector<RangeMeasurement> measurements_;
  std::vector<Interval> feasible_;
  int outliers_;
  // Scratch, sized once: a contractor instance is not shared between threads.
  mutable std::vector<Interval> x_, y_;
  mutable std::vector<std::pair<double, int>> events_;
};

}  // namespace gesmi
