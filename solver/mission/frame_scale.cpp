#include "solver/mission/frame_scale.h"

#include <algorithm>

namespace gesmi {

double frame_scale_within(double distance) {
  return 1.01 * (distance * distance / (2.0 * kWgs84SmallestRadius * kWgs84SmallestRadius));
}

double depth_scale_within(double depth) { return 1.01 * (std::max(depth, 0.0) / kWgs84SmallestRadius); }

}  // namespace gesmi
