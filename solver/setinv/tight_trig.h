#pragma once
// Sine and cosine for the localization models, on points and boxes: the interval
// versions are the core's (tight also when an end point is an extremum, e.g.
// cos([0, 0.05]) = [0.99875, 1]); the double versions are libm's. One name for both,
// so that a model templated on the number type calls tight_cos(theta) either way.

#include <cmath>

#include "solver/interval/interval.h"

namespace gesmi {

inline Interval tight_cos(const Interval& x) { return cos(x); }
inline Interval tight_sin(const Interval& x) { return sin(x); }
inline double tight_cos(double x) { return std::cos(x); }
inline double tight_sin(double x) { return std::sin(x); }

}  // namespace gesmi
