#pragma once
// The smoother's first linearisation point from the same problem on a coarse chain
// (docs/comparison.md, "Where the linearisations start").
//
// Without biases every factor but the detections' is linear in the positions (the
// depth's variance follows the estimate's depth, a weak dependence), so the passes of the
// Gauss-Newton iteration are spent moving the detections' linearisation point: started
// from the dead reckoning, the reference mission needs three full passes (they move the
// estimate 2.5 m, 8 mm, then 0.02 mm). The coarse chain keeps every kCoarseStride-th
// sample, the last one and the samples of the fixes and of the associated marks, with the
// odometry between two of them summed: its delta the sum of the steps' deltas, its
// covariance the sum of theirs (the marginal of that stretch's odometry); the depth
// readings between them are left out. It holds 1.6 % of the samples. Its positions at
// those samples and its mines, the corrections interpolated in between, are the full
// chain's first linearisation point.
//
// The depth readings err by up to metres, and average out only over all of them: one in
// 64 left the coarse chain's depths centimetres from the full chain's, and the ranges
// carried that into the positions. So the depths come from a scalar smoother of every
// depth reading with the odometry's vertical steps (smoothed_depths()): the coarse chain
// holds its nodes at them, and the start takes them for every step, each vertical step
// conditioned on the coarse solution's horizontal step (the odometry couples the two where
// the robot pitches). From that point the full chain's first pass moved nothing more than
// 0.5 mm on the reference mission and at 10^7 steps: it converges after one pass. The
// full chain still decides, by its own rule, when it has converged: only the point it
// starts from changes.

#include <span>
#include <vector>

#include "solver/kalman/arrowhead_chain.h"
#include "solver/kalman/kalman_measurements.h"
#include "solver/mission/mission.h"
#include "solver/network/mission_network.h"

namespace gesmi {

struct KalmanOptions;

/// A sample in this many is a node of the coarse chain (at 10 Hz, one every 6.4 s).
inline constexpr std::size_t kCoarseStride = 64;

/// The coarse chain's nodes, increasing: every `stride`-th step from 0, the last step, and
/// the steps of the fixes and of the marks associated with a mine (step_at()).
std::vector<std::size_t> coarse_nodes(const Mission& mission, std::span<const PositionFix> fixes, std::size_t stride);

/// The odometry between consecutive nodes: for nodes a < b, the steps a .. b-1 with
/// deltas delta[k] and information W_k become one step of delta sum(delta[k]) and
/// information (sum W_k^-1)^-1.
struct CoarseOdometry {
  std::vector<Vec3d> delta;
  std::vector<ArrowheadChain::Symmetric3> information;
};
CoarseOdometry coarse_odometry(std::span<const std::size_t> nodes, std::span<const Vec3d> delta,
                               std::span<const ArrowheadChain::Symmetric3> information);

/// The depth of every step, from the depth readings (variance depth_variance() at the
/// depth of `point`) and the odometry's vertical steps (delta[k].z, variance the zz entry
/// of W_k^-1), by a scalar Kalman smoother with a weak prior on the first depth. With
/// `conditioned`, each vertical step is the odometry's given the horizontal step between
/// `point`'s positions: delta_z - W_zh r_h / W_zz with r_h = h_{k+1} - h_k - delta_h, of
/// variance 1 / W_zz.
std::vector<double> smoothed_depths(const Mission& mission, const SensorModel& model, double noise_factor,
                                    std::span<const Vec3d> delta,
                                    std::span<const ArrowheadChain::Symmetric3> information, const FlatPoints& point,
                                    bool conditioned);

struct CoarseStart {
  int linearisations = 0;  // of the coarse chain; 0: not started from it
};

/// Moves `lin` (the dead reckoning: every position, no mine placed) to the coarse chain's
/// solution, linearised again until no coordinate moves more than the tolerance, the
/// steps stop shrinking (kStalledStepRatio) or options.max_iterations is reached. `delta`
/// and `information` are the fixed odometry (no biases); `marks` the marks' samples.
/// Nothing is moved (linearisations 0) when the coarse chain would hold more than half
/// the samples, or when its solution is not finite; the depths of every step replace the
/// interpolated ones only where all are finite.
CoarseStart start_from_coarse_chain(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes,
                                    const KalmanOptions& options, std::span<const MarkSample> marks,
                                    std::span<const Vec3d> delta,
                                    std::span<const ArrowheadChain::Symmetric3> information, KalmanLinearisation& lin);

}  // namespace gesmi
