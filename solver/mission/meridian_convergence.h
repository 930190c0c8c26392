#pragma once
// Meridian convergence: the angle between true north at a point and the north axis
// of a local tangent frame. The gyrocompass measures heading from true north, the
// solver integrates in the local frame, so the heading box grows by this angle
// (docs/model.md, "The local frame's north").

namespace gesmi {

/// WGS84 semi-major axis (m), a defining constant of the ellipsoid.
inline constexpr double kWgs84SemiMajorAxis = 6378137.0;

/// An upper bound (rad) of the convergence at any point within `distance` metres of
/// a frame whose origin lies at `origin_latitude` (deg): distance / R seen from the
/// Earth's centre, times tan of the largest latitude within it, with 1 % of margin
/// on the radius and the product. Infinite when the distance is.
double meridian_convergence_within(double origin_latitude, double distance);

/// meridian_convergence_within() for one origin and many distances, with the tangent of
/// the origin's latitude taken once: within 12.6 km (an angle a <= 0.002 rad from the
/// Earth's centre) tan(latitude + a) is bounded by the addition formula with
/// a (1 + a^2/3 + a^4/3) >= tan a, and the few roundings by 2^-40 relative; farther out,
/// the same as meridian_convergence_within(). Never below that function, at most 1e-11
/// relative above its formula (tests/solver/mission/meridian_convergence_test.cpp,
/// against long double).
class MeridianConvergence {
 public:
  explicit MeridianConvergence(double origin_latitude);
  double within(double distance) const;

 private:
  double origin_latitude_;  // deg
  double latitude_;         // |origin_latitude| in rad
  double tan_latitude_;
};

}  // namespace gesmi
