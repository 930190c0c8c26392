// The chain solver against closed forms: a dense least-squares solve of the same
// linear-Gaussian problem (means and covariances), and the textbook Kalman filter with
// Rauch-Tung-Striebel smoothing on a chain without static unknowns.

#include "solver/kalman/arrowhead_chain.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <random>
#include <span>
#include <vector>

namespace gesmi {
namespace {

using MatX = Eigen::MatrixXd;
using VecX = Eigen::VectorXd;

Eigen::Matrix3d random_spd(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix3d a;
  for (int i = 0; i < 9; ++i) a(i / 3, i % 3) = u(rng);
  return scale * (a * a.transpose() + 0.5 * Eigen::Matrix3d::Identity());
}

// The same factors applied to both a chain and a dense information matrix.
struct Both {
  std::size_t n, q;
  ArrowheadChain chain;
  MatX lambda;
  VecX eta;
  Both(std::size_t n_, std::size_t q_) : n(n_), q(q_), chain(n_, q_, 1e-12), lambda(MatX::Zero(3 * n_ + q_, 3 * n_ + q_)), eta(VecX::Zero(3 * n_ + q_)) {
    lambda.bottomRightCorner(q_, q_) = 1e-12 * MatX::Identity(q_, q_);
  }
  Eigen::Index p(std::size_t k) const { return static_cast<Eigen::Index>(3 * k); }
  Eigen::Index m() const { return static_cast<Eigen::Index>(3 * n); }
  void position(std::size_t k, const Eigen::Matrix3d& w, const Eigen::Vector3d& mean) {
    chain.add_position(k, w, mean);
    lambda.block<3, 3>(p(k), p(k)) += w;
    eta.segment<3>(p(k)) += w * mean;
  }
  void step(std::size_t k, const Eigen::Matrix3d& w, const Eigen::Vector3d& delta) {
    chain.add_step(k, w, delta);
    lambda.block<3, 3>(p(k), p(k)) += w;
    lambda.block<3, 3>(p(k + 1), p(k + 1)) += w;
    lambda.block<3, 3>(p(k), p(k + 1)) -= w;
    lambda.block<3, 3>(p(k + 1), p(k)) -= w;
    eta.segment<3>(p(k)) -= w * delta;
    eta.segment<3>(p(k + 1)) += w * delta;
  }
  void mixed(std::size_t k, const Eigen::RowVector3d& hp, const Eigen::RowVectorXd& hm, double z, double w) {
    chain.add_mixed(k, hp, hm, z, w);
    Eigen::RowVectorXd h = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(3 * n + q));
    h.segment<3>(p(k)) = hp;
    h.tail(static_cast<Eigen::Index>(q)) = hm;
    lambda += w * h.transpose() * h;
    eta += w * z * h.transpose();
  }
  // Random steps of information about `step_scale` between all positions, and a random
  // prior of information about 0.5 on every `prior_every`-th position.
  void random_chain(std::mt19937_64& rng, double step_scale, std::size_t prior_every) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t k = 0; k + 1 < n; ++k)
      step(k, random_spd(rng, step_scale), Eigen::Vector3d(u(rng), u(rng), u(rng)));
    for (std::size_t k = 0; k < n; k += prior_every)
      position(k, random_spd(rng, 0.5), Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
  // A mixed row of random coefficients and value, of information weight + u (u in [-1, 1]).
  void random_mixed(std::mt19937_64& rng, std::size_t k, double weight) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::RowVectorXd hm = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(q));
    for (std::size_t i = 0; i < q; ++i) hm(static_cast<Eigen::Index>(i)) = u(rng);
    mixed(k, Eigen::RowVector3d(u(rng), u(rng), u(rng)), hm, u(rng), weight + u(rng));
  }
};

