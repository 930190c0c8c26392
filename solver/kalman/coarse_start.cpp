#include "solver/kalman/coarse_start.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/kalman/chain_factors.h"
#include "solver/kalman/kalman_smoother.h"

namespace gesmi {
namespace {

// The mission at the nodes, as linearise_measurements() reads it without the odometry:
// the time and depth there, the marks and the mines (each fix and associated mark falls
// on the node of its step: step_at() gives it, no node lying between its time and that step).
Mission mission_at_nodes(const Mission& m, std::span<const std::size_t> nodes) {
  Mission coarse;
  coarse.time.reserve(nodes.size());
  coarse.depth.reserve(nodes.size());
  for (const std::size_t k : nodes) {
    coarse.time.push_back(m.time[k]);
    coarse.depth.push_back(m.depth[k]);
  }
  coarse.mark_time = m.mark_time;
  coarse.mark_mine = m.mark_mine;
  coarse.mark_range = m.mark_range;
  coarse.mark_side = m.mark_side;
  coarse.mine_count = m.mine_count;
  return coarse;
}

// The odometry's vertical step k and its variance, given the horizontal step between the
// point's positions when `conditioned` (smoothed_depths()), from W_k itself: the marginal
// variance C_zz is W's xy cofactor over its determinant; given h, z's information is W_zz
// and its mean moves by -W_zh r_h / W_zz (C_zh C_hh^-1 r_h in covariances). No inverse.
std::pair<double, double> vertical_step(std::span<const Vec3d> delta, std::span<const ArrowheadChain::Symmetric3> information,
                                        const FlatPoints& point, bool conditioned, std::size_t k) {
  const ArrowheadChain::Symmetric3& w = information[k];
  if (!conditioned) {
    const double cofactor = w.xx * w.yy - w.xy * w.xy;
    const double determinant = w.xx * (w.yy * w.zz - w.yz * w.yz) - w.xy * (w.xy * w.zz - w.yz * w.xz) +
                               w.xz * (w.xy * w.yz - w.yy * w.xz);
    return {delta[k][2], cofactor / determinant};
  }
  const double r_x = point[k + 1][0] - point[k][0] - delta[k][0], r_y = point[k + 1][1] - point[k][1] - delta[k][1];
  return {delta[k][2] - (w.xz * r_x + w.yz * r_y) / w.zz, 1.0 / w.zz};
}

// A weak prior on the first depth (the readings decide it), as the chain's on p_0.
constexpr double kFirstDepthPriorVariance = 1e10;
// The bound (m) of the coarse chain's depth readings at its nodes: the smoothed depths,
// held there.
constexpr double kHeldDepthBound = 1e-4;

}  // namespace

std::vector<std::size_t> coarse_nodes(const Mission& m, std::span<const PositionFix> fixes, std::size_t stride) {
  const std::size_t n = m.size();
  if (n == 0) return {};
  if (stride == 0) throw std::invalid_argument("coarse_nodes: the stride must be positive");
  std::vector<std::size_t> nodes;
  nodes.reserve(n / stride + 2 + fixes.size() + m.mark_count());
  for (std::size_t k = 0; k < n; k += stride) nodes.push_back(k);
  nodes.push_back(n - 1);
  for (const PositionFix& fix : fixes) nodes.push_back(step_at(m, fix.time));
  for (std::size_t j = 0; j < m.mark_count(); ++j)
    if (m.mark_mine[j] >= 0) nodes.push_back(step_at(m, m.mark_time[j]));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

CoarseOdometry coarse_odometry(std::span<const std::size_t> nodes, std::span<const Vec3d> delta,
                               std::span<const ArrowheadChain::Symmetric3> information) {
  if (delta.size() != information.size() || (!nodes.empty() && nodes.back() > delta.size()))
    throw std::invalid_argument("coarse_odometry: one delta and one information per step up to the last node");
  CoarseOdometry coarse;
  const std::size_t steps = nodes.empty() ? 0 : nodes.size() - 1;
  coarse.delta.reserve(steps);
  coarse.information.reserve(steps);
  for (std::size_t i = 0; i < steps; ++i) {
    Vec3d sum = Vec3d::Zero();
    Mat3d covariance = Mat3d::Zero();
    for (std::size_t k = nodes[i]; k < nodes[i + 1]; ++k) {
      sum += delta[k];
      covariance += information[k].full().inverse();
    }
    coarse.delta.push_back(sum);
    coarse.information.push_back(ArrowheadChain::Symmetric3::upper_of(covariance.inverse()));
  }
  return coarse;
}

std::vector<double> smoothed_depths(const Mission& m, const SensorModel& model, double noise_factor,
                                    std::span<const Vec3d> delta,
                                    std::span<const ArrowheadChain::Symmetric3> information, const FlatPoints& point,
                                    bool conditioned) {
  const std::size_t n = m.size();
  if (n == 0) return {};
  if (delta.size() + 1 != n || information.size() + 1 != n || point.size() != n || m.depth.size() != n)
    throw std::invalid_argument("smoothed_depths: one delta and one information per step, one point and depth per sample");
  // Forward: the filtered mean and variance per sample (interleaved); backward: the
  // Rauch-Tung-Striebel smoothing, written over the filtered means.
  std::vector<double> filtered(2 * n);
  double mean = point[0][2], variance = kFirstDepthPriorVariance;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) {
      const auto [step, step_variance] = vertical_step(delta, information, point, conditioned, k - 1);
      mean += step;
      variance += step_variance;
    }
    const double reading = depth_variance(model, point[k][2], noise_factor), total = variance + reading;
    mean += variance / total * (m.depth[k] - mean);
    variance = variance * reading / total;  // (not times 1 - gain: after the weak prior that cancels)
    filtered[2 * k] = mean;
    filtered[2 * k + 1] = variance;
  }
  std::vector<double> depth(n);
  depth[n - 1] = filtered[2 * (n - 1)];
  for (std::size_t k = n - 1; k-- > 0;) {
    const auto [step, step_variance] = vertical_step(delta, information, point, conditioned, k);
    const double f = filtered[2 * k], p = filtered[2 * k + 1];
    depth[k] = f + p / (p + step_variance) * (depth[k + 1] - (f + step));
  }
  return depth;
}

