#include <gtest/gtest.h>

#include "solver/interval/box.h"
#include "solver/interval/interval.h"
#include "solver/interval/interval_reverse.h"

using gesmi::Interval;

TEST(IntervalSmoke, AdditionEnclosesTheRealSum) {
  const Interval x = Interval(0.1) + Interval(0.2);
  EXPECT_LE(x.lo(), 0.30000000000000004);
  EXPECT_GE(x.hi(), 0.3);
  EXPECT_TRUE(x.contains(0.3) || x.contains(0.30000000000000004));
}

TEST(IntervalSmoke, EigenMatrixProduct) {
  gesmi::Mat3I r = gesmi::Mat3I::Identity();
  gesmi::Vec3I v(Interval(1, 2), Interval(-1, 1), Interval(0));
  gesmi::Vec3I w = r * v;
  EXPECT_TRUE(w[0].contains(1.5));
  EXPECT_TRUE(w[1].contains(0.0));
}
