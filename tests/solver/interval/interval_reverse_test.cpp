// Reverse operators (solver/interval/interval_reverse.h): contractance (never
// enlarge an argument), soundness on sampled solutions (a point x in X with f(x)
// in Y must stay), symmetric variants (signs flipped, arguments swapped), the
// periodic sin/cos/tan reverses over several periods against the solution sets
// of the math, and bwd_atan2 in all quadrants.

#include "solver/interval/interval_reverse.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::contains;
using test::contains_point;
using test::to_string;

using test::kPiLong;

using Unary = std::function<Interval(const Interval&)>;
using Binary = std::function<Interval(const Interval&, const Interval&)>;
using BwdUnary = std::function<bool(const Interval&, Interval&)>;
using BwdBinary = std::function<bool(const Interval&, Interval&, Interval&)>;

struct UnaryCase {
  std::string name;
  Unary forward;
  BwdUnary backward;
  double lo, hi;  // where arguments are drawn
};
struct BinaryCase {
  std::string name;
  Binary forward;
  BwdBinary backward;
  double lo, hi;
};

std::vector<UnaryCase> unary_cases() {
  std::vector<UnaryCase> cases = {
      {"neg", [](const Interval& x) { return -x; }, bwd_neg, -1e3, 1e3},
      {"sqr", [](const Interval& x) { return sqr(x); }, bwd_sqr, -1e3, 1e3},
      {"sqrt", [](const Interval& x) { return sqrt(x); }, bwd_sqrt, -10, 1e3},
      {"exp", [](const Interval& x) { return exp(x); }, bwd_exp, -50, 50},
      {"log", [](const Interval& x) { return log(x); }, bwd_log, -1, 1e3},
      {"abs", [](const Interval& x) { return abs(x); }, bwd_abs, -1e3, 1e3},
      {"sin", [](const Interval& x) { return sin(x); }, bwd_sin, -30, 30},
      {"cos", [](const Interval& x) { return cos(x); }, bwd_cos, -30, 30},
      {"tan", [](const Interval& x) { return tan(x); }, bwd_tan, -30, 30},
      {"atan", [](const Interval& x) { return atan(x); }, bwd_atan, -1e3, 1e3},
  };
  for (int n = -5; n <= 5; ++n) {
    cases.push_back({"pow" + std::to_string(n), [n](const Interval& x) { return pow(x, n); },
                     [n](const Interval& y, Interval& x) { return bwd_pow(y, x, n); }, -20, 20});
  }
  return cases;
}

std::vector<BinaryCase> binary_cases() {
  return {
      {"add", [](const Interval& a, const Interval& b) { return a + b; }, bwd_add, -1e3, 1e3},
      {"sub", [](const Interval& a, const Interval& b) { return a - b; }, bwd_sub, -1e3, 1e3},
      {"mul", [](const Interval& a, const Interval& b) { return a * b; }, bwd_mul, -1e3, 1e3},
      {"div", [](const Interval& a, const Interval& b) { return a / b; }, bwd_div, -1e3, 1e3},
      {"min", [](const Interval& a, const Interval& b) { return min(a, b); }, bwd_min, -1e3, 1e3},
      {"max", [](const Interval& a, const Interval& b) { return max(a, b); }, bwd_max, -1e3, 1e3},
      {"atan2", [](const Interval& y, const Interval& x) { return atan2(y, x); }, bwd_atan2, -1e3, 1e3},
  };
}

