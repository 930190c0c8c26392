// The Kalman smoother on simulated missions: accurate and consistent with uniform
// errors (its 3-sigma containment is reported, not asserted to be 100 %), and the
// options are validated.

#include "solver/kalman/kalman_smoother.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "solver/kalman/arrowhead_chain.h"
#include "solver/kalman/chain_factors.h"
#include "solver/kalman/kalman_measurements.h"
#include "solver/sim/simulator.h"
#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

// A 2400 s reference-like mission, seed 1, with the given errors.
Mission simulated_2400s(SimulatedErrors errors) {
  SimulationOptions so;
  so.seed = 1;
  so.errors = errors;
  so.duration = 2400.0;
  return simulate_mission(so);
}

TEST(KalmanSmoother, EstimatesTheTinyMissionAndItsMine) {
  const test::TinyMission t = test::make_tiny_mission(3, test::TinyErrors::uniform);
  const KalmanResult r = kalman_smooth(t.mission, t.mission.model, t.fixes);
  ASSERT_EQ(r.steps, t.mission.size());
  for (std::size_t k = 0; k < r.steps; k += 100) {
    EXPECT_NEAR(r.mean[3 * k], t.mission.truth_x[k], 5.0) << k;
    EXPECT_NEAR(r.mean[3 * k + 1], t.mission.truth_y[k], 5.0) << k;
  }
  EXPECT_NEAR(r.mine_mean[0], t.mission.truth_mines[0], 5.0);
  EXPECT_NEAR(r.mine_mean[1], t.mission.truth_mines[1], 5.0);
  for (int a = 0; a < 3; ++a) EXPECT_GT(r.covariance[static_cast<std::size_t>(4 * a)], 0.0);
}

// Without biases the smoother linearises the odometry once, by its dead reckoning, and
// adds those steps again at every pass (FactorSet::odometry, then reset_keeping_steps,
// add_steps_again and FactorSet::without_odometry): the system solved must be, bit for
// bit, the one of every factor linearised at the pass's point, as before that saving.
TEST(KalmanSmoother, TheOdometryKeptIsTheOdometryLinearisedAgain) {
  const test::TinyMission t = test::make_tiny_mission(3, test::TinyErrors::uniform);
  const Mission& m = t.mission;
  const std::size_t n = m.size(), mines = static_cast<std::size_t>(m.mine_count);
  // A linearisation point away from the dead reckoning: the truth, shifted.
  KalmanLinearisation point;
  for (std::size_t k = 0; k < n; ++k) point.position.push_back(Vec3d(m.truth_x[k] + 3.0, m.truth_y[k] - 2.0, m.truth_z[k]));
  point.mine.assign(mines, Vec3d::Zero());
  point.mine_known.assign(mines, 0);
  // (the smoother's prior, p_0 near the origin, as a residual at the point)
  const auto prior = [](ArrowheadChain& chain, const KalmanLinearisation& lin) {
    chain.add_position(0, Mat3d::Identity() * 1e-10, -lin.position[0]);
  };

  ArrowheadChain kept(n, 3 * mines);
  struct KeepSteps final : MeasurementSink {
    ArrowheadChain& chain;
    std::vector<Vec3d> delta;
    explicit KeepSteps(ArrowheadChain& c) : chain(c) {}
    void odometry(std::size_t k, const Mat3d& information, const Vec3d& step, const BiasJacobian&) override {
      chain.add_step(k, information, step);
      delta.push_back(step);
    }
    void scalar(std::size_t, const Eigen::RowVector3d&, int, const Eigen::RowVector3d&, const BiasRow&, double, double,
                const ConstraintRef*) override {}
  } keep(kept);
  KalmanLinearisation lin_kept = point;
  linearise_measurements(m, m.model, t.fixes, {1.0, false, FactorSet::odometry}, lin_kept, keep);
  for (int pass = 0; pass < 2; ++pass) {  // (the second pass at the first one's estimate)
    kept.reset_keeping_steps();
    kept.add_steps_again(keep.delta, lin_kept.position.values());
    prior(kept, lin_kept);  // (after the steps, as the smoother adds it: the same sums, a + b = b + a)
    ChainBuilder kept_builder(kept, mines, false, lin_kept);
    linearise_measurements(m, m.model, t.fixes, {1.0, false, FactorSet::without_odometry}, lin_kept, kept_builder);
    kept.solve();

    ArrowheadChain again(n, 3 * mines);
    KalmanLinearisation lin_again = lin_kept;
    if (pass == 0) lin_again = point;
    prior(again, lin_again);
    ChainBuilder builder(again, mines, false, lin_again);
    linearise_measurements(m, m.model, t.fixes, {1.0, false, FactorSet::all}, lin_again, builder);
    again.solve();
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_EQ(kept.mean(k), again.mean(k)) << "pass " << pass << ", step " << k;
      ASSERT_EQ(kept.covariance(k), again.covariance(k)) << "pass " << pass << ", step " << k;
    }
    EXPECT_EQ(kept.static_mean(), again.static_mean());
    EXPECT_EQ(kept.static_covariance(), again.static_covariance());
    for (std::size_t k = 0; k < n; ++k) lin_kept.position[k] += kept.mean(k);  // (the means are corrections)
  }
}

