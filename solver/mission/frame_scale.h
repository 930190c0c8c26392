#pragma once
// The local tangent frame's scale against the sea surface (docs/model.md, "The local
// frame's scale"). The solver integrates DVL speeds, measured along the surface, in
// the plane tangent at the origin, which is an orthogonal projection of the surface:
// it shrinks a step at distance rho from the origin by at most
// 1 - cos(rho / M) <= rho^2 / (2 M^2), M = b^2 / a the smallest radius of curvature.
// And a robot at depth D sees the surface point above it move faster than itself by
// D / (R - D) <= D / (M - D).

namespace gesmi {

/// WGS84's flattening, a defining constant of the ellipsoid.
inline constexpr double kWgs84Flattening = 1.0 / 298.257223563;
/// WGS84's equatorial radius a (m), a defining constant; also the smallest prime
/// vertical radius N, so a cos(latitude) bounds a degree of longitude's metres below.
inline constexpr double kWgs84EquatorialRadius = 6378137.0;
/// WGS84's smallest radius of curvature b^2 / a = a (1 - f)^2 (m): the meridian's, at
/// the equator.
inline constexpr double kWgs84SmallestRadius =
    kWgs84EquatorialRadius * (1.0 - kWgs84Flattening) * (1.0 - kWgs84Flattening);

/// An upper bound of the frame's relative scale error along a path anywhere within
/// `distance` metres of the origin: 1.01 distance² / (2 M²); the 1 % covers the
/// higher-order terms and the roundings (measured against WGS84 geodesics in
/// tests/io/geodesy_test.cpp). Infinite when the distance is.
double frame_scale_within(double distance);

/// An upper bound of how much faster than the robot the surface point above it moves,
/// relatively, for a robot at most `depth` metres deep: 1.01 depth / M, which covers
/// depth / (M - depth) up to 60 km deep.
double depth_scale_within(double depth);

/// How far apart, on each axis, a sonar's offset e (robot minus mine, `range` metres
/// long, in the local frame at the robot) and the frame's q - m (the tangent plane's
/// north and east, depths along each point's own vertical) can be, for a relative
/// scale error at most `scale` (frame and depth): scale times the range horizontally,
/// plus the surface's drop over the range, 1.01 range² / (2 M), vertically. Rounded up.
double sonar_frame_slack(double scale, double range);

}  // namespace gesmi