TEST(ArrowheadChain, MatchesADenseLeastSquaresSolve) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = 60, q = 6;
  Both b(n, q);
  for (std::size_t k = 0; k + 1 < n; ++k) b.step(k, random_spd(rng, 50.0), Eigen::Vector3d(u(rng), u(rng), u(rng)));
  for (std::size_t k = 0; k < n; k += 7)
    b.position(k, random_spd(rng, 0.5), Eigen::Vector3d(u(rng), u(rng), 10 * u(rng)));
  for (const std::size_t k : {std::size_t{11}, std::size_t{12}, std::size_t{30}, std::size_t{45}, std::size_t{59}})
    for (int r = 0; r < 3; ++r) b.random_mixed(rng, k, 3.0);
  b.chain.solve();
  const Eigen::LDLT<MatX> dense(b.lambda);
  const VecX x = dense.solve(b.eta);
  const MatX cov = dense.solve(MatX::Identity(b.lambda.rows(), b.lambda.cols()));
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_LT((b.chain.mean(k) - x.segment<3>(b.p(k))).norm(), 1e-8) << k;
    EXPECT_LT((b.chain.covariance(k) - cov.block<3, 3>(b.p(k), b.p(k))).norm(), 1e-8) << k;
  }
  EXPECT_LT((b.chain.static_mean() - x.tail(q)).norm(), 1e-8);
  EXPECT_LT((b.chain.static_covariance() - cov.bottomRightCorner(q, q)).norm(), 1e-8);
  // The solve worked in place: a second one without reset() and new factors is refused,
  // and after release_workspace() too.
  EXPECT_THROW(b.chain.solve(), std::logic_error);
  b.chain.release_workspace();
  EXPECT_THROW(b.chain.solve(), std::logic_error);
}

// take_covariances() hands over the blocks covariance(k) showed, symmetric bit for bit (so
// that the smoother's result reads them row-major), against the dense inverse; only after
// the covariance pass, and once per solve.
TEST(ArrowheadChain, HandsOverItsCovariancesSymmetricAndOnce) {
  std::mt19937_64 rng(11);
  const std::size_t n = 40, q = 3;
  Both b(n, q);
  b.random_chain(rng, 20.0, 9);
  for (const std::size_t k : {std::size_t{5}, std::size_t{21}, std::size_t{39}})
    for (int r = 0; r < 3; ++r) b.random_mixed(rng, k, 3.0);
  b.chain.solve_means();
  EXPECT_THROW(b.chain.take_covariances(), std::logic_error);  // no covariance pass yet
  b.chain.solve_covariances();
  std::vector<Eigen::Matrix3d> shown;
  for (std::size_t k = 0; k < n; ++k) shown.push_back(b.chain.covariance(k));
  const std::vector<double> taken = b.chain.take_covariances();
  ASSERT_EQ(taken.size(), 9 * n);
  const MatX cov = Eigen::LDLT<MatX>(b.lambda).solve(MatX::Identity(b.lambda.rows(), b.lambda.cols()));
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> row_major(taken.data() + 9 * k);
    ASSERT_EQ(Eigen::Matrix3d(row_major), shown[k]) << k;  // also column-major: symmetric bit for bit
    EXPECT_LT((Eigen::Matrix3d(row_major) - cov.block<3, 3>(b.p(k), b.p(k))).norm(), 1e-8) << k;
  }
  EXPECT_THROW(b.chain.take_covariances(), std::logic_error);  // handed over already
  EXPECT_THROW(b.chain.covariance(0), std::logic_error);       // (the blocks are gone)
  EXPECT_THROW(b.chain.add_position(0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()), std::logic_error);
  EXPECT_THROW(b.chain.add_position_row(0, Eigen::RowVector3d(0, 0, 1), 1.0, 1.0), std::logic_error);
  b.chain.reset();  // the blocks again, zero
  b.chain.add_position(0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
}

