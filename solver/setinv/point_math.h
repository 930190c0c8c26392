#pragma once
// Point (double) overloads of the interval functions, so that one model templated on
// the number type compiles for double and for Interval (seed 000 section 3, seed 004
// section II). Inside namespace gesmi an unqualified sqr(x) or sin(x) would otherwise
// find the Interval overloads and silently convert a double into an interval.

#include <cmath>
#include <type_traits>

#include "solver/interval/interval.h"
#include "solver/interval/interval_bool.h"

namespace gesmi {

inline double sqr(double x) { return x * x; }
inline double sqrt(double x) { return std::sqrt(x); }
inline double abs(double x) { return std::fabs(x); }
inline double min(double x, double y) { return x < y ? x : y; }
inline double max(double x, double y) { return x < y ? y : x; }
inline double sin(double x) { return std::sin(x); }
inline double cos(double x) { return std::cos(x); }
inline double atan2(double y, double x) { return std::atan2(y, x); }
inline double exp(double x) { return std::exp(x); }

/// Membership of a point in an interval (the Interval form returns an IBool).
inline bool member(double x, const Interval& y) { return y.contains(x); }

/// The Boolean type that goes with a number type: bool for points, IBool for boxes.
template <class T>
using BoolOf = std::conditional_t<std::is_same_v<T, Interval>, IBool, bool>;

template <class T>
inline constexpr bool is_interval_v = std::is_same_v<T, Interval>;

/// "No echo": +inf on points; on intervals [DBL_MAX, +inf], a representable set that
/// lies above every finite measurement (an Interval cannot hold +inf alone).
template <class T>
T far_away() {
  if constexpr (is_interval_v<T>)
    return Interval::from_bounds(std::numeric_limits<double>::max(), kInf);
  else
    return kInf;
}

}  // namespace gesmi
