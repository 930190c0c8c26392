#pragma once
// The sonar model of seeds 000 (section 4), 002 and 004 (Table 3): the remoteness
// r(s, u1, u2, a, b) of an oriented segment [a b] from the emission cone C(s, u1,
// u2) is the distance from s to the nearest point of [a b] ∩ C, infinite when the
// segment is outside the cone or s is behind its reflecting face. Written once as a
// chi-algorithm (seed 000, Table 2, with its Remark 2 test) templated on the number
// type: on points it simulates a sonar, on boxes it is the inclusion function.
//
// The nearest point is one of h (projection of s on the line (ab)), h1, h2 (the
// cone's edges meeting (ab)), a and b; each candidate counts when it lies on the
// segment and in the cone, which (4.10) states as sign conditions.
//
// Options of the sensor (docs/setinversion.md, section 3.1): a blind distance b, below
// which nothing is heard (seed 000, after (4.6)); and a maximum range, beyond which
// the sonar reports "no echo" (seed 002, section 3.1), which only changes the
// measurement's feasible set (feasible_range).

#include <cmath>
#include <span>

#include "solver/interval/interval.h"
#include "solver/setinv/localization/geometry2d.h"
#include "solver/setinv/localization/localization_map.h"

namespace gesmi {

namespace detail {
template <class T>
BoolOf<T> all_nonpositive(const T& a, const T& b) {
  return leq(a, T(0.0)) && leq(b, T(0.0));
}
template <class T>
bool may_hold(const BoolOf<T>& c) {
  if constexpr (is_interval_v<T>)
    return c.may_be_true();
  else
    return c;
}
}  // namespace detail

/// Seed 000, Table 2 (+ Remark 2). u1 and u2 are the unit edge vectors of the cone,
/// det(u1, u2) > 0. With a blind distance b > 0 (0: none) only points at distance
/// >= b are heard. [ab] ∩ C is convex, so its distances fill [nearest, farthest]:
/// the wall answers max(nearest, b) when farthest >= b, and nothing when it lies
/// wholly in the blind zone. The farthest point is an end of the piece: a, b, h1, h2.
template <class T>
T remoteness(const Vec2T<T>& s, const Vec2T<T>& u1, const Vec2T<T>& u2, const Segment& w, double blind) {
  using detail::all_nonpositive;
  using detail::may_hold;
  const Vec2T<T> sa = lift<T>(w.ax, w.ay) - s, sb = lift<T>(w.bx, w.by) - s;
  const Vec2T<T> ab = lift<T>(w.bx, w.by) - lift<T>(w.ax, w.ay);
  // Step 6 first: behind the reflecting face (det(sa, sb) <= 0), nothing comes back.
  const T face = det(sa, sb);
  if constexpr (!is_interval_v<T>) {
    if (face <= 0.0) return far_away<T>();
  } else {
    if (face.hi() <= 0.0) return far_away<T>();
  }
  // Remark 2 of seed 000 (4.11): the whole cone turns away from the face.
  const T d1ab = det(u1, ab), d2ab = det(u2, ab);
  const BoolOf<T> away = all_nonpositive(d1ab, d2ab);
  if constexpr (!is_interval_v<T>) {
    if (away) return far_away<T>();
  } else {
    if (away.is_true()) return far_away<T>();
  }
  T r = far_away<T>();
  T farthest = T(0.0);  // of the candidates that are ends of [ab] ∩ C; 0 for none
  const auto candidate = [&](const BoolOf<T>& holds, auto distance) {
    if (may_hold<T>(holds)) r = min(r, select(holds, distance(), far_away<T>()));
  };
  const auto end_candidate = [&](const BoolOf<T>& holds, auto distance) {
    if (!may_hold<T>(holds)) return;
    const T d = distance();
    r = min(r, select(holds, d, far_away<T>()));
    if (blind > 0.0) farthest = max(farthest, select(holds, d, T(0.0)));
  };
  // Step 1: h, the orthogonal projection, at distance det(ab, as) / |ab|.
  candidate(all_nonpositive(dot(ab, sa), -dot(ab, sb)) && all_nonpositive(dot(u1, ab), -dot(u2, ab)),
            [&] { return abs(det(ab, sa)) / norm(ab); });
  // Sides of a and b against the cone's edges, shared by steps 2 to 5.
  const T u1a = det(u1, sa), u1b = det(u1, sb), u2a = det(u2, sa), u2b = det(u2, sb);
  // Steps 2-3: h1 and h2, along u1 and u2 (det, not the scalar product printed in
  // seed 000's Example 1: the distance along u is det(ab, sa) / det(ab, u)).
  end_candidate(all_nonpositive(u1a, -u1b), [&] { return abs(det(ab, sa) / d1ab); });
  end_candidate(all_nonpositive(u2a, -u2b), [&] { return abs(det(ab, sa) / d2ab); });
  // Steps 4-5: the end points, when inside the cone.
  end_candidate(all_nonpositive(-u1a, u2a), [&] { return norm(sa); });
  end_candidate(all_nonpositive(-u1b, u2b), [&] { return norm(sb); });
  // The blind zone: heard from distance b on, when some of the piece lies there.
  if (blind > 0.0) r = select(leq(T(blind), farthest), max(r, T(blind)), far_away<T>());
  // Step 6 on boxes where the face test is undecided, and Remark 2's test.
  if constexpr (is_interval_v<T>) {
    r = chi(face, far_away<T>(), r);
    r = select(away, far_away<T>(), r);
  }
  return r;
}

/// The cone of a range sensor for a robot at p: its vertex s and edges u1, u2.
template <class T>
struct SensorCone {
  Vec2T<T> s, u1, u2;
};

template <class T>
SensorCone<T> sensor_cone(const Pose<T>& p, const T& cos_theta, const T& sin_theta, const RangeSensor& sensor) {
  using std::cos, std::sin;  // for doubles; intervals find gesmi's by argument lookup
  const T a1 = p.theta + (T(sensor.heading) - T(sensor.half_aperture));
  const T a2 = p.theta + (T(sensor.heading) + T(sensor.half_aperture));
  return {robot_to_world(p, cos_theta, sin_theta, sensor.x, sensor.y), {cos(a1), sin(a1)}, {cos(a2), sin(a2)}};
}

/// f_i(p) of seed 000 (4.6): the range a sensor reports, min over the walls.
/// `nearest` (points only) receives the index of the wall that gives it, or -1.
template <class T>
T simulated_range(const Pose<T>& p, const RangeSensor& sensor, std::span<const Segment> walls, int* nearest = nullptr) {
  using std::cos, std::sin;
  const T c = cos(p.theta), s = sin(p.theta);
  const SensorCone<T> cone = sensor_cone(p, c, s, sensor);
  T best = far_away<T>();
  if (nearest) *nearest = -1;
  for (std::size_t j = 0; j < walls.size(); ++j) {
    const T r = remoteness(cone.s, cone.u1, cone.u2, walls[j], sensor.blind_distance);
    if constexpr (!is_interval_v<T>) {
      if (nearest && r < best) *nearest = static_cast<int>(j);
    }
    best = min(best, r);
  }
  return best;
}

/// Feasible interval of an echo d: [d (1 - alpha), d (1 + alpha)].
inline Interval range_interval(double d, double alpha) {
  return Interval(d) * (Interval(1.0) + Interval(-alpha, alpha));
}

/// Feasible set of f_i(p) for a measurement. "No echo" says the reading would have
/// exceeded max_range M; a true range r gives readings in [r / (1 + alpha), r / (1 -
/// alpha)], so r > M (1 - alpha), closed as [M (1 - alpha), +inf]. It holds the
/// infinite remoteness [DBL_MAX, +inf] (no wall in the cone at all).
inline Interval feasible_range(const RangeMeasurement& m, const RangeSensor& sensor) {
  if (!m.no_echo()) return range_interval(m.range, sensor.precision);
  const Interval beyond = Interval(sensor.max_range) * (Interval(1.0) - Interval(sensor.precision));
  return Interval(beyond.lo(), kInf);
}

}  // namespace gesmi