TEST(KalmanSmoother, ReportsItsContainmentOnSimulatedMissions) {
  for (const SimulatedErrors errors : {SimulatedErrors::uniform, SimulatedErrors::worst_case}) {
    SimulationOptions o;
    o.seed = 5;
    o.errors = errors;
    const Mission m = simulate_mission(o);
    const KalmanResult r = kalman_smooth(m, m.model, gps_fixes(m));
    const Containment c = three_sigma_containment(r, m);
    std::printf("[ report ] %s errors: truth within 3 sigma at %.1f %% (horizontal), %.1f %% (vertical) of steps, "
                "%.0f %% of mines\n",
                errors == SimulatedErrors::uniform ? "uniform" : "worst-case", 100.0 * c.horizontal, 100.0 * c.vertical,
                100.0 * c.mines);
    for (const double f : {c.horizontal, c.vertical, c.mines, c.mines_plane}) {
      EXPECT_GE(f, 0.0);
      EXPECT_LE(f, 1.0);
    }
    // With errors as the model assumes, the estimate stays close to the truth.
    if (errors == SimulatedErrors::uniform) {
      for (std::size_t i = 0; i < r.mines; ++i)
        EXPECT_NEAR(r.mine_mean[3 * i], m.truth_mines[3 * i], 3.0) << "mine " << i;
    }
  }
}

// The linearisations go on until no coordinate moves more than the tolerance: on
// worst-case data two from the dead reckoning (the old fixed count, and start) are not
// enough, the converged estimate is a fixed point (one more linearisation moves it by no
// more than the tolerance plus the chain's rounding floor), and a cap reached is reported
// as not converged.
TEST(KalmanSmoother, IteratesUntilTheStepIsBelowTheTolerance) {
  const Mission m = simulated_2400s(SimulatedErrors::worst_case);
  const auto fixes = gps_fixes(m);
  KalmanOptions from_dead_reckoning;
  from_dead_reckoning.start = KalmanStart::dead_reckoning;
  const KalmanResult converged = kalman_smooth(m, m.model, fixes, from_dead_reckoning);
  EXPECT_TRUE(converged.converged);
  EXPECT_LE(converged.last_step, KalmanOptions{}.tolerance);
  EXPECT_GT(converged.iterations, 2);
  std::printf("worst case, 2400 s: converged after %d linearisations, last step %.2g m\n", converged.iterations,
              converged.last_step);

  KalmanOptions two = from_dead_reckoning;
  two.max_iterations = 2;
  const KalmanResult capped = kalman_smooth(m, m.model, fixes, two);
  EXPECT_FALSE(capped.converged);
  EXPECT_EQ(capped.iterations, 2);
  EXPECT_GT(capped.last_step, two.tolerance);

  KalmanOptions one_more = from_dead_reckoning;
  one_more.max_iterations = converged.iterations + 1;
  one_more.tolerance = 0.0;
  const KalmanResult next = kalman_smooth(m, m.model, fixes, one_more);
  double moved = 0.0, moved_from_capped = 0.0;
  for (std::size_t i = 0; i < next.mean.size(); ++i) {
    moved = std::max(moved, std::fabs(next.mean[i] - converged.mean[i]));
    moved_from_capped = std::max(moved_from_capped, std::fabs(capped.mean[i] - converged.mean[i]));
  }
  EXPECT_LE(moved, KalmanOptions{}.tolerance + 1e-3);
  EXPECT_GT(moved_from_capped, 0.01);  // two linearisations were centimetres or more away
  std::printf("one more linearisation moved the estimate %.2g m; two linearisations were %.2g m away\n", moved,
              moved_from_capped);
}

