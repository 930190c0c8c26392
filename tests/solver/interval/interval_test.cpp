// gesmi::Interval (solver/interval/interval.h): representation, empty and
// unbounded cases, the extended division of IEEE 1788, mid/rad/width and the
// enclosure property of the arithmetic. Expected values are the mathematical
// results; sampled points are checked in x87 long double, where the sums and
// products of the short doubles used are exact.

#include "solver/interval/interval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::contains;

using test::kMax;
const Interval kEmpty = Interval::empty();
const Interval kEntire = Interval::entire();

TEST(Interval, DefaultIsTheWholeLine) {
  EXPECT_TRUE(Interval().is_entire());
  EXPECT_EQ(Interval(), Interval(-kInf, kInf));
}

TEST(Interval, EmptyHasOneRepresentation) {
  for (const Interval& e : {Interval(2.0, 1.0), Interval(std::nan(""), 1.0), Interval(kInf), Interval(-kInf, -kInf),
                            Interval(kInf, kInf), Interval(std::nan("")), kEmpty}) {
    EXPECT_TRUE(e.is_empty());
    EXPECT_EQ(e.lo(), kInf);
    EXPECT_EQ(e.hi(), -kInf);
    EXPECT_EQ(e, kEmpty);
  }
  EXPECT_FALSE(kEmpty.contains(0.0));
  EXPECT_TRUE(kEmpty.is_subset(Interval(1.0)));
  EXPECT_FALSE(kEmpty.intersects(kEntire));
}

TEST(Interval, OperationsOnEmptyAreEmpty) {
  const Interval x(1.0, 2.0);
  EXPECT_TRUE((x + kEmpty).is_empty());
  EXPECT_TRUE((kEmpty - x).is_empty());
  EXPECT_TRUE((x * kEmpty).is_empty());
  EXPECT_TRUE((kEmpty / x).is_empty());
  EXPECT_TRUE(sqr(kEmpty).is_empty());
  EXPECT_TRUE(sqrt(kEmpty).is_empty());
  EXPECT_TRUE(abs(kEmpty).is_empty());
  EXPECT_TRUE(min(x, kEmpty).is_empty());
  EXPECT_TRUE((-kEmpty).is_empty());
  EXPECT_EQ(hull(kEmpty, x), x);
  EXPECT_TRUE(intersect(kEmpty, x).is_empty());
  EXPECT_TRUE(std::isnan(kEmpty.width()));
  EXPECT_TRUE(std::isnan(kEmpty.mid()));
  EXPECT_TRUE(std::isnan(kEmpty.rad()));
}

TEST(Interval, UnboundedArithmeticFollowsTheLimits) {
  EXPECT_EQ(Interval(1.0, kInf) + Interval(-kInf, 2.0), kEntire);
  EXPECT_EQ(Interval(1.0, kInf) - Interval(1.0, kInf), kEntire);
  EXPECT_EQ(Interval(1.0, kInf) * Interval(0.0), Interval(0.0));  // 0 * x = 0 for every real x
  EXPECT_EQ(kEntire * Interval(0.0), Interval(0.0));
  EXPECT_EQ(Interval(-kInf, -1.0) * Interval(-kInf, -1.0), Interval(1.0, kInf));
  EXPECT_EQ(Interval(-kInf, -1.0) * Interval(2.0, 3.0), Interval(-kInf, -2.0));
  EXPECT_EQ(Interval(0.0, kInf) * Interval(-1.0, 1.0), kEntire);
  EXPECT_EQ(sqr(Interval(-kInf, 2.0)), Interval(0.0, kInf));
  EXPECT_EQ(sqrt(Interval(-4.0, kInf)), Interval(0.0, kInf));
  EXPECT_TRUE(sqrt(Interval(-4.0, -1.0)).is_empty());
  EXPECT_EQ(Interval(kMax) + Interval(kMax), Interval(kMax, kInf));  // overflow: still encloses 2 max
}

