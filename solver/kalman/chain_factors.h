#pragma once
// The measurement model's factors (kalman_measurements.h) in the terms of the chain
// solver (arrowhead_chain.h): positions p_k on the chain, and the static unknowns m =
// (mines, biases). With biases, the chain carries p'_k = p_k - G_k b instead of p_k,
// where G_k is the odometry's sensitivity to the biases summed from the start: the
// odometry between the p' is then free of the biases (a chain factor), and each
// measurement on p_k becomes one on p'_k and b (hp G_k), a mixed factor.
//
// The chain's unknowns are the corrections from the linearisation point (p_k = p_lin,k +
// x_k, m = m_lin + dm, b = b_lin + db): every factor is given as its residual at that
// point. In positions, a chain of 10^7 steps left a rounding floor of 2-12 mm in the
// means, from the kilometres its information vectors carried; in corrections the
// rounding scales with the corrections, and the iteration converges instead of stalling
// (docs/comparison.md, "When the smoother stops"). The chain's own weak prior on the static
// unknowns (ArrowheadChain's prior_info) is then one on their corrections: a damping of
// 1e-12, where it pulled the mines and biases toward zero.

#include <Eigen/Core>
#include <vector>

#include "solver/kalman/arrowhead_chain.h"
#include "solver/kalman/kalman_measurements.h"

namespace gesmi {

class ChainFactors : public MeasurementSink {
 public:
  /// mines: the mine count; biases: whether the last kBiasCount static unknowns are the
  /// biases. The unknowns are corrections from `point`, which must outlive this object
  /// (a mine placed while the factors are generated is read when its rows come).
  ChainFactors(std::size_t steps, std::size_t mines, bool biases, const KalmanLinearisation& point);

  std::size_t static_count() const { return static_count_; }
  std::size_t bias_offset() const { return 3 * mines_; }  // the first bias among the static unknowns
  bool biases() const { return biases_; }
  /// G_k: p_k = p'_k + G_k b (zero without biases).
  const BiasJacobian& sensitivity(std::size_t k) const { return g_[biases_ ? k : 0]; }
  /// The correction of p_k from the point, given the chain's solution: x_k + G_k db.
  Vec3d position_correction(const ArrowheadChain& solved, std::size_t k) const;

  void odometry(std::size_t k, const Mat3d& information, const Vec3d& delta, const BiasJacobian& jacobian) final;
  void scalar(std::size_t k, const Eigen::RowVector3d& hp, int mine, const Eigen::RowVector3d& hm, const BiasRow& hb,
              double z, double w, const ConstraintRef* source) final;

 protected:
  /// x_{k+1} - x_k = delta with information W (the corrections of p').
  virtual void chain_step(std::size_t k, const Mat3d& information, const Vec3d& delta) = 0;
  /// z = hp . x_k + hm . (dm, db) with information w; hm empty when it would be zero.
  virtual void chain_row(std::size_t k, const Eigen::RowVector3d& hp, const Eigen::RowVectorXd& hm, double z, double w,
                         const ConstraintRef* source) = 0;

 private:
  std::size_t mines_, static_count_;
  bool biases_;
  const KalmanLinearisation& point_;
  std::vector<BiasJacobian> g_;  // per step, with biases only (one entry otherwise)
  Eigen::RowVectorXd hm_;        // reused
};

/// The weak prior on the first position (GPS may be absent: p_0 near the origin), as a
/// residual at the point (with the biases' priors, the only factors not from a measurement).
inline void add_first_position_prior(ArrowheadChain& chain, const KalmanLinearisation& point) {
  chain.add_position(0, Mat3d::Identity() * 1e-10, -point.position[0]);
}

/// Adds the factors to a chain.
class ChainBuilder final : public ChainFactors {
 public:
  ChainBuilder(ArrowheadChain& chain, std::size_t mines, bool biases, const KalmanLinearisation& point)
      : ChainFactors(chain.size(), mines, biases, point), chain_(chain) {}

 private:
  void chain_step(std::size_t k, const Mat3d& information, const Vec3d& delta) override {
    chain_.add_step(k, information, delta);
  }
  void chain_row(std::size_t k, const Eigen::RowVector3d& hp, const Eigen::RowVectorXd& hm, double z, double w,
                 const ConstraintRef*) override {
    if (hm.size() == 0)
      chain_.add_position_row(k, hp, z, w);
    else
      chain_.add_mixed(k, hp, hm, z, w);
  }
  ArrowheadChain& chain_;
};

}  // namespace gesmi