// Mines are judged by their Gaussian's 99.73 % region, in 3-D and in the plane, not axis
// by axis: with unit variances and a north-east correlation of 0.9, an error (3.2, 3.2)
// is beyond 3 sigma on each axis but d^2 = 2 a^2 / (1 + rho) = 10.78 lies inside both
// regions (limits 14.16 and 11.83); an error (2.5, -2.5) is within 3 sigma on each axis
// but d^2 = 2 a^2 / (1 - rho) = 125 lies outside. The trajectory is judged per axis.
TEST(KalmanSmoother, ContainmentJudgesMinesByTheirRegionAndStepsPerAxis) {
  Mission m;
  m.truth_x = {0.0, 0.0};
  m.truth_y = {0.0, 0.0};
  m.truth_z = {0.0, 0.0};
  m.truth_mines = {3.2, 3.2, 0.0, 2.5, -2.5, 0.0};
  KalmanResult r;
  r.steps = 2;
  r.mines = 2;
  r.mean = {0.0, 0.0, 0.0, 2.9, 0.0, 3.1};  // step 1: inside horizontally, outside vertically
  r.covariance.assign(18, 0.0);
  for (int k = 0; k < 2; ++k)
    for (int a = 0; a < 3; ++a) r.covariance[static_cast<std::size_t>(9 * k + 4 * a)] = 1.0;
  r.mine_mean.assign(6, 0.0);
  const std::vector<double> correlated = {1.0, 0.9, 0.0, 0.9, 1.0, 0.0, 0.0, 0.0, 1.0};
  r.mine_covariance = correlated;
  r.mine_covariance.insert(r.mine_covariance.end(), correlated.begin(), correlated.end());
  const Containment c = three_sigma_containment(r, m);
  EXPECT_DOUBLE_EQ(c.horizontal, 1.0);
  EXPECT_DOUBLE_EQ(c.vertical, 0.5);
  EXPECT_DOUBLE_EQ(c.mines, 0.5);
  EXPECT_DOUBLE_EQ(c.mines_plane, 0.5);
  m.truth_mines[3] = m.truth_mines[4] = 0.0;  // the second mine at its mean
  EXPECT_DOUBLE_EQ(three_sigma_containment(r, m).mines, 1.0);
  EXPECT_TRUE(std::isnan(three_sigma_containment(r, Mission{}).horizontal));
  // Counted step by step as a reader streams the truth (gesmi kalman): the same, and
  // steps out of order or missing are refused.
  ContainmentCount count(r);
  count.add(0, m.truth_x[0], m.truth_y[0], m.truth_z[0]);
  EXPECT_THROW(count.finish(m.truth_mines), std::logic_error);  // step 1 missing
  EXPECT_THROW(count.add(0, 0.0, 0.0, 0.0), std::logic_error);  // step 0 again
  count.add(1, m.truth_x[1], m.truth_y[1], m.truth_z[1]);
  EXPECT_THROW(count.add(2, 0.0, 0.0, 0.0), std::logic_error);  // beyond the result's steps
  const Containment streamed = count.finish(m.truth_mines);
  EXPECT_DOUBLE_EQ(streamed.horizontal, 1.0);
  EXPECT_DOUBLE_EQ(streamed.vertical, 0.5);
  EXPECT_DOUBLE_EQ(streamed.mines, 1.0);
  EXPECT_TRUE(std::isnan(ContainmentCount(r).finish(m.truth_mines).mines));  // no truth: all NaN
}

