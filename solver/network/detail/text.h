#pragma once
// Number formatting for the solver's one-line explanations (report text, not
// I/O): std::to_chars, so that solver/ needs no stdio.

#include <charconv>
#include <string>

#include "solver/interval/interval.h"

namespace gesmi::detail {

/// x with `digits` digits after the point.
inline std::string fixed(double x, int digits) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed, digits);
  return std::string(buffer, result.ptr);
}

inline std::string format_interval(const Interval& x) {
  if (x.is_empty()) return "[empty]";
  return "[" + fixed(x.lo(), 2) + ", " + fixed(x.hi(), 2) + "]";
}

inline std::string format_time(double t) { return fixed(t, 1) + " s"; }

}  // namespace gesmi::detail
