#include "tools/gesmi/json_writer.h"

#include <cmath>
#include <cstdio>

namespace gesmi::cli {

std::string json_number(double x) {
  if (std::isnan(x)) return "null";
  if (x == kInf) return "\"inf\"";
  if (x == -kInf) return "\"-inf\"";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_interval(const Interval& x) {
  if (x.is_empty()) return "null";
  return "[" + json_number(x.lo()) + ", " + json_number(x.hi()) + "]";
}

}  // namespace gesmi::cli
