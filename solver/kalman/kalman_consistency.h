#pragma once
// What a competent Kalman user checks (docs/comparison.md): the normalised chi-square
// of the whole fit against its expected band, and a residual test of each GPS fix and
// each mark (normalised residuals and the leave-one-out chi-square).
//
// At the converged estimate the fit is a linear least-squares problem. Its chi-square
// is the sum of every squared residual times its information; with N scalar
// measurements (priors included) and P unknowns it follows chi2(N - P) when the model
// holds. For one input with residual r, noise R and posterior H P H^T = V, the
// prediction error left out of the fit is R (R - V)^-1 r with covariance
// R (R - V)^-1 R, so its chi-square is r^T (R - V)^-1 r on the input's rows (one
// relinearisation short of refitting without it). An input that alone determines what
// it measures (the only mark of a mine) has R - V singular: it cannot be tested.

#include <cstddef>
#include <vector>

#include "solver/network/constraint_ref.h"

namespace gesmi {

/// An input is flagged when its leave-one-out chi-square exceeds this quantile of its
/// law (the probability of |x| <= 3 sigma for one Gaussian).
inline constexpr double kResidualTestProbability = 0.9973;
/// The band of chi2 / dof the fit is expected in.
inline constexpr double kChiSquareBandProbability = 0.95;

struct KalmanConsistency {
  double chi2 = 0.0;
  double dof = 0.0;  // scalar measurements minus unknowns
  double chi2_per_dof = 0.0;
  double band_low = 0.0, band_high = 0.0;  // the central kChiSquareBandProbability of chi2 / dof
  bool consistent = false;                 // chi2 / dof within the band
};

struct InputTest {
  ConstraintRef input;
  double time = 0.0;
  int dof = 0;                   // the input's scalar measurements
  double chi2 = 0.0;             // leave-one-out; NaN when the input cannot be tested
  double max_normalised = 0.0;   // the largest |r_i| / sqrt((R - V)_ii); NaN likewise
  bool flagged = false;
};

/// The central band of chi2(dof) / dof holding `probability`.
void chi_square_band(double dof, double probability, double& low, double& high);
/// The quantile of chi2(dof) at `probability`.
double chi_square_quantile(double dof, double probability);

}  // namespace gesmi
