// The sensor enclosures in blocks (sensor_kernel.h). This file is compiled with
// -frounding-math (solver/CMakeLists.txt). Each block runs two passes: libmvec's sin
// and cos (vector_sin_cos.h) in the caller's (round to nearest) mode, then the
// interval arithmetic in a non-inlined function between the two mode switches of
// UpwardRounding, where an upper bound is a plain operation and a lower bound is kept
// negated: x lies in [-n, h] and both n and h are upper bounds, computed by plain
// rounded-up operations.

#include "solver/network/sensors/sensor_kernel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "solver/interval/rounding.h"
#include "solver/interval/upward_rounding.h"
#include "solver/model/vector_sin_cos.h"
#include "solver/network/sensors/sensor_boxes.h"

namespace gesmi {
namespace {

constexpr std::size_t kBlock = 512;
/// Widest angle box (half-width, rad) the narrow-angle sin/cos form takes, as sin_cos().
constexpr double kNarrowAngle = 0.05;
/// x in [-n, h]; both bounds are rounded up.
struct Bounds {
  double n, h;
};

// Upward mode only (the functions below are inlined into the non-inlined loops).
inline Bounds add(Bounds x, Bounds y) { return {x.n + y.n, x.h + y.h}; }
inline Bounds sub(Bounds x, Bounds y) { return {x.n + y.h, x.h + y.n}; }
/// The four endpoint products, each rounded up, for both bounds: branch-free, so that
/// the loops vectorise. With x = [a, b] = [-x.n, x.h] and y = [c, d] = [-y.n, y.h]:
/// hi = max(ac, ad, bc, bd) and -lo = max(-ac, -ad, -bc, -bd), where a negation is exact.
inline Bounds mul(Bounds x, Bounds y) {
  const double hi = std::max(std::max(x.n * y.n, x.h * y.h), std::max((-x.n) * y.h, (-x.h) * y.n));
  const double neg_lo = std::max(std::max(x.n * y.h, x.h * y.n), std::max((-x.n) * y.n, (-x.h) * y.h));
  return {neg_lo, hi};
}
inline double mag(Bounds x) { return std::max(x.n, x.h); }

/// One block's readings, filled in round-to-nearest mode: libmvec's values of sin and cos of
/// each angle reading, the angle boxes' half-widths, the velocity readings and their
/// per-sample half-widths (when the mission gives them).
struct BlockInputs {
  std::array<std::array<double, kBlock>, 3> sin, cos, radius, velocity, velocity_bound;
};

/// Sine and cosine of every angle in [m - r, m + r], from s = sin m and c = cos m
/// (libmvec, within kVectorLibmRelative |y| + kVectorLibmAbsolute of the true y): sin x
/// lies in sin m ± (|cos m| r + r²/2), and cos x in cos m ± (|sin m| r + r²/2) (Taylor
/// with a Lagrange remainder, |sin''|, |cos''| <= 1).
inline void narrow_sin_cos(double s, double c, double r, Bounds& sin_box, Bounds& cos_box) {
  const double s_error = std::fabs(s) * kVectorLibmRelative + kVectorLibmAbsolute;
  const double c_error = std::fabs(c) * kVectorLibmRelative + kVectorLibmAbsolute;
  const double quadratic = 0.5 * (r * r);
  const double sin_spread = s_error + ((std::fabs(c) + c_error) * r + quadratic);
  const double cos_spread = c_error + ((std::fabs(s) + s_error) * r + quadratic);
  sin_box = {std::min(1.0, (-s) + sin_spread), std::min(1.0, s + sin_spread)};
  cos_box = {std::min(1.0, (-c) + cos_spread), std::min(1.0, c + cos_spread)};
}

struct VelocityModel {
  double relative, absolute;  // bound = relative |v| + absolute, unless given per sample
  double frame;               // plus frame times the box's largest |vx| + |vy| + |vz|, on every component
  bool per_sample[3];
};

/// R v = Rz(psi) Ry(theta) Rx(phi) v for samples [0, n) of a block, as body_to_world
/// (three plane rotations), into out[i][offset + j].
[[gnu::noinline]] void rotate_block(const BlockInputs& in, std::size_t n, const VelocityModel& vm,
                                    WorldVelocityBoxes& out, std::size_t offset) {
  const UpwardRounding upward;
  for (std::size_t j = 0; j < n; ++j) {
    Bounds sine[3], cosine[3], v[3];
    for (int a = 0; a < 3; ++a) narrow_sin_cos(in.sin[a][j], in.cos[a][j], in.radius[a][j], sine[a], cosine[a]);
    double own[3], largest = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double speed = std::fabs(in.velocity[i][j]);
      own[i] = vm.per_sample[i] ? in.velocity_bound[i][j] : vm.relative * speed + vm.absolute;
      largest = largest + (speed + own[i]);
    }
    const double frame = vm.frame * largest;
    for (int i = 0; i < 3; ++i) {
      const double value = in.velocity[i][j];
      const double bound = own[i] + frame;
      v[i] = {(-value) + bound, value + bound};
    }
    // Rx(phi), then Ry(theta), then Rz(psi).
    const Bounds y1 = sub(mul(cosine[0], v[1]), mul(sine[0], v[2]));
    const Bounds z1 = add(mul(sine[0], v[1]), mul(cosine[0], v[2]));
    const Bounds x2 = add(mul(cosine[1], v[0]), mul(sine[1], z1));
    const Bounds z2 = sub(mul(cosine[1], z1), mul(sine[1], v[0]));
    const Bounds x3 = sub(mul(cosine[2], x2), mul(sine[2], y1));
    const Bounds y3 = add(mul(sine[2], x2), mul(cosine[2], y1));
    const Bounds w[3] = {x3, y3, z2};
    for (int i = 0; i < 3; ++i) {
      out.neg_lo[i][offset + j] = w[i].n;
      out.hi[i][offset + j] = w[i].h;
    }
  }
}

/// Fills a block's inputs for samples [first, first + n) in the caller's rounding mode;
/// samples the narrow-angle form cannot take get harmless values and are listed.
void read_block(const Mission& m, const SensorModel& model, std::size_t first, std::size_t n, BlockInputs& in,
                std::vector<std::size_t>& skipped) {
  const std::vector<double>* angles[3] = {&m.roll, &m.pitch, &m.heading};
  const std::vector<double>* angle_widths[3] = {&m.half_widths.roll, &m.half_widths.pitch, &m.half_widths.heading};
  const double model_widths[3] = {model.roll, model.pitch, model.heading};
  const std::vector<double>* velocities[3] = {&m.vx, &m.vy, &m.vz};
  const std::vector<double>* velocity_widths[3] = {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz};
  // (readings beyond kVectorLibmLargest, NaN included, are skipped below: their values
  // do not matter)
  for (int a = 0; a < 3; ++a) sin_cos_many(angles[a]->data() + first, n, in.sin[a].data(), in.cos[a].data());
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = first + j;
    bool narrow = true;
    for (int a = 0; a < 3; ++a) {
      const double angle = (*angles[a])[k];
      const double r = angle_widths[a]->empty() ? model_widths[a] : (*angle_widths[a])[k];
      narrow = narrow && std::fabs(angle) < kVectorLibmLargest && r >= 0.0 && r <= kNarrowAngle;
      in.radius[a][j] = r;
    }
    for (int i = 0; i < 3; ++i) {
      const double value = (*velocities[i])[k];
      const double bound = velocity_widths[i]->empty() ? 0.0 : (*velocity_widths[i])[k];
      narrow = narrow && std::isfinite(value) && std::fabs(value) < 1e100 && bound >= 0.0 && bound < 1e100;
      in.velocity[i][j] = value;
      in.velocity_bound[i][j] = bound;
    }
    if (narrow) continue;
    skipped.push_back(k);
    for (int a = 0; a < 3; ++a) {
      in.sin[a][j] = 0.0;
      in.cos[a][j] = 1.0;
      in.radius[a][j] = 0.0;
      in.velocity[a][j] = 0.0;
      in.velocity_bound[a][j] = 0.0;
    }
  }
}

