#pragma once
// Angle constants shared by the models, the simulators and the files in degrees.

#include <numbers>

namespace gesmi {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

}  // namespace gesmi
