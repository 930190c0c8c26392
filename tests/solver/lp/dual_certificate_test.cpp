// Certified bounds from Lagrange multipliers (solver/lp/dual_certificate.h) on random
// small linear programs built around a known feasible point, with multipliers from
// COIN-OR CLP (optimal), perturbed, of the wrong sign, random and zero. Independent
// oracles: the exact value of the certificate's formula in rational arithmetic
// (boost::multiprecision), which the rounded bound must never exceed; the objective at
// the known feasible point, which no bound may exceed; and CLP's optimum, which the
// bound from CLP's own duals must reach to within its tolerance.

#include "solver/lp/dual_certificate.h"

#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_int.hpp>
#include <coin/ClpSimplex.hpp>
#include <coin/CoinPackedMatrix.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace gesmi {
namespace {

using Rational = boost::multiprecision::cpp_rational;

struct Instance {
  LinearProgram lp;
  std::vector<double> objective, feasible;
};

// n columns in [-10, 10] (one unbounded side now and then), m dense rows with random
// coefficients around a feasible point; finite row bounds unless `infinite_rows`.
Instance random_instance(std::mt19937_64& random, bool infinite_rows) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> size(2, 6);
  Instance x;
  const std::size_t n = static_cast<std::size_t>(size(random)), m = static_cast<std::size_t>(size(random) + 2);
  x.lp.columns = n;
  for (std::size_t j = 0; j < n; ++j) {
    x.feasible.push_back(5.0 * unit(random));
    x.lp.column_lower.push_back(infinite_rows && unit(random) > 0.7 ? -INFINITY : -10.0);
    x.lp.column_upper.push_back(10.0);
    x.objective.push_back(unit(random) / 3.0);  // (thirds: not exact in binary)
  }
  for (std::size_t i = 0; i < m; ++i) {
    std::vector<std::size_t> columns;
    std::vector<double> coefficients;
    double at = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      columns.push_back(j);
      coefficients.push_back(3.0 * unit(random) / 7.0);
      at += coefficients.back() * x.feasible[j];
    }
    double lower = at - std::fabs(unit(random)) - 1e-3, upper = at + std::fabs(unit(random)) + 1e-3;
    if (infinite_rows && unit(random) > 0.5) (unit(random) > 0.0 ? lower : upper) = unit(random) > 0.0 ? -INFINITY : INFINITY;
    if (lower == INFINITY) lower = -INFINITY;
    if (upper == -INFINITY) upper = INFINITY;
    x.lp.add_row(columns, coefficients, lower, upper);
  }
  return x;
}

struct ClpAnswer {
  bool optimal = false;
  double objective = 0.0;
  std::vector<double> duals;
};

ClpAnswer solve_with_clp(const Instance& x) {
  const LinearProgram& lp = x.lp;
  std::vector<int> starts, indices;
  for (std::size_t i = 0; i <= lp.rows(); ++i) starts.push_back(static_cast<int>(lp.row_start[i]));
  for (std::size_t c : lp.column) indices.push_back(static_cast<int>(c));
  std::vector<int> lengths;
  for (std::size_t i = 0; i < lp.rows(); ++i) lengths.push_back(starts[i + 1] - starts[i]);
  const CoinPackedMatrix matrix(false, static_cast<int>(lp.columns), static_cast<int>(lp.rows()),
                                static_cast<CoinBigIndex>(lp.value.size()), lp.value.data(), indices.data(), starts.data(),
                                lengths.data());
  const auto finite = [](std::vector<double> v) {
    for (double& b : v) b = std::isinf(b) ? (b > 0 ? COIN_DBL_MAX : -COIN_DBL_MAX) : b;
    return v;
  };
  ClpSimplex model;
  model.setLogLevel(0);
  const std::vector<double> cl = finite(lp.column_lower), cu = finite(lp.column_upper), rl = finite(lp.row_lower),
                            ru = finite(lp.row_upper);
  model.loadProblem(matrix, cl.data(), cu.data(), x.objective.data(), rl.data(), ru.data());
  model.dual();
  ClpAnswer a;
  a.optimal = model.status() == 0;
  a.objective = model.objectiveValue();
  a.duals.assign(model.dualRowSolution(), model.dualRowSolution() + lp.rows());
  return a;
}

// The certificate's formula in exact arithmetic (finite bounds only), with the same
// rule for multipliers that meet an infinite bound.
Rational exact_bound(const LinearProgram& lp, const std::vector<double>& c, const std::vector<double>& lambda) {
  std::vector<Rational> d(c.begin(), c.end());
  Rational bound = 0;
  for (std::size_t i = 0; i < lp.rows(); ++i) {
    const Rational l = lambda[i];
    for (std::size_t k = lp.row_start[i]; k < lp.row_start[i + 1]; ++k) d[lp.column[k]] -= Rational(lp.value[k]) * l;
    bound += std::min(l * Rational(lp.row_lower[i]), l * Rational(lp.row_upper[i]));
  }
  for (std::size_t j = 0; j < lp.columns; ++j)
    bound += std::min(d[j] * Rational(lp.column_lower[j]), d[j] * Rational(lp.column_upper[j]));
  return bound;
}

Rational exact_dot(const std::vector<double>& a, const std::vector<double>& b) {
  Rational s = 0;
  for (std::size_t j = 0; j < a.size(); ++j) s += Rational(a[j]) * Rational(b[j]);
  return s;
}

