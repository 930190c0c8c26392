// The step model's bounds (solver/network/sensors/step_model.h) against velocities of
// bounded second derivative built here: w'' piecewise constant within [-J, J], its
// integrals in closed form in long double. A constant w'' = ±J reaches every bound, so
// the bounds must hold and be reached there. The long double values carry rounding
// errors of about 1e-19 of the velocities' size, which the comparisons allow (1e-16
// of it): far below what any change of the formulas moves.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "solver/network/sensors/step_model.h"

namespace gesmi {
namespace {

// w over [0, dt] from w(0), w'(0), and w'' = acceleration[i] on the i-th of equal pieces.
struct PiecewiseVelocity {
  long double dt, w0, rate0;
  std::vector<long double> acceleration;

  long double piece() const { return dt / static_cast<long double>(acceleration.size()); }
  // The size of the velocities over the step, which the long double errors scale with.
  long double size() const {
    long double largest = 0.0L;
    for (long double c : acceleration) largest = std::max(largest, std::fabs(c));
    return std::fabs(w0) + std::fabs(rate0) * dt + largest * dt * dt;
  }
  // w(s) and its integral over [0, s].
  void at(long double s, long double& w, long double& integral) const {
    w = w0;
    long double rate = rate0;
    integral = 0.0L;
    long double start = 0.0L;
    for (long double c : acceleration) {
      const long double h = std::min(piece(), s - start);
      if (h <= 0.0L) break;
      integral += w * h + rate * h * h / 2.0L + c * h * h * h / 6.0L;
      w += rate * h + c * h * h / 2.0L;
      rate += c * h;
      start += h;
    }
  }
  // The integral over [0, x] of w minus the linear interpolation between w(0) and w(dt).
  long double error_integral(long double x) const {
    long double w_end, unused, w_x, integral;
    at(dt, w_end, unused);
    at(x, w_x, integral);
    return integral - (w0 * x + (w_end - w0) * x * x / (2.0L * dt));
  }
  long double error(long double s) const {
    long double w_end, w_s, unused;
    at(dt, w_end, unused);
    at(s, w_s, unused);
    return w_s - (w0 + (w_end - w0) * s / dt);
  }
};

// value <= bound up to the long double errors of w's computation (of its integral
// when `integral`).
bool below(long double value, double bound, const PiecewiseVelocity& w, bool integral) {
  return value <= bound + 1e-16L * w.size() * (integral ? w.dt : 1.0L);
}

TEST(StepModel, AConstantJerkReachesEveryBound) {
  for (double dt : {0.1, 1.0, 3.7}) {
    for (double jerk : {0.05, 2.0, 10.0}) {
      for (double sign : {-1.0, 1.0}) {
        const PiecewiseVelocity w{dt, 1.3L, -0.4L, {sign * jerk}};
        const long double exact = static_cast<long double>(jerk) * dt * dt * dt / 12.0L;
        const long double trapezoid = w.error_integral(dt);
        EXPECT_NEAR(static_cast<double>(std::fabs(trapezoid)), static_cast<double>(exact), 1e-12 * static_cast<double>(exact));
        const Interval remainder = trapezoid_remainder(Interval(dt), jerk);
        EXPECT_TRUE(below(trapezoid, remainder.hi(), w, true) && below(-trapezoid, -remainder.lo(), w, true)) << dt << " " << jerk;
        EXPECT_LE(remainder.hi(), static_cast<double>(exact) * (1.0 + 1e-12));
        EXPECT_NEAR(trapezoid_remainder_bound(dt, jerk), static_cast<double>(exact), 4e-16 * static_cast<double>(exact));
        const long double middle = std::fabs(w.error(dt / 2.0L));
        const double peak = interpolation_error_peak(dt, jerk);
        EXPECT_TRUE(below(middle, peak, w, false)) << dt << " " << jerk;
        EXPECT_LE(peak, static_cast<double>(middle) * (1.0 + 1e-12));
        for (double x : {0.0, 0.25 * dt, 0.5 * dt, 0.9 * dt, dt}) {
          const double bound = interpolation_error_integral(Interval(dt), Interval(x), jerk).hi();
          const long double value = std::fabs(w.error_integral(x));
          EXPECT_TRUE(below(value, bound, w, true)) << dt << " " << jerk << " " << x;
          EXPECT_LE(bound, static_cast<double>(value) * (1.0 + 1e-12) + 1e-300) << dt << " " << jerk << " " << x;
        }
      }
    }
  }
}

TEST(StepModel, EveryVelocityOfBoundedJerkStaysWithinTheBounds) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double dt = std::exp(2.0 * unit(random));  // 0.14 to 7.4 s
    const double jerk = 10.0 * std::fabs(unit(random));
    PiecewiseVelocity w{dt, 3.0L * unit(random), unit(random), {}};
    const int pieces = 1 + trial % 7;
    for (int i = 0; i < pieces; ++i)
      w.acceleration.push_back(jerk * (trial % 3 == 0 ? (unit(random) < 0 ? -1.0 : 1.0) : unit(random)));
    const Interval remainder = trapezoid_remainder(Interval(dt), jerk);
    const long double trapezoid = w.error_integral(dt);
    ASSERT_TRUE(below(trapezoid, remainder.hi(), w, true) && below(-trapezoid, -remainder.lo(), w, true)) << trial;
    const double x = dt * (0.5 + 0.5 * unit(random));
    ASSERT_TRUE(below(std::fabs(w.error_integral(x)), interpolation_error_integral(Interval(dt), Interval(x), jerk).hi(), w, true))
        << trial;
    ASSERT_TRUE(below(std::fabs(w.error(x)), interpolation_error_peak(dt, jerk), w, false)) << trial;
  }
}

}  // namespace
}  // namespace gesmi
