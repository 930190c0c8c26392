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

bool finite(const Vec3d& v) { return v.allFinite(); }

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

CoarseStart start_from_coarse_chain(const Mission& m, const SensorModel& model, std::span<const PositionFix> fixes,
                                    const KalmanOptions& o, std::span<const MarkSample> marks,
                                    std::span<const Vec3d> delta,
                                    std::span<const ArrowheadChain::Symmetric3> information, KalmanLinearisation& lin) {
  const std::size_t n = m.size(), k_mines = static_cast<std::size_t>(m.mine_count);
  if (o.biases) throw std::logic_error("start_from_coarse_chain: the odometry depends on the biases");
  const std::vector<std::size_t> nodes = coarse_nodes(m, fixes, kCoarseStride);
  if (nodes.size() < 2 || 2 * nodes.size() > n) return {};  // not worth a second chain
  const std::size_t nc = nodes.size();
  const Mission coarse = mission_at_nodes(m, nodes);
  CoarseOdometry odometry = coarse_odometry(nodes, delta, information);
  KalmanLinearisation point;
  point.position.assign(nc, Vec3d::Zero());
  for (std::size_t i = 0; i < nc; ++i) point.position[i] = lin.position[nodes[i]];
  point.mine.assign(k_mines, Vec3d::Zero());
  point.mine_known.assign(k_mines, 0);
  ArrowheadChain chain(nc, 3 * k_mines, std::move(odometry.information));
  const MeasurementOptions measurements{o.noise_factor, false, FactorSet::without_odometry, marks};
  CoarseStart start{0, nc};
  double previous_step = std::numeric_limits<double>::infinity();
  while (start.linearisations < o.max_iterations) {
    ChainBuilder builder(chain, k_mines, false, point);
    chain.reset_keeping_steps();
    chain.add_steps_again(odometry.delta, point.position.values());
    add_first_position_prior(chain, point);
    linearise_measurements(coarse, model, fixes, measurements, point, builder);
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
    if (!finite(point.position[i])) return {};
  for (std::size_t i = 0; i < k_mines; ++i)
    if (point.mine_known[i] && !finite(point.mine[i])) return {};
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
  return start;
}

}  // namespace gesmi
