// ISO 8601 and Unix-time parsing (io/time/utc_time.h) against the C library's timegm
// as an independent calendar, and every refusal.
#include "io/time/utc_time.h"

#include <gtest/gtest.h>

#include "tests/support/timegm_oracle.h"

#include <cstdio>
#include <ctime>
#include <random>

namespace gesmi::io {
namespace {

using test::timegm_seconds;

TEST(UtcTime, RandomInstantsAgreeWithTimegmInEveryZoneForm) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> year(1970, 2199), month(1, 12), day(1, 28), hour(0, 23), minute(0, 59), second(0, 59);
  std::uniform_int_distribution<int> offset_minutes(-14 * 60, 14 * 60);
  for (int i = 0; i < 20000; ++i) {
    const int y = year(rng), mo = month(rng), d = day(rng), h = hour(rng), mi = minute(rng), s = second(rng);
    const int off = offset_minutes(rng) / 15 * 15;
    char text[64];
    const char sign = off < 0 ? '-' : '+';
    const int a = std::abs(off);
    const char* forms[] = {"%04d-%02d-%02dT%02d:%02d:%02d%c%02d:%02d", "%04d-%02d-%02d %02d:%02d:%02d%c%02d%02d"};
    std::snprintf(text, sizeof text, forms[i % 2], y, mo, d, h, mi, s, sign, a / 60, a % 60);
    const std::int64_t expected = timegm_seconds(y, mo, d, h, mi, s) - off * 60;
    const ParsedTime p = parse_iso8601(text);
    if (expected < 0 || expected >= 7258118400) {
      EXPECT_FALSE(p.time) << text;
      continue;
    }
    ASSERT_TRUE(p.time) << text << ": " << p.error;
    EXPECT_EQ(p.time->seconds, expected) << text;
    EXPECT_EQ(p.time->fraction, 0.0);
  }
}

TEST(UtcTime, FormatsWhatTimegmGivesBack) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::int64_t> seconds(0, 7258118399);
  for (int i = 0; i < 20000; ++i) {
    const std::int64_t s = seconds(rng);
    const std::time_t t = static_cast<std::time_t>(s);
    std::tm parts{};
    gmtime_r(&t, &parts);
    char expected[32];
    std::strftime(expected, sizeof expected, "%Y-%m-%dT%H:%M:%SZ", &parts);
    EXPECT_EQ(format_iso8601(s), expected);
    const ParsedTime back = parse_iso8601(expected);
    ASSERT_TRUE(back.time);
    EXPECT_EQ(back.time->seconds, s);
  }
}

TEST(UtcTime, FractionsZoneLettersAndDefaultZone) {
  const ParsedTime a = parse_iso8601("2026-05-14T08:00:00.125Z");
  ASSERT_TRUE(a.time);
  EXPECT_EQ(a.time->seconds, timegm_seconds(2026, 5, 14, 8, 0, 0));
  EXPECT_EQ(a.time->fraction, 0.125);
  EXPECT_EQ(a.time->since(a.time->seconds - 10), 10.125);
  const ParsedTime b = parse_iso8601("2026-05-14T10:00:00,5+02");
  ASSERT_TRUE(b.time);
  EXPECT_EQ(b.time->seconds, a.time->seconds);
  EXPECT_EQ(b.time->fraction, 0.5);
  // No zone: refused, unless the map gives one.
  EXPECT_FALSE(parse_iso8601("2026-05-14T08:00:00").time);
  EXPECT_NE(parse_iso8601("2026-05-14T08:00:00").error.find("timezone"), std::string::npos);
  const ParsedTime c = parse_iso8601("2026-05-14T09:30:00", 5400);
  ASSERT_TRUE(c.time);
  EXPECT_EQ(c.time->seconds, a.time->seconds);
  // Nine nines round to the next second rather than a fraction of 1.
  const ParsedTime d = parse_iso8601("2026-05-14T07:59:59.99999999999999999999Z");
  ASSERT_TRUE(d.time);
  EXPECT_EQ(d.time->seconds, a.time->seconds);
  EXPECT_EQ(d.time->fraction, 0.0);
}

TEST(UtcTime, RefusesWhatIsNotAnInstant) {
  for (const char* bad : {"", "yesterday", "2026-13-01T00:00:00Z", "2026-02-29T00:00:00Z", "2026-04-31T00:00:00Z",
                          "2026-05-14T24:00:00Z", "2026-05-14T08:60:00Z", "2026-05-14T08:00:60Z", "2026-5-14T08:00:00Z",
                          "2026-05-14T08:00Z", "2026-05-14T08:00:00.Z", "2026-05-14T08:00:00+25:00", "2026-05-14T08:00:00 Z",
                          "1969-12-31T23:59:59Z", "2200-01-01T00:00:00Z", "2026-05-14T08:00:00Zjunk", "2026-05-14X08:00:00Z"}) {
    const ParsedTime p = parse_iso8601(bad);
    EXPECT_FALSE(p.time) << bad;
    EXPECT_FALSE(p.error.empty()) << bad;
  }
  EXPECT_TRUE(parse_iso8601("2024-02-29T00:00:00Z").time);  // a leap day
}

TEST(UtcTime, EpochSecondsKeepTheirFraction) {
  const ParsedTime p = parse_epoch_seconds("1778745600.000001");
  ASSERT_TRUE(p.time);
  EXPECT_EQ(p.time->seconds, 1778745600);
  EXPECT_EQ(p.time->since(1778745600), 0.000001);  // a double of 1.7e9 s alone keeps 0.2 us
  for (const char* bad : {"", "-1", "-0.5", "+5", "1e9", "17787456OO", "1778745600.", "1778745600.5.5", "99999999999", "nan"})
    EXPECT_FALSE(parse_epoch_seconds(bad).time) << bad;
  EXPECT_EQ(parse_epoch_utc("2026-05-14T10:00:00+02:00"), 1778745600);
  std::string why;
  EXPECT_FALSE(parse_epoch_utc("2026-05-14T08:00:00.5Z", &why));
  EXPECT_EQ(why, "the epoch is a whole second");
  EXPECT_FALSE(parse_epoch_utc("2026-05-14", &why));
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(parse_utc_offset("UTC"), 0);
  EXPECT_EQ(parse_utc_offset("-05:30"), -19800);
  EXPECT_FALSE(parse_utc_offset("+5"));
}

TEST(UtcTime, FormatsFractionsToTheMicrosecondWithCarries) {
  EXPECT_EQ(format_iso8601_micro(0, 1.5), "1970-01-01T00:00:01.500000Z");
  EXPECT_EQ(format_iso8601_micro(0, 59.9999999), "1970-01-01T00:01:00.000000Z");  // rounds into the next minute
  EXPECT_EQ(format_iso8601_micro(0, -0.25), "1969-12-31T23:59:59.750000Z");
  EXPECT_EQ(format_iso8601_micro(1778745600, 0.1), "2026-05-14T08:00:00.100000Z");
}

}  // namespace
}  // namespace gesmi::io
