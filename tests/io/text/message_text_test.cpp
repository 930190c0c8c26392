// Input text inside one-line messages: escaped control characters and non-UTF-8
// bytes, kept UTF-8, and values cut after kQuotedLength characters.

#include "io/text/message_text.h"

#include <gtest/gtest.h>

#include <string>

namespace gesmi::io {
namespace {

bool only_printable_ascii_or_utf8(const std::string& s) {
  for (const char c : s) {
    const auto b = static_cast<unsigned char>(c);
    if (b < 0x20 || b == 0x7F) return false;
  }
  return true;
}

TEST(MessageText, ControlCharactersBecomeEscapes) {
  EXPECT_EQ(one_line("a\nb"), "a\\nb");
  EXPECT_EQ(one_line("a\r\tb"), "a\\r\\tb");
  EXPECT_EQ(one_line(std::string("1.5\x07", 4)), "1.5\\x07");
  EXPECT_EQ(one_line(std::string("\x00\x1b[31m\x7f", 7)), "\\x00\\x1B[31m\\x7F");
  // C1 controls and the Unicode line separators break lines in some terminals.
  EXPECT_EQ(one_line("x\xc2\x85y"), "x\\u0085y");
  EXPECT_EQ(one_line("x\xe2\x80\xa8y"), "x\\u2028y");
}

TEST(MessageText, BytesThatAreNotUtf8AreEscapedAndUtf8IsKept) {
  EXPECT_EQ(one_line("\xff\xfe" "a"), "\\xFF\\xFEa");
  EXPECT_EQ(one_line("48\xc3(.2"), "48\\xC3(.2");         // truncated sequence
  EXPECT_EQ(one_line("\xc0\xaf"), "\\xC0\\xAF");           // overlong '/'
  EXPECT_EQ(one_line("\xed\xa0\x80"), "\\xED\\xA0\\x80");  // UTF-16 surrogate
  EXPECT_EQ(one_line("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8c\x8a"), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8c\x8a");
  EXPECT_EQ(one_line("back\\slash"), "back\\slash");
}

TEST(MessageText, QuotedValuesAreCutAfterTheLimitInCharactersNotBytes) {
  EXPECT_EQ(quoted_input("abc"), "'abc'");
  EXPECT_EQ(quoted_input(""), "''");
  const std::string exact(kQuotedLength, 'x');
  EXPECT_EQ(quoted_input(exact), "'" + exact + "'");
  EXPECT_EQ(quoted_input(exact + "y"), "'" + exact + "...'");
  std::string accents;
  for (std::size_t i = 0; i < kQuotedLength + 5; ++i) accents += "\xc3\xa9";
  const std::string q = quoted_input(accents);
  EXPECT_EQ(q.size(), 1 + 2 * kQuotedLength + 4) << q;  // never cut inside a character
  EXPECT_EQ(quoted_input(std::string(100000, '9')).size(), kQuotedLength + 5);
}

TEST(MessageText, AnyInputGivesOneLineOfPrintableText) {
  std::string all;
  for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
  const std::string line = one_line(all);
  EXPECT_TRUE(only_printable_ascii_or_utf8(line)) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_TRUE(only_printable_ascii_or_utf8(quoted_input(all)));
}

}  // namespace
}  // namespace gesmi::io
