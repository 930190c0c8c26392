#pragma once
// The consistency checks of kalman_consistency.h evaluated on a solved chain: the
// factors of the last linearisation are generated again (in chain terms) and each
// residual is taken at the solution.

#include <map>
#include <vector>

#include "solver/kalman/chain_factors.h"
#include "solver/kalman/kalman_consistency.h"

namespace gesmi {

class ResidualStatistics final : public ChainFactors {
 public:
  /// `solved` must keep the cross covariances at the steps of the tested inputs.
  ResidualStatistics(const ArrowheadChain& solved, std::size_t mines, bool biases, const KalmanLinearisation& point);
  /// A prior z = dm_j with information w (the biases', as a residual at the point).
  void static_prior(std::size_t j, double z, double w);
  /// The whole fit, given the number of unknowns it determines.
  KalmanConsistency consistency(std::size_t unknowns) const;
  /// One test per GPS fix and mark, in the order of the inputs; times from `time`.
  std::vector<InputTest> tests(std::span<const double> time) const;

 private:
  struct Row {
    std::size_t k;
    Eigen::RowVector3d hp;
    Eigen::RowVectorXd hm;  // empty: zero
    double z, w;
  };
  void chain_step(std::size_t k, const Mat3d& information, const Vec3d& delta) override;
  void chain_row(std::size_t k, const Eigen::RowVector3d& hp, const Eigen::RowVectorXd& hm, double z, double w,
                 const ConstraintRef* source) override;

  const ArrowheadChain& chain_;
  double chi2_ = 0.0;
  std::size_t rows_ = 0;
  std::map<ConstraintRef, std::vector<Row>> inputs_;
};

}  // namespace gesmi
