// OutlierFamily against its definition, by brute force: for every verdict of four
// data and every bound pair, list the subsets O of the data with F ⊆ O ⊆ F ∪ U and
// q_lower <= |O| <= q, and compare each question's answer with that list.

#include "solver/setinv/outliers/outlier_family.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>

namespace gesmi {
namespace {

constexpr std::size_t kData = 4;

std::vector<IBool> verdicts(int code) {
  std::vector<IBool> v;
  for (std::size_t i = 0; i < kData; ++i, code /= 3) v.push_back(code % 3 == 0 ? IBool(true) : code % 3 == 1 ? IBool(false) : IBool::maybe());
  return v;
}

OutlierSet members(unsigned mask) {
  OutlierSet s;
  for (std::size_t i = 0; i < kData; ++i)
    if (mask >> i & 1u) s.push_back(i);
  return s;
}

std::vector<OutlierSet> by_definition(const std::vector<IBool>& v, int q_lower, int q) {
  std::vector<OutlierSet> out;
  for (unsigned mask = 0; mask < (1u << kData); ++mask) {
    bool ok = true;
    for (std::size_t i = 0; i < kData; ++i) {
      const bool in = mask >> i & 1u;
      if (v[i].is_false() && !in) ok = false;  // certainly inconsistent: in every set
      if (v[i].is_true() && in) ok = false;    // certainly consistent: in none
    }
    const int size = std::popcount(mask);
    if (ok && size >= q_lower && size <= q) out.push_back(members(mask));
  }
  return out;
}

TEST(OutlierFamily, EveryAnswerMatchesTheListOfSets) {
  for (int code = 0; code < 81; ++code)
    for (int q = 0; q <= 4; ++q)
      for (int q_lower = 0; q_lower <= q; ++q_lower) {
        const std::vector<IBool> v = verdicts(code);
        const OutlierFamily f(v, q_lower, q);
        std::vector<OutlierSet> expected = by_definition(v, q_lower, q);
        std::sort(expected.begin(), expected.end());
        const std::string where = "code " + std::to_string(code) + " q " + std::to_string(q) + " q_lower " + std::to_string(q_lower);
        std::vector<OutlierSet> listed;
        ASSERT_TRUE(f.enumerate(100, listed)) << where;
        std::sort(listed.begin(), listed.end());
        EXPECT_EQ(listed, expected) << where;
        EXPECT_EQ(f.count(100), expected.size()) << where;
        EXPECT_EQ(f.empty(), expected.empty()) << where;
        EXPECT_EQ(f.single(), expected.size() == 1) << where;
        if (expected.size() == 1) {
          EXPECT_EQ(f.single_set(), expected[0]) << where;
        }
        for (std::size_t i = 0; i < kData; ++i) {
          const auto has_i = [&](const OutlierSet& s) { return std::find(s.begin(), s.end(), i) != s.end(); };
          if (expected.empty()) continue;  // vacuous: no set to agree on
          EXPECT_EQ(f.always_outlier(i), std::all_of(expected.begin(), expected.end(), has_i)) << where << " datum " << i;
          EXPECT_EQ(f.never_outlier(i), std::none_of(expected.begin(), expected.end(), has_i)) << where << " datum " << i;
        }
        for (unsigned mask = 0; mask < (1u << kData); ++mask) {
          const OutlierSet s = members(mask);
          EXPECT_EQ(f.contains(s), std::find(expected.begin(), expected.end(), s) != expected.end()) << where;
        }
        // Intersection with a family of other verdicts and bounds (a sample of them).
        for (int other = 0; other < 81; other += 7) {
          const std::vector<IBool> w = verdicts(other);
          const OutlierFamily g(w, std::max(0, q_lower - 1), q);
          const std::vector<OutlierSet> theirs = by_definition(w, std::max(0, q_lower - 1), q);
          const bool common = std::any_of(expected.begin(), expected.end(), [&](const OutlierSet& s) {
            return std::find(theirs.begin(), theirs.end(), s) != theirs.end();
          });
          EXPECT_EQ(f.intersects(g), common) << where << " other " << other;
        }
      }
}

TEST(OutlierFamily, CountSaturatesAndEnumerateRefusesLongLists) {
  // 20 undetermined data, 10 outliers: C(20, 10) = 184756 sets.
  const std::vector<IBool> v(20, IBool::maybe());
  const OutlierFamily f(v, 10, 10);
  EXPECT_EQ(f.count(1000), 1001u);
  std::vector<OutlierSet> listed;
  EXPECT_FALSE(f.enumerate(1000, listed));
  EXPECT_TRUE(listed.empty());
  const OutlierFamily small(v, 19, 20);  // C(20, 19) + C(20, 20) = 21
  EXPECT_EQ(small.count(1000), 21u);
}

}  // namespace
}  // namespace gesmi
