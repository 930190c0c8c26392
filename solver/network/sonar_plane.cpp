#include "solver/network/sonar_plane.h"

#include <algorithm>

#include "solver/ctc/ctc_distance.h"

namespace gesmi {

Interval box_distance(const Vec3I& a, const Vec3I& b) {
  return sqrt(sqr(a[0] - b[0]) + sqr(a[1] - b[1]) + sqr(a[2] - b[2]));
}

bool boxes_beyond(const Vec3I& a, const Vec3I& b, double reach) {
  // The per-axis gaps, squared and summed to nearest, err by a relative 5 units in the
  // last place at most, far inside the 1e-12 of slack.
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double gap = std::max({0.0, b[i].lo() - a[i].hi(), a[i].lo() - b[i].hi()});
    sum += gap * gap;
  }
  return sum > reach * reach * (1.0 + 1e-12);
}

Vec3I SonarPlane::body_prior(SonarSide on) const {
  const Interval across = on == SonarSide::starboard ? Interval::neg_reals() : Interval::pos_reals();
  return Vec3I(Interval(-along_tolerance, along_tolerance), across, Interval::neg_reals());
}

Vec3I SonarPlane::rough_body_offset(const Vec3I& q, const Vec3I& m) const {
  const Vec3I e = offset(q, m);
  const Interval ez = intersect(e[2], vertical());
  const Interval &ex = e[0], &ey = e[1];
  // world_to_body (euler.h) term by term, the along-track component first: most mines in
  // reach are ahead or behind, out of the plane, and need no more.
  const Attitude<Interval>& a = attitude;
  const Interval x1 = a.heading.cos * ex + a.heading.sin * ey;
  const Interval along = a.pitch.cos * x1 - a.pitch.sin * ez;
  if (ez.is_empty() || !along.intersects(Interval(-along_tolerance, along_tolerance)))
    return Vec3I(Interval::empty(), Interval::empty(), Interval::empty());
  const Interval y1 = a.heading.cos * ey - a.heading.sin * ex;
  const Interval z2 = a.pitch.sin * x1 + a.pitch.cos * ez;
  return Vec3I(along, a.roll.cos * y1 + a.roll.sin * z2, a.roll.cos * z2 - a.roll.sin * y1);
}

bool SonarPlane::may_hold(const Vec3I& rough_body_offset, SonarSide on) const {
  const Vec3I prior = body_prior(on);
  for (int i = 0; i < 3; ++i)
    if (!rough_body_offset[i].intersects(prior[i])) return false;
  return true;
}

Vec3I SonarPlane::offset(const Vec3I& q, const Vec3I& m) const {
  return Vec3I((q[0] - m[0]).inflated(frame_slack), (q[1] - m[1]).inflated(frame_slack),
               (q[2] - m[2]).inflated(frame_slack));
}

Interval SonarPlane::possible_ranges(const Vec3I& q, const Vec3I& m) const {
  const Vec3I e = offset(q, m);
  return sqrt(sqr(e[0]) + sqr(e[1]) + sqr(e[2]));
}

Interval SonarPlane::vertical() const { return -(altitude + Interval(-depth_band, depth_band)); }

namespace {

bool narrow(Vec3I& x, const Vec3I& by) {
  for (int i = 0; i < 3; ++i)
    if (!x[i].intersect_with(by[i])) return false;
  return true;
}

double largest_change(const Vec3I& before, const Vec3I& after) {
  double change = 0.0;
  for (int i = 0; i < 3; ++i)
    change = std::max({change, after[i].lo() - before[i].lo(), before[i].hi() - after[i].hi()});
  return change;
}

}  // namespace

bool SonarPlane::contract(Vec3I& q, Vec3I& m, Interval& r) const {
  const Vec3I prior = body_prior();
  const Interval vertical = this->vertical();
  Interval zero_x(0.0), zero_y(0.0), zero_z(0.0);
  bool ok = true;
  // A few rounds reach the local fixpoint: each round uses what the other frame
  // learnt. Stop early when nothing moves by more than a micrometre.
  for (int round = 0; ok && round < 4; ++round) {
    const Vec3I q_before = q, m_before = m;
    Vec3I e = offset(q, m);
    ok = e[2].intersect_with(vertical);
    ok = ok && contract_distance<3>(r, {&e[0], &e[1], &e[2]}, {&zero_x, &zero_y, &zero_z});
    Vec3I eb = world_to_body(attitude, e);
    ok = ok && narrow(eb, prior);
    ok = ok && contract_distance<3>(r, {&eb[0], &eb[1], &eb[2]}, {&zero_x, &zero_y, &zero_z});
    ok = ok && narrow(e, body_to_world(attitude, eb));
    if (ok)
      for (int i = 0; i < 3; ++i) e[i] = e[i].inflated(frame_slack);
    for (int i = 0; ok && i < 3; ++i) ok = bwd_sub(e[i], q[i], m[i]);
    if (ok && largest_change(q_before, q) < 1e-6 && largest_change(m_before, m) < 1e-6) break;
  }
  if (!ok) {
    for (int i = 0; i < 3; ++i) q[i] = m[i] = Interval::empty();
    r = Interval::empty();
  }
  return ok;
}

}  // namespace gesmi
