#include "solver/kalman/kalman_smoother.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/kalman/arrowhead_chain.h"
#include "solver/kalman/chain_factors.h"
#include "solver/kalman/coarse_start.h"
#include "solver/kalman/residual_statistics.h"

namespace gesmi {
namespace {

// The factors not from a measurement, as residuals at the linearisation point
// (chain_factors.h): the weak prior on the first position and the biases' zero-mean priors.
void add_priors(ArrowheadChain& chain, const ChainFactors& factors, const BiasVec& prior_sigma,
                const KalmanLinearisation& lin) {
  add_first_position_prior(chain, lin);
  if (!factors.biases()) return;
  for (int b = 0; b < kBiasCount; ++b)
    chain.add_static(factors.bias_offset() + static_cast<std::size_t>(b), -lin.bias[b],
                     1.0 / (prior_sigma[b] * prior_sigma[b]));
}

// The steps whose measurements are tested: those of the fixes and associated marks.
std::vector<std::size_t> tested_steps(const Mission& m, std::span<const PositionFix> fixes) {
  std::vector<std::size_t> steps;
  for (const PositionFix& fix : fixes) steps.push_back(step_at(m, fix.time));
  for (std::size_t j = 0; j < m.mark_count(); ++j)
    if (m.mark_mine[j] >= 0) steps.push_back(step_at(m, m.mark_time[j]));
  return steps;
}

// The covariance of p_k from P' = Cov(p'_k), the chain's: P' + G S G^T + X G^T + G X^T,
// with X = Cov(p'_k, b), S = Cov(b); symmetric bit for bit.
Mat3d position_covariance(const Mat3d& chain_covariance, const ArrowheadChain& chain, const ChainFactors& factors,
                          std::size_t k) {
  if (!factors.biases()) return chain_covariance;
  const BiasJacobian& g = factors.sensitivity(k);
  const Eigen::Matrix<double, kBiasCount, kBiasCount> s =
      chain.static_covariance().bottomRightCorner<kBiasCount, kBiasCount>();
  const Mat3d x_g = chain.cross_covariance_columns(k) * g.transpose();
  const Mat3d cov = chain_covariance + g * s * g.transpose() + x_g + x_g.transpose();
  return 0.5 * (cov + cov.transpose());
}

}  // namespace

const char* kalman_start_name(KalmanStart start) {
  return start == KalmanStart::coarse ? "coarse" : "dead-reckoning";
}

std::optional<KalmanStart> kalman_start_from_name(std::string_view name) {
  for (const KalmanStart start : {KalmanStart::coarse, KalmanStart::dead_reckoning})
    if (name == kalman_start_name(start)) return start;
  return std::nullopt;
}

std::string KalmanOptions::validate() const {
  if (!(noise_factor > 0.0) || !std::isfinite(noise_factor)) return "noise-factor: must be a positive number";
  if (max_iterations < 1 || max_iterations > 100) return "max-iterations: must be between 1 and 100";
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) return "tolerance: must be a finite number >= 0";
  if (!(stall_fraction >= 0.0 && stall_fraction < 1.0)) return "stall-fraction: must be a number in [0, 1)";
  return {};
}

