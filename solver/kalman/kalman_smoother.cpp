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

// Follows the odometry from the first position (the first linearisation point); when the
// odometry is fixed, also keeps its factors: the information for the chain, the deltas
// for the passes.
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
};

// The first linearisation: dead reckoning from the first fix (or the origin), biases
// zero, no mine placed. With `fixed_odometry` the odometry's factors are kept in
// `step_information` and `odometry_delta`.
KalmanLinearisation dead_reckoning_point(const Mission& m, const SensorModel& model, std::span<const PositionFix> fixes,
                                         double noise_factor, bool fixed_odometry, std::vector<Vec3d>& odometry_delta,
                                         std::vector<ArrowheadChain::Symmetric3>& step_information) {
  const std::size_t n = m.size(), k_mines = static_cast<std::size_t>(m.mine_count);
  KalmanLinearisation lin;
  lin.position.assign(n, Vec3d::Zero());
  if (n > 0) {
    Vec3d p = fixes.empty() ? Vec3d(0.0, 0.0, m.depth[0]) : Vec3d(fixes[0].box[0].mid(), fixes[0].box[1].mid(), m.depth[0]);
    // (this dead reckoning is the first linearisation point; its depths set the depth
    // variances of the first pass, independently of each reading's error)
    lin.position[0] = p;
    DeadReckoning dead_reckoning(lin.position, fixed_odometry, step_information, odometry_delta);
    if (fixed_odometry) {
      odometry_delta.reserve(n - 1);
      step_information.reserve(n - 1);
    }
    lin.mine.assign(k_mines, Vec3d::Zero());
    lin.mine_known.assign(k_mines, 0);
    linearise_measurements(m, model, {}, {noise_factor, false, FactorSet::odometry}, lin, dead_reckoning);
  }
  // The mines are placed at their first detection in the first pass (the coarse chain's,
  // when the smoothing starts from it).
  lin.mine.assign(k_mines, Vec3d::Zero());
  lin.mine_known.assign(k_mines, 0);
  return lin;
}

// The result before any linearisation of the full chain: its sizes, and every mine NaN.
KalmanResult unsolved_result(std::size_t n, std::size_t k_mines, bool biases, int coarse_linearisations) {
  KalmanResult result;
  result.steps = n;
  result.mines = k_mines;
  result.biases = biases;
  result.coarse_iterations = coarse_linearisations;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  result.mine_mean.assign(3 * k_mines, nan);  // (a mine never detected stays NaN)
  result.mine_covariance.assign(9 * k_mines, nan);
  return result;
}

// What every linearisation of one smoothing reads.
struct SmoothingInputs {
  const Mission& m;
  const SensorModel& model;
  std::span<const PositionFix> fixes;
  const KalmanOptions& o;
  std::size_t n, k_mines;
  bool fixed_odometry;  // the odometry's factors are kept from the dead reckoning
  const std::vector<Vec3d>& odometry_delta;  // (empty without a fixed odometry)
  const MeasurementOptions& measurements;
  const BiasVec& prior_sigma;
};

// The chain of this linearisation (its factors at `lin`), its means solved.
void linearise_and_solve_means(const SmoothingInputs& in, ArrowheadChain& chain, ChainBuilder& builder,
                               KalmanLinearisation& lin) {
  if (in.fixed_odometry) {
    chain.reset_keeping_steps();
    chain.add_steps_again(in.odometry_delta, lin.position.values());  // (first: it writes every block)
    add_priors(chain, builder, in.prior_sigma, lin);
  } else {
    chain.reset();
    add_priors(chain, builder, in.prior_sigma, lin);
  }
  linearise_measurements(in.m, in.model, in.fixes, in.measurements, lin, builder);
  chain.solve_means();  // the covariances only where they are read (judge_linearisation())
}

// The step: how far the new estimate moved any coordinate from the linearisation point
// (for a mine first placed in this pass, from where it was placed): the chain's
// corrections, in metres and in units of that coordinate's smoothed standard deviation.
// `visit(moved, variances)` sees every position then every placed mine; the variances
// are zero unless `with_variances` (which needs the chain's covariances solved).
template <class Visit>
void for_each_move(const SmoothingInputs& in, const ArrowheadChain& chain, const ChainFactors& builder,
                   const KalmanLinearisation& lin, bool with_variances, const Visit& visit) {
  for (std::size_t k = 0; k < in.n; ++k) {
    const Vec3d moved = builder.position_correction(chain, k);
    if (with_variances) visit(moved, position_covariance(chain.covariance(k), chain, builder, k).diagonal());
    else visit(moved, Vec3d::Zero());
  }
  for (std::size_t i = 0; i < in.k_mines; ++i) {
    if (!lin.mine_known[i]) continue;
    const auto b = static_cast<Eigen::Index>(3 * i);
    visit(chain.static_mean().segment<3>(b), chain.static_covariance().diagonal().segment<3>(b));
  }
}

