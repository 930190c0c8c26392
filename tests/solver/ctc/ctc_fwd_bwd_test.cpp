// Forward-backward contraction of expressions: the examples of seed 001 (III-A, III-B)
// and the contractor properties (contractance, soundness on sampled points).

#include "solver/ctc/ctc_fwd_bwd.h"

#include <gtest/gtest.h>

#include <random>

#include "solver/ctc/propagation.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::contains;

TEST(CtcFwdBwd, ContractsTheSumExampleOfSectionIIIA) {
  // z = x + y with x <= 5, y <= 4, z >= 6 gives x in [2,5], y in [1,4], z in [6,9].
  const Expr x = Expr::var(0), y = Expr::var(1), z = Expr::var(2);
  Box box{Interval(-kInf, 5.0), Interval(-kInf, 4.0), Interval(6.0, kInf)};
  CtcFwdBwd(z - (x + y), Interval(0.0)).contract(box);
  EXPECT_TRUE(contains(box[0], Interval(2.0, 5.0)));
  EXPECT_TRUE(contains(box[1], Interval(1.0, 4.0)));
  EXPECT_TRUE(contains(box[2], Interval(6.0, 9.0)));
  EXPECT_LE(box[0].lo(), 2.0);
  EXPECT_GT(box[0].lo(), 2.0 - 1e-12);
}

TEST(CtcFwdBwd, ProvesTheSystemOfSectionIIIBHasNoSolution) {
  // y = x^2, x y = 1, y = -2x + 1: propagation empties the domains.
  const Expr x = Expr::var(0), y = Expr::var(1);
  const std::vector<CtcAny> contractors = {CtcFwdBwd(y - sqr(x), Interval(0.0)), CtcFwdBwd(x * y, Interval(1.0)),
                                           CtcFwdBwd(y + 2.0 * x, Interval(1.0))};
  Box box{Interval::entire(), Interval::entire()};
  const PropagationReport report = propagate(contractors, box);
  EXPECT_TRUE(report.empty);
  EXPECT_TRUE(box[0].is_empty());
  EXPECT_TRUE(box[1].is_empty());
}

TEST(CtcFwdBwd, EmptiesBoxWhenSqrtArgumentIsNegative) {
  const Expr x = Expr::var(0);
  Box box{Interval(-4.0, -1.0)};
  CtcFwdBwd(sqrt(x), Interval(0.0, 1.0)).contract(box);
  EXPECT_TRUE(box[0].is_empty());
}

TEST(CtcFwdBwd, SharedSubexpressionIsOneNodeNarrowedByEachUse) {
  // s + s = 8 with s = x^2: HC4 sees two occurrences of s, so s in [0, 8] and
  // |x| <= sqrt(8); the shared node receives both narrowings.
  const Expr x = Expr::var(0);
  const Expr s = sqr(x);
  Box box{Interval(-10.0, 10.0)};
  CtcFwdBwd(s + s, Interval(8.0)).contract(box);
  EXPECT_TRUE(contains(box[0], Interval(-2.0, 2.0)));
  EXPECT_LE(box[0].hi(), std::sqrt(8.0) + 1e-12);
  EXPECT_GE(box[0].lo(), -std::sqrt(8.0) - 1e-12);
}

// Random boxes, random points inside satisfying the constraint: never removed,
// and the result is always inside the input box.
TEST(CtcFwdBwd, NeverRemovesASolutionAndNeverEnlarges) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const Expr x = Expr::var(0), y = Expr::var(1);
  const Expr f = exp(sin(x) * y) + atan2(y, x) - sqrt(abs(x * y) + 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double px = u(rng), py = u(rng);
    const Interval fp = eval(f, Box{Interval(px), Interval(py)});
    ASSERT_FALSE(fp.is_empty());
    const double w = 0.01 + std::fabs(u(rng));
    const Box prior{Interval(px - w, px + 0.5 * w), Interval(py - 0.3 * w, py + w)};
    Box box = prior;
    CtcFwdBwd(f, Interval(fp.lo() - 1e-9, fp.hi() + 1e-9)).contract(box);
    ASSERT_TRUE(box[0].contains(px) && box[1].contains(py)) << trial;
    EXPECT_TRUE(contains(prior[0], box[0]));
    EXPECT_TRUE(contains(prior[1], box[1]));
  }
}

}  // namespace
}  // namespace gesmi
