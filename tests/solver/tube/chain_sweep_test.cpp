// The upward-rounding kernels must enclose the exact result, agree with the
// portable Interval version up to its extra outward step, and report emptiness.

#include "solver/tube/chain_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <random>
#include <span>
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

namespace gesmi {
namespace {

// The three chains of a tube, each with priors here and there and a few fixes: what
// the joint sweeps must leave, bit for bit, is what one sweep per chain leaves.
struct ThreeChains {
  std::array<std::vector<Interval>, 3> x, v;
  ThreeChains(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> wide(5.0, 50.0);
    for (int a = 0; a < 3; ++a) {
      v[static_cast<std::size_t>(a)] = random_steps(rng, n - 1);
      std::vector<Interval>& chain = x[static_cast<std::size_t>(a)];
      chain.assign(n, Interval::entire());
      double centre = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        if (k > 0) centre += v[static_cast<std::size_t>(a)][k - 1].mid();
        if (k % 89 == 0) chain[k] = Interval(centre - wide(rng), centre + wide(rng));  // a prior here and there
        // Two narrow fixes in a row: narrower than the step between them, which they narrow.
        if (k % 97 == 0 || k % 97 == 1) chain[k] = Interval(centre - 0.005, centre + 0.005);
      }
      chain[0] = Interval(-0.5, 0.5);
      chain[n - 1] = Interval(centre - 1.0, centre + 1.0);  // a final fix
    }
  }
  std::array<std::span<Interval>, 3> positions() { return {x[0], x[1], x[2]}; }
  std::array<std::span<Interval>, 3> steps() { return {v[0], v[1], v[2]}; }
  std::array<std::span<const Interval>, 3> steps_const() { return {v[0], v[1], v[2]}; }
};

void expect_bitwise_equal(const std::vector<Interval>& a, const std::vector<Interval>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i].lo()), std::bit_cast<std::uint64_t>(b[i].lo())) << what << " " << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i].hi()), std::bit_cast<std::uint64_t>(b[i].hi())) << what << " " << i;
  }
}

TEST(ChainSweep, ThreeChainsTogetherAreThreeSweepsBitForBit) {
  std::mt19937_64 rng(19);
  for (const std::size_t n : {std::size_t{2}, std::size_t{3}, std::size_t{5000}}) {
    ThreeChains together(rng, n);
    ThreeChains one_by_one = together;
    const ChainsSweepResult f = chains_forward(together.positions(), together.steps_const());
    const ChainsSweepResult b = chains_backward(together.positions(), together.steps());
    double forward_shrink = 0.0, backward_shrink = 0.0;
    for (int a = 0; a < 3; ++a) {
      const auto i = static_cast<std::size_t>(a);
      const SweepResult fa = chain_forward(one_by_one.x[i], one_by_one.v[i]);
      ASSERT_TRUE(fa.consistent());
      forward_shrink = std::max(forward_shrink, fa.max_shrink);
    }
    for (int a = 0; a < 3; ++a) {
      const auto i = static_cast<std::size_t>(a);
      const SweepResult ba = chain_backward(one_by_one.x[i], one_by_one.v[i]);
      ASSERT_TRUE(ba.consistent());
      backward_shrink = std::max(backward_shrink, ba.max_shrink);
    }
    ASSERT_TRUE(f.consistent() && b.consistent()) << n;
    EXPECT_EQ(f.sweep.max_shrink, forward_shrink) << n;
    EXPECT_EQ(b.sweep.max_shrink, backward_shrink) << n;
    for (std::size_t i = 0; i < 3; ++i) {
      expect_bitwise_equal(together.x[i], one_by_one.x[i], "position");
      expect_bitwise_equal(together.v[i], one_by_one.v[i], "step");
    }
  }
}

// Chains that empty: the result names the first chain, in axis order, that a sweep per
// chain finds empty, and where; the chains before it are swept whole, as one by one.
TEST(ChainSweep, ThreeChainsTogetherNameTheFirstChainThatEmpties) {
  struct Case {
    std::array<std::size_t, 3> empty_at;  // the sample made impossible on each chain (0: none)
    int chain;
    std::size_t first_empty;
  };
  const std::size_t n = 3000;
  // A later chain emptying earlier does not hide an earlier chain emptying later.
  for (const Case& c : {Case{{0, 700, 0}, 1, 700}, Case{{2000, 700, 0}, 0, 2000}, Case{{0, 2500, 300}, 1, 2500},
                        Case{{0, 0, 1200}, 2, 1200}, Case{{900, 900, 900}, 0, 900},
                        // backward, chain 1 empties first (from the end), chain 0 later:
                        Case{{700, 2000, 0}, 0, 700}}) {
    for (const bool forward : {true, false}) {
      std::mt19937_64 rng(23);
      ThreeChains together(rng, n);
      for (std::size_t a = 0; a < 3; ++a) {
        if (c.empty_at[a] == 0) continue;
        // A prior far beyond what the steps allow from either end.
        const std::size_t k = c.empty_at[a];
        together.x[a][k] = Interval(1e6, 1e6 + 1.0);
      }
      ThreeChains one_by_one = together;
      const ChainsSweepResult r = forward ? chains_forward(together.positions(), together.steps_const())
                                          : chains_backward(together.positions(), together.steps());
      ASSERT_FALSE(r.consistent());
      // The expected: sweeps chain by chain, stopping at the first that empties.
      int chain = -1;
      std::size_t first_empty = 0;
      for (std::size_t a = 0; a < 3 && chain < 0; ++a) {
        const SweepResult s = forward ? chain_forward(one_by_one.x[a], one_by_one.v[a])
                                      : chain_backward(one_by_one.x[a], one_by_one.v[a]);
        if (!s.consistent()) {
          chain = static_cast<int>(a);
          first_empty = s.first_empty;
        }
      }
      EXPECT_EQ(r.chain, chain) << forward;
      EXPECT_EQ(r.sweep.first_empty, first_empty) << forward;
      if (forward) {  // (backward, the sample made impossible is found from the end)
        EXPECT_EQ(r.chain, c.chain);
        EXPECT_EQ(r.sweep.first_empty, c.first_empty);
      }
      EXPECT_EQ(r.sweep.max_shrink, kInf);
      for (int a = 0; a <= chain; ++a) {
        const auto i = static_cast<std::size_t>(a);
        expect_bitwise_equal(together.x[i], one_by_one.x[i], "position");
        expect_bitwise_equal(together.v[i], one_by_one.v[i], "step");
      }
      EXPECT_TRUE(together.x[static_cast<std::size_t>(chain)][first_empty].is_empty());
    }
  }
}

}  // namespace
}  // namespace gesmi