namespace {

KalmanResult smooth(const Mission& m, const SensorModel& model, std::span<const PositionFix> fixes,
                    const KalmanOptions& o) {
  const std::size_t n = m.size(), k_mines = static_cast<std::size_t>(m.mine_count);
  const std::size_t q = 3 * k_mines + (o.biases ? kBiasCount : 0);
  // Without biases the odometry does not depend on the linearisation point: the dead
  // reckoning computes its factors once (the information for the chain, the deltas
  // here) and every pass adds them again (four fifths of the rotations of a
  // three-pass smoothing saved).
  const bool fixed_odometry = !o.biases;
  std::vector<Vec3d> odometry_delta;
  std::vector<ArrowheadChain::Symmetric3> step_information;
  // First linearisation: dead reckoning from the first fix (or the origin), biases zero.
  KalmanLinearisation lin;
  lin.position.assign(n, Vec3d::Zero());
  if (n > 0) {
    Vec3d p = fixes.empty() ? Vec3d(0.0, 0.0, m.depth[0]) : Vec3d(fixes[0].box[0].mid(), fixes[0].box[1].mid(), m.depth[0]);
    // (this dead reckoning is the first linearisation point; its depths set the depth
    // variances of the first pass, independently of each reading's error)
    lin.position[0] = p;
    struct DeadReckoning final : MeasurementSink {
      FlatPoints& position;
      bool keeps;  // the odometry is fixed: its factors are kept
      std::vector<ArrowheadChain::Symmetric3>& information_kept;
      std::vector<Vec3d>& delta;
      DeadReckoning(FlatPoints& p, bool keep, std::vector<ArrowheadChain::Symmetric3>& w, std::vector<Vec3d>& d)
          : position(p), keeps(keep), information_kept(w), delta(d) {}
      void odometry(std::size_t k, const Mat3d& information, const Vec3d& step, const BiasJacobian&) override {
        position[k + 1] = position[k] + step;
        if (!keeps) return;
        if (delta.size() != k) throw std::logic_error("kalman_smooth: the odometry steps came out of order");
        // (as ArrowheadChain::add_step accumulates it on a zero block: the same bits)
        information_kept.push_back(ArrowheadChain::Symmetric3{} + ArrowheadChain::Symmetric3::upper_of(information));
        delta.push_back(step);
      }
      void scalar(std::size_t, const Eigen::RowVector3d&, int, const Eigen::RowVector3d&, const BiasRow&, double, double,
                  const ConstraintRef*) override {}
    } dead_reckoning(lin.position, fixed_odometry, step_information, odometry_delta);
    if (fixed_odometry) {
      odometry_delta.reserve(n - 1);
      step_information.reserve(n - 1);
    }
    lin.mine.assign(k_mines, Vec3d::Zero());
    lin.mine_known.assign(k_mines, 0);
    linearise_measurements(m, model, {}, {o.noise_factor, false, FactorSet::odometry}, lin, dead_reckoning);
  }
  // The mines are placed at their first detection in the first pass (the coarse chain's, below).
  lin.mine.assign(k_mines, Vec3d::Zero());
  lin.mine_known.assign(k_mines, 0);
  const std::vector<MarkSample> marks = mark_samples(m);
  // (before the chain takes the steps' information)
  const CoarseStart coarse = fixed_odometry && o.start == KalmanStart::coarse && o.max_iterations >= 1
                                 ? start_from_coarse_chain(m, model, fixes, o, marks, odometry_delta, step_information, lin)
                                 : CoarseStart{};
  // One set of buffers for every linearisation.
  ArrowheadChain chain = fixed_odometry ? ArrowheadChain(n, q, std::move(step_information)) : ArrowheadChain(n, q);

  KalmanResult result;
  result.steps = n;
  result.mines = k_mines;
  result.biases = o.biases;
  result.coarse_iterations = coarse.linearisations;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  result.mine_mean.assign(3 * k_mines, nan);  // (a mine never detected stays NaN)
  result.mine_covariance.assign(9 * k_mines, nan);
  if (o.max_iterations < 1 || n == 0) return result;  // nothing solved (validate() refuses such options)
  const MeasurementOptions measurements{o.noise_factor, o.biases,
                                        fixed_odometry ? FactorSet::without_odometry : FactorSet::all, marks};
  const BiasVec prior_sigma = o.biases ? bias_prior_sigma(model, o.noise_factor) : BiasVec::Zero();
  chain.keep_cross_covariance_at(tested_steps(m, fixes));
  if (o.biases) chain.keep_cross_covariance_columns(3 * k_mines, kBiasCount);
  double previous_step = std::numeric_limits<double>::infinity();
  for (int it = 0; it < o.max_iterations; ++it) {
    ChainBuilder builder(chain, k_mines, o.biases, lin);
    if (fixed_odometry) {
      chain.reset_keeping_steps();
      chain.add_steps_again(odometry_delta, lin.position.values());  // (first: it writes every block)
      add_priors(chain, builder, prior_sigma, lin);
    } else {
      chain.reset();
      add_priors(chain, builder, prior_sigma, lin);
    }
    linearise_measurements(m, model, fixes, measurements, lin, builder);
    chain.solve_means();  // the covariances only where they are read (below)
    ++result.iterations;
    // The step: how far the new estimate moved any coordinate from the linearisation
    // point (for a mine first placed in this pass, from where it was placed): the
    // chain's corrections, in metres and in units of that coordinate's smoothed
    // standard deviation.
    const double infinity = std::numeric_limits<double>::infinity();
    // A NaN move or variance counts as infinitely large: it never converges nor stalls.
    const auto distance = [&](double moved) { return std::isnan(moved) ? infinity : std::fabs(moved); };
    double step = 0.0;
    const auto measure = [&](const Vec3d& moved) {
      for (int c = 0; c < 3; ++c) step = std::max(step, distance(moved[c]));
    };
    double step_sigmas = 0.0;
    const auto measure_sigmas = [&](const Vec3d& moved, const Vec3d& variance) {
      for (int c = 0; c < 3; ++c) {
        const double d = distance(moved[c]);
        const double sigmas = d == 0.0 ? 0.0 : d / std::sqrt(variance[c]);  // +inf when sigma is 0
        step_sigmas = std::max(step_sigmas, std::isnan(sigmas) ? infinity : sigmas);
      }
    };
    const auto each_move = [&](const auto& visit, bool with_variances) {
      for (std::size_t k = 0; k < n; ++k) {
        const Vec3d moved = builder.position_correction(chain, k);
        if (with_variances) visit(moved, position_covariance(chain.covariance(k), chain, builder, k).diagonal());
        else visit(moved, Vec3d::Zero());
      }
      for (std::size_t i = 0; i < k_mines; ++i) {
        if (!lin.mine_known[i]) continue;
        const auto b = static_cast<Eigen::Index>(3 * i);
        visit(chain.static_mean().segment<3>(b), chain.static_covariance().diagonal().segment<3>(b));
      }
    };
    each_move([&](const Vec3d& moved, const Vec3d&) { measure(moved); }, false);
    result.last_step = step;
    result.converged = step <= o.tolerance;
    // Stalled: the steps stopped shrinking (a converging iteration shrinks them, by a third
    // per pass at the slowest seen) while they are negligible against the uncertainty.
    const bool may_stall = !result.converged && step >= kStalledStepRatio * previous_step;
    // The covariances: for the result after the last pass, and to judge a stall.
    if (result.converged || may_stall || it + 1 == o.max_iterations) {
      chain.solve_covariances();
      each_move(measure_sigmas, true);
      result.last_step_sigmas = step_sigmas;
    }
    result.stalled = may_stall && step_sigmas <= o.stall_fraction;
    previous_step = step;
    const bool last = result.converged || result.stalled || it + 1 == o.max_iterations;
    if (last) {
      // The checks on the factors just solved (before the linearisation point moves).
      ResidualStatistics statistics(chain, k_mines, o.biases, lin);
      for (std::size_t k = 0; k < odometry_delta.size(); ++k)
        statistics.odometry(k, chain.step_information(k), odometry_delta[k], BiasJacobian::Zero());
      linearise_measurements(m, model, fixes, measurements, lin, statistics);
      for (int b = 0; b < kBiasCount && o.biases; ++b)
        statistics.static_prior(builder.bias_offset() + static_cast<std::size_t>(b), -lin.bias[b],
                                1.0 / (prior_sigma[b] * prior_sigma[b]));
      // Without a fix the horizontal position is held by the weak prior alone: those two
      // unknowns are not determined by the data.
      std::size_t unknowns = 3 * n + (o.biases ? kBiasCount : 0) - (fixes.empty() ? 2 : 0);
      for (std::size_t i = 0; i < k_mines; ++i) unknowns += lin.mine_known[i] ? 3 : 0;
      result.consistency = statistics.consistency(unknowns);
      result.tests = statistics.tests(m.time);
      for (InputTest& t : result.tests) {  // the input's own time, not its step's
        if (t.input.kind == ConstraintRef::Kind::mark) {
          t.time = m.mark_time[t.input.row];
          continue;
        }
        for (const PositionFix& fix : fixes)
          if (fix.source_index == t.input.row) t.time = fix.time;
      }
      // The result, converted from the chain's terms.
      // Before the result's arrays, so that the peak stays that of a solve: what only the
      // solve and the linearisation needed.
      chain.release_workspace();
      std::vector<Vec3d>().swap(odometry_delta);
      // The means, corrected in the linearisation point's own storage (no second array).
      for (std::size_t k = 0; k < n; ++k) lin.position[k] += builder.position_correction(chain, k);
      result.mean = lin.position.take();
      // The chain's own covariance blocks become the result's (symmetric: column-major is
      // row-major), converted in place with biases.
      result.covariance = chain.take_covariances();
      for (std::size_t k = 0; k < n && o.biases; ++k) {
        Eigen::Map<Mat3d> cov(result.covariance.data() + 9 * k);
        cov = position_covariance(cov, chain, builder, k);
      }
    }
    // The next linearisation point: this one corrected.
    for (std::size_t k = 0; k < n && !last; ++k) lin.position[k] += builder.position_correction(chain, k);
    for (std::size_t i = 0; i < k_mines; ++i)
      if (lin.mine_known[i]) lin.mine[i] += chain.static_mean().segment<3>(static_cast<Eigen::Index>(3 * i));
    if (o.biases) lin.bias += chain.static_mean().tail<kBiasCount>();
    if (last) break;
  }
  if (o.biases) {
    result.bias_estimate = lin.bias;
    result.bias_sigma = chain.static_covariance().bottomRightCorner<kBiasCount, kBiasCount>().diagonal().cwiseSqrt();
    result.bias_prior_sigma = prior_sigma;
  }
  for (std::size_t i = 0; i < k_mines; ++i) {
    if (!lin.mine_known[i]) continue;
    const auto b = static_cast<Eigen::Index>(3 * i);
    for (int r = 0; r < 3; ++r) {
      result.mine_mean[3 * i + static_cast<std::size_t>(r)] = lin.mine[i][r];
      for (int c = 0; c < 3; ++c)
        result.mine_covariance[9 * i + static_cast<std::size_t>(3 * r + c)] = chain.static_covariance()(b + r, b + c);
    }
  }
  return result;
}

}  // namespace

