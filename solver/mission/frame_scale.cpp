#include "solver/mission/frame_scale.h"

#include <algorithm>
#include <limits>

namespace gesmi {

double frame_scale_within(double distance) {
  return 1.01 * (distance * distance / (2.0 * kWgs84SmallestRadius * kWgs84SmallestRadius));
}

double depth_scale_within(double depth) { return 1.01 * (std::max(depth, 0.0) / kWgs84SmallestRadius); }

double sonar_frame_slack(double scale, double range) {
  // Plain doubles: every term is non-negative, so the six roundings to nearest are
  // covered by a relative 8 units in the last place, and underflow by the smallest
  // normal number.
  constexpr double up = 1.0 + 8.0 * std::numeric_limits<double>::epsilon();
  const double drop = 1.01 * (range * range / (2.0 * kWgs84SmallestRadius));
  return (scale * range + drop) * up + std::numeric_limits<double>::min();
}

}  // namespace gesmi
