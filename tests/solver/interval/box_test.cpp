// Intervals inside Eigen (solver/interval/box.h): fixed-size interval vectors and
// matrices use Eigen's products and keep the enclosure property; mixed products
// with double; boxes as std::vector<Interval> with the empty normal form.

#include "solver/interval/box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/support/expect_interval.h"

namespace gesmi {
namespace {

using test::contains;

// A rotation about z by an angle in [a, b], as an interval matrix.
Mat3I rotation_z(const Interval& angle) {
  const Interval c = cos(angle), s = sin(angle);
  Mat3I r;
  r << c, -s, Interval(0.0), s, c, Interval(0.0), Interval(0.0), Interval(0.0), Interval(1.0);
  return r;
}

TEST(Box, MatrixVectorProductEnclosesEveryPointProduct) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-10.0, 10.0), w(0.0, 0.5), unit(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    Mat3I m;
    Vec3I v;
    Mat3d mp;
    Vec3d vp;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        const double a = u(rng);
        m(r, c) = Interval(a, a + w(rng));
        mp(r, c) = m(r, c).lo() + (m(r, c).hi() - m(r, c).lo()) * unit(rng);
      }
      const double a = u(rng);
      v[r] = Interval(a, a + w(rng));
      vp[r] = v[r].lo();
    }
    const Vec3I mv = m * v;
    const Vec3I sum = v + v, diff = v - v;
    for (int r = 0; r < 3; ++r) {
      // The exact point product, in long double (error far below the enclosure's margin).
      long double exact = 0.0L;
      for (int c = 0; c < 3; ++c) exact += static_cast<long double>(mp(r, c)) * vp[c];
      ASSERT_LE(mv[r].lo(), exact + 1e-15L * std::fabs(exact));
      ASSERT_GE(mv[r].hi(), exact - 1e-15L * std::fabs(exact));
      ASSERT_TRUE(sum[r].contains(2 * vp[r]));
      ASSERT_TRUE(diff[r].contains(0.0));
    }
  }
}

TEST(Box, RotationOfAnIntervalAngleEnclosesEveryRotatedPoint) {
  const Interval angle(0.1, 0.2);
  const Vec3I p(Interval(1.0), Interval(2.0), Interval(-1.0, 1.0));
  const Vec3I q = rotation_z(angle) * p;
  for (int k = 0; k <= 10; ++k) {
    const long double t = 0.1L + 0.01L * k;
    const long double x = std::cos(t) * 1.0L - std::sin(t) * 2.0L, y = std::sin(t) * 1.0L + std::cos(t) * 2.0L;
    EXPECT_TRUE(q[0].lo() <= x && x <= q[0].hi());
    EXPECT_TRUE(q[1].lo() <= y && y <= q[1].hi());
  }
  EXPECT_EQ(q[2], Interval(-1.0, 1.0));
}

TEST(Box, MixedProductsWithDoubleAreIntervals) {
  const Mat3d r = Mat3d::Identity() * 0.1;
  const Vec3I v(Interval(1.0, 2.0), Interval(-1.0), Interval(-1.0, 3.0));
  const Vec3I rv = r.cast<Interval>() * v;
  EXPECT_TRUE(contains(rv[0], Interval(0.1, 0.2)));
  const Vec3I scaled = v * 2.0;
  EXPECT_EQ(scaled[0], Interval(2.0, 4.0));
  const Interval dot = v.dot(v);  // products, no dependency: [1,4] + [1,1] + [-3,9]
  EXPECT_EQ(dot, Interval(-1.0, 14.0));
  const Interval squared_norm = v.squaredNorm();  // abs2 is sqr, which knows x*x >= 0: [0,9]
  EXPECT_EQ(squared_norm, Interval(2.0, 14.0));
  EXPECT_EQ(v.norm(), sqrt(Interval(2.0, 14.0)));
}

TEST(Box, EmptyComponentMakesTheWholeBoxEmpty) {
  Box box{Interval(1.0, 2.0), Interval::empty(), Interval(0.0, 5.0)};
  EXPECT_TRUE(is_empty(box));
  normalize_empty(box);
  for (const Interval& x : box) EXPECT_TRUE(x.is_empty());
  const Box full{Interval(1.0, 2.0), Interval(-1.0, 3.0)};
  EXPECT_FALSE(is_empty(full));
  EXPECT_EQ(max_width(full), 4.0);
  EXPECT_EQ(max_width(box), 0.0);
}

}  // namespace
}  // namespace gesmi
