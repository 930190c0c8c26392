// SIVIA: the appendix example of seed 002, merging of children, contractors, limits
// and the generic API on models outside robotics.

#include "solver/setinv/sivia.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "solver/ctc/ctc_fwd_bwd.h"
#include "solver/setinv/invert.h"
#include "tests/solver/setinv/gaussian_example.h"

namespace gesmi {
namespace {

// Seed 002, appendix A: x² + y² − 1 <= 0 and −2x² − y² + 1 <= 0.
struct DiskMinusEllipse {
  std::size_t output_count() const { return 2; }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    y[0] = sqr(p[0]) + sqr(p[1]) - 1.0;
    y[1] = 1.0 - 2.0 * sqr(p[0]) - sqr(p[1]);
  }
};
const Box kAppendixPrior{Interval(-2.5, 2.5), Interval(-2.0, 2.0)};
const Box kNonPositive{Interval::neg_reals(), Interval::neg_reals()};

TEST(Sivia, AppendixExampleBracketsTheAreaAndTheBoundaryShrinksWithEpsilon) {
  const double area = std::numbers::pi - std::numbers::pi / std::sqrt(2.0);
  double previous_boundary = kInf;
  for (double epsilon : {0.2, 0.1, 0.05, 0.02, 0.01, 0.005}) {
    SiviaOptions options;
    options.epsilon = epsilon;
    const SiviaResult r = invert(DiskMinusEllipse{}, kNonPositive, kAppendixPrior, options);
    const double inner = r.inner.volume(), boundary = r.boundary.volume();
    EXPECT_LE(inner, area) << epsilon;
    EXPECT_GE(inner + boundary, area) << epsilon;
    EXPECT_LT(boundary, previous_boundary) << epsilon;
    EXPECT_GT(inner, 0.0) << epsilon;
    previous_boundary = boundary;
  }
  EXPECT_LT(previous_boundary, 0.1);
}

TEST(Sivia, EveryPointOfTheSetIsEnclosedAndInnerPointsSatisfyTheConstraints) {
  SiviaOptions options;
  options.epsilon = 0.05;
  const SiviaResult r = invert(DiskMinusEllipse{}, kNonPositive, kAppendixPrior, options);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-2.5, 2.5), uy(-2.0, 2.0);
  for (int i = 0; i < 20000; ++i) {
    const double x = ux(rng), y = uy(rng);
    const bool in_set = x * x + y * y <= 1.0 && 2 * x * x + y * y >= 1.0;
    if (in_set) {
      EXPECT_TRUE(test::in_paving(r.inner, x, y) || test::in_paving(r.boundary, x, y)) << x << " " << y;
    }
    if (test::in_paving(r.inner, x, y)) {
      EXPECT_TRUE(in_set) << x << " " << y;
    }
  }
}

TEST(Sivia, ChildrenWithTheSameVerdictStayMergedInTheirFather) {
  // Everything is inside: the prior comes back as one box, after one test.
  const auto always = [](const Box&) { return IBool(true); };
  auto test = always;
  SiviaOptions options;
  const SiviaResult r = sivia(test, kAppendixPrior, options);
  ASSERT_EQ(r.inner.size(), 1u);
  EXPECT_EQ(r.boundary.size(), 0u);
  EXPECT_EQ(r.report.boxes_visited, 1u);
  // Undetermined everywhere: all the epsilon-boxes merge back into the prior.
  auto unknown = [](const Box&) { return IBool::maybe(); };
  options.epsilon = 0.5;
  const SiviaResult u = sivia(unknown, kAppendixPrior, options);
  EXPECT_EQ(u.boundary.size(), 1u);
  EXPECT_GT(u.report.boxes_visited, 100u);
}

