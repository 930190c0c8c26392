#include "tests/support/paper_network.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gesmi::test {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// An interval rounded to nearest: what a float implementation of the paper computes.
struct Fi {
  double lo = -kInfinity, hi = kInfinity;
  bool empty() const { return !(lo <= hi); }
  double width() const { return hi - lo; }
};

Fi operator+(Fi a, Fi b) { return {a.lo + b.lo, a.hi + b.hi}; }
Fi operator-(Fi a, Fi b) { return {a.lo - b.hi, a.hi - b.lo}; }
Fi operator-(Fi a) { return {-a.hi, -a.lo}; }
Fi operator*(Fi a, Fi b) {
  if (a.lo == -kInfinity || a.hi == kInfinity || b.lo == -kInfinity || b.hi == kInfinity) {
    // Only products with finite factors occur in the rotations; an unbounded position
    // times a finite weight stays unbounded on the sides it reaches.
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    double lo = kInfinity, hi = -kInfinity;
    for (const double x : p) {
      const double v = std::isnan(x) ? 0.0 : x;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return {lo, hi};
  }
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
Fi scaled(double s, Fi a) { return s >= 0 ? Fi{s * a.lo, s * a.hi} : Fi{s * a.hi, s * a.lo}; }
Fi meet(Fi a, Fi b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }
Fi join(Fi a, Fi b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
Fi square(Fi a) {
  const double l = a.lo * a.lo, h = a.hi * a.hi;
  if (a.lo <= 0.0 && a.hi >= 0.0) return {0.0, std::max(l, h)};
  return {std::min(l, h), std::max(l, h)};
}
// The x with x² in s, restricted to x's current domain.
Fi square_root_in(Fi s, Fi x) {
  if (s.hi < 0.0) return {kInfinity, -kInfinity};
  const double r = std::sqrt(std::max(s.hi, 0.0)), q = std::sqrt(std::max(s.lo, 0.0));
  const Fi positive = meet(Fi{q, r}, x), negative = meet(Fi{-r, -q}, x);
  if (positive.empty()) return negative;
  if (negative.empty()) return positive;
  return join(positive, negative);
}
// sin and cos over a narrow interval (the endpoints, and the extrema inside).
Fi sine(Fi a) {
  double lo = std::min(std::sin(a.lo), std::sin(a.hi)), hi = std::max(std::sin(a.lo), std::sin(a.hi));
  for (double k = std::ceil((a.lo - M_PI / 2) / M_PI); M_PI / 2 + k * M_PI <= a.hi; k += 1.0) {
    const double v = std::sin(M_PI / 2 + k * M_PI);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return {lo, hi};
}
Fi cosine(Fi a) { return sine(a + Fi{M_PI / 2, M_PI / 2}); }

using V3 = std::array<Fi, 3>;
using M3 = std::array<V3, 3>;

// R = Rz(psi) Ry(theta) Rx(phi): the body frame (forward, starboard, down) in NED.
M3 rotation(Fi phi, Fi theta, Fi psi) {
  const Fi cf = cosine(phi), sf = sine(phi), ct = cosine(theta), st = sine(theta), cp = cosine(psi), sp = sine(psi);
  return {{{cp * ct, cp * st * sf - sp * cf, cp * st * cf + sp * sf},
           {sp * ct, sp * st * sf + cp * cf, sp * st * cf - cp * sf},
           {-st, ct * sf, ct * cf}}};
}
V3 times(const M3& r, const V3& v) {
  V3 out;
  for (int i = 0; i < 3; ++i) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
  return out;
}
V3 transposed_times(const M3& r, const V3& v) {
  V3 out;
  for (int i = 0; i < 3; ++i) out[i] = r[0][i] * v[0] + r[1][i] * v[1] + r[2][i] * v[2];
  return out;
}
bool meet_into(V3& a, const V3& b) {
  for (int i = 0; i < 3; ++i) {
    a[i] = meet(a[i], b[i]);
    if (a[i].empty()) return false;
  }
  return true;
}

// ||e|| in r: forward n = sum e_i², n meets r², back to each e_i.
bool distance(V3& e, Fi r) {
  const Fi n = meet(square(e[0]) + square(e[1]) + square(e[2]), square(meet(r, Fi{0.0, kInfinity})));
  if (n.empty()) return false;
  for (int i = 0; i < 3; ++i) {
    const Fi others = square(e[(i + 1) % 3]) + square(e[(i + 2) % 3]);
    e[i] = square_root_in(n - others, e[i]);
    if (e[i].empty()) return false;
  }
  return true;
}

struct Mark {
  std::size_t k;
  int mine;
  Fi range, altitude;
  M3 r;
  bool starboard;
};

// The mark's equations (seed 001, eqs. 8-10) on the position q at the mark and the
// mine box m: a few rounds in both frames.
bool contract_mark(const Mark& mark, const SensorModel& model, V3& q, V3& m) {
  for (int round = 0; round < 4; ++round) {
    V3 e = {q[0] - m[0], q[1] - m[1], q[2] - m[2]};
    e[2] = meet(e[2], -(mark.altitude + Fi{-model.mine_depth_band, model.mine_depth_band}));
    if (e[2].empty() || !distance(e, mark.range)) return false;
    V3 body = transposed_times(mark.r, e);
    const V3 allowed = {Fi{-model.along_track_tolerance, model.along_track_tolerance},
                        mark.starboard ? Fi{-kInfinity, 0.0} : Fi{0.0, kInfinity}, Fi{-kInfinity, 0.0}};
    if (!meet_into(body, allowed) || !distance(body, mark.range)) return false;
    if (!meet_into(e, times(mark.r, body))) return false;
    // e = q - m: back to q and m.
    for (int i = 0; i < 3; ++i) {
      q[i] = meet(q[i], e[i] + m[i]);
      m[i] = meet(m[i], q[i] - e[i]);
      if (q[i].empty() || m[i].empty()) return false;
    }
  }
  return true;
}

std::size_t sample_at(const Mission& m, double t) {
  const auto it = std::lower_bound(m.time.begin(), m.time.end(), t);
  if (it == m.time.end() || *it != t) throw std::invalid_argument("paper network: a fix or mark between samples");
  return static_cast<std::size_t>(it - m.time.begin());
}

}  // namespace

double PaperTube::max_horizontal_width() const {
  double w = 0.0;
  for (std::size_t k = 0; k < north_lo.size(); ++k) w = std::max({w, north_hi[k] - north_lo[k], east_hi[k] - east_lo[k]});
  return w;
}

PaperTube propagate_paper_network(const Mission& mission) {
  const SensorModel& model = mission.model;
  const std::size_t n = mission.size();
  // Increments by the paper's convention, and the barometer's depth.
  std::vector<V3> d(n - 1);
  const auto attitude_at = [&](std::size_t k) {
    return rotation(Fi{mission.roll[k] - model.roll, mission.roll[k] + model.roll},
                    Fi{mission.pitch[k] - model.pitch, mission.pitch[k] + model.pitch},
                    Fi{mission.heading[k] - model.heading - mission.heading_frame_margin,
                       mission.heading[k] + model.heading + mission.heading_frame_margin});
  };
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const auto speed = [&](double v) {
      const double b = model.dvl_relative * std::fabs(v) + model.dvl_absolute;
      return Fi{v - b, v + b};
    };
    const V3 w = times(attitude_at(k), V3{speed(mission.vx[k]), speed(mission.vy[k]), speed(mission.vz[k])});
    const double dt = mission.time[k + 1] - mission.time[k];
    for (int i = 0; i < 3; ++i) d[k][i] = scaled(dt, w[i]);
  }
  std::vector<V3> p(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double b = model.depth_absolute + model.depth_relative * std::fabs(mission.depth[k]);
    p[k][2] = Fi{mission.depth[k] - b, mission.depth[k] + b};
  }
  for (std::size_t i = 0; i < mission.gps_time.size(); ++i) {
    const std::size_t k = sample_at(mission, mission.gps_time[i]);
    p[k][0] = meet(p[k][0], Fi{mission.gps_north[i] - mission.gps_north_halfwidth[i], mission.gps_north[i] + mission.gps_north_halfwidth[i]});
    p[k][1] = meet(p[k][1], Fi{mission.gps_east[i] - mission.gps_east_halfwidth[i], mission.gps_east[i] + mission.gps_east_halfwidth[i]});
  }
  std::vector<Mark> marks;
  for (std::size_t j = 0; j < mission.mark_count(); ++j) {
    if (mission.mark_mine[j] < 0) throw std::invalid_argument("paper network: marks need their mine");
    Mark mark;
    mark.k = sample_at(mission, mission.mark_time[j]);
    mark.mine = mission.mark_mine[j];
    mark.range = Fi{mission.mark_range[j] - model.mark_range, mission.mark_range[j] + model.mark_range};
    mark.altitude = Fi{mission.altitude[mark.k] - model.altitude, mission.altitude[mark.k] + model.altitude};
    mark.r = attitude_at(mark.k);
    mark.starboard = mission.mark_side[j] > 0;
    marks.push_back(mark);
  }
  std::vector<V3> mines(static_cast<std::size_t>(mission.mine_count));

  PaperTube out;
  const auto bounds_of = [&] {
    std::vector<double> b;
    for (const V3& x : p)
      for (const Fi& c : x) b.insert(b.end(), {c.lo, c.hi});
    for (const V3& x : mines)
      for (const Fi& c : x) b.insert(b.end(), {c.lo, c.hi});
    return b;
  };
  for (out.sweeps = 0; out.sweeps < 100; ++out.sweeps) {
    const std::vector<double> before = bounds_of();
    for (std::size_t k = 0; k + 1 < n; ++k)
      for (int i = 0; i < 3; ++i) p[k + 1][i] = meet(p[k + 1][i], p[k][i] + d[k][i]);
    for (std::size_t k = n - 1; k > 0; --k)
      for (int i = 0; i < 3; ++i) p[k - 1][i] = meet(p[k - 1][i], p[k][i] - d[k - 1][i]);
    for (const Mark& mark : marks)
      if (!contract_mark(mark, model, p[mark.k], mines[static_cast<std::size_t>(mark.mine)])) out.consistent = false;
    for (const V3& x : p)
      for (const Fi& c : x) out.consistent = out.consistent && !c.empty();
    if (!out.consistent) break;
    const std::vector<double> after = bounds_of();
    double move = 0.0;
    for (std::size_t i = 0; i < after.size(); ++i)
      if (std::isfinite(after[i]) && std::isfinite(before[i])) move = std::max(move, std::fabs(after[i] - before[i]));
      else if (std::isfinite(after[i]) != std::isfinite(before[i])) move = kInfinity;
    if (move <= 1e-3) break;
  }
  for (const V3& x : p) {
    out.north_lo.push_back(x[0].lo);
    out.north_hi.push_back(x[0].hi);
    out.east_lo.push_back(x[1].lo);
    out.east_hi.push_back(x[1].hi);
  }
  for (const V3& x : mines) {
    out.mine_north_width.push_back(x[0].width());
    out.mine_east_width.push_back(x[1].width());
  }
  return out;
}

}  // namespace gesmi::test
