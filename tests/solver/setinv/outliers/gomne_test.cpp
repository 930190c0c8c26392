// GOMNE (seed 004): minimal outlier number, epsilon halving, prior constraints,
// extra margin and the outliers of each component, on models outside robotics.
// Expected values come from the models (grid sampling), never from the paper.

#include "solver/setinv/outliers/gomne.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "solver/setinv/outliers/hypotheses.h"
#include "solver/setinv/outliers/outlier_sets.h"
#include "tests/solver/setinv/gaussian_example.h"

namespace gesmi {
namespace {

// Seed 004, Example 2 (gaussian_example.h).
using test::GaussianDensity;
const Box& kGaussianData = test::gaussian_data();
const Box& kGaussianFrame = test::gaussian_frame();

int failures(const ImageInBox<GaussianDensity>& data, double p1, double p2, std::vector<std::size_t>* phi = nullptr) {
  const double p[2] = {p1, p2};
  bool ok[6];
  data.evaluate_point(p, ok);
  int n = 0;
  for (std::size_t i = 0; i < 6; ++i)
    if (!ok[i]) {
      ++n;
      if (phi) phi->push_back(i);
    }
  return n;
}

template <class Data>
OutlierPaving refine(Data& data, const GomneResult& r, double epsilon) {
  OutlierRefinementOptions o;
  o.q = r.q_used;
  o.q_lower = r.q_lower;
  o.epsilon = epsilon;
  return refine_by_outliers(data, r.paving, o);
}

bool in_pavings(const SiviaResult& r, double x, double y) {
  for (const Paving* p : {&r.inner, &r.boundary})
    for (std::size_t i = 0; i < p->size(); ++i)
      if (p->box(i)[0].contains(x) && p->box(i)[1].contains(y)) return true;
  return false;
}

TEST(Gomne, GaussianExampleFindsTheMinimalOutlierNumberOfTheGrid) {
  ImageInBox<GaussianDensity> data(GaussianDensity{}, kGaussianData);
  GomneOptions options;
  options.epsilon0 = 0.01;
  options.epsilon_min = 0.0005;
  const GomneResult r = gomne(data, std::span<const Box>(&kGaussianFrame, 1), options);
  ASSERT_TRUE(r.found);
  // The density is singular at p2 = 0 (0 * inf in interval arithmetic), so boxes
  // along p2 = 0 stay undetermined for q = 0 down to epsilon_min: Remark 3's case,
  // with j* known to lie in [q_lower, q_star] only.
  EXPECT_TRUE(r.epsilon_min_reached);
  EXPECT_EQ(r.q_lower, 0);
  // A fine grid never beats the guaranteed minimum, and reaches it.
  int grid_min = 99;
  for (int i = 0; i <= 1000; ++i)
    for (int k = 1; k <= 600; ++k) {
      const double p1 = -2.0 + 0.01 * i, p2 = 0.005 * k;
      const int j = failures(data, p1, p2);
      grid_min = std::min(grid_min, j);
      if (j <= r.q_star) {
        EXPECT_TRUE(in_pavings(r.paving, p1, p2)) << p1 << " " << p2;
      }
    }
  EXPECT_EQ(grid_min, r.q_star);
  // Every q below q* was proved empty: the first steps end with no boxes at all.
  for (const GomneStep& s : r.steps) {
    if (s.q < r.q_star) {
      EXPECT_EQ(s.inner_boxes, 0u);
    }
  }
  EXPECT_EQ(r.steps.back().q, r.q_star);
  // Away from the singularity the same data give an exact answer.
  const Box away{Interval(-2, 8), Interval(0.05, 3)};
  const GomneResult e = gomne(data, std::span<const Box>(&away, 1), options);
  EXPECT_TRUE(e.exact());
  EXPECT_EQ(e.q_star, grid_min);
}

TEST(Gomne, EachComponentNamesTheOutliersOfItsPoints) {
  ImageInBox<GaussianDensity> data(GaussianDensity{}, kGaussianData);
  GomneOptions options;
  options.epsilon0 = 0.005;
  const GomneResult r = gomne(data, std::span<const Box>(&kGaussianFrame, 1), options);
  ASSERT_TRUE(r.found);
  const OutlierPaving refined = refine(data, r, options.epsilon0);
  const auto components = hypothesis_components(refined);
  ASSERT_GE(components.size(), 1u);
  for (const PavingComponent& c : components) {
    if (c.inner.empty()) continue;
    const ComponentOutliers o = component_outliers(data, refined, c, r.q_star);
    ASSERT_TRUE(o.determined);
    EXPECT_EQ(static_cast<int>(o.outliers.size()), r.q_star);
    // Proposition 2: the inner boxes' centres of this component agree.
    for (std::size_t i : c.inner) {
      std::vector<std::size_t> phi;
      const auto b = refined.inner.box(i);
      ASSERT_EQ(failures(data, b[0].mid(), b[1].mid(), &phi), r.q_star);
      EXPECT_EQ(phi, o.outliers);
    }
  }
}

// A line y = a t + b through 8 points, 3 of them spoiled: q* = 3 and the outliers
// are the spoiled ones.
struct Line {
  std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7};
  std::size_t output_count() const { return t.size(); }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    for (std::size_t i = 0; i < t.size(); ++i) y[i] = p[0] * t[i] + p[1];
  }
};

