#pragma once
// The goniometric model of seed 003: a sensor on the robot measures the bearing of
// point landmarks, relative to its own zero direction, within +- delta. A
// measurement is explained at pose p when some landmark visible from the sensor
// (its sight line crosses no wall) has its bearing inside the measurement's
// interval (any_vis_int_land_in_int_m). Templated on the number type: points
// simulate the sensor, boxes give interval Booleans.

#include <cmath>
#include <numbers>
#include <span>

#include "solver/setinv/localization/geometry2d.h"
#include "solver/setinv/localization/localization_map.h"

namespace gesmi {

/// Direction angle of the vector (dx, dy), in any window: the interval atan2 is
/// [-pi, pi] as soon as a box crosses its cut (the negative x axis), so a box on
/// the left is turned by pi first and the result is an interval around pi.
inline double direction_angle(double dy, double dx) { return std::atan2(dy, dx); }
inline Interval direction_angle(const Interval& dy, const Interval& dx) {
  if (dx.hi() < 0.0 && dy.lo() < 0.0 && dy.hi() >= 0.0) return atan2(-dy, -dx) + Interval::pi();
  return atan2(dy, dx);
}

/// Bearing of landmark l seen from a sensor at s whose zero direction is `zero`
/// (world angle), not wrapped: the direction of l minus the zero direction.
template <class T>
T landmark_bearing(const Vec2T<T>& s, const T& zero, const LandmarkPoint& l) {
  return direction_angle(T(l.y) - s.y, T(l.x) - s.x) - zero;
}

/// Is the angle a inside [centre - delta, centre + delta] modulo 2 pi?
inline bool angle_within(double a, double centre, double delta) {
  return std::abs(std::remainder(a - centre, 2.0 * std::numbers::pi)) <= delta;
}
/// Interval form: true when every angle of a is within, false when none is.
inline IBool angle_within(const Interval& a, double centre, double delta) {
  if (a.is_empty()) return IBool::empty();
  const Interval d = a - Interval(centre);
  // Wider than a turn minus the window: it meets the window whatever the shift.
  if (d.width() >= 2.0 * std::numbers::pi - 2.0 * delta) return IBool::maybe();
  // Shift d by whole turns so that its midpoint lies near 0, then compare with the
  // window and with its neighbours one turn away.
  const double turns = std::round(d.mid() / (2.0 * std::numbers::pi));
  const Interval shifted = d - Interval(turns) * Interval::two_pi();
  const Interval window(-delta, delta);
  if (window.is_superset(shifted)) return true;
  const bool meets = shifted.intersects(window) || (shifted - Interval::two_pi()).intersects(window) ||
                     (shifted + Interval::two_pi()).intersects(window);
  return meets ? IBool::maybe() : IBool(false);
}

/// Does the sight line [s, l] properly cross the wall [a, b]? Touching or
/// collinear contacts do not block (a landmark may sit on a wall).
template <class T>
BoolOf<T> sight_crosses(const Vec2T<T>& s, const LandmarkPoint& l, const Segment& w) {
  // Segments whose bounding boxes are apart cannot cross: most walls end here.
  if constexpr (is_interval_v<T>) {
    if (std::max(s.x.hi(), l.x) < std::min(w.ax, w.bx) || std::min(s.x.lo(), l.x) > std::max(w.ax, w.bx) ||
        std::max(s.y.hi(), l.y) < std::min(w.ay, w.by) || std::min(s.y.lo(), l.y) > std::max(w.ay, w.by))
      return IBool(false);
  }
  const Vec2T<T> sl = lift<T>(l.x, l.y) - s;
  const T d1 = det(sl, lift<T>(w.ax, w.ay) - s), d2 = det(sl, lift<T>(w.bx, w.by) - s);
  const T d3 = det(lift<T>(w.bx, w.by) - lift<T>(w.ax, w.ay), s - lift<T>(w.ax, w.ay));
  // Side of the landmark against the wall's line, in intervals for both number
  // types so that points and boxes agree: a landmark on the line (or too close to
  // tell) never counts as blocked.
  const Interval d4 = (Interval(w.bx) - w.ax) * (Interval(l.y) - w.ay) - (Interval(w.by) - w.ay) * (Interval(l.x) - w.ax);
  if (d4.contains(0.0)) return BoolOf<T>(false);
  const T zero(0.0);
  const BoolOf<T> wall_sides = (less(d1, zero) && less(zero, d2)) || (less(zero, d1) && less(d2, zero));
  const BoolOf<T> line_sides = d4.lo() > 0.0 ? less(d3, zero) : less(zero, d3);
  return wall_sides && line_sides;
}

/// Is landmark l visible from s (no wall crossed)?
template <class T>
BoolOf<T> landmark_visible(const Vec2T<T>& s, const LandmarkPoint& l, std::span<const Segment> walls) {
  BoolOf<T> visible(true);
  for (const Segment& w : walls) visible = visible && !sight_crosses(s, l, w);
  return visible;
}

}  // namespace gesmi
