#include "solver/kalman/chain_factors.h"

namespace gesmi {

ChainFactors::ChainFactors(std::size_t steps, std::size_t mines, bool biases, const KalmanLinearisation& point)
    : mines_(mines), static_count_(3 * mines + (biases ? kBiasCount : 0)), biases_(biases), point_(point),
      g_(biases ? std::max<std::size_t>(steps, 1) : 1, BiasJacobian::Zero()),
      hm_(Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(static_count_))) {}

Vec3d ChainFactors::position_correction(const ArrowheadChain& solved, std::size_t k) const {
  if (!biases_) return solved.mean(k);
  return solved.mean(k) + sensitivity(k) * solved.static_mean().tail<kBiasCount>();
}

void ChainFactors::odometry(std::size_t k, const Mat3d& information, const Vec3d& delta, const BiasJacobian& jacobian) {
  // p_{k+1} - p_k = delta + J (b - b_lin) and G_{k+1} = G_k + J leave, with
  // p'_lin,k = p_lin,k - G_k b_lin, x_{k+1} - x_k = delta - (p_lin,k+1 - p_lin,k).
  if (biases_) g_[k + 1] = g_[k] + jacobian;
  const FlatPoints& p = point_.position;
  chain_step(k, information, ArrowheadChain::relative_step(delta, p[k], p[k + 1]));
}

void ChainFactors::scalar(std::size_t k, const Eigen::RowVector3d& hp, int mine, const Eigen::RowVector3d& hm,
                          const BiasRow& hb, double z, double w, const ConstraintRef* source) {
  // The residual at the point: z - hp . p_lin,k - hm . m_lin - hb . b_lin (the terms of
  // p'_lin and of G_k b_lin cancel).
  double residual = z - hp.dot(point_.position[k]);
  if (mine >= 0) residual -= hm.dot(point_.mine[static_cast<std::size_t>(mine)]);
  if (biases_) residual -= hb.dot(point_.bias);
  if (mine < 0 && !biases_) {
    chain_row(k, hp, Eigen::RowVectorXd(), residual, w, source);
    return;
  }
  hm_.setZero();
  if (mine >= 0) hm_.segment<3>(3 * static_cast<Eigen::Index>(mine)) = hm;
  if (biases_) hm_.tail<kBiasCount>() = hb + hp * g_[k];
  chain_row(k, hp, hm_, residual, w, source);
}

}  // namespace gesmi
