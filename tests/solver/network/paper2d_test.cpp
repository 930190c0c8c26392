// Seed 001's academic example: soundness against the model, singletons without
// errors, and at least the tightness of the paper's own decomposition (III-D).

#include "solver/network/paper2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "solver/interval/interval_reverse.h"
#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::contains;
using test::contains_point;

// A configuration of all variables that satisfies equations (5) exactly (up to
// the double rounding of x and z, checked against the domains with a margin).
struct Configuration {
  std::array<std::array<double, 2>, 5> x;
  std::array<std::array<double, 2>, 4> v;
  std::array<double, 2> m;
  std::array<double, 3> z;
};

void expect_inside(const Paper2dDomains& d, const Configuration& c) {
  for (std::size_t k = 0; k < 5; ++k)
    for (std::size_t j = 0; j < 2; ++j) EXPECT_TRUE(contains_point(d.x[k][j], c.x[k][j])) << "x" << k << j;
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t j = 0; j < 2; ++j) EXPECT_TRUE(contains_point(d.v[k][j], c.v[k][j])) << "v" << k << j;
  for (std::size_t j = 0; j < 2; ++j) EXPECT_TRUE(contains_point(d.m[j], c.m[j])) << "m" << j;
  for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(contains_point(d.z[k], c.z[k])) << "z" << k + 1;
}

Configuration truth_configuration() {
  const Paper2dTruth t;
  return Configuration{t.x, t.v, t.m, t.z};
}

// The paper's FORWARD and BACKWARD CONTRACTION (section III-D), written out
// literally, repeated to its fixpoint: the reference our network must not lose to.
Paper2dDomains paper_fixpoint(Paper2dDomains d) {
  for (int iteration = 0; iteration < 10000; ++iteration) {
    const Paper2dDomains before = d;
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t j = 0; j < 2; ++j) d.x[k + 1][j].intersect_with(d.x[k][j] + d.v[k][j]);
    std::array<Interval2, 4> dd;
    for (std::size_t k = 1; k <= 3; ++k) {
      dd[k] = {d.x[k][0] - d.m[0], d.x[k][1] - d.m[1]};
      d.z[k - 1].intersect_with(sqrt(sqr(dd[k][0]) + sqr(dd[k][1])));
    }
    for (std::size_t k = 3; k >= 1; --k) {
      dd[k][0] = hull(intersect(dd[k][0], sqrt(sqr(d.z[k - 1]) - sqr(dd[k][1]))),
                      intersect(dd[k][0], -sqrt(sqr(d.z[k - 1]) - sqr(dd[k][1]))));
      dd[k][1] = hull(intersect(dd[k][1], sqrt(sqr(d.z[k - 1]) - sqr(dd[k][0]))),
                      intersect(dd[k][1], -sqrt(sqr(d.z[k - 1]) - sqr(dd[k][0]))));
      for (std::size_t j = 0; j < 2; ++j) {
        d.x[k][j].intersect_with(dd[k][j] + d.m[j]);
        d.m[j].intersect_with(d.x[k][j] - dd[k][j]);
      }
    }
    for (std::size_t k = 4; k-- > 0;)
      for (std::size_t j = 0; j < 2; ++j) {
        d.x[k][j].intersect_with(d.x[k + 1][j] - d.v[k][j]);
        d.v[k][j].intersect_with(d.x[k + 1][j] - d.x[k][j]);
      }
    bool same = true;
    for (std::size_t j = 0; j < 2; ++j) same = same && before.m[j] == d.m[j];
    for (std::size_t k = 0; k < 5; ++k)
      for (std::size_t j = 0; j < 2; ++j) same = same && before.x[k][j] == d.x[k][j];
    if (same) break;
  }
  return d;
}

// The reference widened by a few units of its last digits: the two fixpoints are
// reached by different sequences of rounded operations.
Interval widened(const Interval& x) {
  if (x.is_empty()) return x;
  const double margin = 1e-12 * (1.0 + std::max(std::fabs(x.lo()), std::fabs(x.hi())));
  return Interval(x.lo() - margin, x.hi() + margin);
}

void expect_subset(const Paper2dDomains& inner, const Paper2dDomains& reference) {
  Paper2dDomains outer = reference;
  for (auto& xk : outer.x)
    for (auto& c : xk) c = widened(c);
  for (auto& vk : outer.v)
    for (auto& c : vk) c = widened(c);
  for (auto& c : outer.m) c = widened(c);
  for (auto& c : outer.z) c = widened(c);
  for (std::size_t k = 0; k < 5; ++k)
    for (std::size_t j = 0; j < 2; ++j) EXPECT_TRUE(contains(outer.x[k][j], inner.x[k][j])) << "x" << k << j;
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t j = 0; j < 2; ++j) EXPECT_TRUE(contains(outer.v[k][j], inner.v[k][j])) << "v" << k << j;
  for (std::size_t j = 0; j < 2; ++j) EXPECT_TRUE(contains(outer.m[j], inner.m[j])) << "m" << j;
  for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(contains(outer.z[k], inner.z[k])) << "z" << k + 1;
}

