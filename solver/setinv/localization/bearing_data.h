#pragma once
// Bearing measurements to point landmarks as data tests (seed 003, section V-A):
// measurement m holds on a box when some landmark, visible from the sensor, has its
// bearing interval inside the measurement's interval. The visibility vector of each
// (sensor, landmark) pair is kept per recursion level and recomputed only while
// undetermined, as in seed 003's extended SIVIA; landmarks that can no longer
// explain a measurement are dropped from its candidates for all sub-boxes.

#include <cstdint>
#include <span>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/depth_state.h"
#include "solver/setinv/localization/localization_map.h"

namespace gesmi {

class BearingData {
 public:
  BearingData(std::vector<Segment> walls, std::vector<LandmarkPoint> landmarks, std::vector<BearingSensor> sensors,
              std::vector<BearingMeasurement> measurements);

  std::size_t datum_count() const { return measurements_.size(); }
  void evaluate(const Box& box, int depth, std::span<IBool> out, int false_budget);

  /// At a point: the visible landmark explaining each measurement (the one nearest
  /// in angle), or -1.
  std::vector<int> associate(const Pose<double>& p) const;
  const std::vector<BearingMeasurement>& measurements() const { return measurements_; }

 private:
  std::vector<Segment> walls_;
  std::vector<LandmarkPoint> landmarks_;
  std::vector<BearingSensor> sensors_;
  std::vector<BearingMeasurement> measurements_;
  std::size_t words_;
  LevelArrays<IBool> visible_;             // per level: (sensor, landmark) visibility
  LevelArrays<IBool> status_;              // per level: verdict of each measurement
  LevelArrays<std::uint64_t> candidates_;  // per level: landmarks that may explain each one
  // Scratch of one evaluation, sized once.
  std::vector<Interval> bearing_;          // (sensor, landmark) bearing on the box
  std::vector<std::uint8_t> fresh_;        // (sensor, landmark) computed in this call
  std::vector<Vec2T<Interval>> position_;  // sensor positions on the box
  std::vector<Interval> zero_;             // sensor zero directions on the box
  std::vector<std::uint8_t> placed_;       // sensor position computed in this call
};

}  // namespace gesmi
