#include "solver/mission/frame_scale.h"

#include <algorithm>

#include "solver/interval/rounding.h"

namespace gesmi {

double frame_scale_within(double distance) {
  return 1.01 * (distance * distance / (2.0 * kWgs84SmallestRadius * kWgs84SmallestRadius));
}

double depth_scale_within(double depth) { return 1.01 * (std::max(depth, 0.0) / kWgs84SmallestRadius); }

double sonar_frame_slack(double scale, double range) {
  const double drop = mul_up(1.01, div_up(mul_up(range, range), 2.0 * kWgs84SmallestRadius));
  return add_up(mul_up(scale, range), drop);
}

}  // namespace gesmi
