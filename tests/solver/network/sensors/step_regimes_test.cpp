// The step regimes and the readings' check (solver/network/sensors/step_regimes.h), against
// truths built here in closed form: a world velocity w(t) made of sines whose second
// derivative is known exactly, a heading that turns smoothly, and readings at the
// corners of their boxes (alternating signs: the largest noise a divided difference
// can see). The true displacement over a step is the integral of w in long double.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "solver/interval/rounding.h"
#include "solver/network/sensors/sensor_priors.h"
#include "solver/network/sensors/step_regimes.h"

namespace gesmi {
namespace {

constexpr long double kPiLong = std::numbers::pi_v<long double>;

// A sine a sin(omega t + phase) and its integral from 0.
struct Sine {
  long double a, omega, phase;
  long double at(long double t) const { return a * std::sin(omega * t + phase); }
  long double integral(long double t) const { return a / omega * (std::cos(phase) - std::cos(omega * t + phase)); }
  long double second_derivative_bound() const { return std::fabs(a) * omega * omega; }
};

// A vertical burst over [start, start + tau]: w_z = A (sin(2 pi u) / 2 - sin(4 pi u) / 4),
// u = (t - start) / tau; its second derivative is A / tau² (-2 pi² sin 2 pi u + 4 pi² sin 4 pi u).
struct Burst {
  long double start = -1.0L, tau = 1.0L, amplitude = 0.0L;
  long double at(long double t) const {
    const long double u = (t - start) / tau;
    if (u <= 0.0L || u >= 1.0L) return 0.0L;
    return amplitude * (std::sin(2 * kPiLong * u) / 2 - std::sin(4 * kPiLong * u) / 4);
  }
  long double integral(long double t) const {
    const long double u = std::clamp((t - start) / tau, 0.0L, 1.0L);
    return amplitude * tau *
           ((1 - std::cos(2 * kPiLong * u)) / (4 * kPiLong) - (1 - std::cos(4 * kPiLong * u)) / (16 * kPiLong));
  }
};

struct Truth {
  Sine w[3];
  long double base[3] = {1.2L, 0.3L, 0.0L};
  Sine turn{0.4L, 0.05L, 0.0L};  // heading = 0.3 + turn: |heading rate| <= 0.02 rad/s
  Burst burst;
  long double velocity(int i, long double t) const { return base[i] + w[i].at(t) + (i == 2 ? burst.at(t) : 0.0L); }
  long double position(int i, long double t) const {
    return base[i] * t + w[i].integral(t) + (i == 2 ? burst.integral(t) : 0.0L);
  }
  long double heading(long double t) const { return 0.3L + turn.at(t); }
};

// Sines whose second derivatives reach 99.9 % of `jerk` on each axis; their derivatives
// (at most 0.999 jerk / 7 = 0.143 m/s² for a jerk of 1 m/s³, plus 0.025 m/s² of the turn)
// stay within max_acceleration (0.2 m/s²), so the rate hull's premise holds too.
Truth smooth_truth(long double jerk) {
  Truth truth;
  const long double omegas[3] = {7.0L, 8.0L, 9.0L};
  for (int i = 0; i < 3; ++i)
    truth.w[i] = Sine{0.999L * jerk / (omegas[i] * omegas[i]), omegas[i], 0.3L * i};
  return truth;
}

// Readings at 10 Hz over `seconds`, 10 m deep, at the corners of the model's boxes
// with alternating signs; roll and pitch zero.
Mission mission_of(const Truth& truth, double seconds) {
  Mission m;
  const std::size_t n = static_cast<std::size_t>(seconds * 10.0) + 1;
  for (std::size_t k = 0; k < n; ++k) {
    const long double t = 0.1L * static_cast<long double>(k);
    const double sign = k % 2 == 0 ? 1.0 : -1.0;
    const long double psi = truth.heading(t);
    const long double wn = truth.velocity(0, t), we = truth.velocity(1, t), wd = truth.velocity(2, t);
    // Body = Rz(psi)^T w (roll and pitch zero).
    const long double body[3] = {std::cos(psi) * wn + std::sin(psi) * we, -std::sin(psi) * wn + std::cos(psi) * we, wd};
    m.time.push_back(static_cast<double>(t));
    m.roll.push_back(0.999 * m.model.roll * sign);
    m.pitch.push_back(-0.999 * m.model.pitch * sign);
    m.heading.push_back(static_cast<double>(psi) + 0.999 * m.model.heading * sign);
    std::vector<double>* dvl[3] = {&m.vx, &m.vy, &m.vz};
    for (int i = 0; i < 3; ++i) {
      // Inside reading ± (a |reading| + b): |error| <= (a |v| + b) / (1 + a), at 99.9 % of it.
      const double v = static_cast<double>(body[i]);
      const double bound = (m.model.dvl_relative * std::fabs(v) + m.model.dvl_absolute) / (1.0 + m.model.dvl_relative);
      dvl[i]->push_back(v + 0.999 * bound * (i == 1 ? -sign : sign));
    }
    m.depth.push_back(10.0 + static_cast<double>(truth.position(2, t)));
    m.altitude.push_back(10.0);
  }
  return m;
}

// Steps whose prior increment misses the true displacement.
std::size_t missed_steps(const Mission& m, const Truth& truth, const StepRegimes& regimes) {
  const SensorPriors priors = frameless_sensor_priors(m, m.model, regimes);
  const std::vector<Interval>* increments[3] = {&priors.dx, &priors.dy, &priors.dz};
  std::size_t missed = 0;
  for (std::size_t k = 0; k + 1 < m.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const long double d = truth.position(i, m.time[k + 1]) - truth.position(i, m.time[k]);
      const Interval& box = (*increments[i])[k];
      if (!(box.lo() <= d + 1e-12L && d - 1e-12L <= box.hi())) {
        ++missed;
        break;
      }
    }
  return missed;
}

TEST(StepRegimes, NoContradictionIsClaimedForATruthWithinTheJerkBound) {
  // The jerk at 99.9 % of max_jerk and readings at the corners of their boxes: the
  // divided differences' intervals must still meet [-J, J] everywhere.
  for (const long double jerk : {1.0L, 0.5L}) {
    Truth truth = smooth_truth(jerk);
    const Mission m = mission_of(truth, 300.0);
    const StepRegimes regimes = classify_steps(m, m.model);
    EXPECT_EQ(regimes.report().fallback_steps, 0u) << "jerk " << static_cast<double>(jerk);
    EXPECT_EQ(regimes.report().surface_steps, 0u);
    EXPECT_EQ(regimes.report().speed_exceeded, 0u);
    EXPECT_EQ(missed_steps(m, truth, regimes), 0u);
  }
}

TEST(StepRegimes, ABurstBeyondTheJerkBoundFallsBackAndTheStepsKeepTheTruth) {
  Truth truth = smooth_truth(0.5L);
  // 10 m/s³ at its peak: the profile's largest second derivative per unit amplitude
  // over 1 s is about 48.4 (sampled finely below).
  long double peak = 0.0L;
  for (int j = 0; j <= 100000; ++j) {
    const long double x = 2 * kPiLong * j / 100000;
    peak = std::max(peak, std::fabs(-2 * kPiLong * kPiLong * std::sin(x) + 4 * kPiLong * kPiLong * std::sin(2 * x)));
  }
  truth.burst = Burst{100.05L, 1.0L, 10.0L / peak};
  const Mission m = mission_of(truth, 200.0);
  const StepRegimes regimes = classify_steps(m, m.model);
  ASSERT_GT(regimes.report().fallback_steps, 0u);
  ASSERT_FALSE(regimes.report().fallback_times.empty());
  // The first run starts within the burst's window and the widest span around it.
  EXPECT_GE(regimes.report().fallback_times.front(), 100.05 - 1.7);
  EXPECT_LE(regimes.report().fallback_times.front(), 101.05);
  EXPECT_EQ(missed_steps(m, truth, regimes), 0u);
  // Without the fall-back the burst's steps lose the truth: the check is what holds it.
  EXPECT_GT(missed_steps(m, truth, StepRegimes{}), 0u);
}

// Depth readings of a robot held at `depth`, alternately at the top and the bottom of
// what their bound allows (every box still holds the truth).
void alternate_depth_readings(Mission& m, double depth) {
  for (std::size_t k = 0; k < m.size(); ++k) {
    const double sign = k % 2 == 0 ? 1.0 : -1.0;
    // |error| <= (d + e |depth|) / (1 + e) keeps depth inside reading ± (d + e |reading|).
    const double bound = (m.model.depth_absolute + m.model.depth_relative * depth) / (1.0 + m.model.depth_relative);
    m.depth[k] = depth + 0.999 * bound * sign;
  }
}

TEST(StepRegimes, TheDepthChainDecidesWhichStepsMayReachTheSurface) {
  Truth truth = smooth_truth(0.5L);
  for (Sine& w : truth.w) w.a = 0.0L;  // level: the vertical increments are about 0
  Mission m = mission_of(truth, 20.0);
  // At 3 m, readings alternately 4.75 and 1.25 m: each shallow reading's box reaches
  // -0.5 m, but the deep ones' boxes start at 2.30 m, and nothing moves the robot
  // between them: no step can reach the 1 m layer.
  alternate_depth_readings(m, 3.0);
  const long double deep = m.depth[0] - (1.5L + 0.2L * m.depth[0]);
  ASSERT_GT(deep, 2.2L);
  EXPECT_EQ(classify_steps(m, m.model).report().surface_steps, 0u);
  // At 0.8 m every box reaches the surface, and so does every step.
  alternate_depth_readings(m, 0.8);
  EXPECT_EQ(classify_steps(m, m.model).report().surface_steps, m.size() - 1);
  // At 3 m with a fix at t = 15.05 s: the one step that holds it.
  alternate_depth_readings(m, 3.0);
  m.gps_time = {15.05};
  const StepRegimes regimes = classify_steps(m, m.model);
  EXPECT_EQ(regimes.report().surface_steps, 1u);
  EXPECT_TRUE(regimes.surface(150));
  // A fix on a sample: both steps around it.
  m.gps_time = {m.time[40]};
  const StepRegimes on_sample = classify_steps(m, m.model);
  EXPECT_EQ(on_sample.report().surface_steps, 2u);
  EXPECT_TRUE(on_sample.surface(39) && on_sample.surface(40));
}

TEST(StepRegimes, SurfaceStepsTakeTheSurfaceJerkAndSpeed) {
  Truth truth = smooth_truth(0.5L);
  Mission m = mission_of(truth, 10.0);
  std::vector<std::uint8_t> flags(m.size() - 1, 0);
  flags[3] = StepRegimes::kSurface;
  flags[5] = StepRegimes::kFallback;
  const StepRegimes regimes(flags);
  const SensorPriors priors = frameless_sensor_priors(m, m.model, regimes);
  const SensorPriors submerged = frameless_sensor_priors(m, m.model, StepRegimes{});
  // Surface: the trapezoid widened by (J_surface - J) dt³ / 12 on each side, never beyond
  // the speed box; fall-back: dt times the submerged speed bound.
  const double extra = (m.model.surface_max_jerk - m.model.max_jerk) * 1e-3 / 12.0;
  EXPECT_NEAR(priors.dz[3].width() - submerged.dz[3].width(), 2.0 * extra, 1e-9);
  EXPECT_NEAR(priors.dx[5].lo(), -0.1 * m.model.max_speed, 1e-12);
  EXPECT_NEAR(priors.dx[5].hi(), 0.1 * m.model.max_speed, 1e-12);
  EXPECT_EQ(priors.dx[4].lo(), submerged.dx[4].lo());
}

}  // namespace
}  // namespace gesmi
