// The Kalman smoother's consistency checks: chi-square quantiles against closed forms,
// the leave-one-out test of a GPS fix against refitting without it, the corrupted mark
// of an outlier mission found by the residual tests, and a mine's only mark reported
// as not testable.

#include "solver/kalman/kalman_consistency.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "solver/kalman/kalman_smoother.h"
#include "solver/sim/simulator.h"

namespace gesmi {
namespace {

TEST(KalmanConsistency, ChiSquareQuantilesMatchClosedForms) {
  // Two degrees of freedom: P(X <= x) = 1 - exp(-x / 2).
  for (const double p : {0.025, 0.5, 0.9973})
    EXPECT_NEAR(chi_square_quantile(2.0, p), -2.0 * std::log(1.0 - p), 1e-9 * (1.0 - std::log(1.0 - p)));
  // Many: Wilson-Hilferty, X/k ~ (1 - 2/(9k) + z sqrt(2/(9k)))^3, z = 1.959964 for 97.5 %.
  const double k = 60000.0, z = 1.959963984540054;
  double low = 0.0, high = 0.0;
  chi_square_band(k, 0.95, low, high);
  const double c = 2.0 / (9.0 * k);
  EXPECT_NEAR(high, std::pow(1.0 - c + z * std::sqrt(c), 3.0), 1e-6);
  EXPECT_NEAR(low, std::pow(1.0 - c - z * std::sqrt(c), 3.0), 1e-6);
  EXPECT_TRUE(std::isnan(chi_square_quantile(0.0, 0.5)));
}

const InputTest* find_test(const KalmanResult& r, ConstraintRef input) {
  const auto it = std::find_if(r.tests.begin(), r.tests.end(), [&](const InputTest& t) { return t.input == input; });
  return it == r.tests.end() ? nullptr : &*it;
}

// The leave-one-out chi-square of a fix, from one fit, equals the one of actually
// refitting without the fix: (z - H x)^T (R + H P H^T)^-1 (z - H x) with the refit's
// mean and covariance at the fix's step (up to the refit's own relinearisation).
TEST(KalmanConsistency, LeaveOneOutOfAFixMatchesRefittingWithoutIt) {
  SimulationOptions o;
  o.seed = 1;
  o.errors = SimulatedErrors::worst_case;
  o.duration = 2400.0;
  const Mission m = simulate_mission(o);
  const std::vector<PositionFix> fixes = gps_fixes(m);
  ASSERT_GE(fixes.size(), 2u);
  for (const bool biases : {false, true}) {
    KalmanOptions options;
    options.biases = biases;
    const KalmanResult all = kalman_smooth(m, m.model, fixes, options);
    for (std::size_t f = 0; f < fixes.size(); ++f) {
      std::vector<PositionFix> others = fixes;
      others.erase(others.begin() + static_cast<std::ptrdiff_t>(f));
      const KalmanResult refit = kalman_smooth(m, m.model, others, options);
      const std::size_t k = step_at(m, fixes[f].time);
      Eigen::Vector2d r;
      Eigen::Matrix2d s;
      for (int a = 0; a < 2; ++a) {
        r[a] = fixes[f].box[a].mid() - refit.mean[3 * k + static_cast<std::size_t>(a)];
        for (int b = 0; b < 2; ++b) s(a, b) = refit.covariance[9 * k + static_cast<std::size_t>(3 * a + b)];
        s(a, a) += uniform_variance(fixes[f].box[a].rad(), 1.0);
      }
      const double expected = r.dot(s.ldlt().solve(r));
      const InputTest* t = find_test(all, ConstraintRef::gps_fix(fixes[f].source_index));
      ASSERT_NE(t, nullptr);
      std::printf("[ report ] %s, fix %zu: leave-one-out chi2 %.4g, refit %.4g\n", biases ? "bias-aware" : "plain", f,
                  t->chi2, expected);
      EXPECT_NEAR(t->chi2, expected, 0.005 * expected + 1e-3);
      EXPECT_EQ(t->dof, 2);
      EXPECT_EQ(t->flagged, t->chi2 > chi_square_quantile(2.0, kResidualTestProbability));
    }
  }
}

// One mark with its range corrupted beyond its bound: the residual tests flag it, and
// it is the most significant input; without the corruption no mark is flagged.
TEST(KalmanConsistency, FlagsTheCorruptedMarkOfAnOutlierMission) {
  SimulationOptions o;
  o.seed = 1;
  o.outliers = 1;
  const Mission m = simulate_mission(o);
  const auto corrupted = static_cast<std::size_t>(
      std::find(m.truth_marks_outlier.begin(), m.truth_marks_outlier.end(), 1) - m.truth_marks_outlier.begin());
  ASSERT_LT(corrupted, m.mark_count());
  const KalmanResult r = kalman_smooth(m, m.model, gps_fixes(m));
  const InputTest* t = find_test(r, ConstraintRef::mark(corrupted));
  ASSERT_NE(t, nullptr);
  EXPECT_TRUE(t->flagged);
  EXPECT_EQ(t->dof, 3);
  for (const InputTest& other : r.tests) {
    if (other.input == t->input) continue;
    EXPECT_LT(other.chi2, t->chi2) << "mark or fix " << other.input.row;
  }

  SimulationOptions clean = o;
  clean.outliers = 0;
  const Mission c = simulate_mission(clean);
  const KalmanResult rc = kalman_smooth(c, c.model, gps_fixes(c));
  ASSERT_EQ(rc.tests.size(), c.mark_count() + gps_fixes(c).size());
  for (const InputTest& other : rc.tests) EXPECT_FALSE(other.flagged) << other.input.row;
}

// A mine seen by one mark only: its three measurements determine the mine's three
// coordinates, so the mark's residual is zero whatever it is and it cannot be tested.
TEST(KalmanConsistency, AMinesOnlyMarkIsNotTestable) {
  SimulationOptions o;
  o.seed = 1;
  o.duration = 2400.0;
  Mission m = simulate_mission(o);
  std::size_t first = m.mark_count();
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    if (m.mark_mine[j] != 0) continue;
    if (first == m.mark_count())
      first = j;
    else
      m.mark_mine[j] = -1;  // the smoother skips marks without a mine
  }
  ASSERT_LT(first, m.mark_count());
  const KalmanResult r = kalman_smooth(m, m.model, gps_fixes(m));
  const InputTest* t = find_test(r, ConstraintRef::mark(first));
  ASSERT_NE(t, nullptr);
  EXPECT_TRUE(std::isnan(t->chi2));
  EXPECT_FALSE(t->flagged);
  EXPECT_EQ(find_test(r, ConstraintRef::mark(first + 1)), nullptr);
}

}  // namespace
}  // namespace gesmi
