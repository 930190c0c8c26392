#pragma once
// Plane geometry templated on the number type (double or Interval): the vectors,
// determinants and scalar products of seed 000 section 4, shared by the range and
// bearing models and their simulators.

#include "solver/setinv/point_math.h"

namespace gesmi {

template <class T>
struct Vec2T {
  T x, y;
};

template <class T>
Vec2T<T> operator-(const Vec2T<T>& a, const Vec2T<T>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class T>
T det(const Vec2T<T>& a, const Vec2T<T>& b) {
  return a.x * b.y - a.y * b.x;
}
template <class T>
T dot(const Vec2T<T>& a, const Vec2T<T>& b) {
  return a.x * b.x + a.y * b.y;
}
template <class T>
T norm(const Vec2T<T>& a) {
  return sqrt(sqr(a.x) + sqr(a.y));
}
/// A constant point as a vector of T.
template <class T>
Vec2T<T> lift(double x, double y) {
  return {T(x), T(y)};
}

/// Oriented wall segment [a b]; its reflecting face is on the left going from a to b.
struct Segment {
  double ax = 0, ay = 0, bx = 0, by = 0;
};

/// A pose p = (x, y, theta) as three numbers.
template <class T>
struct Pose {
  T x, y, theta;
};

/// Where a point fixed in the robot frame at (dx, dy) lies in the world (seed 000, 4.3).
template <class T>
Vec2T<T> robot_to_world(const Pose<T>& p, const T& cos_theta, const T& sin_theta, double dx, double dy) {
  return {p.x + cos_theta * dx - sin_theta * dy, p.y + sin_theta * dx + cos_theta * dy};
}

}  // namespace gesmi
