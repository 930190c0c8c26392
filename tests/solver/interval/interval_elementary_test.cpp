// Elementary functions of intervals (solver/interval/interval_elementary.cpp):
// pow, exp, log, sin, cos, tan, atan, atan2. Expected values come from the math
// (exact special values, extrema, poles, Taylor bounds) and from x87 long double
// libm as an independent oracle 11 bits more precise than double. The rigorous
// randomized check against MPFI is tests/oracle/.

#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "solver/interval/interval.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::contains;

using test::kMax;
using test::kTiny;
using test::kPiLong;

// f's value v (long double, error far below a double ulp) lies in y, up to a
// margin of 2^-58 relative that absorbs the oracle's own error.
::testing::AssertionResult encloses(const Interval& y, long double v) {
  const long double margin = std::fabs(v) * 0x1p-58L;
  if (y.lo() <= v + margin && v - margin <= y.hi()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << test::to_string(y) << " misses " << static_cast<double>(v);
}

// Samples intervals of varied widths inside [lo, hi] and points inside them, and
// checks f(X) encloses each point value given by the oracle g.
void check_sampled(const std::function<Interval(const Interval&)>& f, const std::function<long double(long double)>& g,
                   double lo, double hi, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi), unit(0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    const double a = u(rng), w = (hi - lo) * std::pow(unit(rng), 6.0);
    const Interval x(a, std::min(hi, a + w));
    const Interval y = f(x);
    for (const double t : {x.lo(), x.hi(), x.lo() + (x.hi() - x.lo()) * unit(rng)}) {
      ASSERT_TRUE(encloses(y, g(t))) << "x = " << test::to_string(x) << ", t = " << t;
    }
  }
}

TEST(IntervalElementary, PowerHandlesSignsZerosAndNegativeExponents) {
  EXPECT_EQ(pow(Interval(-2.0, 3.0), 2), Interval(0.0, 9.0));
  EXPECT_EQ(pow(Interval(-2.0, 3.0), 3), Interval(-8.0, 27.0));
  EXPECT_EQ(pow(Interval(-3.0, -2.0), 4), Interval(16.0, 81.0));
  EXPECT_EQ(pow(Interval::entire(), 0), Interval(1.0));
  EXPECT_EQ(pow(Interval(2.0, 4.0), -1), Interval(0.25, 0.5));
  EXPECT_EQ(pow(Interval(-2.0, -1.0), -2), Interval(0.25, 1.0));
  EXPECT_EQ(pow(Interval(-1.0, 1.0), -1), Interval::entire());
  EXPECT_EQ(pow(Interval(-1.0, 1.0), -2), Interval(1.0, kInf));
  EXPECT_EQ(pow(Interval(0.0, 2.0), -2), Interval(0.25, kInf));
  EXPECT_TRUE(pow(Interval(0.0), -2).is_empty());
  EXPECT_TRUE(pow(Interval::empty(), 3).is_empty());
  // 1 / max^2 ~ 3e-617 is below every positive double: [0, denorm_min] is tight.
  EXPECT_EQ(pow(Interval(kMax), -2), Interval(0.0, kTiny));
  EXPECT_EQ(pow(Interval(-kMax), -3), Interval(-kTiny, 0.0));
  EXPECT_EQ(pow(Interval(1.0), INT_MIN), Interval(1.0));
  EXPECT_EQ(pow(Interval(2.0), INT_MIN), Interval(0.0, kTiny));
  EXPECT_EQ(pow(Interval(0.5), INT_MIN).hi(), kInf);
  EXPECT_TRUE(encloses(pow(Interval(10.0), 30), std::pow(10.0L, 30)));
  EXPECT_TRUE(encloses(pow(Interval(1.1), 300), std::pow(static_cast<long double>(1.1), 300)));
  check_sampled([](const Interval& x) { return pow(x, 7); }, [](long double t) { return std::pow(t, 7); }, -30, 30,
                20000, 1);
  check_sampled([](const Interval& x) { return pow(x, -3); }, [](long double t) { return std::pow(t, -3); }, 0.01,
                30, 20000, 2);
}