TEST(Interval, DivisionCoversEveryExtendedCase) {
  // IEEE 1788: x / y is the hull of {a / b : a in x, b in y, b != 0}.
  const Interval pos(1.0, 2.0), neg(-2.0, -1.0), mixed(-1.0, 1.0), zero(0.0);
  EXPECT_TRUE((pos / zero).is_empty());
  EXPECT_TRUE((zero / zero).is_empty());
  EXPECT_EQ(pos / Interval(0.0, 1.0), Interval(1.0, kInf));
  EXPECT_EQ(pos / Interval(-0.0, 1.0), Interval(1.0, kInf));
  EXPECT_EQ(pos / Interval(-1.0, 0.0), Interval(-kInf, -1.0));
  EXPECT_EQ(neg / Interval(0.0, 1.0), Interval(-kInf, -1.0));
  EXPECT_EQ(neg / Interval(-1.0, 0.0), Interval(1.0, kInf));
  EXPECT_EQ(pos / mixed, kEntire);
  EXPECT_EQ(mixed / Interval(0.0, 1.0), kEntire);
  EXPECT_EQ(zero / mixed, zero);
  EXPECT_EQ(Interval(0.0, 1.0) / Interval(0.0, 1.0), Interval(0.0, kInf));
  EXPECT_EQ(Interval(-1.0, 0.0) / Interval(0.0, 1.0), Interval(-kInf, 0.0));
  EXPECT_EQ(pos / Interval(1.0, kInf), Interval(0.0, 2.0));
  EXPECT_EQ(pos / Interval(-kInf, -1.0), Interval(-2.0, 0.0));
  EXPECT_EQ(Interval(2.0, 4.0) / Interval(-2.0, -1.0), Interval(-4.0, -1.0));
  EXPECT_EQ(recip(Interval(2.0, 4.0)), Interval(0.25, 0.5));
  EXPECT_EQ(recip(Interval(0.0, 4.0)), Interval(0.25, kInf));
  const Interval third = Interval(1.0) / Interval(3.0);
  EXPECT_EQ(third.lo(), next_down(third.hi()));  // 1/3 is not a double: one step wide
  EXPECT_LT(3.0L * third.lo(), 1.0L);
  EXPECT_GT(3.0L * third.hi(), 1.0L);
}

TEST(Interval, MidRadAndWidthCoverTheInterval) {
  EXPECT_EQ(Interval(1.0, 2.0).mid(), 1.5);
  EXPECT_EQ(kEntire.mid(), 0.0);
  EXPECT_EQ(Interval(-kInf, 3.0).mid(), -kMax);
  EXPECT_EQ(Interval(3.0, kInf).mid(), kMax);
  EXPECT_EQ(Interval(-kMax, kMax).mid(), 0.0);
  EXPECT_EQ(Interval(kMax / 2, kMax).mid(), 0.75 * kMax);  // lo + hi overflows
  EXPECT_EQ(Interval(1.0, kInf).width(), kInf);
  EXPECT_EQ(Interval(-kMax, kMax).width(), kInf);  // 2 max rounded up
  EXPECT_EQ(Interval(1.0, kInf).rad(), kInf);
  EXPECT_EQ(Interval(5.0).rad(), 0.0);
  EXPECT_EQ(Interval(-3.0, 2.0).mag(), 3.0);
  EXPECT_EQ(Interval(-3.0, 2.0).mig(), 0.0);
  EXPECT_EQ(Interval(-3.0, -2.0).mig(), 2.0);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int i = 0; i < 100000; ++i) {
    const double a = u(rng), b = a + std::ldexp(u(rng) * u(rng), -static_cast<int>(rng() % 40));
    const Interval x(std::min(a, b), std::max(a, b));
    const long double lo = x.lo(), hi = x.hi(), m = x.mid(), r = x.rad(), w = x.width();
    ASSERT_TRUE(x.contains(x.mid()));
    ASSERT_LE(m - r, lo);  // exact in long double: the bounds are within 2^20 of each other
    ASSERT_GE(m + r, hi);
    ASSERT_GE(w, hi - lo);
    ASSERT_LE(w, (hi - lo) * (1 + 0x1p-52L));
  }
}