struct Paper2dCase {
  double dv, dz, dx;
};
const Paper2dCase kCases[] = {{0, 0, kInf}, {1, 0, kInf}, {1, 1, kInf}, {1, 1, 1}, {2, 0.5, 3}, {0.3, 2, kInf}};

TEST(Paper2d, PriorDomainsFollowThePaperRule) {
  const Paper2dDomains d = paper2d_prior({1.0, 2.0, kInf});
  // [a - d, a + 2d], rounded outward by at most an ulp.
  EXPECT_TRUE(contains(d.v[0][0], Interval(39.0, 42.0)));
  EXPECT_LE(d.v[0][0].width(), 3.0 + 1e-13);
  EXPECT_TRUE(contains(d.z[1], Interval(58.0, 64.0)));
  EXPECT_LE(d.z[1].width(), 6.0 + 1e-13);
  EXPECT_TRUE(d.x[4][0].is_entire());
  EXPECT_TRUE(d.m[0].is_entire());
  EXPECT_EQ(d.x[0][0], Interval(0.0));
}

TEST(Paper2d, TrueConfigurationStaysInsideEveryDomain) {
  for (const Paper2dCase& c : kCases) {
    SCOPED_TRACE(::testing::Message() << "dv=" << c.dv << " dz=" << c.dz << " dx=" << c.dx);
    const Paper2dResult r = solve_paper2d(paper2d_prior({c.dv, c.dz, c.dx}));
    EXPECT_FALSE(r.report.empty);
    EXPECT_TRUE(r.report.converged);
    expect_inside(r.domains, truth_configuration());
  }
}

TEST(Paper2d, ExactInputsAndRangesGiveSingletons) {
  const Paper2dResult r = solve_paper2d(paper2d_prior({0.0, 0.0, kInf}));
  const Paper2dDomains& d = r.domains;
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_LE(d.m[j].width(), 1e-9);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_LE(d.x[k][j].width(), 1e-9);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(d.v[k][j].width(), 0.0);
  }
  for (const Interval& z : d.z) EXPECT_EQ(z.width(), 0.0);
}

// Random configurations of the model whose measurements fall in the prior domains
// are solutions of the problem: no contraction may exclude them.
TEST(Paper2d, RandomFeasibleConfigurationsStayInside) {
  std::mt19937_64 rng(2024);
  for (const Paper2dCase& c : kCases) {
    if (c.dz == 0.0) continue;  // exact ranges: the solutions have measure zero
    const Paper2dDomains prior = paper2d_prior({c.dv, c.dz, c.dx});
    const Paper2dResult r = solve_paper2d(prior);
    int accepted = 0;
    for (int attempt = 0; attempt < 200000 && accepted < 300; ++attempt) {
      Configuration conf;
      conf.x[0] = {0.0, 0.0};
      for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t j = 0; j < 2; ++j) {
          const Interval& dom = prior.v[k][j];
          std::uniform_real_distribution<double> u(dom.lo(), dom.hi());
          conf.v[k][j] = dom.is_degenerate() ? dom.lo() : u(rng);
          conf.x[k + 1][j] = conf.x[k][j] + conf.v[k][j];
        }
      std::uniform_real_distribution<double> around(-6.0, 6.0);
      conf.m = {40.0 + around(rng), 60.0 + around(rng)};
      bool feasible = true;
      for (std::size_t k = 1; k <= 3; ++k) {
        conf.z[k - 1] = std::hypot(conf.x[k][0] - conf.m[0], conf.x[k][1] - conf.m[1]);
        // Keep a margin so that the double rounding of x and z cannot matter.
        const Interval& dom = prior.z[k - 1];
        feasible = feasible && conf.z[k - 1] >= dom.lo() + 1e-9 && conf.z[k - 1] <= dom.hi() - 1e-9;
      }
      for (std::size_t j = 0; j < 2; ++j)
        feasible = feasible && conf.x[4][j] >= prior.x[4][j].lo() + 1e-9 && conf.x[4][j] <= prior.x[4][j].hi() - 1e-9;
      if (!feasible) continue;
      ++accepted;
      expect_inside(r.domains, conf);
      if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GE(accepted, 30) << "dv=" << c.dv << " dz=" << c.dz;
  }
}

TEST(Paper2d, IsAtLeastAsTightAsThePapersDecomposition) {
  for (const Paper2dCase& c : kCases) {
    SCOPED_TRACE(::testing::Message() << "dv=" << c.dv << " dz=" << c.dz << " dx=" << c.dx);
    const Paper2dDomains prior = paper2d_prior({c.dv, c.dz, c.dx});
    expect_subset(solve_paper2d(prior).domains, paper_fixpoint(prior));
  }
}

TEST(Paper2d, RejectsNegativeDeltas) {
  EXPECT_FALSE((Paper2dDeltas{-1.0, 0.0, 0.0}.validate().empty()));
  EXPECT_FALSE((Paper2dDeltas{0.0, std::nan(""), 0.0}.validate().empty()));
  EXPECT_TRUE((Paper2dDeltas{0.0, 1.0, kInf}.validate().empty()));
}

}  // namespace
}  // namespace gesmi
