#include "solver/kalman/chain_factors.h"

namespace gesmi {

ChainFactors::ChainFactors(std::size_t steps, std::size_t mines, bool biases, const BiasVec& bias_lin)
    : mines_(mines), static_count_(3 * mines + (biases ? kBiasCount : 0)), biases_(biases), bias_lin_(bias_lin),
      g_(biases ? std::max<std::size_t>(steps, 1) : 1, BiasJacobian::Zero()),
      hm_(Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(static_count_))) {}

void ChainFactors::odometry(std::size_t k, const Mat3d& information, const Vec3d& delta, const BiasJacobian& jacobian) {
  if (!biases_) {
    chain_step(k, information, delta);
    return;
  }
  // p_{k+1} - p_k = delta + J (b - b_lin) and G_{k+1} = G_k + J leave
  // p'_{k+1} - p'_k = delta - J b_lin.
  g_[k + 1] = g_[k] + jacobian;
  chain_step(k, information, delta - jacobian * bias_lin_);
}

void ChainFactors::scalar(std::size_t k, const Eigen::RowVector3d& hp, int mine, const Eigen::RowVector3d& hm,
                          const BiasRow& hb, double z, double w, const ConstraintRef* source) {
  if (mine < 0 && !biases_) {
    chain_row(k, hp, Eigen::RowVectorXd(), z, w, source);
    return;
  }
  hm_.setZero();
  if (mine >= 0) hm_.segment<3>(3 * static_cast<Eigen::Index>(mine)) = hm;
  if (biases_) hm_.tail<kBiasCount>() = hb + hp * g_[k];
  chain_row(k, hp, hm_, z, w, source);
}

}  // namespace gesmi
