// The smoother's start from a coarse chain (coarse_start.h): its nodes, its odometry
// against the full chain's own marginal, and the smoothing it starts, which must end
// where the dead reckoning's start ends, in fewer full linearisations on the reference
// mission.

#include "solver/kalman/coarse_start.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "solver/kalman/kalman_measurements.h"
#include "solver/kalman/kalman_smoother.h"
#include "solver/sim/simulator.h"
#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

Mission simulated(SimulatedErrors errors, double duration) {
  SimulationOptions so;
  so.seed = 1;
  so.errors = errors;
  so.duration = duration;
  return simulate_mission(so);
}

KalmanResult smoothed(const Mission& m, KalmanStart start, bool biases = false) {
  KalmanOptions o;
  o.start = start;
  o.biases = biases;
  return kalman_smooth(m, m.model, gps_fixes(m), o);
}

TEST(CoarseStart, NodesAreEveryStrideTheLastStepTheFixesAndTheAssociatedMarks) {
  const test::TinyMission t = test::make_tiny_mission(3, test::TinyErrors::uniform);
  Mission m = t.mission;
  ASSERT_GE(m.mark_count(), 2u);
  m.mark_mine[1] = -1;  // a mark without its mine: the smoother does not read it
  const std::size_t stride = 100;
  const std::vector<std::size_t> nodes = coarse_nodes(m, t.fixes, stride);
  ASSERT_TRUE(std::is_sorted(nodes.begin(), nodes.end()));
  EXPECT_EQ(std::adjacent_find(nodes.begin(), nodes.end()), nodes.end()) << "a node twice";
  const auto has = [&](std::size_t k) { return std::binary_search(nodes.begin(), nodes.end(), k); };
  for (std::size_t k = 0; k < m.size(); k += stride) EXPECT_TRUE(has(k)) << k;
  EXPECT_TRUE(has(m.size() - 1));
  std::size_t expected = (m.size() + stride - 1) / stride + ((m.size() - 1) % stride != 0);
  for (const PositionFix& fix : t.fixes) {
    const std::size_t k = step_at(m, fix.time);
    EXPECT_TRUE(has(k)) << "fix at " << fix.time;
    expected += k % stride != 0 && k != m.size() - 1;
  }
  const std::size_t marked = step_at(m, m.mark_time[0]), unmarked = step_at(m, m.mark_time[1]);
  EXPECT_TRUE(has(marked));
  expected += marked % stride != 0;
  if (unmarked % stride != 0) {
    EXPECT_FALSE(has(unmarked)) << "the mark without a mine has a node";
  }
  // (the fixes' steps are distinct from the mark's on this mission: the count is exact)
  EXPECT_EQ(nodes.size(), expected);
}

// The coarse step between two nodes is the marginal of the fine steps between them: a
// chain of those steps alone, its first position pinned, gives p_b - p_a that mean and
// that covariance (the chain's own smoother, an independent computation of the sums).
TEST(CoarseStart, TheCoarseStepIsTheMarginalOfTheStepsItJoins) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const std::size_t n = 12;
  std::vector<Vec3d> delta;
  std::vector<ArrowheadChain::Symmetric3> information;
  ArrowheadChain chain(n, 0);
  chain.add_position(0, Mat3d::Identity() * 1e12, Vec3d::Zero());
  for (std::size_t k = 0; k + 1 < n; ++k) {
    Mat3d a;
    for (int i = 0; i < 9; ++i) a.data()[i] = uniform(random);
    const Mat3d w = a * a.transpose() + 0.5 * Mat3d::Identity();  // symmetric positive definite
    const Vec3d d(uniform(random), uniform(random), uniform(random));
    chain.add_step(k, w, d);
    delta.push_back(d);
    information.push_back(ArrowheadChain::Symmetric3::upper_of(w));
  }
  chain.solve();
  const std::vector<std::size_t> nodes = {0, 5, n - 1};
  const CoarseOdometry coarse = coarse_odometry(nodes, delta, information);
  ASSERT_EQ(coarse.delta.size(), 2u);
  ASSERT_EQ(coarse.information.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const std::size_t a = nodes[i], b = nodes[i + 1];
    const Vec3d mean = chain.mean(b) - chain.mean(a);
    // With p_0 pinned, Cov(p_b) - Cov(p_a) is the covariance the steps a..b-1 add.
    const Mat3d covariance = chain.covariance(b) - chain.covariance(a);
    const Mat3d coarse_covariance = coarse.information[i].full().inverse();
    for (int r = 0; r < 3; ++r) {
      EXPECT_NEAR(coarse.delta[i][r], mean[r], 1e-9 * (1.0 + std::fabs(mean[r]))) << "node " << i;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(coarse_covariance(r, c), covariance(r, c), 1e-9 * covariance.norm()) << "node " << i << " (" << r << ", " << c << ")";
    }
  }
  EXPECT_THROW(coarse_odometry(std::vector<std::size_t>{0, n}, delta, information), std::invalid_argument);
}