KalmanResult kalman_smooth(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes,
                           const KalmanOptions& options) {
  return smooth(mission, model, fixes, options);
}

Containment three_sigma_containment(const KalmanResult& r, const Mission& m) {
  ContainmentCount count(r);
  for (std::size_t k = 0; k < m.truth_x.size(); ++k) count.add(k, m.truth_x[k], m.truth_y[k], m.truth_z[k]);
  return count.finish(m.truth_mines);
}

void ContainmentCount::add(std::size_t k, double north, double east, double down) {
  if (k != steps_ || k >= result_.steps) throw std::logic_error("ContainmentCount: steps must come once each, in order");
  const KalmanResult& r = result_;
  const double truth[3] = {north, east, down};
  const auto within = [&](std::size_t a) {
    return std::fabs(truth[a] - r.mean[3 * k + a]) <= 3.0 * std::sqrt(r.covariance[9 * k + 4 * a]);
  };
  horizontal_ += within(0) && within(1);
  vertical_ += within(2);
  ++steps_;
}

Containment ContainmentCount::finish(std::span<const double> truth_mines) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (steps_ == 0) return {nan, nan, nan, nan};
  const KalmanResult& r = result_;
  if (steps_ != r.steps) throw std::logic_error("ContainmentCount: the truth of some steps is missing");
  Containment c;
  c.horizontal = static_cast<double>(horizontal_) / static_cast<double>(r.steps);
  c.vertical = static_cast<double>(vertical_) / static_cast<double>(r.steps);
  const double limit_3d = chi_square_quantile(3.0, kResidualTestProbability);
  const double limit_plane = chi_square_quantile(2.0, kResidualTestProbability);
  std::size_t inside = 0, inside_plane = 0, seen = 0;
  for (std::size_t i = 0; i < r.mines && 3 * i + 2 < truth_mines.size(); ++i) {
    if (std::isnan(r.mine_mean[3 * i])) continue;
    ++seen;
    const Vec3d e(truth_mines[3 * i] - r.mine_mean[3 * i], truth_mines[3 * i + 1] - r.mine_mean[3 * i + 1],
                  truth_mines[3 * i + 2] - r.mine_mean[3 * i + 2]);
    const Mat3d cov = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(&r.mine_covariance[9 * i]);
    inside += e.dot(cov.ldlt().solve(e)) <= limit_3d;
    const Eigen::Vector2d e2 = e.head<2>();
    inside_plane += e2.dot(cov.topLeftCorner<2, 2>().ldlt().solve(e2)) <= limit_plane;
  }
  c.mines = seen ? static_cast<double>(inside) / static_cast<double>(seen) : nan;
  c.mines_plane = seen ? static_cast<double>(inside_plane) / static_cast<double>(seen) : nan;
  return c;
}

}  // namespace gesmi
