#pragma once
// Numbers in the text formats (CSV, GESMI text logs): strict parsing of a whole
// field, and the shortest text that reads back to the same double, so that
// export -> import is exact.

#include <optional>
#include <string>
#include <string_view>

namespace gesmi::io {

/// The whole of `text` as a double (decimal or exponent form; an optional leading
/// '+'; "nan", "inf" and "infinity" in any case); nullopt when it is not a number.
std::optional<double> parse_number(std::string_view text);

/// The whole of `text` as an integer; nullopt otherwise.
std::optional<long long> parse_integer(std::string_view text);

/// Shortest decimal text that parses back to exactly `value` ("nan", "inf", "-inf"
/// for the non-finite values).
std::string format_number(double value);
/// The same text appended to `out`, without allocating per number (the exporters' rows).
void append_number(std::string& out, double value);

/// Why a number read from a file is not usable: "is NaN", "is infinite", or empty
/// when it is finite.
std::string_view non_finite_reason(double value);

}  // namespace gesmi::io
