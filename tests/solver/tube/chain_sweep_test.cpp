// The upward-rounding kernels must enclose the exact result, agree with the
// portable Interval version up to its extra outward step, and report emptiness.

#include "solver/tube/chain_sweep.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace gesmi {
namespace {

// Exact error of a rounded-to-nearest sum (Knuth's TwoSum): a + b = s + e exactly.
double two_sum_error(double a, double b, double s) {
  const double bb = s - a;
  return (a - (s - bb)) + (b - bb);
}
// lo <= a + b exactly?
bool below_exact_sum(double lo, double a, double b) {
  const double s = a + b;
  const double e = two_sum_error(a, b, s);
  return lo < s || (lo == s && e >= 0.0);
}
bool above_exact_sum(double hi, double a, double b) {
  const double s = a + b;
  const double e = two_sum_error(a, b, s);
  return hi > s || (hi == s && e <= 0.0);
}

std::vector<Interval> random_steps(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> centre(-3.0, 3.0), half(0.0, 0.05);
  std::vector<Interval> v(n);
  for (auto& s : v) {
    const double c = centre(rng) * 0.1 + 1e-7 * centre(rng);  // inexact sums
    const double h = half(rng);
    s = Interval(c - h, c + h);
  }
  return v;
}

TEST(ChainSweep, ForwardKernelEnclosesEveryExactSumAndIsWithinThePortableResult) {
  std::mt19937_64 rng(7);
  const std::size_t n = 5000;
  const std::vector<Interval> v = random_steps(rng, n - 1);
  std::vector<Interval> fast(n), portable(n);
  fast[0] = portable[0] = Interval(0.1, 0.3);
  ASSERT_TRUE(chain_forward(fast, v).consistent());
  ASSERT_TRUE(chain_forward_portable(portable, v).consistent());
  for (std::size_t k = 0; k + 1 < n; ++k) {
    EXPECT_TRUE(below_exact_sum(fast[k + 1].lo(), fast[k].lo(), v[k].lo())) << k;
    EXPECT_TRUE(above_exact_sum(fast[k + 1].hi(), fast[k].hi(), v[k].hi())) << k;
    EXPECT_TRUE(portable[k + 1].is_superset(fast[k + 1])) << k;
  }
}

TEST(ChainSweep, BackwardKernelMatchesPortableContractionUpToRounding) {
  std::mt19937_64 rng(11);
  const std::size_t n = 3000;
  std::vector<Interval> v_fast = random_steps(rng, n - 1), v_portable = v_fast;
  std::vector<Interval> fast(n, Interval::entire()), portable(n, Interval::entire());
  fast[0] = portable[0] = Interval(0.0);
  chain_forward(fast, v_fast);
  chain_forward_portable(portable, v_portable);
  // A final fix tighter than dead reckoning, so the backward sweep contracts.
  const std::vector<Interval> after_forward = fast;
  const Interval fix(fast[n - 1].mid() - 0.01, fast[n - 1].mid() + 0.01);
  fast[n - 1].intersect_with(fix);
  portable[n - 1].intersect_with(fix);
  ASSERT_TRUE(chain_backward(fast, v_fast).consistent());
  ASSERT_TRUE(chain_backward_portable(portable, v_portable).consistent());
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_TRUE(portable[k].is_superset(fast[k])) << k;
    EXPECT_LE(portable[k].width() - fast[k].width(), 1e-9) << k;
  }
  // Contracted by the final fix, not just copied: the domain just before it shrank.
  EXPECT_LT(fast[n - 2].width(), 0.1 * after_forward[n - 2].width());
}

TEST(ChainSweep, ReportsTheFirstStepThatBecomesEmpty) {
  std::vector<Interval> x(10, Interval::entire());
  const std::vector<Interval> v(9, Interval(1.0, 1.5));
  x[0] = Interval(0.0);
  x[6] = Interval(100.0, 101.0);  // unreachable: at most 9 m after 6 steps
  std::vector<Interval> y = x;
  const SweepResult fast = chain_forward(x, v);
  const SweepResult portable = chain_forward_portable(y, v);
  EXPECT_EQ(fast.first_empty, 6u);
  EXPECT_EQ(portable.first_empty, 6u);
  EXPECT_TRUE(x[6].is_empty());
}

TEST(ChainSweep, LeavesTheRoundingModeAsItWas) {
  std::vector<Interval> x(4, Interval::entire());
  std::vector<Interval> v(3, Interval(0.1, 0.2));
  x[0] = Interval(0.0);
  chain_forward(x, v);
  chain_backward(x, v);
  volatile double third = 1.0;
  third = third / 3.0;
  EXPECT_EQ(third, 1.0 / 3.0);  // round-to-nearest result
}

}  // namespace
}  // namespace gesmi

namespace gesmi {
namespace {

// A chain at its fixpoint, narrowed at one point: spreading from there until the
// domains stop shrinking gives what full sweeps give.
TEST(ChainSweep, SpreadFromAChangedPointMatchesFullSweeps) {
  std::mt19937_64 rng(3);
  const std::size_t n = 4000;
  std::vector<Interval> v = random_steps(rng, n - 1);
  std::vector<Interval> x(n, Interval::entire());
  x[0] = Interval(-1.0, 1.0);
  ASSERT_TRUE(chain_forward(x, v).consistent());
  x[n - 1] = Interval(x[n - 1].mid() - 1.0, x[n - 1].mid() + 1.0);  // a final fix
  ASSERT_TRUE(chain_backward(x, v).consistent());
  ASSERT_TRUE(chain_forward(x, v).consistent());
  std::vector<Interval> full = x, full_v = v, spread = x, spread_v = v;
  const std::size_t k = n / 3;
  const Interval narrowed(x[k].mid() - 0.001, x[k].mid() + 0.001);
  full[k].intersect_with(narrowed);
  spread[k].intersect_with(narrowed);
  chain_forward(full, full_v);
  chain_backward(full, full_v);
  const SweepResult f = chain_forward_from(spread, spread_v, k, 0.0);
  const SweepResult b = chain_backward_from(spread, spread_v, k, 0.0);
  EXPECT_TRUE(f.consistent());
  EXPECT_TRUE(b.consistent());
  EXPECT_GT(f.last, k);
  EXPECT_LT(b.last, k);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(spread[i], full[i]) << i;
}

}  // namespace
}  // namespace gesmi
