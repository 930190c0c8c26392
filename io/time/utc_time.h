#pragma once
// Absolute times of real logs (docs/formats.md, "Times"): ISO 8601 timestamps and Unix
// epoch seconds, held as whole UTC seconds since 1970-01-01 plus a fraction, so that
// times relative to a mission's epoch keep every digit a double can hold. The
// calendar arithmetic is Howard Hinnant's date library (Debian's
// libhowardhinnant-date-dev); the field syntax is checked strictly here.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gesmi::io {

/// An instant: `seconds` since 1970-01-01T00:00:00Z (leap seconds not counted, as
/// in Unix time) plus `fraction` in [0, 1).
struct UtcTime {
  std::int64_t seconds = 0;
  double fraction = 0.0;
  /// Seconds after `epoch` (whole seconds since 1970), exact to the double's precision.
  double since(std::int64_t epoch) const { return static_cast<double>(seconds - epoch) + fraction; }
};

/// The result of parsing one field: a time, or why the text is not one.
struct ParsedTime {
  std::optional<UtcTime> time;
  std::string error;  // empty when time is set
};

/// "YYYY-MM-DDThh:mm:ss[.f…](Z|±hh:mm|±hhmm|±hh)"; 'T' may be a space. A time
/// without zone takes `default_offset_seconds` when given (the map's `timezone`),
/// and is an error otherwise.
ParsedTime parse_iso8601(std::string_view text, std::optional<int> default_offset_seconds = std::nullopt);

/// A mission's epoch: an ISO 8601 time in whole seconds ("2026-05-14T08:00:00Z"), as
/// seconds since 1970; nullopt, with `why` set, otherwise.
std::optional<std::int64_t> parse_epoch_utc(std::string_view text, std::string* why = nullptr);

/// Seconds since 1970 as text (decimal, e.g. "1717245296.25"), not before 1970 nor
/// after 2200.
ParsedTime parse_epoch_seconds(std::string_view text);

/// A zone designator alone ("Z", "UTC", "+02:00", "-0530"): its offset in seconds.
std::optional<int> parse_utc_offset(std::string_view text);

/// "YYYY-MM-DDThh:mm:ssZ" of whole seconds since 1970.
std::string format_iso8601(std::int64_t seconds);
/// The UTC time `t` seconds after `epoch`, to the microsecond (nearest):
/// "YYYY-MM-DDThh:mm:ss.ffffffZ".
std::string format_iso8601_micro(std::int64_t epoch, double t);

/// Days since 1970-01-01 of a calendar date, or nullopt when the date does not exist.
std::optional<std::int64_t> days_since_1970(int year, int month, int day);

}  // namespace gesmi::io