// A NaN move or variance counts as infinitely large: it never converges nor stalls.
double move_distance(double moved) {
  return std::isnan(moved) ? std::numeric_limits<double>::infinity() : std::fabs(moved);
}

// The step in metres.
double largest_move(const SmoothingInputs& in, const ArrowheadChain& chain, const ChainFactors& builder,
                    const KalmanLinearisation& lin) {
  double step = 0.0;
  for_each_move(in, chain, builder, lin, false, [&](const Vec3d& moved, const Vec3d&) {
    for (int c = 0; c < 3; ++c) step = std::max(step, move_distance(moved[c]));
  });
  return step;
}

// The step in standard deviations (the chain's covariances solved).
double largest_move_in_sigmas(const SmoothingInputs& in, const ArrowheadChain& chain, const ChainFactors& builder,
                              const KalmanLinearisation& lin) {
  const double infinity = std::numeric_limits<double>::infinity();
  double step_sigmas = 0.0;
  for_each_move(in, chain, builder, lin, true, [&](const Vec3d& moved, const Vec3d& variance) {
    for (int c = 0; c < 3; ++c) {
      const double d = move_distance(moved[c]);
      const double sigmas = d == 0.0 ? 0.0 : d / std::sqrt(variance[c]);  // +inf when sigma is 0
      step_sigmas = std::max(step_sigmas, std::isnan(sigmas) ? infinity : sigmas);
    }
  });
  return step_sigmas;
}

// Records the step of linearisation `it` in `result` (converged, stalled) and moves
// `previous_step` to it; whether it is the last linearisation.
bool judge_linearisation(const SmoothingInputs& in, int it, ArrowheadChain& chain, const ChainFactors& builder,
                         const KalmanLinearisation& lin, double& previous_step, KalmanResult& result) {
  const KalmanOptions& o = in.o;
  const double step = largest_move(in, chain, builder, lin);
  result.last_step = step;
  result.converged = step <= o.tolerance;
  // Stalled: the steps stopped shrinking (a converging iteration shrinks them, by a third
  // per pass at the slowest seen) while they are negligible against the uncertainty.
  const bool may_stall = !result.converged && step >= kStalledStepRatio * previous_step;
  double step_sigmas = 0.0;
  // The covariances: for the result after the last pass, and to judge a stall.
  if (result.converged || may_stall || it + 1 == o.max_iterations) {
    chain.solve_covariances();
    step_sigmas = largest_move_in_sigmas(in, chain, builder, lin);
    result.last_step_sigmas = step_sigmas;
  }
  result.stalled = may_stall && step_sigmas <= o.stall_fraction;
  previous_step = step;
  return result.converged || result.stalled || it + 1 == o.max_iterations;
}

// The number of unknowns the data determine (for the fit's degrees of freedom).
std::size_t determined_unknowns(const SmoothingInputs& in, const KalmanLinearisation& lin) {
  // Without a fix the horizontal position is held by the weak prior alone: those two
  // unknowns are not determined by the data.
  std::size_t unknowns = 3 * in.n + (in.o.biases ? kBiasCount : 0) - (in.fixes.empty() ? 2 : 0);
  for (std::size_t i = 0; i < in.k_mines; ++i) unknowns += lin.mine_known[i] ? 3 : 0;
  return unknowns;
}

// Each test at the input's own time, not its step's.
void set_input_times(std::vector<InputTest>& tests, const SmoothingInputs& in) {
  for (InputTest& t : tests) {
    if (t.input.kind == ConstraintRef::Kind::mark) {
      t.time = in.m.mark_time[t.input.row];
      continue;
    }
    for (const PositionFix& fix : in.fixes)
      if (fix.source_index == t.input.row) t.time = fix.time;
  }
}

// The checks on the factors just solved (before the linearisation point moves), gathered
// in `statistics` and recorded in `result`.
void check_residuals(const SmoothingInputs& in, const ArrowheadChain& chain, const ChainFactors& builder,
                     KalmanLinearisation& lin, ResidualStatistics& statistics, KalmanResult& result) {
  for (std::size_t k = 0; k < in.odometry_delta.size(); ++k)
    statistics.odometry(k, chain.step_information(k), in.odometry_delta[k], BiasJacobian::Zero());
  linearise_measurements(in.m, in.model, in.fixes, in.measurements, lin, statistics);
  for (int b = 0; b < kBiasCount && in.o.biases; ++b)
    statistics.static_prior(builder.bias_offset() + static_cast<std::size_t>(b), -lin.bias[b],
                            1.0 / (in.prior_sigma[b] * in.prior_sigma[b]));
  result.consistency = statistics.consistency(determined_unknowns(in, lin));
  result.tests = statistics.tests(in.m.time);
  set_input_times(result.tests, in);
}

