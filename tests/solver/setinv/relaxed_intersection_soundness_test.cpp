// The q-relaxed intersection (solver/setinv/relaxed_intersection.h) against a
// brute force over all subsets: the set of points lying in at least n - q of the
// n intervals is the union, over the subsets of n - q intervals, of their
// intersections, and its hull is what the sweep must return, exactly (its bounds
// are input bounds, so no rounding is involved). Inputs are small random families
// with many ties (shared and touching end points, degenerate intervals), empty and
// unbounded intervals, and every q from 0 to beyond n.

#include "solver/setinv/relaxed_intersection.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace gesmi {
namespace {

Interval brute_force(const std::vector<Interval>& xs, int q) {
  const int n = static_cast<int>(xs.size()), needed = n - q;
  if (needed <= 0) return Interval::entire();
  Interval hull_of_all = Interval::empty();
  for (unsigned subset = 0; subset < (1u << n); ++subset) {
    if (__builtin_popcount(subset) != needed) continue;
    Interval common = Interval::entire();
    for (int i = 0; i < n; ++i)
      if (subset >> i & 1) common = intersect(common, xs[static_cast<std::size_t>(i)]);
    hull_of_all = hull(hull_of_all, common);
  }
  return hull_of_all;
}

std::string text(const std::vector<Interval>& xs) {
  std::string s;
  for (const Interval& x : xs) {
    char b[64];
    if (x.is_empty())
      std::snprintf(b, sizeof b, "[empty] ");
    else
      std::snprintf(b, sizeof b, "[%g, %g] ", x.lo(), x.hi());
    s += b;
  }
  return s;
}

TEST(RelaxedIntersectionSoundness, EqualsTheHullOfAllSubsetIntersections) {
  std::mt19937_64 rng(0x9e1a);
  std::vector<std::pair<double, int>> scratch;
  int failures = 0, cases = 0, non_trivial = 0;
  std::string first;
  for (int c = 0; c < 40000; ++c) {
    const int n = 1 + static_cast<int>(rng() % 8);
    std::vector<Interval> xs;
    for (int i = 0; i < n; ++i) {
      const auto kind = rng() % 12;
      // End points on a coarse grid: ties and touching intervals are frequent.
      const double a = static_cast<double>(static_cast<int>(rng() % 9) - 4) * 0.5;
      const double b = a + static_cast<double>(rng() % 4) * 0.5;
      if (kind == 0)
        xs.push_back(Interval::empty());
      else if (kind == 1)
        xs.push_back(Interval(-kInf, b));
      else if (kind == 2)
        xs.push_back(Interval(a, kInf));
      else if (kind == 3)
        xs.push_back(Interval(a));  // degenerate
      else
        xs.push_back(Interval(a, b));
    }
    for (int q = 0; q <= n + 1; ++q) {
      ++cases;
      const Interval expected = brute_force(xs, q);
      const Interval got = relaxed_intersection(xs, q, scratch);
      non_trivial += !expected.is_empty() && !expected.is_entire();
      if (!(got == expected) && failures++ == 0) {
        char b[120];
        std::snprintf(b, sizeof b, "q = %d: got [%g, %g], the subsets give [%g, %g]", q, got.lo(), got.hi(),
                      expected.lo(), expected.hi());
        first = text(xs) + b;
      }
    }
  }
  std::printf("relaxed intersection: %d cases, %d non-trivial, %d failures\n", cases, non_trivial, failures);
  EXPECT_EQ(failures, 0) << first;
  EXPECT_GT(non_trivial, cases / 3);
}

}  // namespace
}  // namespace gesmi