// The smoother without biases keeps the odometry's information between passes and adds
// its steps again (reset_keeping_steps, add_steps_again), as corrections from the pass's
// point: the system solved must be the one a chain given every factor afresh (the steps
// relative to that point, first, as the smoother adds them) solves, bit for bit,
// whatever the other factors, and whatever the blocks held from the pass before;
// so must the means solved first and the covariances after (solve_means, then
// solve_covariances) be solve()'s.
TEST(ArrowheadChain, StepsKeptAndAddedAgainAndMeansFirstSolveAsOneSolveOfTheStepsGivenAfresh) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = 700, q = 6;  // (several of the backward pass's recomputed blocks)
  std::vector<Eigen::Matrix3d> w;
  std::vector<Eigen::Vector3d> delta;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    w.push_back(random_spd(rng, 50.0));
    delta.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
  // The factors of one pass, which change between passes.
  const auto other_factors = [&](ArrowheadChain& chain, unsigned seed) {
    std::mt19937_64 pass(seed);
    chain.add_position(0, 1e-10 * Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    for (std::size_t k = 0; k < n; k += 5) chain.add_position_row(k, Eigen::RowVector3d(0, 0, 1), 10 * u(pass), 2 + u(pass));
    for (const std::size_t k : {std::size_t{40}, std::size_t{41}, std::size_t{300}, std::size_t{699}}) {
      Eigen::RowVectorXd hm = Eigen::RowVectorXd::Zero(q);
      for (std::size_t i = 0; i < q; ++i) hm(static_cast<Eigen::Index>(i)) = u(pass);
      chain.add_mixed(k, Eigen::RowVector3d(u(pass), u(pass), u(pass)), hm, u(pass), 3.0 + u(pass));
    }
  };
  // The corrections' reference point (the smoother's linearisation point), three numbers a
  // position as the smoother keeps it.
  std::vector<double> reference;
  for (std::size_t k = 0; k < n; ++k)
    for (const double scale : {100.0, 100.0, 10.0}) reference.push_back(scale * u(rng));
  const auto point = [&](std::size_t k) {
    return Eigen::Vector3d(reference[3 * k], reference[3 * k + 1], reference[3 * k + 2]);
  };
  ArrowheadChain kept(n, q);
  for (std::size_t k = 0; k + 1 < n; ++k) kept.add_step(k, w[k], delta[k]);
  // The same information handed to the constructor (the smoother's dead reckoning keeps
  // it before the chain exists): kept as above, and refused with a step missing.
  std::vector<ArrowheadChain::Symmetric3> upper;
  for (const Eigen::Matrix3d& block : w) upper.push_back(ArrowheadChain::Symmetric3::upper_of(block));
  ArrowheadChain given(n, q, upper);
  EXPECT_THROW(given.add_step(0, w[0], delta[0]), std::logic_error);  // would make it 2W
  EXPECT_THROW(ArrowheadChain(n, q, std::vector<ArrowheadChain::Symmetric3>(upper.begin() + 1, upper.end())),
               std::invalid_argument);
  for (const unsigned pass : {1u, 2u, 3u}) {
    kept.reset_keeping_steps();
    // The blocks are not zeroed by reset_keeping_steps(): nothing but add_steps_again(),
    // which writes every one, may come next.
    EXPECT_THROW(kept.add_position(0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()), std::logic_error);
    EXPECT_THROW(kept.add_position_row(0, Eigen::RowVector3d(0, 0, 1), 1.0, 1.0), std::logic_error);
    EXPECT_THROW(kept.solve_means(), std::logic_error);
    kept.add_steps_again(delta, reference);
    other_factors(kept, pass);
    EXPECT_THROW(kept.solve_covariances(), std::logic_error);  // the means first
    kept.solve_means();  // (as the smoother solves a pass that needs no covariance)
    given.reset_keeping_steps();
    given.add_steps_again(delta, reference);
    other_factors(given, pass);
    given.solve();
    ArrowheadChain fresh(n, q);
    for (std::size_t k = 0; k + 1 < n; ++k)
      fresh.add_step(k, w[k], ArrowheadChain::relative_step(delta[k], point(k), point(k + 1)));
    other_factors(fresh, pass);
    fresh.solve();
    for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(kept.mean(k), fresh.mean(k)) << "pass " << pass << ", step " << k;
    kept.solve_covariances();
    EXPECT_THROW(kept.solve_covariances(), std::logic_error);
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_EQ(kept.mean(k), fresh.mean(k)) << "pass " << pass << ", step " << k;
      ASSERT_EQ(kept.covariance(k), fresh.covariance(k)) << "pass " << pass << ", step " << k;
      ASSERT_EQ(given.mean(k), fresh.mean(k)) << "pass " << pass << ", step " << k;
      ASSERT_EQ(given.covariance(k), fresh.covariance(k)) << "pass " << pass << ", step " << k;
    }
    EXPECT_EQ(given.static_covariance(), fresh.static_covariance());
    EXPECT_EQ(kept.static_mean(), fresh.static_mean());
    EXPECT_EQ(kept.static_covariance(), fresh.static_covariance());
  }
  // One delta per step, and only while the steps' information is kept.
  kept.reset_keeping_steps();
  EXPECT_THROW(kept.add_steps_again(std::span<const Eigen::Vector3d>(delta).first(n - 2), reference),
               std::invalid_argument);
  kept.release_workspace();
  EXPECT_THROW(kept.reset_keeping_steps(), std::logic_error);
}

