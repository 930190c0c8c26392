// The waterfall's cheap rejection (boxes_beyond, solver/network/sonar_plane.h): it
// never calls a pair of boxes apart when some two of their points lie within reach.
// Oracle: the distance between the boxes in long double, from the same bounds.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "solver/network/sonar_plane.h"

namespace gesmi {
namespace {

long double distance_between(const Vec3I& a, const Vec3I& b) {
  long double sum = 0.0L;
  for (int i = 0; i < 3; ++i) {
    const long double gap = std::max({0.0L, static_cast<long double>(b[i].lo()) - a[i].hi(),
                                      static_cast<long double>(a[i].lo()) - b[i].hi()});
    sum += gap * gap;
  }
  return std::sqrt(sum);
}

TEST(BoxesBeyond, NeverRejectsBoxesWithinReachAndRejectsMostBeyond) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double reach = 50.0;
  int within = 0, rejected_beyond = 0, beyond = 0;
  for (int n = 0; n < 200000; ++n) {
    // A box, and a second one placed so that their distance is within 1e-9 of the reach
    // half of the time (ties decided by the last bits).
    Vec3I a, b;
    for (int i = 0; i < 3; ++i) {
      const double c = 1000.0 * unit(random);
      a[i] = Interval::around(c, 20.0 * unit(random));
    }
    const double azimuth = 6.283185307179586 * unit(random), elevation = 3.0 * unit(random) - 1.5;
    const double target = n % 2 ? reach * (1.0 + 1e-9 * (unit(random) - 0.5)) : reach * 2.0 * unit(random);
    const double dir[3] = {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                           std::sin(elevation)};
    for (int i = 0; i < 3; ++i) {
      const double edge = dir[i] >= 0 ? a[i].hi() : a[i].lo();
      const double near = edge + target * dir[i];
      b[i] = dir[i] >= 0 ? Interval(near, near + 5.0) : Interval(near - 5.0, near);
    }
    const long double d = distance_between(a, b);
    const bool apart = boxes_beyond(a, b, reach);
    if (d <= reach) {
      ++within;
      ASSERT_FALSE(apart) << "boxes " << static_cast<double>(d) << " m apart called beyond " << reach;
    } else {
      ++beyond;
      rejected_beyond += apart;
    }
  }
  EXPECT_GT(within, 10000);
  EXPECT_GT(rejected_beyond, beyond * 9 / 10);  // the slack is 1e-12: nearly all are decided
  EXPECT_FALSE(boxes_beyond(Vec3I(Interval::entire(), Interval(0.0), Interval(0.0)), Vec3I(Interval(1e9), Interval(0.0), Interval(0.0)), reach));
  EXPECT_TRUE(boxes_beyond(Vec3I(Interval::empty(), Interval(0.0), Interval(0.0)), Vec3I(Interval(1e9), Interval(0.0), Interval(0.0)), reach));
}

}  // namespace
}  // namespace gesmi
