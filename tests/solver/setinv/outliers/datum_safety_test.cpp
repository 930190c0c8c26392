// Remark 6 of seed 004 (datum_safety.h): safety of datum i = vol(S*) / vol(S^(i)),
// S^(i) the set allowing the same q outliers among the other data. Expected values
// from areas computed by hand (triangles and squares) or by counting grid cells.

#include "solver/setinv/outliers/datum_safety.h"

#include <gtest/gtest.h>

namespace gesmi {
namespace {

// y = (p1, p2, p1 + p2, p1 - p2).
struct FourLines {
  std::size_t output_count() const { return 4; }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    y[0] = p[0];
    y[1] = p[1];
    y[2] = p[0] + p[1];
    y[3] = p[0] - p[1];
  }
};

const Box kPrior{Interval(-1, 2), Interval(-1, 2)};

std::vector<DatumSafety> safety_of(const Box& image, int q) {
  ImageInBox<FourLines> data(FourLines{}, image);
  SiviaOptions o;
  o.epsilon = 0.005;
  const SiviaResult s = sivia_q(data, q, std::span<const Box>(&kPrior, 1), o);
  const double inner = s.inner.volume();
  return datum_safety(data, inner, inner + s.boundary.volume(), q, std::span<const Box>(&kPrior, 1), o);
}

TEST(DatumSafety, SquareCutByADiagonalWithoutOutliers) {
  // S = [0,1]^2 cut by p1 + p2 <= 1.5: area 1 - 1/8. Without datum 0 (or 1) the strip
  // 0 <= p1 + p2 <= 1.5 over p2 in [0, 1] has area 1.5; without datum 2 the square
  // has area 1; datum 3 (p1 - p2 in [-5, 5]) holds on the whole prior.
  const Box image{Interval(0, 1), Interval(0, 1), Interval(0, 1.5), Interval(-5, 5)};
  const auto s = safety_of(image, 0);
  ASSERT_EQ(s.size(), 4u);
  const double expected[4] = {0.875 / 1.5, 0.875 / 1.5, 0.875, 1.0};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(s[i].safety.contains(expected[i])) << i << ": [" << s[i].safety.lo() << ", " << s[i].safety.hi() << "]";
    EXPECT_LT(s[i].safety.width(), 0.05) << i;
  }
}

TEST(DatumSafety, AnOutlierIsUnsafeWhenItsRemovalFreesAnotherOutlier) {
  // Datum 3 asks p1 - p2 in [5, 6]: impossible in the prior, so q* = 1 and S_1 is
  // the set above. Without datum 3, S^(3) allows one outlier among data 0..2: its
  // area is counted on a grid of cell centres. Without datum 0, datum 3 still takes
  // the one outlier: S^(0) is the strip of area 1.5 as before.
  const Box image{Interval(0, 1), Interval(0, 1), Interval(0, 1.5), Interval(5, 6)};
  const auto s = safety_of(image, 1);
  constexpr int kCells = 1200;
  const double h = 3.0 / kCells;
  double area = 0.0;
  for (int i = 0; i < kCells; ++i)
    for (int k = 0; k < kCells; ++k) {
      const double p1 = -1.0 + (i + 0.5) * h, p2 = -1.0 + (k + 0.5) * h;
      const int failing = !(p1 >= 0 && p1 <= 1) + !(p2 >= 0 && p2 <= 1) + !(p1 + p2 >= 0 && p1 + p2 <= 1.5);
      area += failing <= 1 ? h * h : 0.0;
    }
  const double expected3 = 0.875 / area;
  EXPECT_LT(expected3, 0.5);
  EXPECT_NEAR(s[3].safety.mid(), expected3, 0.02) << "[" << s[3].safety.lo() << ", " << s[3].safety.hi() << "]";
  EXPECT_TRUE(s[0].safety.contains(0.875 / 1.5));
  EXPECT_TRUE(s[2].safety.contains(0.875));
}

TEST(DatumSafety, RatioOfVolumesIsEnclosedAndClamped) {
  const Interval r = safety_ratio(1.0, 2.0, 4.0, 5.0);
  EXPECT_TRUE(r.contains(0.2));
  EXPECT_TRUE(r.contains(0.5));
  EXPECT_LT(r.width(), 0.31);
  EXPECT_EQ(safety_ratio(1.0, 2.0, 0.0, 5.0).hi(), 1.0);  // no inner box: no upper bound below 1
  EXPECT_EQ(safety_ratio(1.0, 3.0, 2.0, 3.0).hi(), 1.0);
}

}  // namespace
}  // namespace gesmi
