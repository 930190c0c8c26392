#include "solver/network/time_location.h"

#include <algorithm>

#include "solver/network/sensors/sensor_boxes.h"

namespace gesmi {

std::size_t TimeLocation::sample_at_or_after(std::span<const double> time, double t) {
  return static_cast<std::size_t>(std::lower_bound(time.begin(), time.end(), t) - time.begin());
}

TimeLocation TimeLocation::locate(std::span<const double> time, double t, const SensorBoxes& boxes) {
  TimeLocation at;
  const std::size_t k = sample_at_or_after(time, t);
  if (k < time.size() && time[k] == t) {
    at.k = k;
    return at;
  }
  // time[k - 1] < t < time[k]
  at.k = k - 1;
  at.on_grid = false;
  const Interval alpha = Interval(t) - Interval(time[k - 1]), beta = Interval(time[k]) - Interval(t);
  boxes.offsets_between(k - 1, alpha, beta, at.forward, at.backward);
  return at;
}

Vec3I TimeLocation::position(const TubeDomains& d) const {
  if (on_grid) return d.position(k);
  Vec3I q;
  for (int i = 0; i < 3; ++i) q[i] = intersect(d.position(k)[i] + forward[i], d.position(k + 1)[i] - backward[i]);
  return q;
}

bool TimeLocation::narrow(TubeDomains& d, const Vec3I& q) const {
  std::vector<Interval>* axes[] = {&d.px, &d.py, &d.pz};
  for (int i = 0; i < 3; ++i) {
    std::vector<Interval>& p = *axes[i];
    if (on_grid) {
      if (!p[k].intersect_with(q[i])) return false;
    } else {
      if (!p[k].intersect_with(q[i] - forward[i])) return false;
      if (!p[k + 1].intersect_with(q[i] + backward[i])) return false;
    }
  }
  return true;
}

}  // namespace gesmi