// The calls that would solve another system than the one given are refused: a step added
// onto kept information, steps added again twice or after a plain reset, a solve or a
// covariance pass on a released workspace. Chains of no and one position solve.
TEST(ArrowheadChain, RefusesCallsThatWouldSolveAnotherSystem) {
  const Eigen::Matrix3d w = 4.0 * Eigen::Matrix3d::Identity();
  const std::vector<Eigen::Vector3d> delta(3, Eigen::Vector3d(1.0, 0.0, 0.0));
  ArrowheadChain chain(4, 1);
  for (std::size_t k = 0; k < 3; ++k) chain.add_step(k, w, delta[k]);
  chain.reset_keeping_steps();
  EXPECT_THROW(chain.add_step(0, w, delta[0]), std::logic_error);  // would make it 2W
  const std::vector<double> reference(3 * 4, 0.0);
  EXPECT_THROW(chain.add_steps_again(delta, std::span<const double>(reference).first(9)), std::invalid_argument);
  chain.add_steps_again(delta, reference);
  EXPECT_THROW(chain.add_steps_again(delta, reference), std::logic_error);  // twice
  chain.add_position(0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  chain.solve_means();
  EXPECT_LT((chain.mean(3) - Eigen::Vector3d(3.0, 0.0, 0.0)).norm(), 1e-12);  // the three steps from p_0 = 0
  EXPECT_THROW(chain.add_steps_again(delta, reference), std::logic_error);  // after a solve
  chain.release_workspace();
  EXPECT_THROW(chain.solve_covariances(), std::logic_error);  // the workspace is gone
  EXPECT_THROW(chain.reset_keeping_steps(), std::logic_error);
  chain.reset();  // a plain reset: nothing kept, steps are added afresh
  EXPECT_THROW(chain.add_steps_again(delta, reference), std::logic_error);
  chain.add_step(0, w, delta[0]);
  // No and one position: nothing to chain.
  ArrowheadChain none(0, 2);
  EXPECT_NO_THROW(none.solve());
  EXPECT_EQ(none.static_mean().size(), 2);
  ArrowheadChain one(1, 0);
  one.reset_keeping_steps();
  one.add_steps_again({}, std::vector<double>{0.0, 0.0, 0.0});
  one.add_position(0, 2.0 * Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 2.0, 3.0));
  one.solve();
  EXPECT_LT((one.mean(0) - Eigen::Vector3d(1.0, 2.0, 3.0)).norm(), 1e-12);
  EXPECT_LT((one.covariance(0) - 0.5 * Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

// Cross covariances Cov(p_k, m), kept at chosen steps and for chosen columns at every
// step, against the dense inverse; with mixed factors at the first step, at every step of
// a stretch (as the bias-aware smoother makes them), rows on one position and priors on
// the static unknowns.
TEST(ArrowheadChain, CrossCovariancesMatchTheDenseInverse) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = 50, q = 7;
  Both b(n, q);
  b.random_chain(rng, 20.0, 9);
  const auto mixed_row = [&](std::size_t k) { b.random_mixed(rng, k, 2.0); };
  mixed_row(0);
  for (std::size_t k = 20; k < 30; ++k) mixed_row(k);
  mixed_row(41);
  for (std::size_t k = 3; k < n; k += 5) {  // one scalar row on a position
    const Eigen::RowVector3d hp(u(rng), u(rng), u(rng));
    const double z = u(rng), w = 4.0;
    b.chain.add_position_row(k, hp, z, w);
    b.lambda.block<3, 3>(b.p(k), b.p(k)) += w * hp.transpose() * hp;
    b.eta.segment<3>(b.p(k)) += w * z * hp.transpose();
  }
  for (std::size_t j = 4; j < q; ++j) {  // priors on the last static unknowns
    const double z = u(rng), w = 9.0;
    b.chain.add_static(j, z, w);
    b.lambda(b.m() + static_cast<Eigen::Index>(j), b.m() + static_cast<Eigen::Index>(j)) += w;
    b.eta(b.m() + static_cast<Eigen::Index>(j)) += w * z;
  }
  const std::vector<std::size_t> kept = {0, 5, 20, 25, 29, 30, 41, 49};
  b.chain.keep_cross_covariance_at(kept);
  b.chain.keep_cross_covariance_columns(4, 3);
  b.chain.solve();
  const Eigen::LDLT<MatX> dense(b.lambda);
  const VecX x = dense.solve(b.eta);
  const MatX cov = dense.solve(MatX::Identity(b.lambda.rows(), b.lambda.cols()));
  EXPECT_LT((b.chain.static_mean() - x.tail(q)).norm(), 1e-8);
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_LT((b.chain.mean(k) - x.segment<3>(b.p(k))).norm(), 1e-8) << k;
    EXPECT_LT((b.chain.covariance(k) - cov.block<3, 3>(b.p(k), b.p(k))).norm(), 1e-8) << k;
    const MatX cross = cov.block(b.p(k), b.m(), 3, static_cast<Eigen::Index>(q));
    EXPECT_LT((MatX(b.chain.cross_covariance_columns(k)) - cross.rightCols(3)).norm(), 1e-8) << k;
  }
  for (const std::size_t k : kept)
    EXPECT_LT((b.chain.cross_covariance_at(k) - cov.block(b.p(k), b.m(), 3, static_cast<Eigen::Index>(q))).norm(), 1e-8)
        << k;
  EXPECT_THROW(b.chain.cross_covariance_at(1), std::out_of_range);
}

// A chain long enough that the solver recomputes its per-step couplings block by block
// (arrowhead_chain.h): segments starting at a block's last and first steps, one that
// spans block boundaries, and one still open at the end; against a sparse Cholesky
// solve of the same system, at every step for the means and at the steps around the
// boundaries for the covariances and cross covariances.
TEST(ArrowheadChain, MatchesASparseSolveAcrossRecomputedBlocks) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = 1100, q = 5;
  const auto dim = static_cast<Eigen::Index>(3 * n + q);
  ArrowheadChain chain(n, q, 1e-12);
  std::vector<Eigen::Triplet<double>> entries;
  VecX eta = VecX::Zero(dim);
  const auto p = [](std::size_t k) { return static_cast<Eigen::Index>(3 * k); };
  const auto m = static_cast<Eigen::Index>(3 * n);
  const auto add_block = [&](Eigen::Index r, Eigen::Index c, const MatX& block) {
    for (Eigen::Index i = 0; i < block.rows(); ++i)
      for (Eigen::Index j = 0; j < block.cols(); ++j) entries.emplace_back(r + i, c + j, block(i, j));
  };
  add_block(m, m, 1e-12 * MatX::Identity(q, q));
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Eigen::Matrix3d w = random_spd(rng, 50.0);
    const Eigen::Vector3d delta(u(rng), u(rng), u(rng));
    chain.add_step(k, w, delta);
    add_block(p(k), p(k), w);
    add_block(p(k + 1), p(k + 1), w);
    add_block(p(k), p(k + 1), -w);
    add_block(p(k + 1), p(k), -w);
    eta.segment<3>(p(k)) -= w * delta;
    eta.segment<3>(p(k + 1)) += w * delta;
  }
  for (std::size_t k = 0; k < n; k += 7) {
    const Eigen::Matrix3d w = random_spd(rng, 0.5);
    const Eigen::Vector3d mean(u(rng), u(rng), 10 * u(rng));
    chain.add_position(k, w, mean);
    add_block(p(k), p(k), w);
    eta.segment<3>(p(k)) += w * mean;
  }
  const std::vector<std::size_t> events = {5, 255, 256, 300, 770, 1040};
  for (const std::size_t k : events) {
    for (int r = 0; r < 3; ++r) {
      const Eigen::RowVector3d hp(u(rng), u(rng), u(rng));
      Eigen::RowVectorXd hm(q);
      for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(q); ++i) hm(i) = u(rng);
      const double z = u(rng), w = 3.0 + u(rng);
      chain.add_mixed(k, hp, hm, z, w);
      Eigen::RowVectorXd h = Eigen::RowVectorXd::Zero(3 + static_cast<Eigen::Index>(q));
      h.head<3>() = hp;
      h.tail(static_cast<Eigen::Index>(q)) = hm;
      const MatX hh = w * h.transpose() * h;
      add_block(p(k), p(k), hh.topLeftCorner<3, 3>());
      add_block(p(k), m, hh.topRightCorner(3, static_cast<Eigen::Index>(q)));
      add_block(m, p(k), hh.bottomLeftCorner(static_cast<Eigen::Index>(q), 3));
      add_block(m, m, hh.bottomRightCorner(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q)));
      eta.segment<3>(p(k)) += w * z * hp.transpose();
      eta.tail(static_cast<Eigen::Index>(q)) += w * z * hm.transpose();
    }
  }
  std::vector<std::size_t> checked;
  for (const std::size_t centre : {std::size_t{0}, std::size_t{256}, std::size_t{512}, std::size_t{768},
                                   std::size_t{1024}, std::size_t{1096}})
    for (std::size_t k = centre >= 4 ? centre - 4 : 0; k < std::min(centre + 4, n); ++k) checked.push_back(k);
  chain.keep_cross_covariance_at(checked);
  chain.keep_cross_covariance_columns(1, 3);
  chain.solve();

  Eigen::SparseMatrix<double> lambda(dim, dim);
  lambda.setFromTriplets(entries.begin(), entries.end());  // duplicates are summed
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> sparse(lambda);
  ASSERT_EQ(sparse.info(), Eigen::Success);
  const VecX x = sparse.solve(eta);
  // Relative to the size of what is compared: the cross covariances far into a segment
  // are small (about 1e-5 here), and an absolute tolerance would not see an error in them.
  // The two solves agree to about 1e-13 relative; a 1e-8 error in one block's kept T_k fails.
  const auto close = [](const MatX& got, const MatX& expected) {
    return (got - expected).norm() <= 1e-10 * expected.norm() + 1e-300;
  };
  for (std::size_t k = 0; k < n; ++k) EXPECT_TRUE(close(chain.mean(k), x.segment<3>(p(k)))) << k;
  EXPECT_TRUE(close(chain.static_mean(), x.tail(static_cast<Eigen::Index>(q))));
  const MatX static_columns = sparse.solve(MatX(MatX::Identity(dim, dim).rightCols(static_cast<Eigen::Index>(q))));
  EXPECT_TRUE(close(chain.static_covariance(), static_columns.bottomRows(static_cast<Eigen::Index>(q))));
  for (const std::size_t k : checked) {
    const MatX columns = sparse.solve(MatX(MatX::Identity(dim, dim).middleCols(p(k), 3)));
    EXPECT_TRUE(close(chain.covariance(k), columns.middleRows(p(k), 3))) << k;
    const MatX cross = static_columns.middleRows(p(k), 3);
    EXPECT_TRUE(close(chain.cross_covariance_at(k), cross)) << k;
    EXPECT_TRUE(close(MatX(chain.cross_covariance_columns(k)), cross.middleCols(1, 3))) << k;
  }
}

