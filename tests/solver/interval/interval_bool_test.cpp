// Interval Booleans and Kearfott's chi function (solver/interval/interval_bool.h):
// the truth tables of the three-valued logic, comparisons of intervals, and chi
// on points, intervals and Booleans (seed 000, section 2).

#include "solver/interval/interval_bool.h"

#include <gtest/gtest.h>

#include <random>

namespace gesmi {
namespace {

const IBool kYes(true), kNo(false), kMaybe = IBool::maybe(), kNone = IBool::empty();

// The set of values of an IBool, as a bit mask: 1 = false possible, 2 = true possible.
int values(IBool b) { return (b.may_be_false() ? 1 : 0) | (b.may_be_true() ? 2 : 0); }

// The image of a binary Boolean operator over the value sets of a and b.
template <class Op>
int image(IBool a, IBool b, Op op) {
  int out = 0;
  for (const bool u : {false, true})
    for (const bool v : {false, true})
      if ((values(a) >> u & 1) && (values(b) >> v & 1)) out |= op(u, v) ? 2 : 1;
  return out;
}

TEST(IBool, LogicIsTheImageOfTheValueSets) {
  for (const IBool a : {kYes, kNo, kMaybe}) {
    for (const IBool b : {kYes, kNo, kMaybe}) {
      EXPECT_EQ(values(a && b), image(a, b, [](bool u, bool v) { return u && v; }));
      EXPECT_EQ(values(a || b), image(a, b, [](bool u, bool v) { return u || v; }));
      EXPECT_EQ(values(hull(a, b)), values(a) | values(b));
    }
    EXPECT_EQ(values(!a), image(a, a, [](bool u, bool) { return !u; }));
  }
}

TEST(IBool, EmptyPropagates) {
  EXPECT_TRUE((kNone && kYes).is_empty());
  EXPECT_TRUE((kMaybe || kNone).is_empty());
  EXPECT_TRUE((!kNone).is_empty());
  EXPECT_EQ(hull(kNone, kNo), kNo);
  EXPECT_FALSE(kNone.may_be_true() || kNone.may_be_false());
}

TEST(IBool, ComparisonsAreCertainOnlyWhenEveryPairAgrees) {
  const Interval a(1.0, 2.0), b(2.0, 3.0), c(2.5, 4.0);
  EXPECT_EQ(leq(a, b), kYes);  // every point of a is <= every point of b
  EXPECT_EQ(less(a, b), kMaybe);  // 2 < 2 is false, 1 < 3 is true
  EXPECT_EQ(less(a, c), kYes);
  EXPECT_EQ(greater(c, a), kYes);
  EXPECT_EQ(geq(a, c), kNo);
  EXPECT_EQ(leq(c, a), kNo);
  EXPECT_EQ(member(Interval(2.2, 2.4), b), kYes);
  EXPECT_EQ(member(Interval(2.9, 3.4), b), kMaybe);
  EXPECT_EQ(member(Interval(5.0), b), kNo);
  EXPECT_TRUE(leq(Interval::empty(), a).is_empty());
  // Sampled: the IBool contains the truth value of every pair of points.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < 20000; ++i) {
    const double p = u(rng), q = u(rng), r = u(rng), s = u(rng);
    const Interval x(std::min(p, q), std::max(p, q)), y(std::min(r, s), std::max(r, s));
    for (const double t : {x.lo(), x.hi(), p})
      for (const double w : {y.lo(), y.hi(), r}) {
        ASSERT_TRUE(values(leq(x, y)) >> (t <= w) & 1);
        ASSERT_TRUE(values(less(x, y)) >> (t < w) & 1);
      }
  }
}

TEST(IBool, ChiSelectsByTheSignOfItsFirstArgument) {
  EXPECT_EQ(chi(-1.0, 2.0, 3.0), 2.0);
  EXPECT_EQ(chi(0.0, 2.0, 3.0), 2.0);  // a <= 0 selects b
  EXPECT_EQ(chi(1e-300, 2.0, 3.0), 3.0);
  const Interval b(1.0, 2.0), c(5.0, 6.0);
  EXPECT_EQ(chi(Interval(-2.0, 0.0), b, c), b);
  EXPECT_EQ(chi(Interval(0.5, 2.0), b, c), c);
  EXPECT_EQ(chi(Interval(-1.0, 1.0), b, c), Interval(1.0, 6.0));
  EXPECT_TRUE(chi(Interval::empty(), b, c).is_empty());
  EXPECT_EQ(chi(kMaybe, kYes, kNo), kMaybe);
  EXPECT_EQ(chi(kYes, kNo, kYes), kNo);
  EXPECT_EQ(select(kNo, b, c), c);
  EXPECT_EQ(select(kMaybe, b, c), Interval(1.0, 6.0));
  EXPECT_EQ(select(true, 1.0, 2.0), 1.0);
  // Inclusion: chi over an interval contains chi at each of its points.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 10000; ++i) {
    const double p = u(rng), q = u(rng);
    const Interval a(std::min(p, q), std::max(p, q));
    for (const double t : {a.lo(), a.hi(), 0.5 * (p + q)}) ASSERT_TRUE(chi(a, b, c).contains(chi(t, 1.5, 5.5)));
  }
}

}  // namespace
}  // namespace gesmi
