#pragma once
// The between-sample step model of the trapezoid (docs/model.md, "The step model"): within
// a step of duration dt, the world velocity w is the linear interpolation of its values at
// the two samples plus an error e(s), s the time since the first sample, with
// |e(s)| <= J s (dt - s) / 2 when |w''| <= J (the step regime's jerk bound). Every bound
// that rests on it comes from here; the vectorised sensor kernel (sensor_kernel.cpp)
// computes trapezoid_remainder_bound in its own upward rounding, tested equal.

#include "solver/interval/interval.h"
#include "solver/interval/rounding.h"

namespace gesmi {

/// ± J dt³ / 12: what the integral of w over the step may differ from the trapezoid
/// rule dt/2 (w_k + w_k+1).
inline Interval trapezoid_remainder(const Interval& dt, double jerk) {
  return Interval(-1.0, 1.0) * (pow(dt, 3) / Interval(12.0)) * Interval(jerk);
}

/// J dt³ / 12 in plain arithmetic: a few units in the last place from the true value in
/// round to nearest, for screens that add their own margin.
inline double trapezoid_remainder_bound(double dt, double jerk) { return jerk * (((dt * dt) * dt) / 12.0); }

/// J (dt x² / 4 − x³ / 6), the integral of J s (dt − s) / 2 over [0, x]: how far the
/// displacement over the first x of the step may differ from the interpolation's
/// (0 <= x <= dt; the same with the samples swapped for the last x).
inline Interval interpolation_error_integral(const Interval& dt, const Interval& x, double jerk) {
  return Interval(jerk) * (dt * sqr(x) / Interval(4.0) - pow(x, 3) / Interval(6.0));
}

/// J dt² / 8, rounded up: the largest |e| anywhere in the step (at its middle).
inline double interpolation_error_peak(double dt, double jerk) { return mul_up(jerk, mul_up(0.125, mul_up(dt, dt))); }

}  // namespace gesmi
