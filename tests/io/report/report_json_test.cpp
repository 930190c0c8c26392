// The JSON reports' numbers: every double dump_shortest() writes reads back to the same
// double, and its text is as short as std::to_chars' shortest round-trip form (the rule
// for CSV and JSON); bounds therefore never move. nlohmann's own dump, measured beside
// it, reads back too but is sometimes longer. Infinite bounds are
// "inf"/"-inf", empty intervals null, NaN null.

#include "io/report/report_json.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

namespace gesmi::io {
namespace {

TEST(ReportJson, NumbersReadBackExactlyInTheirShortestForm) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> metres(-1e5, 1e5);
  int longer = 0, tested = 0;
  for (int i = 0; i < 200000; ++i) {
    // Half random bit patterns (any magnitude), half metre-scale values.
    double x = i % 2 ? std::bit_cast<double>(rng()) : metres(rng);
    if (!std::isfinite(x)) continue;
    ++tested;
    const std::string text = dump_shortest(nlohmann::json(x)), library = nlohmann::json(x).dump();
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
    ASSERT_EQ(std::strtod(library.c_str(), nullptr), x) << library;
    char shortest[64];
    const auto end = std::to_chars(shortest, shortest + sizeof shortest, x).ptr;
    // Compare significant digits: the two may place the exponent differently.
    const auto digits = [](std::string_view s) {
      const std::size_t e = s.find_first_of("eE");
      std::string_view mantissa = s.substr(0, e);
      std::size_t count = 0;
      bool leading = true;
      for (const char c : mantissa)
        if (c >= '0' && c <= '9') {
          if (leading && c == '0') continue;
          leading = false;
          ++count;
        }
      // Trailing zeros of an integer written without exponent are not significant.
      std::size_t zeros = 0;
      for (auto it = mantissa.rbegin(); it != mantissa.rend() && *it == '0'; ++it) ++zeros;
      return mantissa.find('.') == std::string_view::npos ? count - std::min(count, zeros) : count;
    };
    const std::size_t best = digits(std::string_view(shortest, static_cast<std::size_t>(end - shortest)));
    EXPECT_LE(digits(text), best) << text;
    if (digits(library) > best) ++longer;
  }
  EXPECT_GT(tested, 190000);
  std::printf("nlohmann's dump longer than the shortest for %d of %d doubles\n", longer, tested);
}

TEST(ReportJson, BoundsAndEmptyIntervals) {
  EXPECT_EQ(dump_shortest(interval_json(Interval(-INFINITY, 2.5))), R"(["-inf",2.5])");
  EXPECT_EQ(dump_shortest(interval_json(Interval(0.004, INFINITY))), R"([0.004,"inf"])");
  EXPECT_EQ(dump_shortest(nlohmann::json{{"a", nlohmann::json::array({1, 0.1, "x\"y"})}, {"b", nullptr}}),
            R"({"a":[1,0.1,"x\"y"],"b":null})");
  EXPECT_TRUE(interval_json(Interval::empty()).is_null());
  EXPECT_TRUE(number_json(NAN).is_null());
  EXPECT_EQ(constraint_json(ConstraintRef::gps_fix(3)).dump(), R"({"kind":"gps_fix","row":3})");
}

}  // namespace
}  // namespace gesmi::io
