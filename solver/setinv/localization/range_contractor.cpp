#include "solver/setinv/localization/range_contractor.h"

#include <algorithm>

#include "solver/setinv/localization/range_model.h"
#include "solver/setinv/relaxed_intersection.h"

namespace gesmi {

CtcRangeRelaxed::CtcRangeRelaxed(std::vector<Segment> walls, std::vector<RangeSensor> sensors,
                                 std::vector<RangeMeasurement> measurements, int outliers)
    : walls_(std::move(walls)),
      sensors_(std::move(sensors)),
      measurements_(std::move(measurements)),
      outliers_(outliers),
      x_(measurements_.size()),
      y_(measurements_.size()) {
  for (const RangeMeasurement& m : measurements_) feasible_.push_back(feasible_range(m, sensors_[m.sensor]));
  events_.reserve(2 * measurements_.size());
}

CtcRangeRelaxed CtcRangeRelaxed::with_outliers(int q) const {
  CtcRangeRelaxed c = *this;
  c.outliers_ = q;
  return c;
}

void CtcRangeRelaxed::contract(Box& box) const {
  const Interval c = cos(box[2]), s = sin(box[2]);
  for (std::size_t i = 0; i < measurements_.size(); ++i) {
    if (measurements_[i].no_echo()) {  // no echo point to move back from
      x_[i] = box[0];
      y_[i] = box[1];
      continue;
    }
    const RangeSensor& sensor = sensors_[measurements_[i].sensor];
    const Interval axis = box[2] + Interval(sensor.heading) + Interval(-sensor.half_aperture, sensor.half_aperture);
    const Interval ux = cos(axis), uy = sin(axis);
    const Interval ox = c * sensor.x - s * sensor.y, oy = s * sensor.x + c * sensor.y;
    // Robot position = m - d u - offset, hulled over the walls that meet the box.
    const Interval bx = -feasible_[i] * ux - ox, by = -feasible_[i] * uy - oy;
    Interval hx = Interval::empty(), hy = Interval::empty();
    for (const Segment& w : walls_) {
      const Interval wx = Interval(std::min(w.ax, w.bx), std::max(w.ax, w.bx)) + bx;
      const Interval wy = Interval(std::min(w.ay, w.by), std::max(w.ay, w.by)) + by;
      if (!wx.intersects(box[0]) || !wy.intersects(box[1])) continue;
      hx = hull(hx, intersect(wx, box[0]));
      hy = hull(hy, intersect(wy, box[1]));
    }
    x_[i] = hx;
    y_[i] = hy;
  }
  const bool ok = box[0].intersect_with(relaxed_intersection(x_, outliers_, events_)) &&
                  box[1].intersect_with(relaxed_intersection(y_, outliers_, events_));
  if (!ok) normalize_empty(box);
}

}  // namespace gesmi