CoarseStart start_from_coarse_chain(const Mission& m, const SensorModel& model, std::span<const PositionFix> fixes,
                                    const KalmanOptions& o, std::span<const MarkSample> marks,
                                    std::span<const Vec3d> delta,
                                    std::span<const ArrowheadChain::Symmetric3> information, KalmanLinearisation& lin) {
  const std::size_t n = m.size(), k_mines = static_cast<std::size_t>(m.mine_count);
  if (o.biases) throw std::logic_error("start_from_coarse_chain: the odometry depends on the biases");
  const std::vector<std::size_t> nodes = coarse_nodes(m, fixes, kCoarseStride);
  if (nodes.size() < 2 || 2 * nodes.size() > n) return {};  // not worth a second chain
  const std::size_t nc = nodes.size();
  // The nodes held at the depths of every reading: their ranges then see the depths the
  // full chain will.
  std::vector<double> depth = smoothed_depths(m, model, o.noise_factor, delta, information, lin.position, false);
  Mission coarse = mission_at_nodes(m, nodes);
  for (std::size_t i = 0; i < nc; ++i) coarse.depth[i] = depth[nodes[i]];
  std::vector<double>().swap(depth);
  SensorModel held = model;
  held.depth_absolute = kHeldDepthBound;
  held.depth_relative = 0.0;
  CoarseOdometry odometry = coarse_odometry(nodes, delta, information);
  KalmanLinearisation point;
  point.position.assign(nc, Vec3d::Zero());
  for (std::size_t i = 0; i < nc; ++i) point.position[i] = lin.position[nodes[i]];
  point.mine.assign(k_mines, Vec3d::Zero());
  point.mine_known.assign(k_mines, 0);
  ArrowheadChain chain(nc, 3 * k_mines, std::move(odometry.information));
  const MeasurementOptions measurements{o.noise_factor, false, FactorSet::without_odometry, marks};
  CoarseStart start;
  double previous_step = std::numeric_limits<double>::infinity();
  while (start.linearisations < o.max_iterations) {
    ChainBuilder builder(chain, k_mines, false, point);
    chain.reset_keeping_steps();
    chain.add_steps_again(odometry.delta, point.position.values());
    add_first_position_prior(chain, point);
    linearise_measurements(coarse, held, fixes, measurements, point, builder);
    chain.solve_means();
    ++start.linearisations;
    double step = 0.0;  // (a NaN move leaves it: the finiteness check below refuses the result)
    for (std::size_t i = 0; i < nc; ++i) {
      const Vec3d moved = builder.position_correction(chain, i);
      step = std::max(step, moved.cwiseAbs().maxCoeff());
      point.position[i] += moved;
    }
    for (std::size_t i = 0; i < k_mines; ++i) {
      if (!point.mine_known[i]) continue;
      const Vec3d moved = chain.static_mean().segment<3>(static_cast<Eigen::Index>(3 * i));
      step = std::max(step, moved.cwiseAbs().maxCoeff());
      point.mine[i] += moved;
    }
    if (step <= o.tolerance || step >= kStalledStepRatio * previous_step) break;
    previous_step = step;
  }
  for (std::size_t i = 0; i < nc; ++i)
    if (!point.position[i].allFinite()) return {};
  for (std::size_t i = 0; i < k_mines; ++i)
    if (point.mine_known[i] && !point.mine[i].allFinite()) return {};
  // Between two nodes the correction is interpolated (by the step's index).
  for (std::size_t i = 0; i + 1 < nc; ++i) {
    const std::size_t a = nodes[i], b = nodes[i + 1];
    const Vec3d from = point.position[i] - lin.position[a], to = point.position[i + 1] - lin.position[b];
    for (std::size_t k = a + 1; k < b; ++k)
      lin.position[k] += from + (to - from) * (static_cast<double>(k - a) / static_cast<double>(b - a));
  }
  for (std::size_t i = 0; i < nc; ++i) lin.position[nodes[i]] = point.position[i];
  lin.mine = point.mine;
  lin.mine_known = point.mine_known;
  depth = smoothed_depths(m, model, o.noise_factor, delta, information, lin.position, true);
  if (std::all_of(depth.begin(), depth.end(), [](double d) { return std::isfinite(d); }))
    for (std::size_t k = 0; k < n; ++k) lin.position[k][2] = depth[k];  // (else the interpolated ones stay)
  return start;
}

}  // namespace gesmi
