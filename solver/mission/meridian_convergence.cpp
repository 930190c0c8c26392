#include "solver/mission/meridian_convergence.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/model/angles.h"

namespace gesmi {
namespace {

// The latitude the bound stops at: tan grows without bound towards the pole.
constexpr double kLargestLatitude = std::numbers::pi / 2 - 0.01;
// The angle from the Earth's centre up to which the tangent is bounded by its series
// (12.6 km): the bound is then within 4e-12 relative of the tangent per distance.
constexpr double kNearAngle = 0.002;

// The angle (rad) a distance spans from the Earth's centre, on a radius 1 % short.
double centre_angle(double distance) { return distance / (0.99 * kWgs84SemiMajorAxis); }

}  // namespace

double meridian_convergence_within(double origin_latitude, double distance) {
  // The largest latitude within the distance, not the origin's: at the equator the
  // convergence is not zero a few km north or south of it.
  const double angle = centre_angle(distance);
  const double latitude = std::min(std::fabs(origin_latitude) * kRadiansPerDegree + angle, kLargestLatitude);
  return angle * std::tan(latitude) * 1.01;
}

MeridianConvergence::MeridianConvergence(double origin_latitude)
    : origin_latitude_(origin_latitude),
      latitude_(std::fabs(origin_latitude) * kRadiansPerDegree),
      tan_latitude_(std::tan(latitude_)) {}

double MeridianConvergence::within(double distance) const {
  const double angle = centre_angle(distance);
  // (NaN and infinite distances, far ones and those that reach the largest latitude go
  // the general way)
  if (!(angle <= kNearAngle) || !(latitude_ + angle < kLargestLatitude))
    return meridian_convergence_within(origin_latitude_, distance);
  // tan(x + a) = (tan x + tan a) / (1 - tan x tan a), increasing in tan a, and
  // tan a = a + a^3/3 + 2a^5/15 + ... <= a (1 + a^2/3 + a^4/3) for 0 <= a <= kNearAngle,
  // 0.2 a^4 <= 3.2e-12 relative above it; 1 - tan x tan a stays above 0.0099 below the
  // largest latitude, so that the roundings (2^-53 relative each, the libm tangent's 2 ulp
  // amplified at most a hundredfold) stay below 2^-44: 2^-40 covers them.
  const double square = angle * angle;
  const double tan_angle = angle * (1.0 + square * (1.0 / 3.0 + square / 3.0));
  const double tangent = (tan_latitude_ + tan_angle) / (1.0 - tan_latitude_ * tan_angle);
  // (not 0 where the product underflows, for distances below a micrometre)
  const double tiny = distance > 0.0 ? std::numeric_limits<double>::denorm_min() : 0.0;
  return std::max(angle * tangent * 1.01 * (1.0 + 0x1p-40), tiny);
}

}  // namespace gesmi
