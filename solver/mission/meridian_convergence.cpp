#include "solver/mission/meridian_convergence.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gesmi {

double meridian_convergence_within(double origin_latitude, double distance) {
  // The largest latitude within the distance, not the origin's: at the equator the
  // convergence is not zero a few km north or south of it.
  const double angle = distance / (0.99 * kWgs84SemiMajorAxis);
  const double degree = std::numbers::pi / 180.0;
  const double latitude = std::min(std::fabs(origin_latitude) * degree + angle, std::numbers::pi / 2 - 0.01);
  return angle * std::tan(latitude) * 1.01;
}

}  // namespace gesmi
