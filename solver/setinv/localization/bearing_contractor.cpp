#include "solver/setinv/localization/bearing_contractor.h"

#include "solver/setinv/relaxed_intersection.h"

namespace gesmi {

CtcBearingRelaxed::CtcBearingRelaxed(std::vector<LandmarkPoint> landmarks, std::vector<BearingSensor> sensors,
                                     std::vector<BearingMeasurement> measurements, int outliers)
    : landmarks_(std::move(landmarks)),
      sensors_(std::move(sensors)),
      measurements_(std::move(measurements)),
      outliers_(outliers),
      x_(measurements_.size()),
      y_(measurements_.size()) {
  events_.reserve(2 * measurements_.size());
}

CtcBearingRelaxed CtcBearingRelaxed::with_outliers(int q) const {
  CtcBearingRelaxed c = *this;
  c.outliers_ = q;
  return c;
}

void CtcBearingRelaxed::contract(Box& box) const {
  // With a wide heading every direction is possible: nothing to gain, skip the work.
  if (box[2].width() > 1.0) return;
  const Interval c = cos(box[2]), s = sin(box[2]);
  const Interval ray_length = Interval::pos_reals();
  for (std::size_t m = 0; m < measurements_.size(); ++m) {
    const BearingSensor& sensor = sensors_[measurements_[m].sensor];
    const Interval phi = box[2] + Interval(sensor.heading) + Interval(measurements_[m].bearing) +
                         Interval(-sensor.precision, sensor.precision);
    const Interval cp = cos(phi), sp = sin(phi);
    const Interval ox = c * sensor.x - s * sensor.y, oy = s * sensor.x + c * sensor.y;
    const Interval sx = box[0] + ox, sy = box[1] + oy;  // the sensor's position
    Interval hx = Interval::empty(), hy = Interval::empty();
    for (const LandmarkPoint& l : landmarks_) {
      // The landmark must lie ahead of the sensor: a sign test on doubles first.
      if ((cp.lo() > 0.0 && l.x < sx.lo()) || (cp.hi() < 0.0 && l.x > sx.hi()) || (sp.lo() > 0.0 && l.y < sy.lo()) ||
          (sp.hi() < 0.0 && l.y > sy.hi()))
        continue;
      // s = l - rho u: forward-backward through rho >= 0.
      Interval rho = ray_length;
      if (!rho.intersect_with((Interval(l.x) - sx) / cp) || !rho.intersect_with((Interval(l.y) - sy) / sp)) continue;
      const Interval px = intersect(sx, Interval(l.x) - rho * cp) - ox, py = intersect(sy, Interval(l.y) - rho * sp) - oy;
      const Interval rx = intersect(px, box[0]), ry = intersect(py, box[1]);
      if (rx.is_empty() || ry.is_empty()) continue;
      hx = hull(hx, rx);
      hy = hull(hy, ry);
    }
    x_[m] = hx;
    y_[m] = hy;
  }
  const bool ok = box[0].intersect_with(relaxed_intersection(x_, outliers_, events_)) &&
                  box[1].intersect_with(relaxed_intersection(y_, outliers_, events_));
  if (!ok) normalize_empty(box);
}

}  // namespace gesmi