TEST(Sivia, ContractorsBeforeBisectionKeepTheEnclosureAndExamineFewerBoxes) {
  const Expr x = Expr::var(0), y = Expr::var(1);
  struct Both {
    CtcFwdBwd disk, ellipse;
    void contract(Box& box) const {
      disk.contract(box);
      if (!is_empty(box)) ellipse.contract(box);
    }
  } ctc{CtcFwdBwd(sqr(x) + sqr(y), Interval(-kInf, 1.0)), CtcFwdBwd(2.0 * sqr(x) + sqr(y), Interval(1.0, kInf))};
  SiviaOptions options;
  options.epsilon = 0.01;
  const SiviaResult plain = invert(DiskMinusEllipse{}, kNonPositive, kAppendixPrior, options);
  const SiviaResult contracted = invert(DiskMinusEllipse{}, kNonPositive, kAppendixPrior, options, ctc);
  const double area = std::numbers::pi - std::numbers::pi / std::sqrt(2.0);
  EXPECT_LE(contracted.inner.volume(), area);
  EXPECT_GE(contracted.inner.volume() + contracted.boundary.volume(), area);
  EXPECT_LT(contracted.report.boxes_visited, plain.report.boxes_visited);
  EXPECT_GT(contracted.report.boxes_contracted, 0u);
  EXPECT_LE(contracted.boundary.volume(), plain.boundary.volume());
}

TEST(Sivia, BoxLimitIsReportedAndTheResultStillEncloses) {
  SiviaOptions options;
  options.epsilon = 0.001;
  options.max_boxes = 500;
  const SiviaResult r = invert(DiskMinusEllipse{}, kNonPositive, kAppendixPrior, options);
  EXPECT_TRUE(r.report.box_limit_hit);
  EXPECT_FALSE(r.report.time_limit_hit);
  const double area = std::numbers::pi - std::numbers::pi / std::sqrt(2.0);
  EXPECT_GE(r.inner.volume() + r.boundary.volume(), area);
  EXPECT_LE(r.report.boxes_visited, 520u);
}

TEST(Sivia, TimeLimitIsReported) {
  SiviaOptions options;
  options.epsilon = 1e-6;
  options.max_seconds = 0.02;
  const SiviaResult r = invert(DiskMinusEllipse{}, kNonPositive, kAppendixPrior, options);
  EXPECT_TRUE(r.report.time_limit_hit);
  EXPECT_LT(r.report.seconds, 1.0);
}

TEST(Sivia, ProgressCallbackIsCalled) {
  SiviaOptions options;
  options.epsilon = 0.01;
  options.progress_every = 100;
  int calls = 0;
  options.progress = [&](const SiviaProgress& p) {
    ++calls;
    EXPECT_EQ(p.boxes_visited % 100, 0u);
  };
  const SiviaResult r = invert(DiskMinusEllipse{}, kNonPositive, kAppendixPrior, options);
  EXPECT_EQ(static_cast<std::size_t>(calls), r.report.boxes_visited / 100);
}

TEST(Sivia, PeriodicPriorWiderThanOnePeriodIsCutToOnePeriod) {
  SiviaOptions options;
  options.periodic_dimension = 0;
  options.epsilon = 10.0;
  auto test = [](const Box&) { return IBool(true); };
  const SiviaResult r = sivia(test, Box{Interval(0.0, 20.0)}, options);
  ASSERT_EQ(r.inner.size(), 1u);
  EXPECT_NEAR(r.inner.box(0)[0].hi(), 2.0 * std::numbers::pi, 1e-12);
}

TEST(Sivia, DepthTestsSeeTheirFatherStateFirst) {
  // A test that records the depth of each call: a child is always one level below
  // the box bisected last, as the visibility vectors of seed 003 need.
  std::vector<int> depths;
  auto test = [&](const Box& box, int depth) {
    depths.push_back(depth);
    return box[0].width() > 0.3 ? IBool::maybe() : IBool(box[0].lo() < 0.5);
  };
  SiviaOptions options;
  options.epsilon = 0.01;
  const SiviaResult r = sivia(test, Box{Interval(0.0, 1.0)}, options);
  ASSERT_GE(depths.size(), 3u);
  EXPECT_EQ(depths[0], 0);
  EXPECT_EQ(depths[1], 1);
  for (std::size_t i = 1; i < depths.size(); ++i) EXPECT_LE(depths[i], depths[i - 1] + 1);
  EXPECT_NEAR(r.inner.volume(), 0.5, 1e-12);
}

