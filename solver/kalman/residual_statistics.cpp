#include "solver/kalman/residual_statistics.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace gesmi {

ResidualStatistics::ResidualStatistics(const ArrowheadChain& solved, std::size_t mines, bool biases,
                                       const KalmanLinearisation& point)
    : ChainFactors(solved.size(), mines, biases, point), chain_(solved) {}

void ResidualStatistics::chain_step(std::size_t k, const Mat3d& information, const Vec3d& delta) {
  const Vec3d e = chain_.mean(k + 1) - chain_.mean(k) - delta;
  chi2_ += e.dot(information * e);
  rows_ += 3;
}

void ResidualStatistics::chain_row(std::size_t k, const Eigen::RowVector3d& hp, const Eigen::RowVectorXd& hm, double z,
                                   double w, const ConstraintRef* source) {
  double r = z - hp.dot(chain_.mean(k));
  if (hm.size() > 0) r -= hm.dot(chain_.static_mean());
  chi2_ += w * r * r;
  ++rows_;
  if (source) inputs_[*source].push_back({k, hp, hm, z, w});
}

void ResidualStatistics::static_prior(std::size_t j, double z, double w) {
  const double r = z - chain_.static_mean()[static_cast<Eigen::Index>(j)];
  chi2_ += w * r * r;
  ++rows_;
}

KalmanConsistency ResidualStatistics::consistency(std::size_t unknowns) const {
  KalmanConsistency c;
  c.chi2 = chi2_;
  c.dof = static_cast<double>(rows_) - static_cast<double>(unknowns);
  if (!(c.dof > 0.0)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    c.chi2_per_dof = c.band_low = c.band_high = nan;
    return c;
  }
  c.chi2_per_dof = c.chi2 / c.dof;
  chi_square_band(c.dof, kChiSquareBandProbability, c.band_low, c.band_high);
  c.consistent = c.band_low <= c.chi2_per_dof && c.chi2_per_dof <= c.band_high;
  return c;
}

std::vector<InputTest> ResidualStatistics::tests(std::span<const double> time) const {
  const auto q = static_cast<Eigen::Index>(static_count());
  std::vector<InputTest> out;
  for (const auto& [input, rows] : inputs_) {
    const auto n = static_cast<Eigen::Index>(rows.size());
    const std::size_t k = rows.front().k;  // an input's rows are all at its step
    Eigen::MatrixXd hp(n, 3), hm = Eigen::MatrixXd::Zero(n, q);
    Eigen::VectorXd r(n), noise(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Row& row = rows[static_cast<std::size_t>(i)];
      hp.row(i) = row.hp;
      if (row.hm.size() > 0) hm.row(i) = row.hm;
      r[i] = row.z - row.hp.dot(chain_.mean(k)) - (row.hm.size() > 0 ? row.hm.dot(chain_.static_mean()) : 0.0);
      noise[i] = 1.0 / row.w;
    }
    // V = Cov(H x) with x = (p'_k, m).
    const Eigen::MatrixXd cross = chain_.cross_covariance_at(k);  // Cov(p'_k, m)
    const Eigen::MatrixXd hp_cross_hm = hp * cross * hm.transpose();
    const Eigen::MatrixXd v = hp * chain_.covariance(k) * hp.transpose() + hp_cross_hm + hp_cross_hm.transpose() +
                              hm * chain_.static_covariance() * hm.transpose();
    Eigen::MatrixXd c = -v;
    c.diagonal() += noise;
    // Testable when R - V keeps a share of R in every direction (scaled by R^-1/2).
    const Eigen::VectorXd scale = noise.cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd scaled = scale.asDiagonal() * c * scale.asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (scaled + scaled.transpose()),
                                                               Eigen::EigenvaluesOnly);
    InputTest t;
    t.input = input;
    t.time = time[k];
    t.dof = static_cast<int>(n);
    if (eigen.eigenvalues().minCoeff() > 1e-6) {
      t.chi2 = r.dot(c.ldlt().solve(r));
      t.max_normalised = (r.array() / c.diagonal().array().sqrt()).abs().maxCoeff();
      t.flagged = t.chi2 > chi_square_quantile(n, kResidualTestProbability);
    } else {
      t.chi2 = t.max_normalised = std::numeric_limits<double>::quiet_NaN();
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace gesmi