// The scalar smoother of the depths against a dense least-squares solve of the same
// quadratic: the depth readings (variance at the point's depth), the weak prior on the
// first depth, and the odometry's steps, either their vertical part alone (marginal
// variance C_zz) or in full with the horizontal held at the point's (the conditioned
// steps: z minimising the 3-D odometry's quadratic given h).
TEST(CoarseStart, SmoothedDepthsSolveTheirLeastSquaresProblem) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const std::size_t n = 30;
  Mission m;
  FlatPoints point;
  std::vector<Vec3d> delta;
  std::vector<ArrowheadChain::Symmetric3> information;
  for (std::size_t k = 0; k < n; ++k) {
    m.time.push_back(static_cast<double>(k));
    m.depth.push_back(10.0 + uniform(random));
    point.push_back(Vec3d(5.0 * uniform(random), 5.0 * uniform(random), 10.0 + 0.5 * uniform(random)));
  }
  std::vector<Mat3d> w;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    Mat3d a;
    for (int i = 0; i < 9; ++i) a.data()[i] = uniform(random);
    w.push_back(a * a.transpose() + 0.3 * Mat3d::Identity());
    information.push_back(ArrowheadChain::Symmetric3::upper_of(w.back()));
    delta.push_back(Vec3d(uniform(random), uniform(random), 0.2 * uniform(random)));
  }
  const SensorModel model;
  for (const bool conditioned : {false, true}) {
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
    const auto e = [](std::size_t k) { return static_cast<Eigen::Index>(k); };
    h(0, 0) += 1e-10;  // (the weak prior, variance 1e10, at the point's first depth)
    g(0) += 1e-10 * point[0][2];
    for (std::size_t k = 0; k < n; ++k) {
      const double r = 1.0 / depth_variance(model, point[k][2], 1.0);
      h(e(k), e(k)) += r;
      g(e(k)) += r * m.depth[k];
    }
    for (std::size_t k = 0; k + 1 < n; ++k) {
      // (z_{k+1} - z_k - b) with weight q: b, q from the marginal, or from the full W
      // with the horizontal residual fixed: W_zz (dz)^2 + 2 dz W_zh r_h + const.
      double q = 0.0, b = 0.0;
      if (!conditioned) {
        q = 1.0 / w[k].inverse()(2, 2);
        b = delta[k][2];
      } else {
        const Eigen::Vector2d r_h = (point[k + 1] - point[k]).head<2>() - delta[k].head<2>();
        q = w[k](2, 2);
        b = delta[k][2] - w[k].block<1, 2>(2, 0).dot(r_h) / w[k](2, 2);
      }
      h(e(k), e(k)) += q;
      h(e(k + 1), e(k + 1)) += q;
      h(e(k), e(k + 1)) -= q;
      h(e(k + 1), e(k)) -= q;
      g(e(k + 1)) += q * b;
      g(e(k)) -= q * b;
    }
    const Eigen::VectorXd dense = h.ldlt().solve(g);
    const std::vector<double> depth = smoothed_depths(m, model, 1.0, delta, information, point, conditioned);
    ASSERT_EQ(depth.size(), n);
    for (std::size_t k = 0; k < n; ++k)
      EXPECT_NEAR(depth[k], dense(e(k)), 1e-9) << (conditioned ? "conditioned, " : "") << "step " << k;
  }
}