VelocityModel velocity_model(const Mission& m, const SensorModel& model) {
  // v ± (a |v| + b) as SensorBoxes::velocity() without frame margins: the depth's alone.
  return {model.dvl_relative,
          model.dvl_absolute,
          m.depth_scale_margin,
          {!m.half_widths.vx.empty(), !m.half_widths.vy.empty(), !m.half_widths.vz.empty()}};
}

void resize(WorldVelocityBoxes& w, std::size_t n) {
  for (int i = 0; i < 3; ++i) {
    w.neg_lo[i].resize(n);
    w.hi[i].resize(n);
  }
}

/// The steps' increments from the world velocity boxes of samples [first, last + 1)
/// (index k - first), as SensorBoxes::step_increment.
[[gnu::noinline]] void step_block(const double* time, const WorldVelocityBoxes& w, std::size_t first,
                                  std::size_t last, StepModel step_model, double jerk,
                                  const StepIncrementArrays& out) {
  const UpwardRounding upward;
  Interval* d[3] = {out.dx, out.dy, out.dz};
  for (std::size_t k = first; k < last; ++k) {
    const std::size_t j = k - first;
    const Bounds dt{time[k] - time[k + 1], time[k + 1] - time[k]};
    Bounds a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = {w.neg_lo[i][j], w.hi[i][j]};
      b[i] = {w.neg_lo[i][j + 1], w.hi[i][j + 1]};
    }
    Bounds inc[3];
    double turn_north, turn_east;
    if (step_model == StepModel::sample) {
      // dt times sample k's world velocity.
      for (int i = 0; i < 3; ++i) inc[i] = mul(dt, a[i]);
      turn_north = dt.h * mag(a[0]);
      turn_east = dt.h * mag(a[1]);
    } else {
      // Trapezoid: dt/2 (w_k + w_k+1) ± J dt³ / 12.
      const Bounds half{dt.n * 0.5, dt.h * 0.5};
      const double remainder = jerk * (((dt.h * dt.h) * dt.h) / 12.0);
      for (int i = 0; i < 3; ++i) {
        inc[i] = mul(half, add(a[i], b[i]));
        inc[i] = {inc[i].n + remainder, inc[i].h + remainder};
      }
      turn_north = half.h * (mag(a[0]) + mag(b[0]));
      turn_east = half.h * (mag(a[1]) + mag(b[1]));
    }
    for (int i = 0; i < 3; ++i) d[i][k] = Interval::from_bounds(-inc[i].n, inc[i].h);
    // The conversion to float rounds up too; beyond the float range it is undefined, so
    // those (absurd) sensitivities are infinite.
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    out.turn_north[k] = turn_north <= kFloatMax ? static_cast<float>(turn_north) : std::numeric_limits<float>::infinity();
    out.turn_east[k] = turn_east <= kFloatMax ? static_cast<float>(turn_east) : std::numeric_limits<float>::infinity();
  }
}

