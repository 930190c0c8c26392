#pragma once
// The C library's timegm as an independent calendar for the UTC time tests.

#include <cstdint>
#include <ctime>

namespace gesmi::test {

/// Seconds since 1970 of a UTC date and time, by timegm.
inline std::int64_t timegm_seconds(int year, int month, int day, int hour, int minute, int second) {
  std::tm t{};
  t.tm_year = year - 1900;
  t.tm_mon = month - 1;
  t.tm_mday = day;
  t.tm_hour = hour;
  t.tm_min = minute;
  t.tm_sec = second;
  return static_cast<std::int64_t>(timegm(&t));
}

}  // namespace gesmi::test