TEST(DualCertificate, NeverAboveItsExactValueNorAFeasiblePointWhateverTheMultipliers) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int tight = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Instance x = random_instance(random, false);
    const ClpAnswer clp = solve_with_clp(x);
    ASSERT_TRUE(clp.optimal) << trial;  // bounded columns around a feasible point
    std::vector<std::vector<double>> candidates = {clp.duals, std::vector<double>(x.lp.rows(), 0.0)};
    std::vector<double> perturbed = clp.duals, flipped = clp.duals, wild(x.lp.rows());
    for (std::size_t i = 0; i < x.lp.rows(); ++i) {
      perturbed[i] *= 1.0 + 1e-3 * unit(random);
      flipped[i] = -flipped[i];
      wild[i] = 10.0 * unit(random);
    }
    candidates.insert(candidates.end(), {perturbed, flipped, wild});
    const Rational at_feasible = exact_dot(x.objective, x.feasible);
    for (const std::vector<double>& lambda : candidates) {
      const double bound = certified_lower_bound(x.lp, x.objective, lambda);
      ASSERT_LE(Rational(bound), exact_bound(x.lp, x.objective, lambda)) << trial;
      ASSERT_LE(Rational(bound), at_feasible) << trial;
    }
    // CLP's own duals reach its optimum.
    const double from_duals = certified_lower_bound(x.lp, x.objective, clp.duals);
    const double scale = 1.0 + std::fabs(clp.objective);
    EXPECT_LE(from_duals, clp.objective + 1e-9 * scale) << trial;
    EXPECT_GE(from_duals, clp.objective - 1e-7 * scale) << trial;
    tight += from_duals >= clp.objective - 1e-9 * scale;
  }
  EXPECT_GT(tight, 390);
}

TEST(DualCertificate, InfiniteBoundsGiveFiniteBoundsWhereTheMultipliersAllow) {
  std::mt19937_64 random(12);
  int finite = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Instance x = random_instance(random, true);
    const ClpAnswer clp = solve_with_clp(x);
    if (!clp.optimal) continue;  // (unbounded with an infinite column)
    const double bound = certified_lower_bound(x.lp, x.objective, clp.duals);
    ASSERT_LE(Rational(std::max(bound, -1e300)), exact_dot(x.objective, x.feasible)) << trial;
    ASSERT_FALSE(std::isnan(bound));
    ASSERT_LE(bound, clp.objective + 1e-9 * (1.0 + std::fabs(clp.objective))) << trial;
    finite += std::isfinite(bound);
  }
  EXPECT_GT(finite, 100);
}

TEST(DualCertificate, AFarkasRayCertifiesAnEmptySet) {
  // 1 <= x + y <= inf, -inf <= x + y <= 0.5, x and y in [-10, 10]: empty.
  LinearProgram lp;
  lp.columns = 2;
  lp.column_lower = {-10.0, -10.0};
  lp.column_upper = {10.0, 10.0};
  lp.add_row({0, 1}, {1.0, 1.0}, 1.0, INFINITY);
  lp.add_row({0, 1}, {1.0, 1.0}, -INFINITY, 0.5);
  EXPECT_TRUE(certifies_empty(lp, std::vector<double>{1.0, -1.0}));
  EXPECT_EQ(certified_lower_bound(lp, std::vector<double>{0.0, 0.0}, std::vector<double>{1.0, -1.0}), 0.5);
  EXPECT_FALSE(certifies_empty(lp, std::vector<double>{0.0, 0.0}));
  EXPECT_FALSE(certifies_empty(lp, std::vector<double>{-1.0, 1.0}));  // the wrong signs meet the infinite sides: zeros
  // A feasible set is never certified empty, whatever the multipliers.
  lp.row_upper[1] = 2.0;
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(-5.0, 5.0);
  for (int k = 0; k < 1000; ++k) ASSERT_FALSE(certifies_empty(lp, std::vector<double>{unit(random), unit(random)}));
}

TEST(DualCertificate, MalformedProgramsAreRefused) {
  LinearProgram lp;
  lp.columns = 1;
  lp.column_lower = {0.0};
  lp.column_upper = {1.0};
  lp.add_row({0}, {1.0}, 0.0, 1.0);
  const std::vector<double> c{1.0}, lambda{1.0};
  EXPECT_NO_THROW(certified_lower_bound(lp, c, lambda));
  EXPECT_THROW(certified_lower_bound(lp, std::vector<double>{1.0, 2.0}, lambda), std::invalid_argument);
  EXPECT_THROW(certified_lower_bound(lp, std::vector<double>{NAN}, lambda), std::invalid_argument);
  LinearProgram inverted = lp;
  inverted.row_lower[0] = 2.0;
  EXPECT_THROW(certified_lower_bound(inverted, c, lambda), std::invalid_argument);
  LinearProgram wrong_column = lp;
  wrong_column.column[0] = 3;
  EXPECT_THROW(certified_lower_bound(wrong_column, c, lambda), std::invalid_argument);
  // Multipliers that are not finite are taken as zeros.
  EXPECT_EQ(certified_lower_bound(lp, c, std::vector<double>{NAN}), 0.0);
}

}  // namespace
}  // namespace gesmi