Box line_data() {
  Box y;
  for (int i = 0; i < 8; ++i) y.push_back(Interval::around(0.5 * i + 1.0, 0.1));
  y[1] = Interval::around(7.0, 0.1);
  y[4] = Interval::around(-3.0, 0.1);
  y[6] = Interval::around(0.0, 0.1);
  return y;
}

TEST(Gomne, LineWithThreeSpoiledPointsHasThreeOutliersAndNamesThem) {
  ImageInBox<Line> data(Line{}, line_data());
  const Box prior{Interval(-5, 5), Interval(-10, 10)};
  GomneOptions options;
  options.epsilon0 = 0.01;
  const GomneResult r = gomne(data, std::span<const Box>(&prior, 1), options);
  ASSERT_TRUE(r.exact());
  EXPECT_EQ(r.q_star, 3);
  const OutlierPaving refined = refine(data, r, options.epsilon0);
  const auto components = hypothesis_components(refined);
  ASSERT_EQ(components.size(), 1u);
  const ComponentOutliers o = component_outliers(data, refined, components[0], r.q_star);
  ASSERT_TRUE(o.determined);
  EXPECT_EQ(o.outliers, (std::vector<std::size_t>{1, 4, 6}));
  EXPECT_TRUE(components[0].hull[0].contains(0.5));
  EXPECT_TRUE(components[0].hull[1].contains(1.0));
}

TEST(Gomne, ExtraMarginCharacterisesTheLargerSet) {
  ImageInBox<Line> data(Line{}, line_data());
  const Box prior{Interval(-5, 5), Interval(-10, 10)};
  GomneOptions options;
  options.epsilon0 = 0.02;
  options.extra_outliers = 1;
  const GomneResult r = gomne(data, std::span<const Box>(&prior, 1), options);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.q_star, 3);
  EXPECT_EQ(r.q_used, 4);
  options.extra_outliers = 0;
  const GomneResult plain = gomne(data, std::span<const Box>(&prior, 1), options);
  EXPECT_GT(r.paving.inner.volume() + r.paving.boundary.volume(),
            plain.paving.inner.volume() + plain.paving.boundary.volume());
}

TEST(Gomne, PriorConstraintRemovesTheExcludedRegion) {
  ImageInBox<Line> data(Line{}, line_data());
  const Box prior{Interval(-5, 5), Interval(-10, 10)};
  GomneOptions options;
  options.epsilon0 = 0.01;
  // g(p) = p0 - 0.45 <= 0 excludes the true slope 0.5: more outliers are needed.
  const auto g = [](const Box& box) { return leq(box[0], Interval(0.45)); };
  const GomneResult r = gomne(data, std::span<const Box>(&prior, 1), options, g);
  ASSERT_TRUE(r.found);
  EXPECT_GT(r.q_star, 3);
  EXPECT_LE(r.paving.inner.hull()[0].hi(), 0.45);
}

// Exact data through one point: S_0 is a single point, with no inner box.
struct TwoLines {
  std::size_t output_count() const { return 2; }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    y[0] = p[0] + p[1];
    y[1] = p[0] - p[1];
  }
};

TEST(Gomne, EpsilonMinStopsHalvingWhenTheSetHasNoInterior) {
  ImageInBox<TwoLines> data(TwoLines{}, Box{Interval(1.0), Interval(0.0)});
  const Box prior{Interval(-1, 2), Interval(-1, 2)};
  GomneOptions options;
  options.epsilon0 = 0.1;
  options.epsilon_min = 0.01;
  const GomneResult r = gomne(data, std::span<const Box>(&prior, 1), options);
  EXPECT_TRUE(r.epsilon_min_reached);
  EXPECT_EQ(r.q_lower, 0);
  EXPECT_EQ(r.q_star, 2);  // S_1 is two lines: no interior either
  EXPECT_FALSE(r.exact());
  EXPECT_TRUE(in_pavings(r.paving, 0.5, 0.5));
}

// One datum, undetermined on every box holding P and false elsewhere.
struct NearPoint {
  double x, y;
  std::size_t datum_count() const { return 1; }
  void evaluate(const Box& box, int, std::span<IBool> out, int) const {
    out[0] = box[0].contains(x) && box[1].contains(y) ? IBool::maybe() : IBool(false);
  }
};

TEST(Gomne, StopsHalvingEpsilonWhenNoBoundaryBoxCanBeSplit) {
  // Around (1/3, 1/3) doubles are 2^-54 apart: from epsilon0 = 2^-10 about 45
  // halvings reach them. Halving on down to epsilon_min (the smallest subnormal)
  // would take over 1000 more SIVIA runs that change nothing.
  NearPoint data{1.0 / 3.0, 1.0 / 3.0};
  const Box prior{Interval(0, 1), Interval(0, 1)};
  GomneOptions options;
  options.epsilon0 = std::ldexp(1.0, -10);
  options.epsilon_min = std::numeric_limits<double>::denorm_min();
  options.max_outliers = 0;
  const GomneResult r = gomne(data, std::span<const Box>(&prior, 1), options);
  EXPECT_TRUE(r.epsilon_min_reached);
  EXPECT_FALSE(r.found);
  EXPECT_LT(r.steps.size(), 50u);
  EXPECT_TRUE(in_pavings(r.paving, data.x, data.y));
}

}  // namespace
}  // namespace gesmi
