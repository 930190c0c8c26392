#pragma once
// Assertions on intervals shared by the tests.

#include <gtest/gtest.h>

#include <string>

#include "solver/interval/interval.h"

namespace gesmi::test {

std::string to_string(const Interval& x);

/// outer contains inner (every point), with a readable failure message.
::testing::AssertionResult contains(const Interval& outer, const Interval& inner);
::testing::AssertionResult contains_point(const Interval& outer, double x);

}  // namespace gesmi::test