// x ± r per sample: the upper bound x + r rounded up, the lower -(r - x) rounded up.
// Zeros are signed as sub_down() signs them (round to nearest, then a step down): an
// exact cancellation is +0, hence 0 - (r - x); and x - 0 is x itself, -0 included.
[[gnu::noinline]] void depth_block(const double* depth, const double* given, std::size_t n, double absolute,
                                   double relative, Interval* out) {
  const UpwardRounding upward;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = depth[k], r = given ? given[k] : absolute + relative * std::fabs(x);
    out[k] = Interval(r == 0.0 ? x - r : 0.0 - (r - x), x + r);
  }
}

}  // namespace

void depth_boxes(const Mission& mission, const SensorModel& model, Interval* out) {
  const std::vector<double>& given = mission.half_widths.depth;
  depth_block(mission.depth.data(), given.empty() ? nullptr : given.data(), mission.size(), model.depth_absolute,
              model.depth_relative, out);
}

void world_velocity_boxes(const Mission& mission, const SensorModel& model, std::size_t first, std::size_t last,
                          WorldVelocityBoxes& out) {
  resize(out, last - first);
  out.skipped.clear();
  const VelocityModel vm = velocity_model(mission, model);
  BlockInputs in;
  for (std::size_t start = first; start < last; start += kBlock) {
    const std::size_t n = std::min(kBlock, last - start);
    read_block(mission, model, start, n, in, out.skipped);
    rotate_block(in, n, vm, out, start - first);
  }
}

std::vector<std::size_t> kernel_step_increments(const Mission& mission, const SensorModel& model, std::size_t first,
                                                std::size_t last, const StepIncrementArrays& out,
                                                const StepRegimes& regimes) {
  std::vector<std::size_t> left;
  WorldVelocityBoxes w;
  for (std::size_t start = first; start < last; start += kBlock) {
    const std::size_t end = std::min(start + kBlock, last);
    world_velocity_boxes(mission, model, start, end + 1, w);
    step_block(mission.time.data(), w, start, end, model.step_model, model.max_jerk, out);
    // Steps touching a skipped sample, steps of another regime, and trapezoid steps
    // whose rate hull may cut.
    const std::size_t before = left.size();
    for (const std::size_t k : w.skipped) {
      if (k > start) left.push_back(k - 1);
      if (k < end) left.push_back(k);
    }
    for (std::size_t k = start; k < end; ++k)
      if (regimes.special(k)) left.push_back(k);
    if (model.step_model == StepModel::trapezoid)
      for (std::size_t k = start; k < end; ++k)
        if (trapezoid_takes_rate_hull(model, sub_up(mission.time[k + 1], mission.time[k])))
          left.push_back(k);
    std::sort(left.begin() + static_cast<std::ptrdiff_t>(before), left.end());
    left.erase(std::unique(left.begin() + static_cast<std::ptrdiff_t>(before), left.end()), left.end());
  }
  return left;
}

}  // namespace gesmi