// The result, converted from the chain's terms, after the last pass (which is why
// `odometry_delta` can be released).
void take_position_estimates(const SmoothingInputs& in, ArrowheadChain& chain, const ChainFactors& builder,
                    KalmanLinearisation& lin, std::vector<Vec3d>& odometry_delta, KalmanResult& result) {
  // Before the result's arrays, so that the peak stays that of a solve: what only the
  // solve and the linearisation needed.
  chain.release_workspace();
  std::vector<Vec3d>().swap(odometry_delta);
  // The means, corrected in the linearisation point's own storage (no second array).
  for (std::size_t k = 0; k < in.n; ++k) lin.position[k] += builder.position_correction(chain, k);
  result.mean = lin.position.take();
  // The chain's own covariance blocks become the result's (symmetric: column-major is
  // row-major), converted in place with biases.
  result.covariance = chain.take_covariances();
  for (std::size_t k = 0; k < in.n && in.o.biases; ++k) {
    Eigen::Map<Mat3d> cov(result.covariance.data() + 9 * k);
    cov = position_covariance(cov, chain, builder, k);
  }
}

// The next linearisation point: this one corrected (after the last pass, the positions
// are the result's already: take_position_estimates()).
void move_linearisation_point(const SmoothingInputs& in, const ArrowheadChain& chain, const ChainFactors& builder,
                              bool last, KalmanLinearisation& lin) {
  for (std::size_t k = 0; k < in.n && !last; ++k) lin.position[k] += builder.position_correction(chain, k);
  for (std::size_t i = 0; i < in.k_mines; ++i)
    if (lin.mine_known[i]) lin.mine[i] += chain.static_mean().segment<3>(static_cast<Eigen::Index>(3 * i));
  if (in.o.biases) lin.bias += chain.static_mean().tail<kBiasCount>();
}

// The static unknowns' estimates after the last pass: the biases, and the placed mines.
void take_mines_and_biases(const SmoothingInputs& in, const ArrowheadChain& chain, const KalmanLinearisation& lin,
                           KalmanResult& result) {
  if (in.o.biases) {
    result.bias_estimate = lin.bias;
    result.bias_sigma = chain.static_covariance().bottomRightCorner<kBiasCount, kBiasCount>().diagonal().cwiseSqrt();
    result.bias_prior_sigma = in.prior_sigma;
  }
  for (std::size_t i = 0; i < in.k_mines; ++i) {
    if (!lin.mine_known[i]) continue;
    const auto b = static_cast<Eigen::Index>(3 * i);
    for (int r = 0; r < 3; ++r) {
      result.mine_mean[3 * i + static_cast<std::size_t>(r)] = lin.mine[i][r];
      for (int c = 0; c < 3; ++c)
        result.mine_covariance[9 * i + static_cast<std::size_t>(3 * r + c)] = chain.static_covariance()(b + r, b + c);
    }
  }
}

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
  KalmanLinearisation lin =
      dead_reckoning_point(m, model, fixes, o.noise_factor, fixed_odometry, odometry_delta, step_information);
  const std::vector<MarkSample> marks = mark_samples(m);
  // (before the chain takes the steps' information)
  const CoarseStart coarse = fixed_odometry && o.start == KalmanStart::coarse && o.max_iterations >= 1
                                 ? start_from_coarse_chain(m, model, fixes, o, marks, odometry_delta, step_information, lin)
                                 : CoarseStart{};
  // One set of buffers for every linearisation.
  ArrowheadChain chain = fixed_odometry ? ArrowheadChain(n, q, std::move(step_information)) : ArrowheadChain(n, q);

  KalmanResult result = unsolved_result(n, k_mines, o.biases, coarse.linearisations);
  if (o.max_iterations < 1 || n == 0) return result;  // nothing solved (validate() refuses such options)
  const MeasurementOptions measurements{o.noise_factor, o.biases,
                                        fixed_odometry ? FactorSet::without_odometry : FactorSet::all, marks};
  const BiasVec prior_sigma = o.biases ? bias_prior_sigma(model, o.noise_factor) : BiasVec::Zero();
  const SmoothingInputs in{m, model, fixes, o, n, k_mines, fixed_odometry, odometry_delta, measurements, prior_sigma};
  chain.keep_cross_covariance_at(tested_steps(m, fixes));
  if (o.biases) chain.keep_cross_covariance_columns(3 * k_mines, kBiasCount);
  double previous_step = std::numeric_limits<double>::infinity();
  for (int it = 0; it < o.max_iterations; ++it) {
    ChainBuilder builder(chain, k_mines, o.biases, lin);
    linearise_and_solve_means(in, chain, builder, lin);
    ++result.iterations;
    const bool last = judge_linearisation(in, it, chain, builder, lin, previous_step, result);
    if (last) {
      ResidualStatistics statistics(chain, k_mines, o.biases, lin);
      check_residuals(in, chain, builder, lin, statistics, result);
      take_position_estimates(in, chain, builder, lin, odometry_delta, result);
    }
    move_linearisation_point(in, chain, builder, last, lin);
    if (last) break;
  }
  take_mines_and_biases(in, chain, lin, result);
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