// A Gauss-Newton iteration still converging, slowly (each step about 0.6-0.7 of the one
// before: drifting errors with the bias states), is not stopped as stalled, although
// its steps are already far below 1 % of a standard deviation: it reaches the cap,
// not converged. (A rule that stopped whenever a step failed to halve stopped it.)
TEST(KalmanSmoother, DoesNotStopAnIterationThatIsStillConvergingSlowly) {
  const Mission m = simulated_2400s(SimulatedErrors::drifting);
  KalmanOptions o;
  o.biases = true;
  const KalmanResult r = kalman_smooth(m, m.model, gps_fixes(m), o);
  EXPECT_FALSE(r.stalled) << "last step " << r.last_step << " m, " << r.last_step_sigmas << " sigma";
  EXPECT_EQ(r.iterations, o.max_iterations);
  EXPECT_LE(r.last_step_sigmas, o.stall_fraction);  // the sigma test alone would have stopped it
}

// Each reason starts with the option it is about, as the gesmi command spells it.
TEST(KalmanSmoother, ValidatesItsOptions) {
  const auto starts_with = [](const std::string& why, const char* option) { return why.rfind(option, 0) == 0; };
  KalmanOptions o;
  EXPECT_TRUE(o.validate().empty());
  o.noise_factor = 0.0;
  EXPECT_TRUE(starts_with(o.validate(), "noise-factor: ")) << o.validate();
  o.noise_factor = 1.0;
  for (const int bad : {0, 101}) {
    o.max_iterations = bad;
    EXPECT_TRUE(starts_with(o.validate(), "max-iterations: ")) << o.validate();
  }
  o.max_iterations = 20;
  o.tolerance = -1.0;
  EXPECT_TRUE(starts_with(o.validate(), "tolerance: ")) << o.validate();
  o.tolerance = 1e-3;
  for (const double bad : {-0.1, 1.0, std::nan("")}) {
    o.stall_fraction = bad;
    EXPECT_TRUE(starts_with(o.validate(), "stall-fraction: ")) << bad;
  }
}

// A tolerance the rounding floor never lets the steps reach (0): the linearisations stop
// when the step stops shrinking while it is within stall_fraction of every coordinate's
// standard deviation, well before the cap; the estimate is then within a few times that
// fraction of a standard deviation of where the cap's last linearisation leaves it. With
// stall_fraction 0 they go on to the cap, not stalled.
//
// The floor is the rounding of the corrections the chain solves for (chain_factors.h),
// not of the positions: on this mission, whose worst-case errors make the iteration
// shrink its steps only about five-fold a pass, the steps go below a nanometre before
// they stall. (Solved in positions, they stalled at 0.6 mm after 9 passes.)
TEST(KalmanSmoother, StopsAtTheRoundingFloorWhenTheStepsStallWithinTheUncertainty) {
  const Mission m = simulated_2400s(SimulatedErrors::worst_case);
  const auto fixes = gps_fixes(m);
  KalmanOptions unreachable;
  unreachable.tolerance = 0.0;
  unreachable.max_iterations = 60;
  const KalmanResult stalled = kalman_smooth(m, m.model, fixes, unreachable);
  EXPECT_TRUE(stalled.stalled);
  EXPECT_FALSE(stalled.converged);
  EXPECT_LT(stalled.iterations, unreachable.max_iterations);
  EXPECT_LE(stalled.last_step_sigmas, unreachable.stall_fraction);
  EXPECT_GT(stalled.last_step, 0.0);
  EXPECT_LT(stalled.last_step, 1e-9);

  KalmanOptions to_the_cap = unreachable;
  to_the_cap.stall_fraction = 0.0;
  const KalmanResult capped = kalman_smooth(m, m.model, fixes, to_the_cap);
  EXPECT_FALSE(capped.stalled);
  EXPECT_EQ(capped.iterations, to_the_cap.max_iterations);
  double worst = 0.0;  // in standard deviations of the capped estimate
  for (std::size_t k = 0; k < capped.steps; ++k)
    for (std::size_t a = 0; a < 3; ++a)
      worst = std::max(worst, std::fabs(stalled.mean[3 * k + a] - capped.mean[3 * k + a]) /
                                  std::sqrt(capped.covariance[9 * k + 4 * a]));
  EXPECT_LE(worst, 5.0 * unreachable.stall_fraction);
  std::printf("stalled after %d linearisations (last step %.2g m, %.2g sigma); %.2g sigma from the cap's estimate\n",
              stalled.iterations, stalled.last_step, stalled.last_step_sigmas, worst);
}

}  // namespace
}  // namespace gesmi
