#include "solver/sim/extra_motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gesmi {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBurstDuration = 1.0;  // s

// max over x of |-2 pi² sin x + 4 pi² sin 2x|: the burst profile's peak second derivative
// per unit amplitude over a 1 s burst.
double burst_profile_peak() {
  double peak = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    const double x = 2.0 * kPi * i / 20000.0;
    peak = std::max(peak, std::fabs(-2.0 * kPi * kPi * std::sin(x) + 4.0 * kPi * kPi * std::sin(2.0 * x)));
  }
  return peak;
}

}  // namespace

ExtraMotion::ExtraMotion(const SimulationOptions& options) : o_(options) {
  if (o_.bursts <= 0 || o_.burst_jerk <= 0.0) return;
  const double submerged = o_.duration - 2.0 * o_.surface;
  for (int i = 0; i < o_.bursts; ++i) burst_starts_.push_back(o_.surface + (i + 1) * submerged / (o_.bursts + 1));
  burst_amplitude_ = o_.burst_jerk * kBurstDuration * kBurstDuration / burst_profile_peak();
}

bool ExtraMotion::at_surface(double t) const {
  return o_.surface > 0.0 && (t < o_.surface || t > o_.duration - o_.surface);
}

void ExtraMotion::at(double t, Vec3d& displacement, Vec3d& velocity) const {
  displacement = Vec3d::Zero();
  velocity = Vec3d::Zero();
  if (o_.wave_height > 0.0 && at_surface(t)) waves(t, displacement, velocity);
  if (!burst_starts_.empty()) bursts(t, displacement, velocity);
}

void ExtraMotion::waves(double t, Vec3d& displacement, Vec3d& velocity) const {
  // The fade: 1 inside the phase, a half cosine over its last (first) period or less.
  const double ramp = std::min(o_.wave_period, o_.surface);
  double fade = 1.0, fade_rate = 0.0;
  const double before_dive = o_.surface - t, after_surfacing = t - (o_.duration - o_.surface);
  const double into = std::min(before_dive >= 0.0 ? before_dive : after_surfacing, ramp);  // s from the phase's edge
  if (into < ramp) {
    fade = 0.5 * (1.0 - std::cos(kPi * into / ramp));
    // d fade / d into, and d into / dt = -1 before the dive, +1 after surfacing.
    fade_rate = 0.5 * kPi / ramp * std::sin(kPi * into / ramp) * (before_dive >= 0.0 ? -1.0 : 1.0);
  }
  const double a = 0.5 * o_.wave_height, w = 2.0 * kPi / o_.wave_period;
  const double s = std::sin(w * t), c = std::cos(w * t);
  displacement[1] += fade * a * c;  // sway, east
  displacement[2] += fade * a * s;  // heave, down
  velocity[1] += fade_rate * a * c - fade * a * w * s;
  velocity[2] += fade_rate * a * s + fade * a * w * c;
}

void ExtraMotion::bursts(double t, Vec3d& displacement, Vec3d& velocity) const {
  for (const double start : burst_starts_) {
    const double u = (t - start) / kBurstDuration;
    if (u <= 0.0) continue;
    // After a burst its displacement stays: z(1) = 0 by the profile, so nothing is added.
    if (u >= 1.0) continue;
    const double A = burst_amplitude_, x = 2.0 * kPi * u;
    displacement[2] += A * kBurstDuration * ((1.0 - std::cos(x)) / (4.0 * kPi) - (1.0 - std::cos(2.0 * x)) / (16.0 * kPi));
    velocity[2] += A * (0.5 * std::sin(x) - 0.25 * std::sin(2.0 * x));
  }
}

}  // namespace gesmi