// Started from the coarse chain, the smoothing converges where the dead reckoning's
// start converges: within the tolerance in every mean (each is within its last step of
// the same fixed point), and with the same covariances but for the linearisation point's
// share (the ranges' directions, a millimetre apart).
TEST(CoarseStart, EndsWhereTheDeadReckoningsStartEnds) {
  for (const SimulatedErrors errors : {SimulatedErrors::uniform, SimulatedErrors::worst_case}) {
    const Mission m = simulated(errors, 2400.0);
    const KalmanResult coarse = smoothed(m, KalmanStart::coarse);
    const KalmanResult dead_reckoning = smoothed(m, KalmanStart::dead_reckoning);
    ASSERT_TRUE(coarse.converged);
    ASSERT_TRUE(dead_reckoning.converged);
    EXPECT_GT(coarse.coarse_iterations, 0);
    EXPECT_EQ(dead_reckoning.coarse_iterations, 0);
    double mean = 0.0, covariance = 0.0;
    for (std::size_t i = 0; i < coarse.mean.size(); ++i) mean = std::max(mean, std::fabs(coarse.mean[i] - dead_reckoning.mean[i]));
    for (std::size_t i = 0; i < coarse.mine_mean.size(); ++i)
      mean = std::max(mean, std::fabs(coarse.mine_mean[i] - dead_reckoning.mine_mean[i]));
    for (std::size_t k = 0; k < coarse.steps; ++k)
      for (int a = 0; a < 3; ++a) {
        const std::size_t d = 9 * k + static_cast<std::size_t>(4 * a);
        covariance = std::max(covariance, std::fabs(coarse.covariance[d] / dead_reckoning.covariance[d] - 1.0));
      }
    EXPECT_LE(mean, KalmanOptions{}.tolerance);
    EXPECT_LE(covariance, 1e-3);
    EXPECT_NEAR(coarse.consistency.chi2, dead_reckoning.consistency.chi2, 1e-4 * dead_reckoning.consistency.chi2);
    std::printf("[ report ] %s errors, 2400 s: %d full linearisations after %d coarse ones, against %d from the dead "
                "reckoning; means %.2g m apart, variances %.2g relative\n",
                simulated_errors_name(errors), coarse.iterations, coarse.coarse_iterations, dead_reckoning.iterations,
                mean, covariance);
  }
}

// On the reference-like mission the coarse chain saves two full linearisations of three:
// from the dead reckoning the passes move the estimate metres, millimetres, then
// hundredths of one; from the coarse chain's point (its depths those of every reading)
// the first moves nothing more than the tolerance, and converges.
TEST(CoarseStart, SavesFullLinearisationsOnTheReferenceMission) {
  const Mission m = simulated(SimulatedErrors::uniform, SimulationOptions{}.duration);
  const KalmanResult coarse = smoothed(m, KalmanStart::coarse);
  const KalmanResult dead_reckoning = smoothed(m, KalmanStart::dead_reckoning);
  ASSERT_TRUE(coarse.converged);
  ASSERT_TRUE(dead_reckoning.converged);
  EXPECT_LT(coarse.iterations, dead_reckoning.iterations);
  EXPECT_EQ(coarse.iterations, 1);
  std::printf("[ report ] reference-like mission: %d full linearisations after %d coarse ones, against %d from the "
              "dead reckoning\n",
              coarse.iterations, coarse.coarse_iterations, dead_reckoning.iterations);
}

// With biases the odometry depends on them: the smoothing starts from the dead reckoning.
TEST(CoarseStart, WithBiasesTheDeadReckoningIsTheStart) {
  const Mission m = simulated(SimulatedErrors::uniform, 600.0);
  const KalmanResult biased = smoothed(m, KalmanStart::coarse, true);
  EXPECT_EQ(biased.coarse_iterations, 0);
  const KalmanResult dead_reckoning = smoothed(m, KalmanStart::dead_reckoning, true);
  EXPECT_EQ(biased.mean, dead_reckoning.mean);
}

// When the coarse chain would hold more than half the samples (here the first 200
// samples, a fix at every other one) the smoothing starts from the dead reckoning: the
// same result, bit for bit.
TEST(CoarseStart, ACoarseChainAsLongAsTheMissionIsNotSolved) {
  const test::TinyMission t = test::make_tiny_mission(3, test::TinyErrors::uniform);
  Mission m = t.mission;
  const std::size_t n = 200;
  for (auto* column : {&m.time, &m.roll, &m.pitch, &m.heading, &m.vx, &m.vy, &m.vz, &m.altitude, &m.depth})
    column->resize(n);
  ASSERT_TRUE(m.half_widths.vx.empty()) << "per-sample half-widths to cut too";
  for (auto* column : {&m.mark_time, &m.mark_range}) column->clear();
  for (auto* column : {&m.mark_mine, &m.mark_side}) column->clear();
  std::vector<PositionFix> everywhere;
  for (std::size_t k = 0; k < n; k += 2) {
    PositionFix fix = t.fixes.front();
    fix.time = m.time[k];
    everywhere.push_back(fix);
  }
  ASSERT_GT(2 * coarse_nodes(m, everywhere, kCoarseStride).size(), m.size());
  KalmanOptions o;
  const KalmanResult coarse = kalman_smooth(m, m.model, everywhere, o);
  EXPECT_EQ(coarse.coarse_iterations, 0);
  o.start = KalmanStart::dead_reckoning;
  EXPECT_EQ(coarse.mean, kalman_smooth(m, m.model, everywhere, o).mean);
}

}  // namespace
}  // namespace gesmi
