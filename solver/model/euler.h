#pragma once
// Body-to-world rotation of seed 001's kinematics p' = R(phi, theta, psi) v_r, with
// R = Rz(psi) Ry(theta) Rx(phi) (NED world frame; body x forward, y starboard,
// z down). One template serves the simulator and Kalman smoother (double) and the
// interval contractors (Interval): the rotation is applied as three plane
// rotations, which is cheaper and no looser than forming the interval matrix.

#include <cmath>
#include <optional>

#include "solver/interval/box.h"

namespace gesmi {

template <class T>
struct SinCos {
  T sin, cos;
};

inline SinCos<double> sin_cos(double angle) { return {std::sin(angle), std::cos(angle)}; }

/// Enclosures of sin and cos over an interval. For narrow intervals (the sensor
/// boxes: a few milliradians) a first-order Taylor form around the midpoint with a
/// Lagrange remainder r^2/2 is as tight as the exact range and needs one libm call
/// each; wider ones use the general interval functions.
SinCos<Interval> sin_cos(const Interval& angle);

/// What the narrow form of sin_cos starts from: the box's half-width r (rounded up) and
/// libm's sine and cosine at its rounded midpoint, each widened by kLibmSteps; none for
/// an empty box or one wider than 0.05 rad. The waterfall's kernel finishes the form in
/// its own rounding mode from these values (waterfall_kernel.h).
struct NarrowAngle {
  double radius;
  Interval sin_mid, cos_mid;
};
std::optional<NarrowAngle> narrow_angle(const Interval& angle);

/// Attitude (roll phi, pitch theta, heading psi) with its sines and cosines.
template <class T>
struct Attitude {
  SinCos<T> roll, pitch, heading;
};

template <class T>
Attitude<T> make_attitude(const T& roll, const T& pitch, const T& heading) {
  return {sin_cos(roll), sin_cos(pitch), sin_cos(heading)};
}

/// v_world = Rz(psi) Ry(theta) Rx(phi) v_body.
template <class T>
Vec3<T> body_to_world(const Attitude<T>& a, const Vec3<T>& v) {
  // Rx(phi): rotation in the (y, z) plane.
  const T y1 = a.roll.cos * v[1] - a.roll.sin * v[2];
  const T z1 = a.roll.sin * v[1] + a.roll.cos * v[2];
  // Ry(theta): rotation in the (z, x) plane.
  const T x2 = a.pitch.cos * v[0] + a.pitch.sin * z1;
  const T z2 = a.pitch.cos * z1 - a.pitch.sin * v[0];
  // Rz(psi): rotation in the (x, y) plane.
  const T x3 = a.heading.cos * x2 - a.heading.sin * y1;
  const T y3 = a.heading.sin * x2 + a.heading.cos * y1;
  return Vec3<T>(x3, y3, z2);
}

/// v_body = R^T v_world = Rx(-phi) Ry(-theta) Rz(-psi) v_world.
template <class T>
Vec3<T> world_to_body(const Attitude<T>& a, const Vec3<T>& v) {
  const T x1 = a.heading.cos * v[0] + a.heading.sin * v[1];
  const T y1 = a.heading.cos * v[1] - a.heading.sin * v[0];
  const T x2 = a.pitch.cos * x1 - a.pitch.sin * v[2];
  const T z2 = a.pitch.sin * x1 + a.pitch.cos * v[2];
  const T y3 = a.roll.cos * y1 + a.roll.sin * z2;
  const T z3 = a.roll.cos * z2 - a.roll.sin * y1;
  return Vec3<T>(x2, y3, z3);
}

}  // namespace gesmi
