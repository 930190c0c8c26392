// Connected components of pavings, with wrap-around of a periodic dimension.

#include "solver/setinv/components.h"

#include <gtest/gtest.h>

#include <numbers>

#include "solver/setinv/invert.h"

namespace gesmi {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Two disjoint disks: (x+2)² + y² <= 1 or (x-2)² + y² <= 1, as min of two outputs.
struct TwoDisks {
  std::size_t output_count() const { return 1; }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    y[0] = min(sqr(p[0] + 2.0) + sqr(p[1]), sqr(p[0] - 2.0) + sqr(p[1]));
  }
};

TEST(Components, TwoDisksGiveTwoComponentsWithTheirHulls) {
  SiviaOptions options;
  options.epsilon = 0.05;
  const SiviaResult r = invert(TwoDisks{}, Box{Interval(-kInf, 1.0)}, Box{Interval(-4, 4), Interval(-3, 3)}, options);
  const auto components = connected_components(r.inner, r.boundary);
  ASSERT_EQ(components.size(), 2u);
  for (const PavingComponent& c : components) {
    EXPECT_GT(c.inner.size(), 0u);
    EXPECT_GT(c.boundary.size(), 0u);
    const double centre = c.hull[0].mid();
    EXPECT_NEAR(std::abs(centre), 2.0, 0.06);
    EXPECT_TRUE(c.hull[0].is_superset(Interval(std::abs(centre) > 0 ? centre - 0.99 : 0, centre + 0.99)));
    EXPECT_NEAR(c.inner_volume + c.boundary_volume, std::numbers::pi, 0.6);
  }
  EXPECT_EQ(components[0].inner.size() + components[1].inner.size(), r.inner.size());
}

TEST(Components, BoxesTouchingAtACornerAreConnected) {
  Paving p(2);
  p.add(Box{Interval(0, 1), Interval(0, 1)});
  p.add(Box{Interval(1, 2), Interval(1, 2)});
  p.add(Box{Interval(3, 4), Interval(0, 1)});
  const auto c = connected_components(p, Paving(2));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].inner.size(), 2u);
}

TEST(Components, PeriodicDimensionConnectsAcrossThePeriod) {
  Paving boundary(2);
  boundary.add(Box{Interval(0, 1), Interval(0.0, 0.1)});
  boundary.add(Box{Interval(0, 1), Interval(kTwoPi - 0.1, kTwoPi)});
  boundary.add(Box{Interval(0, 1), Interval(3.0, 3.1)});
  ComponentOptions options;
  options.periodic_dimension = 1;
  options.period = kTwoPi;
  const auto c = connected_components(Paving(2), boundary, options);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].boundary.size(), 2u);
  // The hull is the short arc across 0, not [0, 2 pi].
  EXPECT_NEAR(c[0].hull[1].lo(), -0.1, 1e-9);
  EXPECT_NEAR(c[0].hull[1].hi(), 0.1, 1e-9);
  // Without the periodic option the two ends are apart.
  EXPECT_EQ(connected_components(Paving(2), boundary).size(), 3u);
}

TEST(Components, WrappedHullHandlesOverflowingArcs) {
  const Interval h = wrapped_hull({Interval(0.5, 1.0), Interval(2.0, 2.5), Interval(6.0, 9.0)}, kTwoPi, 0.0);
  // [6, 9] covers [0, 2.717] after wrapping, so the hull is [6, 9] exactly.
  EXPECT_NEAR(h.lo(), 6.0 - kTwoPi, 1e-12);
  EXPECT_NEAR(h.hi(), 9.0 - kTwoPi, 1e-12);
  const Interval full = wrapped_hull({Interval(0, 3), Interval(3, 6.3)}, kTwoPi, 0.0);
  EXPECT_NEAR(full.width(), kTwoPi, 1e-9);
}

}  // namespace
}  // namespace gesmi
