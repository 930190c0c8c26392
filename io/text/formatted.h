#pragma once
// printf's formatting into a std::string, for the lines of the text summaries.

#include <cstdio>
#include <string>

namespace gesmi::io {

/// The text printf would print, cut at 511 characters.
template <class... Values>
std::string formatted(const char* pattern, Values... values) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

}  // namespace gesmi::io