// Random intervals and points, with zeros, degenerate and unbounded intervals.
struct Sampler {
  std::mt19937_64 rng;
  explicit Sampler(unsigned seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  double value(double lo, double hi) {
    switch (rng() % 8) {
      case 0: return 0.0;
      case 1: return std::round(uniform(lo, hi));
      default: return uniform(lo, hi);
    }
  }
  Interval interval(double lo, double hi) {
    double a = value(lo, hi), b = rng() % 6 == 0 ? a : value(lo, hi);
    if (a > b) std::swap(a, b);
    if (rng() % 10 == 0) a = -kInf;
    if (rng() % 10 == 0) b = kInf;
    return Interval(a, b);
  }
  double point(const Interval& x) {
    const double lo = std::max(x.lo(), -1e6), hi = std::min(x.hi(), 1e6);
    switch (rng() % 5) {
      case 0: return lo;
      case 1: return hi;
      default: return std::clamp(uniform(lo, hi), lo, hi);
    }
  }
  // y, or y widened by a random relative amount (y itself is the hardest case).
  Interval widened(const Interval& y) {
    if (y.is_empty() || rng() % 2 == 0) return y;
    const double r = std::ldexp(1.0, -static_cast<int>(rng() % 50));
    return Interval(y.lo() - std::fabs(y.lo()) * r - r, y.hi() + std::fabs(y.hi()) * r + r);
  }
};

TEST(IntervalReverse, UnaryReversesNeverEnlargeAndReportEmptiness) {
  Sampler s(1);
  for (const UnaryCase& c : unary_cases()) {
    for (int i = 0; i < 20000; ++i) {
      const Interval x0 = s.interval(c.lo, c.hi), y = s.interval(-50, 50);
      Interval x = x0;
      const bool ok = c.backward(y, x);
      ASSERT_TRUE(contains(x0, x)) << c.name << " y = " << to_string(y);
      ASSERT_EQ(ok, !x.is_empty()) << c.name;
    }
  }
}

TEST(IntervalReverse, BinaryReversesNeverEnlargeAndReportEmptiness) {
  Sampler s(2);
  for (const BinaryCase& c : binary_cases()) {
    for (int i = 0; i < 20000; ++i) {
      const Interval a0 = s.interval(c.lo, c.hi), b0 = s.interval(c.lo, c.hi), y = s.interval(-50, 50);
      Interval a = a0, b = b0;
      const bool ok = c.backward(y, a, b);
      ASSERT_TRUE(contains(a0, a) && contains(b0, b)) << c.name << " y = " << to_string(y);
      ASSERT_EQ(ok, !a.is_empty()) << c.name;
      ASSERT_EQ(a.is_empty(), b.is_empty()) << c.name << ": emptiness must be total";
    }
  }
}

TEST(IntervalReverse, UnaryReversesKeepEverySampledSolution) {
  Sampler s(3);
  for (const UnaryCase& c : unary_cases()) {
    for (int i = 0; i < 20000; ++i) {
      Interval x = s.interval(c.lo, c.hi);
      const double p = s.point(x);
      const Interval y = s.widened(c.forward(Interval(p)));  // encloses f(p)
      if (y.is_empty()) continue;                            // p outside the domain of f
      const Interval x0 = x;
      ASSERT_TRUE(c.backward(y, x)) << c.name << " lost p = " << p << " in " << to_string(x0) << ", y = " << to_string(y);
      ASSERT_TRUE(contains_point(x, p)) << c.name << " x0 = " << to_string(x0) << ", y = " << to_string(y);
    }
  }
}

TEST(IntervalReverse, BinaryReversesKeepEverySampledSolution) {
  Sampler s(4);
  for (const BinaryCase& c : binary_cases()) {
    for (int i = 0; i < 20000; ++i) {
      Interval a = s.interval(c.lo, c.hi), b = s.interval(c.lo, c.hi);
      const double p = s.point(a), q = s.point(b);
      const Interval y = s.widened(c.forward(Interval(p), Interval(q)));
      if (y.is_empty()) continue;  // (p, q) outside the domain (q = 0 for div, origin for atan2)
      const Interval a0 = a, b0 = b;
      ASSERT_TRUE(c.backward(y, a, b)) << c.name << " lost (" << p << ", " << q << ") in " << to_string(a0) << " x "
                                       << to_string(b0) << ", y = " << to_string(y);
      ASSERT_TRUE(contains_point(a, p) && contains_point(b, q))
          << c.name << " (" << p << ", " << q << "), y = " << to_string(y);
    }
  }
}

// |u - v| is within a few ulps of the magnitudes involved (for results computed
// through differently rounded but mirrored pieces).
bool nearly_equal(const Interval& u, const Interval& v) {
  if (u.is_empty() || v.is_empty()) return u.is_empty() && v.is_empty();
  const auto close = [](double p, double q) { return p == q || std::fabs(p - q) <= 1e-13 * (1.0 + std::fabs(p)); };
  return close(u.lo(), v.lo()) && close(u.hi(), v.hi());
}

TEST(IntervalReverse, SwappedAndNegatedArgumentsGiveMirroredResults) {
  Sampler s(5);
  for (int i = 0; i < 20000; ++i) {
    const Interval y = s.interval(-50, 50), a0 = s.interval(-20, 20), b0 = s.interval(-20, 20);
    // y = a + b = b + a, y = a * b = b * a: one pass depends on which argument is
    // narrowed first, but the fixpoints agree, with the results swapped.
    for (const BwdBinary& commutative : {BwdBinary(bwd_add), BwdBinary(bwd_mul)}) {
      Interval a = a0, b = b0, a2 = a0, b2 = b0;
      for (int k = 0; k < 60; ++k) {
        commutative(y, a, b);
        commutative(y, b2, a2);
      }
      ASSERT_TRUE(nearly_equal(a, a2)) << to_string(a) << " vs " << to_string(a2);
      ASSERT_TRUE(nearly_equal(b, b2));
    }
    Interval a, b, a2, b2;
    // -y = (-a) * b: negating y and a negates the result for a.
    a = a0, b = b0, a2 = -a0, b2 = b0;
    bwd_mul(y, a, b);
    bwd_mul(-y, a2, b2);
    ASSERT_EQ(a, -a2);
    ASSERT_EQ(b, b2);
    // y = a - b is y = a + (-b).
    a = a0, b = b0, a2 = a0, b2 = -b0;
    bwd_sub(y, a, b);
    bwd_add(y, a2, b2);
    ASSERT_EQ(a, a2);
    ASSERT_EQ(b, -b2);
    // Even functions: the result for -x is the mirror of the result for x.
    for (const auto& even : {BwdUnary(bwd_sqr), BwdUnary(bwd_abs), BwdUnary([](const Interval& c, Interval& x) {
                               return bwd_pow(c, x, 4);
                             })}) {
      Interval x = a0, xm = -a0;
      even(y, x);
      even(y, xm);
      ASSERT_EQ(x, -xm);
    }
    // Odd power: y = x^3 and -y = (-x)^3.
    Interval x = a0, xm = -a0;
    bwd_pow(y, x, 3);
    bwd_pow(-y, xm, 3);
    ASSERT_EQ(x, -xm);
  }
}

TEST(IntervalReverse, PeriodicReversesAreSymmetric) {
  Sampler s(6);
  for (int i = 0; i < 20000; ++i) {
    const Interval c = s.interval(-1.2, 1.2), x = s.interval(-40, 40);
    ASSERT_TRUE(nearly_equal(sin_rev(-c, -x), -sin_rev(c, x))) << to_string(c) << " " << to_string(x);
    ASSERT_TRUE(nearly_equal(cos_rev(c, -x), -cos_rev(c, x))) << to_string(c) << " " << to_string(x);
    const Interval t = s.interval(-50, 50);
    ASSERT_TRUE(nearly_equal(tan_rev(-t, -x), -tan_rev(t, x))) << to_string(t) << " " << to_string(x);
  }
}

// Hull of the solutions in [lo, hi] of the periodic families base_j + k period,
// computed in long double from the math (asin, acos, atan and pi).
struct Hull {
  long double lo = INFINITY, hi = -INFINITY;
};
Hull solution_hull(const std::vector<long double>& bases, long double period, double lo, double hi) {
  Hull h;
  for (const long double b : bases) {
    for (long double k = std::floor((lo - b) / period) - 1; b + k * period <= hi + period; ++k) {
      const long double v = b + k * period;
      if (v < lo || v > hi) continue;
      h.lo = std::min(h.lo, v);
      h.hi = std::max(h.hi, v);
    }
  }
  return h;
}

::testing::AssertionResult matches_hull(const Interval& r, const Hull& h, const std::string& what) {
  if (h.lo > h.hi) {
    if (r.is_empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << what << ": expected empty, got " << to_string(r);
  }
  const long double tol = 1e-12L * (1.0L + std::fabs(h.lo) + std::fabs(h.hi));
  if (r.lo() <= h.lo && r.hi() >= h.hi && r.lo() > h.lo - tol && r.hi() < h.hi + tol)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": got " << to_string(r) << ", solutions span ["
                                       << static_cast<double>(h.lo) << ", " << static_cast<double>(h.hi) << "]";
}

TEST(IntervalReverse, SinCosTanReversesFindTheExtremeSolutionsOverSeveralPeriods) {
  Sampler s(7);
  for (int i = 0; i < 20000; ++i) {
    const double c = s.uniform(-1.0, 1.0), t = s.uniform(-20.0, 20.0);
    const double lo = s.uniform(-1e3, 1e3), hi = lo + s.uniform(0.0, 8.0) * (1 + static_cast<double>(s.rng() % 6));
    const Interval x(lo, hi);
    const long double as = std::asin(static_cast<long double>(c)), ac = std::acos(static_cast<long double>(c));
    const long double at = std::atan(static_cast<long double>(t));
    ASSERT_TRUE(
        matches_hull(sin_rev(Interval(c), x), solution_hull({as, kPiLong - as}, 2 * kPiLong, lo, hi), "sin_rev"));
    ASSERT_TRUE(matches_hull(cos_rev(Interval(c), x), solution_hull({ac, -ac}, 2 * kPiLong, lo, hi), "cos_rev"));
    ASSERT_TRUE(matches_hull(tan_rev(Interval(t), x), solution_hull({at}, kPiLong, lo, hi), "tan_rev"));
  }
}

TEST(IntervalReverse, PeriodicReversesOnKnownSets) {
  // sin x = 1/2 on [0, 13]: pi/6 + 2k pi and 5pi/6 + 2k pi; the extremes are pi/6 and
  // 5pi/6 + 2pi (pi/6 + 4pi = 13.09 is just outside).
  EXPECT_TRUE(matches_hull(sin_rev(Interval(0.5), Interval(0.0, 13.0)), {kPiLong / 6, 17 * kPiLong / 6}, "sin"));
  // cos x = 1/2 on [-10, 10]: +-pi/3 + 2k pi; the extremes are -7pi/3 and 7pi/3.
  EXPECT_TRUE(matches_hull(cos_rev(Interval(0.5), Interval(-10.0, 10.0)), {-7 * kPiLong / 3, 7 * kPiLong / 3}, "cos"));
  // tan x = 1 on [-5, 5]: pi/4 + k pi; the extremes are -3pi/4 and 5pi/4.
  EXPECT_TRUE(matches_hull(tan_rev(Interval(1.0), Interval(-5.0, 5.0)), {-3 * kPiLong / 4, 5 * kPiLong / 4}, "tan"));
  // No solution inside: sin x = 1 only at pi/2 + 2k pi.
  EXPECT_TRUE(sin_rev(Interval(1.0), Interval(2.0, 3.0)).is_empty());
  EXPECT_TRUE(sin_rev(Interval(2.0, 3.0), Interval::entire()).is_empty());
  EXPECT_EQ(sin_rev(Interval(-1.0, 1.0), Interval(2.0, 3.0)), Interval(2.0, 3.0));
  // Unbounded on one side: the finite end contracts to the last solution before it.
  const Interval left = cos_rev(Interval(1.0), Interval(-kInf, 1.0));
  EXPECT_EQ(left.lo(), -kInf);
  EXPECT_LE(left.hi(), 1e-15);
  EXPECT_GE(left.hi(), 0.0);
  const Interval right = sin_rev(Interval(0.0), Interval(0.5, kInf));  // first solution: pi
  EXPECT_LE(right.lo(), kPiLong);
  EXPECT_GT(right.lo(), kPiLong - 1e-15L);
  EXPECT_EQ(right.hi(), kInf);
}

TEST(IntervalReverse, Atan2ReverseKeepsPointsInEveryQuadrantAndOnTheCut) {
  Sampler s(8);
  std::vector<double> angles = {0.0, 0.3, 1.2, 1.5707963267948966, 2.0, 3.0, 3.141592653589793, -0.3, -1.2,
                                -1.5707963267948966, -2.0, -3.0, -3.141592653589793};
  for (int i = 0; i < 200; ++i) angles.push_back(s.uniform(-3.2, 3.2));
  for (const double phi : angles) {
    for (const double r : {1e-3, 1.0, 7.0, 1e4}) {
      const double x = r * std::cos(phi), y = r * std::sin(phi);
      const Interval theta = s.widened(atan2(Interval(y), Interval(x)));
      Interval yy = Interval(-2e4, 2e4), xx = Interval(-2e4, 2e4);
      ASSERT_TRUE(bwd_atan2(theta, yy, xx)) << phi << " " << r;
      ASSERT_TRUE(contains_point(xx, x) && contains_point(yy, y)) << "phi = " << phi << ", r = " << r;
    }
  }
  // Exactly on the cut: (x, y) = (-2, 0) has angle pi.
  Interval yy(-1.0, 1.0), xx(-3.0, -1.0);
  ASSERT_TRUE(bwd_atan2(Interval::pi(), yy, xx));
  EXPECT_TRUE(yy.contains(0.0));
  EXPECT_TRUE(xx.contains(-2.0));
}

TEST(IntervalReverse, Atan2ReverseContractsTheBoxInEachQuadrant) {
  // theta = pi/4 +- 0.01 with |y| <= 1: y = x tan(theta) gives |x| <= 1 / tan(pi/4 - 0.01).
  const long double bound = 1.0L / std::tan(kPiLong / 4 - 0.01L);
  for (const int quadrant : {0, 1, 2, 3}) {
    const long double center = kPiLong / 4 + quadrant * kPiLong / 2 - (quadrant >= 2 ? 2 * kPiLong : 0);
    const Interval theta(static_cast<double>(center - 0.01L), static_cast<double>(center + 0.01L));
    const double sx = (quadrant == 0 || quadrant == 3) ? 1.0 : -1.0, sy = quadrant <= 1 ? 1.0 : -1.0;
    Interval x = sx > 0 ? Interval(0.0, 10.0) : Interval(-10.0, 0.0);
    Interval y = sy > 0 ? Interval(0.0, 1.0) : Interval(-1.0, 0.0);
    ASSERT_TRUE(bwd_atan2(theta, y, x)) << quadrant;
    EXPECT_GE(std::fabs(sx > 0 ? x.hi() : x.lo()), bound - 1e-12L) << quadrant;  // sound
    EXPECT_LE(std::fabs(sx > 0 ? x.hi() : x.lo()), bound + 1e-9L) << quadrant;   // tight
  }
  // An angle outside the box's range empties it.
  Interval x(1.0, 2.0), y(1.0, 2.0);
  EXPECT_FALSE(bwd_atan2(Interval(-1.0, -0.5), y, x));
  EXPECT_TRUE(x.is_empty() && y.is_empty());
}

TEST(IntervalReverse, MulRevToPairSplitsAroundZero) {
  // x * [-1, 1] = [1, 2]: |x| >= 1, two pieces.
  const auto [first, second] = mul_rev_to_pair(Interval(-1.0, 1.0), Interval(1.0, 2.0));
  EXPECT_EQ(first, Interval(-kInf, -1.0));
  EXPECT_EQ(second, Interval(1.0, kInf));
  EXPECT_EQ(mul_rev(Interval(-1.0, 1.0), Interval(1.0, 2.0), Interval(-0.5, 3.0)), Interval(1.0, 3.0));
  EXPECT_TRUE(mul_rev(Interval(0.0), Interval(1.0, 2.0)).is_empty());
  EXPECT_EQ(mul_rev(Interval(0.0), Interval(-1.0, 2.0)), Interval::entire());
  EXPECT_EQ(mul_rev(Interval(2.0, 4.0), Interval(4.0, 8.0)), Interval(1.0, 4.0));
}

TEST(IntervalReverse, PowerReverseFindsRealRoots) {
  EXPECT_EQ(pow_rev(Interval(4.0, 9.0), Interval::entire(), 2), Interval(-3.0, 3.0));
  EXPECT_EQ(pow_rev(Interval(4.0, 9.0), Interval(0.0, 10.0), 2), Interval(2.0, 3.0));
  EXPECT_EQ(pow_rev(Interval(-8.0, 27.0), Interval::entire(), 3), Interval(-2.0, 3.0));
  EXPECT_TRUE(pow_rev(Interval(-9.0, -4.0), Interval::entire(), 2).is_empty());
  EXPECT_EQ(pow_rev(Interval(0.25, 1.0), Interval(0.0, kInf), -2), Interval(1.0, 2.0));
  EXPECT_TRUE(pow_rev(Interval(0.0), Interval::entire(), -2).is_empty());  // x^-2 is never 0
  EXPECT_EQ(pow_rev(Interval(2.0), Interval::entire(), 0), Interval::empty());
  EXPECT_EQ(pow_rev(Interval(1.0), Interval(3.0, 4.0), 0), Interval(3.0, 4.0));
  // Cube root of 2 = 1.2599210498948731647672...: within two steps (the directed
  // cubes that certify the bounds are themselves within an ulp or two).
  const Interval r = pow_rev(Interval(2.0), Interval(0.0, kInf), 3);
  EXPECT_LE(r.lo(), 1.2599210498948731647672L);
  EXPECT_GE(r.hi(), 1.2599210498948731647672L);
  EXPECT_LE(r.hi(), step_up(r.lo(), 2));
  // denorm_min^(1/3) = 2^-358 exactly, and x^-3 <= denorm_min gives x >= 2^358.
  EXPECT_EQ(pow_rev(Interval(0.0, 0x1p-1074), Interval(0.0, kInf), -3).lo(), 0x1p358);
  // A large exponent does not loop n times per check.
  const Interval big = pow_rev(Interval(2.0), Interval(0.0, kInf), 1000000);
  const long double root = std::exp(std::log(2.0L) / 1e6L);  // 2^(1e-6)
  EXPECT_LE(big.lo(), root);
  EXPECT_GE(big.hi(), root);
  EXPECT_LT(big.width(), 1e-12);
}

}  // namespace
}  // namespace gesmi