TEST(IntervalElementary, ExpAndLogKeepExactSpecialValues) {
  EXPECT_EQ(exp(Interval(0.0)), Interval(1.0));
  EXPECT_EQ(log(Interval(1.0)), Interval(0.0));
  EXPECT_EQ(exp(Interval::entire()), Interval(0.0, kInf));
  EXPECT_EQ(log(Interval(0.0, 1.0)), Interval(-kInf, 0.0));
  EXPECT_EQ(log(Interval(0.0, kInf)), Interval::entire());
  EXPECT_TRUE(log(Interval(-2.0, 0.0)).is_empty());
  EXPECT_EQ(log(Interval(-2.0, 1.0)), Interval(-kInf, 0.0));
  // Near overflow (ln max = 709.7827...): exp(709.78) is finite, exp(709.79) is not.
  const Interval near_overflow = exp(Interval(709.78, 709.79));
  EXPECT_LT(near_overflow.lo(), kMax);
  EXPECT_EQ(near_overflow.hi(), kInf);
  EXPECT_TRUE(encloses(exp(Interval(709.78)), std::exp(static_cast<long double>(709.78))));
  // Near underflow the true value is still positive: the upper bound must be too.
  EXPECT_GT(exp(Interval(-745.2)).hi(), 0.0);
  EXPECT_EQ(exp(Interval(-800.0)).lo(), 0.0);
  EXPECT_GT(exp(Interval(-800.0)).hi(), 0.0);
  EXPECT_TRUE(encloses(log(Interval(kTiny)), std::log(static_cast<long double>(kTiny))));
  EXPECT_TRUE(encloses(log(Interval(1.0 + 0x1p-52)), 0x1p-52L));  // log(1 + e) = e - e^2/2...
  EXPECT_LT(log(Interval(1.0 + 0x1p-52)).lo(), 0x1p-52);
  check_sampled([](const Interval& x) { return exp(x); }, [](long double t) { return std::exp(t); }, -700, 700, 20000,
                3);
  check_sampled([](const Interval& x) { return log(x); }, [](long double t) { return std::log(t); }, 1e-300, 1e300,
                20000, 4);
  check_sampled([](const Interval& x) { return log(x); }, [](long double t) { return std::log(t); }, 0.5, 2.0, 20000,
                5);
}

TEST(IntervalElementary, SineAndCosineReachTheirExtremaInside) {
  EXPECT_EQ(sin(Interval(1.0, 2.0)).hi(), 1.0);   // pi/2 inside
  EXPECT_EQ(cos(Interval(3.0, 3.3)).lo(), -1.0);  // pi inside
  EXPECT_EQ(sin(Interval(4.0, 5.0)).lo(), -1.0);  // 3pi/2 inside
  EXPECT_EQ(cos(Interval(-1.0, 1.0)).hi(), 1.0);
  EXPECT_EQ(sin(Interval(0.0, 7.0)), Interval(-1.0, 1.0));  // wider than 2pi
  EXPECT_EQ(cos(Interval(0.0, kInf)), Interval(-1.0, 1.0));
  EXPECT_TRUE(sin(Interval::empty()).is_empty());
  EXPECT_EQ(sin(Interval(0.0)), Interval(0.0));
  EXPECT_EQ(cos(Interval(0.0)), Interval(1.0));
  EXPECT_EQ(sin(Interval(0.0, 0.5)).lo(), 0.0);  // sin(0) = 0 exactly
  EXPECT_TRUE(sin(Interval::pi()).contains(0.0));
  EXPECT_TRUE(cos(Interval::half_pi()).contains(0.0));
  EXPECT_LT(sin(Interval::pi()).width(), 1e-15);
}

TEST(IntervalElementary, CosineIsTightWhenAnEndPointIsZero) {
  // Regression: cos([0, 0.05]) was [-1, 1] because -sin(0) = 0 left the trend open.
  // cos x >= 1 - x^2 / 2 bounds the tight result from below.
  for (const Interval& x : {Interval(0.0, 0.05), Interval(-0.05, 0.0), Interval(-0.0, 0.05)}) {
    const Interval c = cos(x);
    EXPECT_EQ(c.hi(), 1.0);
    EXPECT_GT(c.lo(), 1.0 - 0.05 * 0.05 / 2 - 1e-15) << test::to_string(c);
    EXPECT_TRUE(encloses(c, std::cos(0.05L)));
  }
  EXPECT_EQ(cos(Interval(0.0, 4.0)).lo(), -1.0);  // still reaches pi
}

TEST(IntervalElementary, SineOfHugeArgumentsUsesAnAccurateReduction) {
  // sin(1e22) = -0.8522008497671888017727... (a classic argument-reduction test).
  EXPECT_TRUE(encloses(sin(Interval(1e22)), -0.8522008497671888017727L));
  check_sampled([](const Interval& x) { return sin(x); }, [](long double t) { return std::sin(t); }, -1e6, 1e6, 20000,
                6);
  check_sampled([](const Interval& x) { return cos(x); }, [](long double t) { return std::cos(t); }, -10, 10, 20000, 7);
  check_sampled([](const Interval& x) { return sin(x); }, [](long double t) { return std::sin(t); }, -1e-3, 1e-3,
                20000, 8);
}