// A model outside robotics: exponential decay y(t) = a exp(-b t) measured at four
// times with bounded errors; the parameter set is checked against sampling.
struct ExponentialDecay {
  std::vector<double> times{0.5, 1.0, 2.0, 4.0};
  std::size_t output_count() const { return times.size(); }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    for (std::size_t i = 0; i < times.size(); ++i) y[i] = p[0] * exp(-times[i] * p[1]);
  }
};

TEST(Sivia, GenericApiInvertsAParameterEstimationModel) {
  const ExponentialDecay model;
  const double a = 2.0, b = 0.7;
  Box image;
  for (double t : model.times) image.push_back(Interval::around(a * std::exp(-b * t), 0.05));
  const Box prior{Interval(0.0, 5.0), Interval(0.0, 3.0)};
  SiviaOptions options;
  options.epsilon = 0.005;
  const SiviaResult r = invert(model, image, prior, options);
  EXPECT_TRUE(test::in_paving(r.inner, a, b) || test::in_paving(r.boundary, a, b));
  EXPECT_GT(r.inner.size(), 0u);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ua(0.0, 5.0), ub(0.0, 3.0);
  int consistent = 0;
  for (int i = 0; i < 200000; ++i) {
    const double pa = ua(rng), pb = ub(rng);
    bool ok = true;
    for (std::size_t k = 0; k < model.times.size(); ++k) ok = ok && image[k].contains(pa * std::exp(-pb * model.times[k]));
    consistent += ok;
    if (ok) {
      EXPECT_TRUE(test::in_paving(r.inner, pa, pb) || test::in_paving(r.boundary, pa, pb));
    } else {
      EXPECT_FALSE(test::in_paving(r.inner, pa, pb));
    }
  }
  EXPECT_GT(consistent, 10);
}

// The set {P}: undetermined on every box holding P, whatever its width, so only the
// spacing of doubles can stop the bisection.
struct HoldsPoint {
  double x, y;
  IBool operator()(const Box& box) const {
    return box[0].contains(x) && box[1].contains(y) ? IBool::maybe() : IBool(false);
  }
};

TEST(Sivia, EpsilonBelowTheSpacingOfDoublesEndsAtUnsplittableBoxes) {
  // The widest side is bisected: both sides shrink together until the x side, near
  // 1/3 where doubles are 2^-54 apart, cannot be split (about 55 halvings of [-1, 1]
  // each). y, near -3e-310, could go on to subnormal widths, but the widest side
  // decides: the depth is bounded by the spacing of doubles, not by epsilon.
  HoldsPoint test{1.0 / 3.0, -3e-310};
  SiviaOptions options;
  options.epsilon = std::numeric_limits<double>::denorm_min();
  const SiviaResult r = sivia(test, Box{Interval(-1, 1), Interval(-1, 1)}, options);
  EXPECT_GE(r.report.boxes_unsplittable, 1u);
  EXPECT_TRUE(r.inner.empty());
  EXPECT_TRUE(test::in_paving(r.boundary, test.x, test.y));
  EXPECT_EQ(r.report.boxes_at_epsilon, 0u);
  EXPECT_GE(r.report.max_depth, 2 * 54);
  EXPECT_LE(r.report.max_depth, 2 * 56);
  // Each boundary box is one unsplittable box, or two merged back into their father.
  for (std::size_t i = 0; i < r.boundary.size(); ++i)
    EXPECT_LE(r.boundary.box(i)[0].width(), std::ldexp(1.0, -53));
}

TEST(Sivia, FinestEpsilonIsTwiceTheSpacingOfDoublesAtTheLargestScaledMagnitude) {
  // Spacing of doubles: 2^-49 in [8, 16), 2^-52 in [1, 2), 2^-51 in [2, 4).
  const Box prior{Interval(-10, 4), Interval(0, 1), Interval(-std::numbers::pi, std::numbers::pi)};
  EXPECT_EQ(finest_epsilon(std::span<const Box>(&prior, 1), {1.0, 1.0, 1.0}), std::ldexp(1.0, -48));
  EXPECT_EQ(finest_epsilon(std::span<const Box>(&prior, 1), {1.0, 1.0, 16.0}), std::ldexp(1.0, -46));
}

}  // namespace
}  // namespace gesmi