// Textbook Kalman filter and RTS smoother for x(k+1) = x(k) + u(k) + w, y(k) = x(k) + v.
TEST(ArrowheadChain, MatchesTheTextbookKalmanRtsSmoother) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = 200;
  std::vector<Eigen::Vector3d> control(n), measurement(n);
  std::vector<Eigen::Matrix3d> q_noise(n), r_noise(n);
  ArrowheadChain chain(n, 0);
  const Eigen::Matrix3d p0 = 100.0 * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d x0(1.0, -2.0, 3.0);
  chain.add_position(0, p0.inverse(), x0);
  for (std::size_t k = 0; k < n; ++k) {
    control[k] = Eigen::Vector3d(u(rng), u(rng), u(rng));
    measurement[k] = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 10.0;
    q_noise[k] = random_spd(rng, 0.01);
    r_noise[k] = random_spd(rng, 2.0);
    chain.add_position(k, r_noise[k].inverse(), measurement[k]);
    if (k + 1 < n) chain.add_step(k, q_noise[k].inverse(), control[k]);
  }
  chain.solve();
  // Forward filter.
  std::vector<Eigen::Vector3d> xf(n), xp(n);
  std::vector<Eigen::Matrix3d> pf(n), pp(n);
  Eigen::Vector3d x = x0;
  Eigen::Matrix3d p = p0;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) {
      x = xf[k - 1] + control[k - 1];
      p = pf[k - 1] + q_noise[k - 1];
    }
    xp[k] = x;
    pp[k] = p;
    const Eigen::Matrix3d gain = p * (p + r_noise[k]).inverse();
    xf[k] = x + gain * (measurement[k] - x);
    pf[k] = (Eigen::Matrix3d::Identity() - gain) * p;
  }
  // RTS backward pass.
  Eigen::Vector3d xs = xf[n - 1];
  Eigen::Matrix3d ps = pf[n - 1];
  EXPECT_LT((chain.mean(n - 1) - xs).norm(), 1e-9);
  for (std::size_t k = n - 1; k-- > 0;) {
    const Eigen::Matrix3d c = pf[k] * pp[k + 1].inverse();
    xs = xf[k] + c * (xs - xp[k + 1]);
    ps = pf[k] + c * (ps - pp[k + 1]) * c.transpose();
    EXPECT_LT((chain.mean(k) - xs).norm(), 1e-9) << k;
    EXPECT_LT((chain.covariance(k) - ps).norm(), 1e-9) << k;
  }
}

}  // namespace
}  // namespace gesmi
