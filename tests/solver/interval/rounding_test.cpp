// Outward steps and directed operations on doubles (solver/interval/rounding.h).
// Oracles: exact values from the math, and x87 long double (64-bit significand),
// in which the sums and products of the short doubles used here are exact.

#include "solver/interval/rounding.h"
#include "tests/support/expect_interval.h"

#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <limits>
#include <random>

namespace gesmi {
namespace {

using test::kMax;
using test::kTiny;

static_assert(std::numeric_limits<long double>::digits >= 64, "the oracle needs x87 long double");

// A random double with at most `bits` significant bits and exponent in [-e, e].
double short_double(std::mt19937_64& rng, int bits, int e) {
  std::uniform_int_distribution<long long> mantissa(1LL << (bits - 1), (1LL << bits) - 1);
  std::uniform_int_distribution<int> exponent(-e, e);
  const double m = static_cast<double>(mantissa(rng));
  return std::ldexp(rng() & 1 ? -m : m, exponent(rng) - bits);
}

TEST(Rounding, NextUpAndDownStepOneDouble) {
  EXPECT_EQ(next_up(0.0), kTiny);
  EXPECT_EQ(next_up(-0.0), kTiny);
  EXPECT_EQ(next_down(0.0), -kTiny);
  EXPECT_EQ(next_up(-kTiny), 0.0);
  EXPECT_EQ(next_up(1.0), 1.0 + 0x1p-52);
  EXPECT_EQ(next_down(1.0), 1.0 - 0x1p-53);  // below a power of two the step halves
  EXPECT_EQ(next_up(-1.0), -1.0 + 0x1p-53);
  EXPECT_EQ(next_up(kMax), kInf);
  EXPECT_EQ(next_down(-kMax), -kInf);
  EXPECT_EQ(next_up(-kInf), -kMax);
  EXPECT_EQ(next_up(kInf), kInf);
  EXPECT_EQ(next_down(-kInf), -kInf);
  EXPECT_TRUE(std::isnan(next_up(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_EQ(step_up(1.0, 4), 1.0 + 4 * 0x1p-52);
  EXPECT_EQ(step_down(1.0, 2), 1.0 - 2 * 0x1p-53);
}

TEST(Rounding, DirectedSumsBracketTheExactSumWithinOneStep) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 200000; ++i) {
    const double a = short_double(rng, 53, 5), b = short_double(rng, 30, 5);
    const long double exact = static_cast<long double>(a) + b;  // exact: spans <= 64 bits
    const double lo = add_down(a, b), hi = add_up(a, b);
    ASSERT_LE(lo, exact);
    ASSERT_GE(hi, exact);
    if (static_cast<long double>(lo) == exact) ASSERT_EQ(lo, hi) << a << " + " << b;
    else ASSERT_EQ(next_up(lo), hi) << a << " + " << b;
    ASSERT_EQ(sub_down(a, -b), lo);
    ASSERT_EQ(sub_up(a, -b), hi);
  }
}

// A second oracle for sums: the processor's own directed rounding modes, over doubles of
// every sign and magnitude (subnormals, zeros, huge), not only short ones; sums that
// overflow are OverflowGoesToMaxOrInfinityByDirection's, and zeros are compared as
// numbers.
double sum_rounded(double a, double b, int mode) {
  const int before = std::fegetround();
  std::fesetround(mode);
  volatile double x = a, y = b;  // (computed here, at run time, in that mode)
  const volatile double sum = x + y;
  std::fesetround(before);
  return sum;
}

TEST(Rounding, DirectedSumsAreTheProcessorsDirectedRoundings) {
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> kind(0, 3);
  const auto any_double = [&] {
    switch (kind(rng)) {
      case 0: return short_double(rng, 53, 1070);                 // subnormal to huge
      case 1: return short_double(rng, 53, 4);                    // ordinary
      case 2: return std::ldexp(short_double(rng, 53, 2), -1060);  // subnormal
      default: return rng() & 1 ? 0.0 : -0.0;
    }
  };
  for (int i = 0; i < 400000; ++i) {
    const double a = any_double();
    const double b = i % 3 == 0 ? -a * (1.0 + std::ldexp(short_double(rng, 20, 0), -40)) : any_double();  // near cancellation
    const double up = sum_rounded(a, b, FE_UPWARD), down = sum_rounded(a, b, FE_DOWNWARD);
    if (!std::isfinite(up) || !std::isfinite(down)) continue;  // (overflow: OverflowGoesToMaxOrInfinityByDirection)
    // (as numbers: an exact zero sum is +0 here, -0 rounded downward)
    ASSERT_EQ(add_up(a, b), up) << a << " + " << b;
    ASSERT_EQ(add_down(a, b), down) << a << " + " << b;
  }
}

TEST(Rounding, DirectedProductsAndQuotientsBracketTheExactValue) {
  std::mt19937_64 rng(12);
  for (int i = 0; i < 200000; ++i) {
    const double a = short_double(rng, 53, 100), b = short_double(rng, 11, 100);
    const long double product = static_cast<long double>(a) * b;  // 53 + 11 bits: exact
    const double lo = mul_down(a, b), hi = mul_up(a, b);
    ASSERT_LE(lo, product);
    ASSERT_GE(hi, product);
    ASSERT_TRUE(lo == hi ? static_cast<long double>(lo) == product : next_up(lo) == hi);
    // q = a / b: the exact quotient is below q exactly when q * b > a (b > 0).
    const double qlo = div_down(a, b), qhi = div_up(a, b);
    const long double s = b > 0 ? 1.0L : -1.0L;
    ASSERT_LE(s * (static_cast<long double>(qlo) * b), s * a) << a << " / " << b;
    ASSERT_GE(s * (static_cast<long double>(qhi) * b), s * a) << a << " / " << b;
    ASSERT_TRUE(qlo == qhi || next_up(qlo) == qhi);
  }
}

TEST(Rounding, DirectedSquareRootsBracketTheRoot) {
  EXPECT_EQ(sqrt_down(2.25), 1.5);
  EXPECT_EQ(sqrt_up(2.25), 1.5);
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1e6);
  for (int i = 0; i < 100000; ++i) {
    const double x = u(rng);
    const long double root = std::sqrt(static_cast<long double>(x));
    const double lo = sqrt_down(x), hi = sqrt_up(x);
    ASSERT_LE(lo, root);
    ASSERT_GE(hi, root);
    ASSERT_TRUE(lo == hi ? static_cast<long double>(lo) * lo == x : next_up(lo) == hi);
  }
}

TEST(Rounding, SubnormalResultsAreDirectedExactly) {
  // denorm_min / 2 lies strictly between 0 and denorm_min.
  EXPECT_EQ(mul_down(kTiny, 0.5), 0.0);
  EXPECT_EQ(mul_up(kTiny, 0.5), kTiny);
  EXPECT_EQ(mul_down(-kTiny, 0.5), -kTiny);
  EXPECT_EQ(mul_up(-kTiny, 0.5), 0.0);
  EXPECT_EQ(div_down(3 * kTiny, 2.0), kTiny);  // 1.5 denorm_min
  EXPECT_EQ(div_up(3 * kTiny, 2.0), 2 * kTiny);
  EXPECT_EQ(div_down(3 * kTiny, -2.0), -2 * kTiny);
  EXPECT_EQ(mul_down(0x1p-537, 0x1p-537), kTiny);  // exact products stay exact
  EXPECT_EQ(mul_up(0x1p-537, 0x1p-537), kTiny);
  EXPECT_EQ(mul_down(3 * kTiny, 1.0 / 3.0), 0.0);   // 3 * RN(1/3) is just below 1
  EXPECT_EQ(mul_up(3 * kTiny, 1.0 / 3.0), kTiny);
  EXPECT_EQ(sqrt_down(kTiny), 0x1p-537);
  EXPECT_EQ(sqrt_up(kTiny), 0x1p-537);
  EXPECT_EQ(next_up(sqrt_down(2 * kTiny)), sqrt_up(2 * kTiny));  // 2^-536.5 is irrational
}

TEST(Rounding, OverflowGoesToMaxOrInfinityByDirection) {
  EXPECT_EQ(add_down(kMax, kMax), kMax);
  EXPECT_EQ(add_up(kMax, kMax), kInf);
  EXPECT_EQ(add_up(-kMax, -kMax), -kMax);
  EXPECT_EQ(add_down(-kMax, -kMax), -kInf);
  EXPECT_EQ(mul_down(kMax, 2.0), kMax);
  EXPECT_EQ(mul_up(kMax, 2.0), kInf);
  EXPECT_EQ(div_down(kMax, 0.5), kMax);
  EXPECT_EQ(div_up(-kMax, 0.5), -kMax);
  // A finite sum that rounds to max steps to infinity on its outward side only.
  EXPECT_EQ(add_up(kMax, 1.0), kInf);
  EXPECT_EQ(add_down(kMax, 1.0), kMax);
  EXPECT_EQ(add_down(-kMax, -1.0), -kInf);
  EXPECT_EQ(add_up(-kMax, -1.0), -kMax);
  EXPECT_EQ(add_down(kInf, 1.0), kInf);  // infinite bounds are kept
  EXPECT_EQ(add_up(-kInf, 1.0), -kInf);
}

TEST(Rounding, ZeroTimesInfinityIsZeroAndDivisionByInfinityIsZero) {
  EXPECT_EQ(mul_down(0.0, kInf), 0.0);
  EXPECT_EQ(mul_up(-kInf, 0.0), 0.0);
  EXPECT_EQ(div_down(1.0, kInf), 0.0);
  EXPECT_EQ(div_up(-1.0, kInf), 0.0);
  EXPECT_EQ(div_down(0.0, 0.5), 0.0);
}

TEST(Rounding, DirectedPowersBracketAnExactIntegerPower) {
  // 3^40 = 12157665459056928801 < 2^64: exact in long double, not in double.
  long double exact = 1.0L;
  for (int i = 0; i < 40; ++i) exact *= 3;
  EXPECT_LT(pow_down(3.0, 40), exact);
  EXPECT_GT(pow_up(3.0, 40), exact);
  EXPECT_LT(pow_up(3.0, 40) - pow_down(3.0, 40), 1e-14 * static_cast<double>(exact));
  EXPECT_EQ(pow_down(2.0, 10), 1024.0);
  EXPECT_EQ(pow_up(0.5, 3), 0.125);
  EXPECT_EQ(pow_down(7.0, 0), 1.0);
  EXPECT_EQ(pow_up(kMax, 2), kInf);
  EXPECT_EQ(pow_down(kMax, 2), kMax);
  EXPECT_EQ(pow_down(0x1p-600, 2), 0.0);  // 2^-1200 underflows
  EXPECT_EQ(pow_up(0x1p-600, 2), kTiny);
}

}  // namespace
}  // namespace gesmi

namespace gesmi {
namespace {

// The bit-addition fast path of step_up/step_down agrees with repeated next_up.
TEST(Rounding, SteppingSeveralUlpsEqualsRepeatedSingleSteps) {
  const double samples[] = {1.0, -1.0, 0x1p-999, -0x1p-999, 3.7e-300, -2.5e299, 0x1p52, 1.0 - 0x1p-53, -(1.0 - 0x1p-53),
                            0.1, -0.3, 0x1p-1022, 5e-324, 0.0, -0.0, 1.7e308, -1.7e308};
  for (const double x : samples) {
    for (int steps = 0; steps <= 8; ++steps) {
      double up = x, down = x;
      for (int i = 0; i < steps; ++i) {
        up = next_up(up);
        down = next_down(down);
      }
      EXPECT_EQ(step_up(x, steps), up) << x << " " << steps;
      EXPECT_EQ(step_down(x, steps), down) << x << " " << steps;
    }
  }
}

}  // namespace
}  // namespace gesmi
