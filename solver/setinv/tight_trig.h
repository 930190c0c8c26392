#pragma once
// Sine and cosine of intervals for the localization models. The interval core's
// cos([0, 0.05]) is [-1, 1]: it decides extrema from the sign of the derivative at
// the end points and gives up when that sign is 0, which happens exactly at
// theta = 0, a bisection point of every prior [-pi, pi]. These versions decide
// extrema by locating the multiples of pi with the enclosures of pi and 2 pi, and
// widen the libm values at the end points by the same kLibmSteps as the core.
// (tests/solver/setinv/tight_trig_test.cpp keeps a disabled test of the core.)

#include "solver/interval/interval.h"

namespace gesmi {

Interval tight_cos(const Interval& x);
Interval tight_sin(const Interval& x);

/// Point forms, so templated models call one name for both number types.
inline double tight_cos(double x) { return std::cos(x); }
inline double tight_sin(double x) { return std::sin(x); }

}  // namespace gesmi
