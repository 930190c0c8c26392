#pragma once
// The Kalman smoother's measurement model (seed 001, section VI), linearised at a point:
// every measurement as a factor on the positions p_k, the mines and, in the
// bias-aware variant, nine constant sensor biases b (docs/comparison.md). The
// smoother's builder, its statistics and its tests all read the model from here, so it
// is written once.
//
// Biases are reading errors (reading = truth + bias), one per part of a bound: heading
// (rad); DVL scale per body axis (a relative error: the reading is v (1 + s)) and DVL
// offset per axis (m/s), as the DVL bound is relative plus absolute; the depth's scale
// and offset likewise (reading = d (1 + s) + o). The odometry is linear in the DVL
// biases; the heading's and the depth scale's are linearised.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/constraint_ref.h"
#include "solver/network/mission_network.h"

namespace gesmi {

inline constexpr int kBiasCount = 9;
enum BiasIndex { bias_heading, bias_dvl_scale_x, bias_dvl_offset_x = 4, bias_depth_scale = 7, bias_depth_offset };
using BiasVec = Eigen::Matrix<double, kBiasCount, 1>;
using BiasRow = Eigen::Matrix<double, 1, kBiasCount>;
using BiasJacobian = Eigen::Matrix<double, 3, kBiasCount>;

struct BiasDescription {
  std::string_view name, unit;
};
/// The biases' names and units, in their order in BiasVec.
const std::array<BiasDescription, kBiasCount>& bias_descriptions();
/// Prior standard deviations from the sensor bounds: a bound b is a uniform law on
/// [-b, b], of variance factor * b^2 / 3.
BiasVec bias_prior_sigma(const SensorModel& model, double noise_factor);

/// Variance of a uniform law on [-bound, bound], scaled by the noise factor.
inline double uniform_variance(double bound, double factor) { return factor * bound * bound / 3.0; }
/// A depth reading's variance where the estimate's depth is `depth` (the bound grows with
/// the depth; evaluated at the estimate, not at the reading: linearise_measurements()).
inline double depth_variance(const SensorModel& model, double depth, double factor) {
  return uniform_variance(model.depth_absolute + model.depth_relative * std::fabs(depth), factor);
}

/// Points p_0..p_{n-1} stored flat, three numbers each (x0 y0 z0 x1 ...): the
/// linearisation point's positions, whose storage becomes the smoother's means (at 10^7
/// steps a second 240 MB array cost the kernel's zeroing of its pages).
class FlatPoints {
 public:
  void assign(std::size_t n, const Vec3d& p) {
    values_.resize(3 * n);
    for (std::size_t k = 0; k < n; ++k) (*this)[k] = p;
  }
  void push_back(const Vec3d& p) { values_.insert(values_.end(), p.data(), p.data() + 3); }
  std::size_t size() const { return values_.size() / 3; }
  Eigen::Map<Vec3d> operator[](std::size_t k) { return Eigen::Map<Vec3d>(values_.data() + 3 * k); }
  Eigen::Map<const Vec3d> operator[](std::size_t k) const { return Eigen::Map<const Vec3d>(values_.data() + 3 * k); }
  /// The three numbers of every point, in order.
  std::span<const double> values() const { return values_; }
  /// Moves the numbers out (no copy); no points are left.
  std::vector<double> take() {
    std::vector<double> taken = std::move(values_);
    values_.clear();
    return taken;
  }

 private:
  std::vector<double> values_;
};

/// Where the model is linearised: positions, mines, biases.
struct KalmanLinearisation {
  FlatPoints position;          // per step
  std::vector<Vec3d> mine;      // per mine
  std::vector<char> mine_known; // placed at its first detection
  BiasVec bias = BiasVec::Zero();
};

/// Receives the linearised factors, in this order: every odometry step (k increasing),
/// then the scalar measurements.
class MeasurementSink {
 public:
  virtual ~MeasurementSink() = default;
  /// p_{k+1} - p_k = delta + jacobian (b - b_lin), with information `information`.
  virtual void odometry(std::size_t k, const Mat3d& information, const Vec3d& delta, const BiasJacobian& jacobian) = 0;
  /// z = hp . p_k + hm . m_mine + hb . b, with information w (mine -1: none). `source` is
  /// the mark or fix it comes from, if any (depth readings have none).
  virtual void scalar(std::size_t k, const Eigen::RowVector3d& hp, int mine, const Eigen::RowVector3d& hm,
                      const BiasRow& hb, double z, double w, const ConstraintRef* source) = 0;
};

/// Which factors linearise_measurements() generates.
enum class FactorSet {
  all,
  odometry,          // the odometry steps alone (a dead reckoning)
  without_odometry,  // the scalar measurements alone (an odometry kept from an earlier pass)
};

/// What the detections read of the navigation: the attitude and altitude at a mark's
/// step (step_at() of its time).
struct MarkSample {
  double roll = 0.0, pitch = 0.0, heading = 0.0, altitude = 0.0;
};
/// One per mark of the mission, in table order (the mission's attitude and altitude
/// must be there); none for a mission without samples.
std::vector<MarkSample> mark_samples(const Mission& mission);

struct MeasurementOptions {
  double noise_factor = 1.0;
  bool biases = false;  // compute the bias terms (zero otherwise)
  FactorSet factors = FactorSet::all;
  /// The marks' samples (mark_samples()), computed once for every pass; empty: read
  /// from the mission. A view: the samples must outlive these options.
  std::span<const MarkSample> marks{};
};

/// Generates the factors at `lin`; places a mine not yet placed at its first
/// detection (in the sonar plane, on the declared side, below the robot by the altitude).
void linearise_measurements(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes,
                            const MeasurementOptions& options, KalmanLinearisation& lin, MeasurementSink& sink);

/// The step of each fix (the first sample at or after its time).
std::size_t step_at(const Mission& mission, double time);

}  // namespace gesmi
