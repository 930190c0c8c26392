#include "solver/setinv/localization/bearing_data.h"

#include <cmath>

#include "solver/setinv/localization/bearing_model.h"

namespace gesmi {

BearingData::BearingData(std::vector<Segment> walls, std::vector<LandmarkPoint> landmarks,
                         std::vector<BearingSensor> sensors, std::vector<BearingMeasurement> measurements)
    : walls_(std::move(walls)),
      landmarks_(std::move(landmarks)),
      sensors_(std::move(sensors)),
      measurements_(std::move(measurements)),
      words_(words_for(landmarks_.size())),
      visible_(sensors_.size() * landmarks_.size(), IBool::maybe()),
      status_(measurements_.size(), IBool::maybe()),
      candidates_(measurements_.size() * words_, ~std::uint64_t{0}),
      bearing_(sensors_.size() * landmarks_.size()),
      fresh_(sensors_.size() * landmarks_.size()),
      position_(sensors_.size()),
      zero_(sensors_.size()),
      placed_(sensors_.size()) {}

void BearingData::evaluate(const Box& box, int depth, std::span<IBool> out, int false_budget) {
  IBool* visible = visible_.enter(depth);
  IBool* status = status_.enter(depth);
  std::uint64_t* candidates = candidates_.enter(depth);
  std::fill(fresh_.begin(), fresh_.end(), 0);
  std::fill(placed_.begin(), placed_.end(), 0);
  const Pose<Interval> p{box[0], box[1], box[2]};
  Interval c, s;
  bool trig = false;
  const std::size_t n_landmarks = landmarks_.size();
  int falses = 0;
  for (std::size_t m = 0; m < measurements_.size(); ++m) falses += status[m].is_false();
  for (std::size_t m = 0; m < measurements_.size(); ++m) {
    if (!status[m].is_maybe() || falses > false_budget) continue;
    const std::size_t k = measurements_[m].sensor;
    const BearingSensor& sensor = sensors_[k];
    if (!placed_[k]) {
      if (!trig) {
        c = cos(p.theta);
        s = sin(p.theta);
        trig = true;
      }
      position_[k] = robot_to_world(p, c, s, sensor.x, sensor.y);
      zero_[k] = p.theta + sensor.heading;
      placed_[k] = 1;
    }
    std::uint64_t* mine = candidates + m * words_;
    IBool explained(false);
    for (std::size_t r = 0; r < n_landmarks && !explained.is_true(); ++r) {
      if (!test_bit(mine, r)) continue;
      const std::size_t kr = k * n_landmarks + r;
      // Bearing first: visibility (the costly part) only matters inside the window.
      if (!fresh_[kr]) {
        bearing_[kr] = landmark_bearing(position_[k], zero_[k], landmarks_[r]);
        fresh_[kr] = 1;
      }
      const IBool inside = angle_within(bearing_[kr], measurements_[m].bearing, sensor.precision);
      if (inside.is_false()) {
        clear_bit(mine, r);
        continue;
      }
      if (visible[kr].is_maybe() && fresh_[kr] == 1) {
        visible[kr] = landmark_visible(position_[k], landmarks_[r], walls_);
        fresh_[kr] = 2;  // visibility refreshed on this box
      }
      if (visible[kr].is_false()) {
        clear_bit(mine, r);
        continue;
      }
      explained = explained || (visible[kr] && inside);
    }
    status[m] = explained;
    falses += explained.is_false();
  }
  std::copy(status, status + measurements_.size(), out.begin());
}

std::vector<int> BearingData::associate(const Pose<double>& p) const {
  std::vector<int> result(measurements_.size(), -1);
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  for (std::size_t m = 0; m < measurements_.size(); ++m) {
    const BearingSensor& sensor = sensors_[measurements_[m].sensor];
    const Vec2T<double> at = robot_to_world(p, c, s, sensor.x, sensor.y);
    double best = kInf;
    for (std::size_t r = 0; r < landmarks_.size(); ++r) {
      if (!landmark_visible(at, landmarks_[r], walls_)) continue;
      const double b = landmark_bearing(at, p.theta + sensor.heading, landmarks_[r]);
      const double off = std::abs(std::remainder(b - measurements_[m].bearing, 2.0 * std::numbers::pi));
      if (off <= sensor.precision && off < best) {
        best = off;
        result[m] = static_cast<int>(r);
      }
    }
  }
  return result;
}

}  // namespace gesmi
