#include "io/text/message_text.h"

#include <cstdint>
#include <cstdio>

namespace gesmi::io {
namespace {

// Length of the valid UTF-8 sequence starting at text[i] and its code point, or 0.
std::size_t utf8_sequence(std::string_view text, std::size_t i, std::uint32_t& code) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  if (b < 0x80) {
    code = b;
    return 1;
  }
  std::size_t length = 0;
  std::uint32_t minimum = 0;
  if ((b & 0xE0) == 0xC0) {
    length = 2;
    code = b & 0x1Fu;
    minimum = 0x80;
  } else if ((b & 0xF0) == 0xE0) {
    length = 3;
    code = b & 0x0Fu;
    minimum = 0x800;
  } else if ((b & 0xF8) == 0xF0) {
    length = 4;
    code = b & 0x07u;
    minimum = 0x10000;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3Fu);
  }
  // Overlong forms, UTF-16 surrogates and values past U+10FFFF are not UTF-8.
  if (code < minimum || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF) return 0;
  return length;
}

std::string hex_escape(const char* format, std::uint32_t value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, format, static_cast<unsigned>(value));
  return buffer;
}

}  // namespace

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    std::uint32_t code = 0;
    const std::size_t length = utf8_sequence(text, i, code);
    if (length == 0) {
      out += hex_escape("\\x%02X", static_cast<unsigned char>(text[i]));
      ++i;
      continue;
    }
    if (code == '\n') out += "\\n";
    else if (code == '\r') out += "\\r";
    else if (code == '\t') out += "\\t";
    else if (code < 0x20 || code == 0x7F) out += hex_escape("\\x%02X", code);
    else if ((code >= 0x80 && code <= 0x9F) || code == 0x2028 || code == 0x2029) out += hex_escape("\\u%04X", code);
    else out.append(text.substr(i, length));
    i += length;
  }
  return out;
}

std::string quoted_input(std::string_view value) {
  std::size_t end = 0, characters = 0;
  while (end < value.size() && characters < kQuotedLength) {
    std::uint32_t code = 0;
    const std::size_t length = utf8_sequence(value, end, code);
    end += length == 0 ? 1 : length;
    ++characters;
  }
  const bool cut = end < value.size();
  return "'" + one_line(value.substr(0, end)) + (cut ? "...'" : "'");
}

}  // namespace gesmi::io