TEST(Interval, SetOperationsAndRelations) {
  const Interval a(1.0, 3.0), b(2.0, 5.0);
  EXPECT_EQ(intersect(a, b), Interval(2.0, 3.0));
  EXPECT_TRUE(intersect(a, Interval(4.0, 5.0)).is_empty());
  EXPECT_EQ(hull(a, b), Interval(1.0, 5.0));
  EXPECT_EQ(hull(a, 7.0), Interval(1.0, 7.0));
  EXPECT_EQ(min(a, b), Interval(1.0, 3.0));
  EXPECT_EQ(max(a, b), Interval(2.0, 5.0));
  EXPECT_EQ(abs(Interval(-4.0, 2.0)), Interval(0.0, 4.0));
  EXPECT_TRUE(Interval(2.0, 2.5).is_interior_subset(a));
  EXPECT_FALSE(Interval(1.0, 2.0).is_interior_subset(a));
  EXPECT_TRUE(kEntire.is_interior_subset(kEntire));  // the interior of R is R
  EXPECT_TRUE(precedes(Interval(1.0, 2.0), Interval(2.0, 3.0)));
  EXPECT_FALSE(strictly_precedes(Interval(1.0, 2.0), Interval(2.0, 3.0)));
  EXPECT_TRUE(precedes(kEmpty, a));
  EXPECT_TRUE(weakly_less(a, b));
  EXPECT_FALSE(weakly_less(b, a));
  EXPECT_TRUE(strictly_less(a, b));
  EXPECT_TRUE(strictly_less(Interval(-kInf, 1.0), Interval(-kInf, 2.0)));
  EXPECT_FALSE(strictly_less(Interval(1.0, kInf), Interval(2.0, 3.0)));
  EXPECT_TRUE(weakly_less(kEmpty, kEmpty));
  EXPECT_FALSE(weakly_less(kEmpty, a));
}

// Random intervals whose bounds (and sampled points) have at most `bits`
// significant bits and exponents in [-20, 20]: sums and products of 24-bit points
// are exact in long double, and so is a 53-bit bound times an 11-bit point.
struct ShortSampler {
  std::mt19937_64 rng{31};
  double value(int bits) {
    std::uniform_int_distribution<long long> mantissa(1LL << (bits - 1), (1LL << bits) - 1);
    std::uniform_int_distribution<int> exponent(-20, 20);
    const double m = std::ldexp(static_cast<double>(mantissa(rng)), exponent(rng) - bits);
    return rng() % 8 == 0 ? 0.0 : (rng() & 1 ? -m : m);
  }
  Interval interval(int bits) {
    const double a = value(bits), b = value(bits);
    return Interval(std::min(a, b), std::max(a, b));
  }
  double point(const Interval& x, int bits) {  // an end point, or a short double inside
    switch (rng() % 4) {
      case 0: return x.lo();
      case 1: return x.hi();
      default: {
        const double v = value(bits);
        return x.contains(v) ? v : x.lo();
      }
    }
  }
};

// a / b lies in q, decided exactly: q.lo * b <= a <= q.hi * b for b > 0.
bool contains_quotient(const Interval& q, double a, double b) {
  const long double s = b > 0 ? 1.0L : -1.0L, lb = b;
  return s * (q.lo() * lb) <= s * a && s * a <= s * (q.hi() * lb);
}

TEST(Interval, ArithmeticEnclosesEveryPointResult) {
  ShortSampler s;
  for (int i = 0; i < 200000; ++i) {
    const Interval x = s.interval(24), y = s.interval(24), d = s.interval(11);
    const double a = s.point(x, 24), b = s.point(y, 24), c = s.point(d, 11);
    const long double la = a, lb = b;
    const Interval sum = x + y, diff = x - y, prod = x * y, sq = sqr(x);
    ASSERT_TRUE(sum.lo() <= la + lb && la + lb <= sum.hi());
    ASSERT_TRUE(diff.lo() <= la - lb && la - lb <= diff.hi());
    ASSERT_TRUE(prod.lo() <= la * lb && la * lb <= prod.hi());
    ASSERT_TRUE(sq.lo() <= la * la && la * la <= sq.hi());
    if (c != 0.0) {
      ASSERT_TRUE(contains_quotient(x / d, a, c)) << a << " / " << c;
    }
    if (a >= 0.0) {
      const Interval r = sqrt(x);
      const long double root = std::sqrt(la);
      ASSERT_TRUE(r.lo() <= root && root <= r.hi());
    }
  }
}

TEST(Interval, SquareOfAMixedIntervalStartsAtZero) {
  EXPECT_EQ(sqr(Interval(-2.0, 3.0)), Interval(0.0, 9.0));
  EXPECT_EQ(Interval(-2.0, 3.0) * Interval(-2.0, 3.0), Interval(-6.0, 9.0));  // no dependency tracking
  EXPECT_EQ(sqr(Interval(-3.0, -2.0)), Interval(4.0, 9.0));
  EXPECT_EQ(sqr(Interval(0.1)).lo(), mul_down(0.1, 0.1));
}

}  // namespace
}  // namespace gesmi