TEST(IntervalElementary, TangentIsUnboundedExactlyAcrossAPole) {
  EXPECT_EQ(tan(Interval(1.0, 2.0)), Interval::entire());  // pi/2 inside
  EXPECT_EQ(tan(Interval(0.0)), Interval(0.0));
  EXPECT_EQ(tan(Interval(0.0, 4.0)), Interval::entire());
  // Regression: the widest interval without a pole was taken for one that has one.
  const double h = Interval::half_pi().lo();  // the double just below pi/2
  const Interval widest = tan(Interval(-h, h));
  EXPECT_TRUE(widest.is_bounded());
  EXPECT_TRUE(encloses(widest, std::tan(static_cast<long double>(h))));
  EXPECT_EQ(tan(Interval(-h, Interval::half_pi().hi())), Interval::entire());
  check_sampled([](const Interval& x) { return tan(x); }, [](long double t) { return std::tan(t); }, -1.5, 1.5, 20000,
                9);
}

TEST(IntervalElementary, ArctangentStaysWithinHalfPi) {
  const Interval a = atan(Interval::entire());  // the closure reaches +-pi/2
  EXPECT_GE(a.hi(), kPiLong / 2);
  EXPECT_LE(a.lo(), -kPiLong / 2);
  EXPECT_LE(a.hi(), Interval::half_pi().hi());
  EXPECT_GE(a.lo(), -Interval::half_pi().hi());
  EXPECT_EQ(atan(Interval(0.0)), Interval(0.0));
  EXPECT_TRUE(encloses(atan(Interval(1.0)), kPiLong / 4));
  check_sampled([](const Interval& x) { return atan(x); }, [](long double t) { return std::atan(t); }, -1e3, 1e3,
                20000, 10);
}

TEST(IntervalElementary, Atan2CoversEveryQuadrantAndTheCut) {
  EXPECT_TRUE(encloses(atan2(Interval(1.0), Interval(1.0)), kPiLong / 4));
  EXPECT_TRUE(encloses(atan2(Interval(1.0), Interval(-1.0)), 3 * kPiLong / 4));
  EXPECT_TRUE(encloses(atan2(Interval(-1.0), Interval(-1.0)), -3 * kPiLong / 4));
  EXPECT_TRUE(encloses(atan2(Interval(-1.0), Interval(1.0)), -kPiLong / 4));
  EXPECT_EQ(atan2(Interval(0.0), Interval(-1.0)), Interval::pi());  // the cut belongs to +pi
  EXPECT_EQ(atan2(Interval(0.0), Interval(2.0)), Interval(0.0));
  EXPECT_TRUE(atan2(Interval(0.0), Interval(0.0)).is_empty());
  // Across the cut: angles near -pi and near +pi.
  EXPECT_EQ(atan2(Interval(-1.0, 1.0), Interval(-2.0, -1.0)), Interval(-Interval::pi().hi(), Interval::pi().hi()));
  // Touching the cut from above only: the angle stays in [3pi/4, pi].
  const Interval upper = atan2(Interval(0.0, 1.0), Interval(-2.0, -1.0));
  EXPECT_TRUE(encloses(upper, kPiLong));
  EXPECT_GE(upper.lo(), 2.0);
  // Boxes around the origin.
  EXPECT_EQ(atan2(Interval(0.0, 1.0), Interval(-1.0, 1.0)), Interval(0.0, Interval::pi().hi()));
  EXPECT_EQ(atan2(Interval(-1.0, 1.0), Interval(0.0, 1.0)), Interval(-Interval::half_pi().hi(), Interval::half_pi().hi()));
  check_sampled([](const Interval& x) { return atan2(x, Interval(0.5, 2.0)); },
                [](long double t) { return std::atan2(t, 0.5L); }, -3, 3, 5000, 11);
}

TEST(IntervalElementary, Atan2OfAnUnderflowingAngleIsNotZero) {
  // Regression: atan2(1e-300, 1e300) = 1e-600 underflows to 0 in libm, and 0 was
  // taken as exact, giving [0, 0], which excludes the true positive angle.
  const Interval a = atan2(Interval(1e-300), Interval(1e300));
  EXPECT_GT(a.hi(), 0.0);
  EXPECT_GE(a.lo(), 0.0);  // y > 0: the angle is positive
  const Interval b = atan2(Interval(-1e-300), Interval(1e300));
  EXPECT_LT(b.lo(), 0.0);
  EXPECT_LE(b.hi(), 0.0);
}

}  // namespace
}  // namespace gesmi
