// Refining S_q's pavings until phi is known per box (outlier_refinement.h), on seed
// 004's Example 2 at q = 2. Expected values come from phi evaluated in plain doubles
// on a grid (gaussian_example.h).

#include "solver/setinv/outliers/outlier_refinement.h"

#include <gtest/gtest.h>

#include "tests/solver/setinv/gaussian_example.h"

namespace gesmi {
namespace {

using test::gaussian_phi;

struct Example2 {
  ImageInBox<test::GaussianDensity> data{test::GaussianDensity{}, test::gaussian_data()};
  SiviaResult sq;
  OutlierPaving refined;
  Example2() {
    SiviaOptions o;
    o.epsilon = 0.01;
    sq = sivia_q(data, 2, std::span<const Box>(&test::gaussian_frame(), 1), o);
    OutlierRefinementOptions r;
    r.q = 2;
    r.epsilon = 0.01;
    refined = refine_by_outliers(data, sq, r);
  }
};

TEST(OutlierRefinement, StillEnclosesTheSetAndStaysInsideSiviasBoxes) {
  const Example2 e;
  ASSERT_FALSE(e.refined.limit_hit());
  ASSERT_GT(e.refined.inner.size(), 0u);
  for (int i = 0; i <= 500; ++i)
    for (int k = 0; k < 300; ++k) {
      const double p1 = -2.0 + 0.02 * i, p2 = 0.005 + 0.01 * k;
      if (gaussian_phi(p1, p2).size() > 2) continue;
      bool found = false;
      for (std::size_t b = 0; b < e.refined.size() && !found; ++b) found = test::point_in(e.refined.box(b), p1, p2);
      EXPECT_TRUE(found) << p1 << " " << p2;
    }
  // Box for box inside the given pavings: inner boxes inside inner boxes.
  const auto inside_one = [](std::span<const Interval> box, const Paving& p) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.box(i)[0].is_superset(box[0]) && p.box(i)[1].is_superset(box[1])) return true;
    return false;
  };
  for (std::size_t b = 0; b < e.refined.inner.size(); ++b) EXPECT_TRUE(inside_one(e.refined.inner.box(b), e.sq.inner));
  for (std::size_t b = 0; b < e.refined.boundary.size(); ++b)
    EXPECT_TRUE(inside_one(e.refined.boundary.box(b), e.sq.inner) || inside_one(e.refined.boundary.box(b), e.sq.boundary));
}

TEST(OutlierRefinement, WhereOneSetFitsEveryPointOfTheSetHasIt) {
  const Example2 e;
  std::size_t single = 0, checked = 0;
  for (std::size_t b = 0; b < e.refined.size(); ++b) {
    const OutlierFamily& f = e.refined.families[b];
    const auto box = e.refined.box(b);
    for (int i = 1; i < 6; ++i)
      for (int k = 1; k < 6; ++k) {
        const double p1 = box[0].lo() + box[0].width() * i / 6.0, p2 = box[1].lo() + box[1].width() * k / 6.0;
        const auto phi = gaussian_phi(p1, p2);
        if (e.refined.inside(b)) {
          EXPECT_LE(phi.size(), 2u) << p1 << " " << p2;
        }
        if (phi.size() > 2) continue;
        EXPECT_TRUE(f.contains(phi)) << p1 << " " << p2;
        if (f.single()) {
          EXPECT_EQ(phi, f.single_set()) << p1 << " " << p2;
          ++checked;
        }
      }
    single += f.single();
  }
  // Most of the set is resolved: only boxes at epsilon keep several sets.
  EXPECT_GT(single, e.refined.size() / 2);
  EXPECT_GT(checked, 1000u);
}

}  // namespace
}  // namespace gesmi
