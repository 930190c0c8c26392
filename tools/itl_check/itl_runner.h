#pragma once
// Runs one ITL test against gesmi's interval library.
//
// A bare-interval test of an implemented operation passes when every interval
// result of the library CONTAINS the expected one (IEEE 1788 tightest results,
// the library rounds outward) and every number or Boolean result is equal.
// Decorated tests, tests expecting an exception and unimplemented operations
// are skipped.

#include <string>

#include "tools/itl_check/itl_parser.h"

namespace gesmi::itl {

enum class Outcome { passed, failed, skipped };

struct TestResult {
  Outcome outcome = Outcome::skipped;
  std::string message;  // why it failed or was skipped
  /// Excess width of the library's intervals over the expected ones, in ulps
  /// (steps between doubles; +inf when an expected finite bound came back
  /// infinite or an expected empty set came back non-empty). Negative when the
  /// test has no interval result.
  double excess_ulps = -1.0;
};

TestResult run(const Test& test);

/// Number of steps between consecutive doubles from a up to b (negative when
/// b < a); +inf when they differ and one of them is infinite.
double ulp_distance(double a, double b);

std::string to_string(const Value& value);

}  // namespace gesmi::itl
