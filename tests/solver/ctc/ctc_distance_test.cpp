#include "solver/ctc/ctc_distance.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

TEST(CtcDistance, ContractsAPointOnACircleToTheRightQuarter) {
  // ||x - (0,0)|| = 5 with x in [3, 10] x [0, 10]: x_1 in [3, 5], x_2 in [0, 4].
  Interval z(5.0), x0(3.0, 10.0), x1(0.0, 10.0), m0(0.0), m1(0.0);
  ASSERT_TRUE(contract_distance<2>(z, {&x0, &x1}, {&m0, &m1}));
  EXPECT_TRUE(test::contains(x0, Interval(3.0, 5.0)));
  EXPECT_LE(x0.hi(), 5.0 + 1e-12);
  EXPECT_TRUE(test::contains(x1, Interval(0.0, 4.0)));
  EXPECT_LE(x1.hi(), 4.0 + 1e-12);
}

TEST(CtcDistance, ReportsAnUnreachableRange) {
  Interval z(1.0, 2.0), a0(10.0, 11.0), a1(0.0), a2(0.0), b0(0.0), b1(0.0), b2(0.0);
  EXPECT_FALSE(contract_distance<3>(z, {&a0, &a1, &a2}, {&b0, &b1, &b2}));
  EXPECT_TRUE(z.is_empty());
  EXPECT_TRUE(a0.is_empty());
}

TEST(CtcDistance, KeepsEverySampledSolutionIn3D) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-50.0, 50.0), w(0.0, 5.0);
  for (int trial = 0; trial < 5000; ++trial) {
    double a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = u(rng);
      b[i] = u(rng);
    }
    const double d = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    Interval z(d - w(rng), d + w(rng));
    Interval ia[3], ib[3];
    for (int i = 0; i < 3; ++i) {
      ia[i] = Interval(a[i] - w(rng), a[i] + w(rng));
      ib[i] = Interval(b[i] - w(rng), b[i] + w(rng));
    }
    ASSERT_TRUE(contract_distance<3>(z, {&ia[0], &ia[1], &ia[2]}, {&ib[0], &ib[1], &ib[2]}));
    EXPECT_TRUE(z.contains(d));
    for (int i = 0; i < 3; ++i) {
      ASSERT_TRUE(ia[i].contains(a[i])) << trial;
      ASSERT_TRUE(ib[i].contains(b[i])) << trial;
    }
  }
}

}  // namespace
}  // namespace gesmi
