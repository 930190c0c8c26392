#include "io/time/utc_time.h"

#include <charconv>
#include <cmath>

#include <date/date.h>

namespace gesmi::io {
namespace {

constexpr std::int64_t kLatestSeconds = 7258118400;  // 2200-01-01T00:00:00Z

// Exactly `digits` decimal digits at text[at...]; advances `at`.
std::optional<int> fixed_digits(std::string_view text, std::size_t& at, int digits) {
  if (at + static_cast<std::size_t>(digits) > text.size()) return std::nullopt;
  int value = 0;
  for (int i = 0; i < digits; ++i) {
    const char c = text[at + static_cast<std::size_t>(i)];
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
  }
  at += static_cast<std::size_t>(digits);
  return value;
}

bool expect(std::string_view text, std::size_t& at, char c) {
  if (at >= text.size() || text[at] != c) return false;
  ++at;
  return true;
}

ParsedTime failure(std::string reason) { return {std::nullopt, std::move(reason)}; }

// "Z", "±hh:mm", "±hhmm" or "±hh" from text[at] to the end: the offset in seconds.
std::optional<int> zone_offset(std::string_view text, std::size_t at) {
  const std::string_view zone = text.substr(at);
  if (zone == "Z" || zone == "z") return 0;
  if (zone.empty() || (zone[0] != '+' && zone[0] != '-')) return std::nullopt;
  const int sign = zone[0] == '-' ? -1 : 1;
  std::size_t i = 1;
  const auto hours = fixed_digits(zone, i, 2);
  if (!hours) return std::nullopt;
  int minutes = 0;
  if (i < zone.size()) {
    expect(zone, i, ':');
    const auto m = fixed_digits(zone, i, 2);
    if (!m || i != zone.size()) return std::nullopt;
    minutes = *m;
  }
  if (*hours > 23 || minutes > 59) return std::nullopt;
  return sign * (*hours * 3600 + minutes * 60);
}

}  // namespace

std::optional<std::int64_t> days_since_1970(int year, int month, int day) {
  const date::year_month_day ymd{date::year{year}, date::month{static_cast<unsigned>(month)},
                                 date::day{static_cast<unsigned>(day)}};
  if (month < 1 || month > 12 || day < 1 || day > 31 || !ymd.ok()) return std::nullopt;
  return date::sys_days{ymd}.time_since_epoch().count();
}

std::optional<int> parse_utc_offset(std::string_view text) {
  if (text == "UTC" || text == "utc") return 0;
  return zone_offset(text, 0);
}

ParsedTime parse_iso8601(std::string_view text, std::optional<int> default_offset_seconds) {
  const std::string_view shape = "expected an ISO 8601 time YYYY-MM-DDThh:mm:ss[.fff](Z|+hh:mm)";
  std::size_t at = 0;
  const auto year = fixed_digits(text, at, 4);
  if (!year || !expect(text, at, '-')) return failure(std::string(shape));
  const auto month = fixed_digits(text, at, 2);
  if (!month || !expect(text, at, '-')) return failure(std::string(shape));
  const auto day = fixed_digits(text, at, 2);
  if (!day || !(expect(text, at, 'T') || expect(text, at, ' ') || expect(text, at, 't'))) return failure(std::string(shape));
  const auto hour = fixed_digits(text, at, 2);
  if (!hour || !expect(text, at, ':')) return failure(std::string(shape));
  const auto minute = fixed_digits(text, at, 2);
  if (!minute || !expect(text, at, ':')) return failure(std::string(shape));
  const auto second = fixed_digits(text, at, 2);
  if (!second) return failure(std::string(shape));
  double fraction = 0.0;
  if (at < text.size() && (text[at] == '.' || text[at] == ',')) {
    const std::size_t start = at + 1;
    std::size_t end = start;
    while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
    if (end == start) return failure(std::string(shape));
    // "0.<digits>" read by from_chars: the nearest double to the decimal fraction.
    std::string decimal = "0.";
    decimal.append(text.substr(start, end - start));
    std::from_chars(decimal.data(), decimal.data() + decimal.size(), fraction);
    at = end;
  }
  if (*hour > 23 || *minute > 59 || *second > 59)
    return failure("the time of day " + std::string(text.substr(11, 8)) + " does not exist (leap seconds are not accepted)");
  const auto days = days_since_1970(*year, *month, *day);
  if (!days) return failure("the date " + std::string(text.substr(0, 10)) + " does not exist");
  std::optional<int> offset;
  if (at == text.size()) {
    if (!default_offset_seconds)
      return failure("no time zone: end the time with Z (UTC) or an offset like +02:00, or give the map's time a timezone");
    offset = default_offset_seconds;
  } else {
    offset = zone_offset(text, at);
    if (!offset) return failure("bad time zone '" + std::string(text.substr(at)) + "' (expected Z, +hh:mm, +hhmm or +hh)");
  }
  const std::int64_t seconds = *days * 86400 + *hour * 3600 + *minute * 60 + *second - *offset;
  if (seconds < 0 || seconds >= kLatestSeconds) return failure("the time is before 1970 or after 2200");
  // A fraction that rounds to 1.0 (".9999999999999999999") moves to the next second.
  if (fraction >= 1.0) return {UtcTime{seconds + 1, 0.0}, {}};
  return {UtcTime{seconds, fraction}, {}};
}

std::optional<std::int64_t> parse_epoch_utc(std::string_view text, std::string* why) {
  const ParsedTime parsed = parse_iso8601(text);
  if (parsed.time && parsed.time->fraction == 0.0) return parsed.time->seconds;
  if (why) *why = parsed.time ? "the epoch is a whole second" : parsed.error;
  return std::nullopt;
}

ParsedTime parse_epoch_seconds(std::string_view text) {
  // Whole and fractional parts apart: a double of 1.7e9 s keeps only 0.2 µs.
  const std::size_t dot = text.find('.');
  const std::string_view whole = text.substr(0, dot);
  std::int64_t seconds = 0;
  const auto [end, ec] = std::from_chars(whole.data(), whole.data() + whole.size(), seconds);
  // Digits only: "-0.5" would read as 0 and then + 0.5.
  if (whole.empty() || whole.find_first_not_of("0123456789") != std::string_view::npos || ec != std::errc() ||
      end != whole.data() + whole.size())
    return failure("expected Unix time in seconds since 1970 (like 1717245296.25)");
  double fraction = 0.0;
  if (dot != std::string_view::npos) {
    const std::string_view digits = text.substr(dot + 1);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos)
      return failure("expected Unix time in seconds since 1970 (like 1717245296.25)");
    std::string decimal = "0.";
    decimal.append(digits);
    std::from_chars(decimal.data(), decimal.data() + decimal.size(), fraction);
  }
  if (seconds < 0 || seconds >= kLatestSeconds) return failure("the time is before 1970 or after 2200");
  if (fraction >= 1.0) return {UtcTime{seconds + 1, 0.0}, {}};
  return {UtcTime{seconds, fraction}, {}};
}

std::string format_iso8601(std::int64_t seconds) {
  const std::int64_t days = static_cast<std::int64_t>(std::floor(static_cast<double>(seconds) / 86400.0));
  const std::int64_t in_day = seconds - days * 86400;
  const date::year_month_day ymd{date::sys_days{date::days{days}}};
  char text[32];
  std::snprintf(text, sizeof text, "%04d-%02u-%02uT%02d:%02d:%02dZ", static_cast<int>(ymd.year()),
                static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()), static_cast<int>(in_day / 3600),
                static_cast<int>(in_day / 60 % 60), static_cast<int>(in_day % 60));
  return text;
}

std::string format_iso8601_micro(std::int64_t epoch, double t) {
  const double whole = std::floor(t);
  auto micro = static_cast<std::int64_t>(std::llround((t - whole) * 1e6));
  auto seconds = epoch + static_cast<std::int64_t>(whole);
  if (micro == 1000000) {
    micro = 0;
    ++seconds;
  }
  std::string text = format_iso8601(seconds);
  char fraction[16];
  std::snprintf(fraction, sizeof fraction, ".%06lldZ", static_cast<long long>(micro));
  text.pop_back();  // the 'Z'
  return text + fraction;
}

}  // namespace gesmi::io
