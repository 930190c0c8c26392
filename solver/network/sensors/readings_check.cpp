// The readings' check (readings_check.h). Screens run in round-to-nearest with room for
// their rounding; only the screened candidates are computed in interval arithmetic,
// which alone decides.

#include "solver/network/sensors/readings_check.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/interval/rounding.h"
#include "solver/model/euler.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/network/sensors/step_model.h"

namespace gesmi {
namespace {

// Spans of the divided differences (samples on each side): at 10 Hz from 0.1 s, where
// a short burst shows, to 1.6 s, where the readings' noise weighs 256 times less.
constexpr std::size_t kSpans[] = {1, 4, 16};
constexpr std::size_t kWidestSpan = 16;
constexpr std::size_t kStepsPerBlock = 2048;

Interval component(const WorldVelocityBoxes& w, int i, std::size_t j) {
  return Interval::from_bounds(-w.neg_lo[i][j], w.hi[i][j]);
}

// World velocity boxes R v of samples [first, last), frameless, then widened by the
// zone's turn and scale (frame_margins.h).
void world_boxes(const Mission& m, const SensorModel& model, std::size_t first, std::size_t last, WorldVelocityBoxes& w) {
  world_velocity_boxes(m, model, first, last, w);
  if (!w.skipped.empty()) {
    const FrameMargins none{};
    const SensorBoxes frameless(m, model, none);
    for (const std::size_t k : w.skipped) {
      const Vec3I v = body_to_world(make_attitude(frameless.roll(k), frameless.pitch(k), frameless.heading(k)),
                                    frameless.velocity(k));
      for (int i = 0; i < 3; ++i) {
        w.neg_lo[i][k - first] = -v[i].lo();
        w.hi[i][k - first] = v[i].hi();
      }
    }
  }
  const double turn = m.heading_frame_margin, scale = m.frame_scale_margin;
  if (turn == 0.0 && scale == 0.0) return;
  // Each bound plus its widening, rounded up: the sum to nearest moved up by a unit in
  // the last place of its magnitude and the smallest subnormal.
  const auto up = [](double x, double y) {
    const double sum = x + y;
    return sum + std::fabs(sum) * 0x1p-52 + std::numeric_limits<double>::denorm_min();
  };
  for (std::size_t j = 0; j < last - first; ++j) {
    const double north = std::max(w.neg_lo[0][j], w.hi[0][j]), east = std::max(w.neg_lo[1][j], w.hi[1][j]);
    const double widen[2] = {frame_widening(turn, scale, east, north), frame_widening(turn, scale, north, east)};
    for (int i = 0; i < 2; ++i) {
      w.neg_lo[i][j] = up(w.neg_lo[i][j], widen[i]);
      w.hi[i][j] = up(w.hi[i][j], widen[i]);
    }
  }
}

// The smallest |w''| the readings allow somewhere between samples k - span and k + span
// on component i (indices into w from `first`): the magnitude nearest 0 of the second
// divided difference's interval, outward rounded (0 when it holds 0).
double least_second_derivative(const Mission& m, const WorldVelocityBoxes& w, std::size_t first, int i, std::size_t k,
                               std::size_t span) {
  const Interval before = Interval(m.time[k]) - Interval(m.time[k - span]);
  const Interval after = Interval(m.time[k + span]) - Interval(m.time[k]);
  const Interval w0 = component(w, i, k - first);
  const Interval slope_after = (component(w, i, k + span - first) - w0) / after;
  const Interval slope_before = (w0 - component(w, i, k - span - first)) / before;
  const Interval second = Interval(2.0) * (slope_after - slope_before) / (before + after);
  return std::max({0.0, second.lo(), -second.hi()});
}

// Centres and radii of a block's world velocity boxes, in round-to-nearest: the screen.
struct BlockMidpoints {
  std::vector<double> mid[3], rad[3];
  void fill(const WorldVelocityBoxes& w, std::size_t count) {
    for (int i = 0; i < 3; ++i) {
      mid[i].resize(count);
      rad[i].resize(count);
      for (std::size_t j = 0; j < count; ++j) {
        mid[i][j] = 0.5 * (w.hi[i][j] - w.neg_lo[i][j]);
        rad[i][j] = 0.5 * (w.hi[i][j] + w.neg_lo[i][j]);
      }
    }
  }
};

// The centres k of [from, to) whose divided difference over `span` may exceed `jerk`
// on some component: least_second_derivative's test in round-to-nearest, with room for
// its rounding. `b` holds samples from `first` on; `scratch` holds the weights.
void suspects(const Mission& m, const BlockMidpoints& b, std::size_t first, std::size_t from, std::size_t to,
              std::size_t span, double jerk, std::vector<double> (&scratch)[4], std::vector<std::size_t>& out) {
  if (to <= from) return;
  const std::size_t count = to - from;
  // The samples span before, at and span after each centre from `from` on (from >= span).
  const double* before_t = m.time.data() + (from - span);
  const double* at_t = m.time.data() + from;
  const double* after_t = m.time.data() + (from + span);
  const double limit = jerk * (1.0 - 1e-9) - 1e-9;
  for (std::vector<double>& v : scratch) v.resize(count);
  double* __restrict a0 = scratch[0].data();
  double* __restrict a1 = scratch[1].data();
  double* __restrict a2 = scratch[2].data();
  double* __restrict excess = scratch[3].data();
  // Second divided difference = a2 w(k + span) - a0 w(k) + a1 w(k - span).
  for (std::size_t j = 0; j < count; ++j) {
    const double h1 = at_t[j] - before_t[j], h2 = after_t[j] - at_t[j], c = 2.0 / (h1 + h2);
    a1[j] = c / h1;
    a2[j] = c / h2;
    a0[j] = a1[j] + a2[j];
    excess[j] = -1.0;
  }
  const std::size_t at = from - first;  // the block's index of `from`
  for (int i = 0; i < 3; ++i) {
    const double* __restrict mid_before = b.mid[i].data() + (at - span);
    const double* __restrict mid_at = b.mid[i].data() + at;
    const double* __restrict mid_after = b.mid[i].data() + (at + span);
    const double* __restrict rad_before = b.rad[i].data() + (at - span);
    const double* __restrict rad_at = b.rad[i].data() + at;
    const double* __restrict rad_after = b.rad[i].data() + (at + span);
    for (std::size_t j = 0; j < count; ++j) {
      const double centre = a2[j] * mid_after[j] - a0[j] * mid_at[j] + a1[j] * mid_before[j];
      const double radius = a2[j] * rad_after[j] + a0[j] * rad_at[j] + a1[j] * rad_before[j];
      excess[j] = std::max(excess[j], std::fabs(centre) - radius - limit);
    }
  }
  for (std::size_t j = 0; j < count; ++j)
    if (excess[j] > 0.0) out.push_back(from + j);
}

struct Gather {
  const Mission& m;
  const SensorModel& model;
  const StepRegimes& regimes;
  ReadingsEvidence& evidence;
};

// The samples [start, end) whose world box holds no velocity within max_speed: the
// smallest |w|² the box allows, rounded down.
void gather_speeds(Gather& g, const WorldVelocityBoxes& w, std::size_t first, std::size_t start, std::size_t end) {
  const double submerged = mul_up(g.model.max_speed, g.model.max_speed);
  const auto least = [&](int i, std::size_t k) { return std::max({0.0, -w.neg_lo[i][k - first], -w.hi[i][k - first]}); };
  for (std::size_t k = start; k < end; ++k) {
    // A screen in round-to-nearest (five roundings, well within the relative 1e-9).
    const double x = least(0, k), y = least(1, k), z = least(2, k);
    if (x * x + y * y + z * z <= submerged * (1.0 - 1e-9)) continue;
    const double squared = add_down(add_down(mul_down(x, x), mul_down(y, y)), mul_down(z, z));
    if (squared > submerged) g.evidence.speeds.push_back({k, squared});
  }
}

// The vertical increments of steps [start, end) under the regimes, as the step model
// encloses them from the world velocity boxes (without the rate hull, which only
// narrows them): dt/2 (w_k + w_k+1) +- J dt³/12, within the speed box at the surface;
// the speed box alone on a fall-back step.
void gather_vertical_steps(Gather& g, const WorldVelocityBoxes& w, std::size_t first, std::size_t start,
                           std::size_t end) {
  const double* neg_lo = w.neg_lo[2].data();
  const double* hi = w.hi[2].data();
  for (std::size_t k = start; k < end && k + 1 < g.m.size(); ++k) {
    const double dt = g.m.time[k + 1] - g.m.time[k];
    const Interval speed = speed_step(g.m, k, g.regimes.speed(g.model, k));
    const double speed_lo = speed.lo(), speed_hi = speed.hi();
    if (g.regimes.fallback(k)) {
      g.evidence.dz.set(k, speed);
      continue;
    }
    const std::size_t j = k - first;
    const double remainder = trapezoid_remainder_bound(dt, g.regimes.jerk(g.model, k));
    const double lo = -0.5 * dt * (neg_lo[j] + neg_lo[j + 1]) - remainder;
    const double up = 0.5 * dt * (hi[j] + hi[j + 1]) + remainder;
    const double margin = outward(std::fabs(lo) + std::fabs(up) + remainder);
    double a = lo - margin, b = up + margin;
    if (g.regimes.surface(k) && a <= speed_hi && b >= speed_lo) {
      a = std::max(a, speed_lo);
      b = std::min(b, speed_hi);
    }
    g.evidence.dz.set(k, Interval::from_bounds(a, b));
  }
}

// Per block: the world boxes once, then the speeds, the vertical increments, and every
// centre and span whose readings contradict max_jerk, with the least |w''| they prove.
void gather_blocks(Gather& g) {
  const std::size_t n = g.m.size();
  WorldVelocityBoxes w;
  BlockMidpoints b;
  std::vector<std::size_t> candidates;
  std::vector<double> scratch[4];
  for (std::size_t start = 0; start < n; start += kStepsPerBlock) {
    const std::size_t end = std::min(n, start + kStepsPerBlock);
    const std::size_t first = start >= kWidestSpan ? start - kWidestSpan : 0;
    const std::size_t last = std::min(n, end + kWidestSpan);
    world_boxes(g.m, g.model, first, last, w);
    gather_speeds(g, w, first, start, end);
    gather_vertical_steps(g, w, first, start, end);
    b.fill(w, last - first);
    for (const std::size_t span : kSpans) {
      if (n <= 2 * span) break;
      candidates.clear();
      suspects(g.m, b, first, std::max(start, span), std::min(end, n - span), span, g.model.max_jerk, scratch, candidates);
      for (const std::size_t k : candidates) {
        double least = 0.0;
        for (int i = 0; i < 3; ++i) least = std::max(least, least_second_derivative(g.m, w, first, i, k, span));
        if (least > g.model.max_jerk) g.evidence.jerks.push_back({k, span, least});
      }
    }
  }
}

// Whether two boxes of a quantity whose rate is at most `rate` cannot both hold dt
// apart: their difference excludes [-rate dt, rate dt].
bool rate_contradicted(const Interval& a, const Interval& b, double rate, double dt_hi) {
  const Interval change = b - a;
  const double reach = mul_up(rate, dt_hi);
  return change.lo() > reach || change.hi() < -reach;
}

// Whether step k's readings may break the rate hull's premise: a DVL component or an
// angle that changes by more than its rate bound allows plus both readings' own bounds
// (which the boxes' radii are never below).
bool rates_suspect(const Mission& m, const SensorModel& model, std::size_t k) {
  const double dt = m.time[k + 1] - m.time[k];
  const double reach_v = model.max_acceleration * dt * (1.0 - 1e-9), reach_a = model.max_attitude_rate * dt * (1.0 - 1e-9);
  const std::vector<double>* dvl[3] = {&m.vx, &m.vy, &m.vz};
  const std::vector<double>* dvl_widths[3] = {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz};
  for (int i = 0; i < 3; ++i) {
    const double a = (*dvl[i])[k], b = (*dvl[i])[k + 1];
    const std::vector<double>& h = *dvl_widths[i];
    const double own = h.empty() ? model.dvl_relative * (std::fabs(a) + std::fabs(b)) + 2.0 * model.dvl_absolute : h[k] + h[k + 1];
    if (std::fabs(b - a) - own > reach_v) return true;
  }
  const std::vector<double>* angles[3] = {&m.roll, &m.pitch, &m.heading};
  const std::vector<double>* angle_widths[3] = {&m.half_widths.roll, &m.half_widths.pitch, &m.half_widths.heading};
  const double bounds[3] = {model.roll, model.pitch, model.heading};
  constexpr double kTurn = 2.0 * std::numbers::pi;
  for (int i = 0; i < 3; ++i) {
    double change = std::fabs((*angles[i])[k + 1] - (*angles[i])[k]);
    if (i == 2 && change > std::numbers::pi) change = std::fabs(change - kTurn * std::round(change / kTurn));
    const std::vector<double>& h = *angle_widths[i];
    const double own = h.empty() ? 2.0 * bounds[i] : h[k] + h[k + 1];
    if (change - own > reach_a) return true;
  }
  return false;
}

// The steps whose readings break the rate hull's premise: a DVL component beyond
// max_acceleration, an angle beyond max_attitude_rate.
void gather_rates(Gather& g) {
  const SensorBoxes boxes(g.m, g.model, zone_frame(g.m));
  const double acceleration = g.model.max_acceleration, rate = g.model.max_attitude_rate;
  for (std::size_t k = 0; k + 1 < g.m.size(); ++k) {
    if (!rates_suspect(g.m, g.model, k)) continue;
    const SensorBoxes::SampleBoxes p = boxes.sample(k), q = boxes.sample(k + 1);
    const double dt_hi = sub_up(g.m.time[k + 1], g.m.time[k]);
    bool contradicted = false;
    for (int i = 0; i < 3; ++i) contradicted = contradicted || rate_contradicted(p.velocity[i], q.velocity[i], acceleration, dt_hi);
    contradicted = contradicted || rate_contradicted(p.roll, q.roll, rate, dt_hi) ||
                   rate_contradicted(p.pitch, q.pitch, rate, dt_hi) ||
                   rate_contradicted(p.heading, boxes.next_heading(q, k), rate, dt_hi);
    if (contradicted) g.evidence.rate_steps.push_back(k);
  }
}

// The largest jerk bound of steps [first, last).
double window_jerk(const StepRegimes& regimes, const SensorModel& model, std::size_t first, std::size_t last) {
  for (std::size_t k = first; k < last; ++k)
    if (regimes.surface(k)) return model.surface_max_jerk;
  return model.max_jerk;
}

}  // namespace

Interval speed_step(const Mission& mission, std::size_t k, double v) {
  const double reach = v * (mission.time[k + 1] - mission.time[k]);
  return Interval::from_bounds(-reach - outward(reach), reach + outward(reach));
}

ReadingsEvidence gather_evidence(const Mission& mission, const SensorModel& model, const StepRegimes& regimes) {
  ReadingsEvidence evidence(mission.size() > 0 ? mission.size() - 1 : 0);
  Gather g{mission, model, regimes, evidence};
  gather_blocks(g);
  gather_rates(g);
  return evidence;
}

void flag_contradicted(const ReadingsEvidence& evidence, const SensorModel& model, const StepRegimes& surface,
                       std::vector<std::uint8_t>& flags) {
  for (const ReadingsEvidence::Jerk& j : evidence.jerks)
    if (j.least > window_jerk(surface, model, j.centre - j.span, j.centre + j.span))
      for (std::size_t s = j.centre - j.span; s < j.centre + j.span; ++s) flags[s] |= StepRegimes::kFallback;
  for (const std::size_t k : evidence.rate_steps)
    if (!surface.surface(k)) flags[k] |= StepRegimes::kFallback;
}

void report_speeds(const ReadingsEvidence& evidence, const Mission& mission, const SensorModel& model,
                   const StepRegimes& surface, StepRegimeReport& report) {
  const double at_surface = mul_up(model.surface_max_speed, model.surface_max_speed);
  for (const ReadingsEvidence::Speed& s : evidence.speeds) {
    const std::size_t k = s.sample;
    const bool surface_sample = (k > 0 && surface.surface(k - 1)) || (k + 1 < mission.size() && surface.surface(k));
    if (surface_sample && s.least_squared <= at_surface) continue;
    ++report.speed_exceeded;
    if (report.speed_exceeded_times.size() < StepRegimeReport::kShownTimes) report.speed_exceeded_times.push_back(mission.time[k]);
  }
}

}  // namespace gesmi
