#pragma once
// Input text shown inside a one-line error message. A message must stay one readable
// line whatever the input holds, so every reader that echoes a value from a file or the
// command line goes through `quoted_input`, and tools/gesmi/main.cpp passes each message
// through `one_line` before printing it (the last line of defence for paths and
// anything a reader forgot):
//
//   throw FormatError(where + ": expected a number, found " + quoted_input(field));
//   // nav.csv:3: vx: expected a number, found '1.5\x07'

#include <cstddef>
#include <string>
#include <string_view>

namespace gesmi::io {

/// Echoed input values are cut after this many characters (UTF-8 code points).
inline constexpr std::size_t kQuotedLength = 60;

/// `text` made safe for one line: control characters (\n, \r, \t, \xNN, and the C1
/// controls and line separators as \uNNNN) and bytes that are not UTF-8 (\xNN) are
/// escaped; a backslash stays as it is. Valid non-ASCII UTF-8 is kept.
std::string one_line(std::string_view text);

/// An input value for a message: cut to kQuotedLength characters (then "..."),
/// escaped by one_line, in single quotes: '1.5\x07', 'xxxx...'.
std::string quoted_input(std::string_view value);

}  // namespace gesmi::io
