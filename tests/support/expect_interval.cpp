#include "tests/support/expect_interval.h"

#include <cstdio>

namespace gesmi::test {

std::string to_string(const Interval& x) {
  if (x.is_empty()) return "[empty]";
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "[%.17g, %.17g]", x.lo(), x.hi());
  return buffer;
}

::testing::AssertionResult contains(const Interval& outer, const Interval& inner) {
  if (outer.is_superset(inner)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << to_string(outer) << " does not contain " << to_string(inner);
}

::testing::AssertionResult contains_point(const Interval& outer, double x) {
  if (outer.contains(x)) return ::testing::AssertionSuccess();
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return ::testing::AssertionFailure() << to_string(outer) << " does not contain " << buffer;
}

}  // namespace gesmi::test
