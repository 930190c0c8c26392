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

}  // namespace gesmi
