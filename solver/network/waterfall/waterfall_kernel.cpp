// The waterfall's cells in the upward rounding mode (waterfall_kernel.h). This file is
// compiled with -frounding-math (solver/CMakeLists.txt). Every bound is the directed
// rounding of one real operation, as in the portable Interval: an upper bound is the
// plain operation, a lower bound -((-a) op b), which is exact directed rounding
// (docs/intervals.md, section 9). The portable add_down, mul_down, sqrt_down ... give the
// same directed roundings (rounding.h), so each bound equals Interval's up to the sign of
// a zero; the operations below follow sonar_ranges(), SonarPlane and contract_distance
// one for one, in the same order.

#include "solver/network/waterfall/waterfall_kernel.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "solver/interval/upward_rounding.h"
#include "solver/model/euler.h"

namespace gesmi {

bool prepare_kernel_step(const Vec3I& position, const Interval& roll, const Interval& pitch, const Interval& heading,
                         const Interval& altitude, double frame_slack, KernelStep& out) {
  const auto moderate = [](const Interval& x) {
    return !x.is_empty() && x.lo() >= -kKernelMagnitude && x.hi() <= kKernelMagnitude;
  };
  for (int i = 0; i < 3; ++i) {
    if (!moderate(position[i])) return false;
    out.p_lo[i] = position[i].lo();
    out.p_hi[i] = position[i].hi();
  }
  if (!moderate(altitude) || !(frame_slack >= 0.0 && frame_slack <= kKernelMagnitude)) return false;
  out.altitude_lo = altitude.lo();
  out.altitude_hi = altitude.hi();
  out.frame_slack = frame_slack;
  const Interval* angles[3] = {&roll, &pitch, &heading};
  for (int a = 0; a < 3; ++a) {
    const std::optional<NarrowAngle> narrow = narrow_angle(*angles[a]);
    if (!narrow) return false;
    out.radius[a] = narrow->radius;
    out.sin_lo[a] = narrow->sin_mid.lo();
    out.sin_hi[a] = narrow->sin_mid.hi();
    out.cos_lo[a] = narrow->cos_mid.lo();
    out.cos_hi[a] = narrow->cos_mid.hi();
  }
  return true;
}

bool kernel_takes(const Vec3I& mine) {
  for (int i = 0; i < 3; ++i)
    if (mine[i].is_empty() || mine[i].lo() < -kKernelMagnitude || mine[i].hi() > kKernelMagnitude) return false;
  return true;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Upward mode only (everything below is inlined into the non-inlined kernel).

/// [lo, hi] as in Interval: the empty set is lo = +inf, hi = -inf, so that hull and
/// intersection are the same min and max.
struct I {
  double lo, hi;
};
constexpr I kEmpty{kInf, -kInf};
constexpr I kZero{0.0, 0.0};

inline bool is_empty(I x) { return !(x.lo <= x.hi); }
/// Interval::intersect_with.
inline bool narrow(I& x, I y) {
  x = {std::max(x.lo, y.lo), std::min(x.hi, y.hi)};
  if (x.lo > x.hi) x = kEmpty;
  return !is_empty(x);
}
inline I intersect(I x, I y) {
  narrow(x, y);
  return x;
}
inline I hull(I x, I y) { return {std::min(x.lo, y.lo), std::max(x.hi, y.hi)}; }
inline bool intersects(I x, I y) { return !is_empty(x) && !is_empty(y) && x.lo <= y.hi && y.lo <= x.hi; }

// Directed roundings of one operation: RU is the plain one.
inline double add_down(double a, double b) { return -((-a) - b); }
inline double sub_down(double a, double b) { return -(b - a); }
inline double mul_down(double a, double b) { return -((-a) * b); }
inline double next_down_positive(double r) { return std::bit_cast<double>(std::bit_cast<std::uint64_t>(r) - 1); }
/// RD(sqrt x) for x > 0 finite: r = RU(sqrt x) unless r*r exceeds x, which both
/// roundings of r*r equal x excludes (then r*r = x exactly).
inline double sqrt_down(double x) {
  const double r = std::sqrt(x);
  return (r * r == x && mul_down(r, r) == x) ? r : next_down_positive(r);
}

// The Interval operations on non-empty operands (the callers never pass an empty one).
inline I operator+(I x, I y) { return {add_down(x.lo, y.lo), x.hi + y.hi}; }
inline I operator-(I x, I y) { return {sub_down(x.lo, y.hi), x.hi - y.lo}; }
inline I operator-(I x) { return {-x.hi, -x.lo}; }
/// The four end point products: their directed roundings bound the exact extremes, as
/// the portable product's case analysis picks them.
inline I operator*(I x, I y) {
  const double lo = std::min(std::min(mul_down(x.lo, y.lo), mul_down(x.lo, y.hi)),
                             std::min(mul_down(x.hi, y.lo), mul_down(x.hi, y.hi)));
  const double hi = std::max(std::max(x.lo * y.lo, x.lo * y.hi), std::max(x.hi * y.lo, x.hi * y.hi));
  return {lo, hi};
}
inline I inflated(I x, double r) { return {sub_down(x.lo, r), x.hi + r}; }
/// sqr(): from the smallest and largest magnitudes.
inline I sqr(I x) {
  const double mig = x.lo >= 0.0 ? x.lo : (x.hi <= 0.0 ? -x.hi : 0.0);
  const double mag = std::max(-x.lo, x.hi);
  return {std::max(0.0, mul_down(mig, mig)), mag * mag};
}
/// sqrt() of a non-empty x >= 0 somewhere.
inline I sqrt(I x) { return {x.lo <= 0.0 ? 0.0 : sqrt_down(x.lo), std::sqrt(x.hi)}; }
/// bwd_sqr(y, x): x narrowed to +-sqrt(y), pow_rev's hull of the two roots.
inline bool bwd_sqr(I y, I& x) {
  const I c = intersect(y, {0.0, kInf});
  I root = kEmpty;
  if (!is_empty(c)) {
    const double lo = (c.lo == 0.0 || c.lo == kInf) ? c.lo : sqrt_down(c.lo);
    const double hi = (c.hi == 0.0 || c.hi == kInf) ? c.hi : std::sqrt(c.hi);
    root = {lo, hi};
  }
  const I both = is_empty(root) ? kEmpty : hull(intersect(root, x), intersect(-root, x));
  return narrow(x, both);
}
/// bwd_sub(y, x1, x2) for y = x1 - x2.
inline bool bwd_sub(I y, I& x1, I& x2) { return narrow(x1, y + x2) && narrow(x2, x1 - y); }

using V = I[3];

struct Attitude3 {
  I rs, rc, ps, pc, hs, hc;  // sin and cos of roll, pitch, heading
};

/// sin_cos()'s narrow form from narrow_angle()'s values.
inline void narrow_sin_cos(double r, double s_lo, double s_hi, double c_lo, double c_hi, I& sine, I& cosine) {
  const double quadratic = 0.5 * (r * r);
  const double sin_spread = std::max(-c_lo, c_hi) * r + quadratic;
  const double cos_spread = std::max(-s_lo, s_hi) * r + quadratic;
  sine = {std::max(-1.0, sub_down(s_lo, sin_spread)), std::min(1.0, s_hi + sin_spread)};
  cosine = {std::max(-1.0, sub_down(c_lo, cos_spread)), std::min(1.0, c_hi + cos_spread)};
}

/// world_to_body (euler.h).
inline void world_to_body(const Attitude3& a, const V v, V out) {
  const I x1 = a.hc * v[0] + a.hs * v[1];
  const I y1 = a.hc * v[1] - a.hs * v[0];
  const I x2 = a.pc * x1 - a.ps * v[2];
  const I z2 = a.ps * x1 + a.pc * v[2];
  out[0] = x2;
  out[1] = a.rc * y1 + a.rs * z2;
  out[2] = a.rc * z2 - a.rs * y1;
}

/// body_to_world (euler.h).
inline void body_to_world(const Attitude3& a, const V v, V out) {
  const I y1 = a.rc * v[1] - a.rs * v[2];
  const I z1 = a.rs * v[1] + a.rc * v[2];
  const I x2 = a.pc * v[0] + a.ps * z1;
  const I z2 = a.pc * z1 - a.ps * v[0];
  out[0] = a.hc * x2 - a.hs * y1;
  out[1] = a.hs * x2 + a.hc * y1;
  out[2] = z2;
}

/// contract_distance<3>(z, a, b) with b the three zero intervals of contract().
inline bool contract_distance(I& z, V a, V b) {
  I d[3], s[3];
  I sum = kZero;
  for (int i = 0; i < 3; ++i) {
    d[i] = a[i] - b[i];
    s[i] = sqr(d[i]);
    sum = sum + s[i];
  }
  if (!narrow(z, sqrt(sum))) return false;
  const I positive = intersect(z, {0.0, kInf});
  if (is_empty(positive)) return false;
  I sum_back = sum;
  if (!narrow(sum_back, sqr(positive))) return false;
  for (int i = 0; i < 3; ++i) {
    I others = kZero;
    for (int j = 0; j < 3; ++j)
      if (j != i) others = others + s[j];
    if (!narrow(s[i], sum_back - others)) return false;
  }
  for (int i = 0; i < 3; ++i)
    if (!bwd_sqr(s[i], d[i]) || !bwd_sub(d[i], a[i], b[i])) return false;
  return true;
}

/// SonarPlane::offset: q - m widened by the frame slack.
inline void offset(const V q, const V m, double slack, V e) {
  for (int i = 0; i < 3; ++i) e[i] = inflated(q[i] - m[i], slack);
}

enum class Stop { go_on, stop, undecided };

/// Whether largest_change(before, after) < 1e-6 in round-to-nearest (SonarPlane::contract),
/// where each change is after.lo - before.lo or before.hi - after.hi rounded to nearest:
/// settled when both directed roundings of a change fall on one side (RD <= RN <= RU).
/// `so_far`: stop, or what an earlier box decided.
inline Stop small_change(const V before, const V after, Stop so_far) {
  constexpr double kMove = 1e-6;
  if (so_far == Stop::go_on) return so_far;
  for (int i = 0; i < 3; ++i) {
    const double changes_up[2] = {after[i].lo - before[i].lo, before[i].hi - after[i].hi};
    const double changes_down[2] = {sub_down(after[i].lo, before[i].lo), sub_down(before[i].hi, after[i].hi)};
    for (int c = 0; c < 2; ++c) {
      if (changes_down[c] >= kMove) return Stop::go_on;
      if (!(changes_up[c] < kMove)) so_far = Stop::undecided;
    }
  }
  return so_far;
}

struct Plane {
  Attitude3 attitude;
  I vertical;
  double along_tolerance, frame_slack;
};

/// SonarPlane::contract on one side (1 starboard, -1 port): r narrowed, or false when the
/// geometry cannot hold; `undecided` set when the stopping test could not be settled.
inline bool contract(const Plane& plane, int side, V q, V m, I& r, bool& undecided) {
  const I prior[3] = {{-plane.along_tolerance, plane.along_tolerance},
                      side > 0 ? I{-kInf, 0.0} : I{0.0, kInf},
                      {-kInf, 0.0}};
  V zeros = {kZero, kZero, kZero};
  for (int round = 0; round < 4; ++round) {
    const V q_before = {q[0], q[1], q[2]}, m_before = {m[0], m[1], m[2]};
    V e, eb, back;
    offset(q, m, plane.frame_slack, e);
    if (!narrow(e[2], plane.vertical) || !contract_distance(r, e, zeros)) return false;
    world_to_body(plane.attitude, e, eb);
    for (int i = 0; i < 3; ++i)
      if (!narrow(eb[i], prior[i])) return false;
    if (!contract_distance(r, eb, zeros)) return false;
    body_to_world(plane.attitude, eb, back);
    for (int i = 0; i < 3; ++i)
      if (!narrow(e[i], back[i])) return false;
    for (int i = 0; i < 3; ++i) e[i] = inflated(e[i], plane.frame_slack);
    for (int i = 0; i < 3; ++i)
      if (!bwd_sub(e[i], q[i], m[i])) return false;
    const Stop stop = small_change(m_before, m, small_change(q_before, q, Stop::stop));
    if (stop == Stop::undecided) {
      undecided = true;
      return true;
    }
    if (stop == Stop::stop) break;
  }
  return true;
}

/// sonar_ranges() for one pair.
inline KernelCell pair_cell(const SonarGeometry& g, const Plane& plane, const KernelStep& step, const KernelMine& mine) {
  constexpr KernelCell kNone{0.0, 0.0, KernelVerdict::none};
  V p, m, e;
  for (int i = 0; i < 3; ++i) {
    p[i] = {step.p_lo[i], step.p_hi[i]};
    m[i] = {mine.lo[i], mine.hi[i]};
  }
  // SonarPlane::rough_body_offset and may_hold.
  offset(p, m, plane.frame_slack, e);
  const I ez = intersect(e[2], plane.vertical);
  if (is_empty(ez)) return kNone;
  const Attitude3& a = plane.attitude;
  const I x1 = a.hc * e[0] + a.hs * e[1];
  const I along = a.pc * x1 - a.ps * ez;
  if (!intersects(along, {-plane.along_tolerance, plane.along_tolerance})) return kNone;
  const I y1 = a.hc * e[1] - a.hs * e[0];
  const I z2 = a.ps * x1 + a.pc * ez;
  const I across = a.rc * y1 + a.rs * z2, down = a.rc * z2 - a.rs * y1;
  if (!(down.lo <= 0.0)) return kNone;
  const bool sides[2] = {(g.sonar_side != SonarSide::port) && across.lo <= 0.0,        // starboard
                         (g.sonar_side != SonarSide::starboard) && across.hi >= 0.0};  // port
  if (!sides[0] && !sides[1]) return kNone;
  // SonarPlane::possible_ranges within the swath.
  const I distance = sqrt((sqr(e[0]) + sqr(e[1])) + sqr(e[2]));
  const I swath{0.0, g.max_range};
  if (!intersects(distance, swath)) return kNone;
  const I reach = intersect(distance, swath);
  I ranges = kEmpty;
  for (int s = 0; s < 2; ++s) {
    if (!sides[s]) continue;
    V q = {p[0], p[1], p[2]}, mm = {m[0], m[1], m[2]};
    I r = reach;
    bool undecided = false;
    const bool ok = contract(plane, s == 0 ? 1 : -1, q, mm, r, undecided);
    if (undecided) return {0.0, 0.0, KernelVerdict::undecided};
    if (ok) ranges = hull(ranges, r);
  }
  if (is_empty(ranges)) return kNone;
  return {ranges.lo, ranges.hi, KernelVerdict::ranges};
}

[[gnu::noinline]] void ranges_upward(const SonarGeometry& g, std::span<const KernelStep> steps,
                                     std::span<const KernelMine> mines, std::span<const KernelPair> pairs,
                                     std::span<KernelCell> cells) {
  const UpwardRounding upward;
  std::size_t planned = steps.size();  // the step whose plane is built
  Plane plane{};
  for (std::size_t j = 0; j < pairs.size(); ++j) {
    const KernelStep& step = steps[pairs[j].step];
    if (pairs[j].step != planned) {
      planned = pairs[j].step;
      I sine[3], cosine[3];
      for (int a = 0; a < 3; ++a)
        narrow_sin_cos(step.radius[a], step.sin_lo[a], step.sin_hi[a], step.cos_lo[a], step.cos_hi[a], sine[a], cosine[a]);
      plane.attitude = {sine[0], cosine[0], sine[1], cosine[1], sine[2], cosine[2]};
      // SonarPlane::vertical: -(altitude + [-band, band]).
      plane.vertical = -(I{step.altitude_lo, step.altitude_hi} + I{-g.depth_band, g.depth_band});
      plane.along_tolerance = g.along_tolerance;
      plane.frame_slack = step.frame_slack;
    }
    cells[j] = pair_cell(g, plane, step, mines[pairs[j].mine]);
  }
}

}  // namespace

void kernel_sonar_ranges(const SonarGeometry& geometry, std::span<const KernelStep> steps,
                         std::span<const KernelMine> mines, std::span<const KernelPair> pairs,
                         std::span<KernelCell> cells) {
  ranges_upward(geometry, steps, mines, pairs, cells);
}

}  // namespace gesmi
