#include "solver/setinv/localization/range_data.h"

#include "solver/setinv/localization/range_model.h"

namespace gesmi {

RangeData::RangeData(std::vector<Segment> walls, std::vector<RangeSensor> sensors,
                     std::vector<RangeMeasurement> measurements)
    : walls_(std::move(walls)),
      sensors_(std::move(sensors)),
      measurements_(std::move(measurements)),
      words_(words_for(walls_.size())),
      status_(measurements_.size(), IBool::maybe()),
      candidates_(measurements_.size() * words_, ~std::uint64_t{0}) {
  for (const RangeMeasurement& m : measurements_) feasible_.push_back(feasible_range(m, sensors_[m.sensor]));
}

void RangeData::evaluate(const Box& box, int depth, std::span<IBool> out, int false_budget) {
  IBool* status = status_.enter(depth);
  std::uint64_t* candidates = candidates_.enter(depth);
  const Pose<Interval> p{box[0], box[1], box[2]};
  const Interval c = cos(p.theta), s = sin(p.theta);
  int falses = 0;
  for (std::size_t i = 0; i < measurements_.size(); ++i) falses += status[i].is_false();
  for (std::size_t i = 0; i < measurements_.size(); ++i) {
    if (!status[i].is_maybe() || falses > false_budget) continue;
    const Interval& y = feasible_[i];
    const bool unbounded = y.hi() == kInf;  // "no echo": only walls below y.lo decide
    const RangeSensor& sensor = sensors_[measurements_[i].sensor];
    const SensorCone<Interval> cone = sensor_cone(p, c, s, sensor);
    std::uint64_t* mine = candidates + i * words_;
    Interval nearest = far_away<Interval>();
    bool below = false;
    for (std::size_t j = 0; j < walls_.size() && !below; ++j) {
      if (!test_bit(mine, j)) continue;
      const Interval r = remoteness(cone.s, cone.u1, cone.u2, walls_[j], sensor.blind_distance);
      if (r.lo() > y.hi() || (unbounded && r.lo() >= y.lo()))
        clear_bit(mine, j);  // cannot decide the verdict, on this box and its sub-boxes
      else if (r.hi() < y.lo())
        below = true;  // a nearer wall surely answers: the range is below y
      else
        nearest = min(nearest, r);
    }
    status[i] = below ? IBool(false) : member(nearest, y);
    falses += status[i].is_false();
  }
  std::copy(status, status + measurements_.size(), out.begin());
}

double RangeData::simulate(const Pose<double>& p, std::size_t i) const {
  return simulated_range(p, sensors_[measurements_[i].sensor], walls_);
}

std::vector<int> RangeData::associate(const Pose<double>& p) const {
  std::vector<int> walls(measurements_.size(), -1);
  for (std::size_t i = 0; i < measurements_.size(); ++i) {
    int nearest = -1;
    const double r = simulated_range(p, sensors_[measurements_[i].sensor], walls_, &nearest);
    if (feasible_[i].contains(r)) walls[i] = measurements_[i].no_echo() ? kNoWallInRange : nearest;
  }
  return walls;
}

}  // namespace gesmi
