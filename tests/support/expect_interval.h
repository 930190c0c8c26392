#pragma once
// Assertions on intervals shared by the tests.

#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <string>

#include "solver/interval/interval.h"

namespace gesmi::test {

/// The largest and the smallest positive doubles, and pi to long double precision, for
/// expected bounds.
inline constexpr double kMax = std::numeric_limits<double>::max();
inline constexpr double kTiny = std::numeric_limits<double>::denorm_min();
inline constexpr long double kPiLong = std::numbers::pi_v<long double>;

/// Whether x holds a value computed in long double (compared exactly, not rounded to double).
inline bool holds(const Interval& x, long double value) { return x.lo() <= value && value <= x.hi(); }

std::string to_string(const Interval& x);

/// outer contains inner (every point), with a readable failure message.
::testing::AssertionResult contains(const Interval& outer, const Interval& inner);
::testing::AssertionResult contains_point(const Interval& outer, double x);

}  // namespace gesmi::test
